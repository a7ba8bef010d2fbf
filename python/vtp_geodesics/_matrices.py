"""Distance matrices (private; ``vtp_geodesics.Solver.matrix``): one row per source, the rows on all cores,
dense or sparse (scipy.sparse.csr_matrix) within a limit."""

import math as _math

import numpy as _np

from ._arguments import check_float, check_method, check_threads, recommended_lambda, vertex_list


class Matrices:
    """The distance matrices of ``Solver`` (which holds the compiled solver ``_core``)."""

    def matrix(self, sources=None, *, targets=None, max_distance=_math.inf, dtype=_np.float64, threads=0,
               progress=False, method="vtp", lam=recommended_lambda):
        """Distance matrix, one row per source, rows computed in parallel on all cores.

        Parameters
        ----------
        sources : array-like of int, optional
            Row sources (vertex indices; may repeat). Default: every vertex (an n x n matrix).
        targets : array-like of int, optional
            Columns (vertex indices). Default: every vertex.
        max_distance : float, default inf
            With a finite limit, each row's propagation stops at it and the result is a
            ``scipy.sparse.csr_matrix`` holding exactly the entries <= max_distance (including the 0 of a
            source in its own column); without, a dense ndarray.
        dtype : numpy.float64 or numpy.float32
            Type of the entries. float32 is written directly (no float64 copy of the matrix is made):
            each entry is the float64 distance rounded to float32.
        threads : int, default 0
            Rows computed at the same time (0: the solver's ``threads``, all cores by default).
        progress : bool, default False
            Write "rows done / total" to stderr about five times a second.
        method : "vtp" or "avtp", default "vtp"
            Each row is computed on one thread; "pvtp" and "pavtp" give the same rows as "vtp" and "avtp".
        lam : float, default ``vtp_geodesics.recommended_lambda``
            Reset step of "avtp".

        Returns
        -------
        ndarray (len(sources), len(targets)) of ``dtype`` with ``inf`` where unreachable, or
        scipy.sparse.csr_matrix of that shape and dtype when ``max_distance`` is finite. Row i is bitwise
        the result of ``distances(sources[i])`` (restricted to the targets).

        Ctrl-C (KeyboardInterrupt) stops the computation: no new row starts, the rows under way finish
        (within about one row's time), and KeyboardInterrupt is raised; no thread is left running.
        """
        src = _np.arange(self._n, dtype=_np.int64) if sources is None else vertex_list(sources, "sources")
        all_columns = targets is None
        cols = _np.zeros(0, dtype=_np.int64) if all_columns else vertex_list(targets, "targets")
        dt = _np.dtype(dtype)
        if dt not in (_np.dtype(_np.float64), _np.dtype(_np.float32)):
            raise TypeError("dtype must be numpy.float64 or numpy.float32, got %s" % dt)
        single = dt == _np.dtype(_np.float32)
        limit = check_float(max_distance, "max_distance")
        method = check_method(method)
        if method in ("pvtp", "pavtp"):
            method = method[1:]
        if limit < 0 or limit != limit:
            raise ValueError("max_distance must be >= 0 (inf for none), got %r" % max_distance)
        args = (src, cols, all_columns, limit, single, method, check_float(lam, "lam"), check_threads(threads),
                bool(progress))
        ncols = self._n if all_columns else cols.shape[0]
        if limit < _math.inf:
            import scipy.sparse
            data, indices, indptr = self._core.matrix_sparse(*args)
            return scipy.sparse.csr_matrix((data, indices, indptr), shape=(src.shape[0], ncols), copy=False)
        return self._core.matrix_dense(*args)
