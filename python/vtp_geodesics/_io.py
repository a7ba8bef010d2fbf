"""Reading mesh files (private; see ``vtp_geodesics.read_mesh``)."""

import os as _os
import warnings as _warnings

from . import _core
from ._arguments import check_threads


def read_mesh(path, *, threads=0):
    """Reads a mesh file with the readers of the command-line tools: ``read_mesh(path) -> (V, F)``.

    Reads OFF, OBJ, PLY, STL and GOCAD TS files (the format comes from the extension). A file that is not a
    valid triangle mesh is repaired as ``vtp_geodesics`` (the tool) repairs it: polygons triangulated,
    duplicate points merged, degenerate faces removed, faces reoriented, non-manifold vertices duplicated;
    what was done is reported as a ``UserWarning``, and the vertices are then those of the repaired mesh.

    Returns ``V``, float64 array (n, 3) of vertex coordinates, and ``F``, int64 array (m, 3) of vertex
    indices (0-based) of the triangles. Raises FileNotFoundError if there is no such file, ValueError if the
    file cannot be read or used (the message names the problem).
    """
    path = _os.fspath(path)
    if not _os.path.exists(path):
        raise FileNotFoundError("no such file: '%s'" % path)
    V, F, repairs, _reader, _direct = _core.read_mesh(path, check_threads(threads))
    if repairs:
        _warnings.warn("read_mesh('%s'): the file is not a valid triangle mesh and was repaired: %s"
                       % (path, repairs), UserWarning, stacklevel=2)
    return V, F
