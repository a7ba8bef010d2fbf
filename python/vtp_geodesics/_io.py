"""Reading mesh files (private; see ``vtp_geodesics.read_mesh``)."""

import os as _os
import warnings as _warnings

from . import _core
from ._arguments import check_threads


def read_mesh(path, *, threads=0, repair=True):
    """Reads a mesh file with the readers of the command-line tools: ``read_mesh(path) -> (V, F)``.

    Reads OFF, OBJ, PLY, STL and GOCAD TS files (the format comes from the extension).

    With ``repair=True`` (the default), a file that is not a valid triangle mesh is repaired as
    ``vtp_geodesics`` (the tool) repairs it: polygons triangulated, duplicate points merged, degenerate faces
    removed, faces reoriented, non-manifold vertices duplicated; what was done is reported as a
    ``UserWarning``, and V and F are then **those of the repaired mesh** (vertices appended, dropped or
    merged: not the file's numbering). A valid triangle mesh is returned as it is in the file.

    With ``repair=False``, V and F are **the file's own** vertices and triangles, in the file's order, as
    they are (``Solver(V, F)`` then repairs them the same way and gives every result on the file's vertex
    numbers, as the tool does); a file with faces of more than three vertices raises ValueError.

    The first ``Solver(V, F)`` built on the arrays returned (the same faces and number of vertices) counts
    this reading in its ``statistics`` (``read_seconds``, and the check of the faces in ``repair_seconds``),
    and builds its mesh from that check of a valid OFF file instead of checking the faces again; the record is
    kept until then, or until the next ``read_mesh()``.

    Returns ``V``, float64 array (n, 3) of vertex coordinates, and ``F``, int64 array (m, 3) of vertex
    indices (0-based) of the triangles. Raises FileNotFoundError if there is no such file, ValueError if the
    file cannot be read or used (the message names the problem).
    """
    path = _os.fspath(path)
    if not _os.path.exists(path):
        raise FileNotFoundError("no such file: '%s'" % path)
    V, F, repairs, _reader, _direct = _core.read_mesh(path, check_threads(threads), not repair)
    if repairs:
        _warnings.warn("read_mesh('%s'): the file is not a valid triangle mesh and was repaired: %s"
                       % (path, repairs), UserWarning, stacklevel=2)
    return V, F
