"""The arguments of the package's functions, converted and checked (private).

Every check of a type, a dtype or a shape is here, and only here: the compiled layer (``_core``) takes the
C-ordered float64 and int64 arrays made here and checks the values (indices in range, finite coordinates,
barycentric coordinates, a manifold mesh, the method, the limits). Python is the place for these checks because
it is where the arguments are normalised (an int or a list becomes an array, a point a row, ``(face,
barycentric)`` pairs and xyz positions are told apart), so that the messages name what the user gave.
"""

import numpy as _np

from . import _core

#: The methods of the library (names for ``method=``), from its method table.
methods = tuple(m["name"] for m in _core.method_table() if m["available"])

#: The window-reset step (in mean edge lengths) recommended for the approximate methods: the default of
#: ``lam``.
recommended_lambda = _core.recommended_lambda


class _VertexZero(int):
    """The default of ``sources``: vertex 0, unless ``points`` are given (then no vertex)."""

    def __repr__(self):
        return "0"


SOURCE_DEFAULT = _VertexZero(0)


def source_vertices(sources, points):
    """``sources`` (``SOURCE_DEFAULT``, an int or an array-like of them) -> int64 (k,)."""
    if sources is SOURCE_DEFAULT and points is not None:
        return _np.zeros(0, dtype=_np.int64)
    return vertex_list(sources, "sources")


def query_sources(sources, points, locate):
    """The sources of a query, checked (the one preamble of distances(), path(), log_map() and the curves): the
    vertices of ``sources`` int64 (k,), and the ``points`` as faces int64 (m,) and barycentric float64 (m, 3).
    Raises ValueError if there is none."""
    src = source_vertices(sources, points)
    pf, pb = surface_points(points, locate)
    if src.size == 0 and pf.size == 0:
        raise ValueError("no source: sources is empty and no points are given")
    return src, pf, pb


def as_float_array(x, name):
    try:
        a = _np.asarray(x)
    except Exception as e:  # ragged lists and the like
        raise ValueError("%s cannot be read as an array of numbers: %s" % (name, e)) from None
    if a.dtype.kind not in "fiu" or a.dtype == _np.bool_:
        raise TypeError("%s must hold real numbers, got dtype %s" % (name, a.dtype))
    return _np.ascontiguousarray(a, dtype=_np.float64)


def as_index_array(x, name, ndim=None):
    try:
        a = _np.asarray(x)
    except Exception as e:
        raise ValueError("%s cannot be read as an array of indices: %s" % (name, e)) from None
    if a.size == 0 and a.dtype.kind == "f":  # an empty list comes out as float64
        a = a.astype(_np.int64)
    if a.dtype.kind not in "iu" or a.dtype == _np.bool_:
        raise TypeError("%s must hold integer indices, got dtype %s" % (name, a.dtype))
    if a.dtype.kind == "u" and a.size and a.max() > _np.iinfo(_np.int64).max:
        raise ValueError("%s: index out of range" % name)
    a = _np.ascontiguousarray(a, dtype=_np.int64)
    if ndim is not None and a.ndim != ndim:
        raise ValueError("%s must be %d-dimensional, got shape %s" % (name, ndim, a.shape))
    return a


def mesh_arrays(V, F):
    """V, F -> float64 (n, 3), int64 (m, 3)."""
    V = as_float_array(V, "V")
    F = as_index_array(F, "F")
    if V.ndim != 2 or V.shape[1] != 3:
        raise ValueError("V must have shape (n, 3), got shape %s" % (V.shape,))
    if F.ndim != 2 or F.shape[1] != 3:
        raise ValueError("F must have shape (m, 3) (triangles), got shape %s" % (F.shape,))
    return V, F


def vertex_list(x, name):
    """An int or an array-like of vertex indices -> int64 (k,)."""
    if x is None:
        return _np.zeros(0, dtype=_np.int64)
    if isinstance(x, (bool, _np.bool_)):
        raise TypeError("%s must be a vertex index or an array of them, got a bool" % name)
    a = as_index_array(x, name)
    if a.ndim == 0:
        a = a.reshape(1)
    if a.ndim != 1:
        raise ValueError("%s must be a vertex index or a 1-dimensional array of them, got shape %s" % (name, a.shape))
    return a


def xyz_rows(xyz):
    """The positions ``xyz`` of ``locate()``, one (3,) or several (k, 3) -> float64 (k, 3)."""
    xyz = as_float_array(xyz, "xyz")
    if xyz.ndim == 1:
        xyz = xyz.reshape(1, -1)
    if xyz.ndim != 2 or xyz.shape[1] != 3:
        raise ValueError("points must have shape (k, 3), got shape %s" % (xyz.shape,))
    return xyz


def xyz_rows_named(xyz, name):
    """Positions (k, 3) named ``name`` in the messages -> float64 (k, 3)."""
    a = as_float_array(xyz, name)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError("%s must be xyz rows of shape (k, 3) or (faces, barycentric) arrays, got shape %s"
                         % (name, a.shape))
    return a


def surface_points(points, locate, name="points"):
    """``points`` -> (faces int64 (k,), barycentric float64 (k, 3)) in the order given: ``(faces, barycentric)``
    arrays as they are, xyz positions (k, 3) through ``locate`` (their nearest surface points); None: none."""
    if points is None:
        return _np.zeros(0, dtype=_np.int64), _np.zeros((0, 3), dtype=_np.float64)
    if isinstance(points, tuple) and len(points) == 2:
        faces = as_index_array(points[0], name + " faces")
        bary = as_float_array(points[1], name + " barycentric coordinates")
        if faces.ndim == 0:
            faces = faces.reshape(1)
        if bary.ndim == 1:
            bary = bary.reshape(1, -1)
        if faces.ndim != 1 or bary.ndim != 2 or bary.shape != (faces.shape[0], 3):
            raise ValueError("%s: (faces, barycentric) must have shapes (k,) and (k, 3), got %s and %s"
                             % (name, faces.shape, bary.shape))
        return faces, bary
    xyz = as_float_array(points, name)
    if xyz.ndim == 1:
        xyz = xyz.reshape(1, -1)
    if xyz.ndim != 2 or xyz.shape[1] != 3:
        raise ValueError("%s must be (faces, barycentric) arrays or xyz rows of shape (k, 3), got shape %s"
                         % (name, xyz.shape))
    return locate(xyz)


def vertices_or_points(points, locate, name="points"):
    """Vertex indices (an int or an integer array (k,)), ``(faces, barycentric)`` arrays or xyz positions (k, 3)
    (their nearest surface points) -> (vertices int64 (k,) or empty, faces int64 (k,), barycentric float64
    (k, 3)): the vertices if given, else the points."""
    if isinstance(points, (bool, _np.bool_)):
        raise TypeError("%s must be vertex indices or points, got a bool" % name)
    if not (isinstance(points, tuple) and len(points) == 2):
        a = _np.asarray(points)
        if a.size == 0:
            return _np.zeros(0, dtype=_np.int64), _np.zeros(0, dtype=_np.int64), _np.zeros((0, 3), dtype=_np.float64)
        if a.dtype.kind in "iu" and a.dtype != _np.bool_:
            if a.ndim > 1:
                raise ValueError("%s: integer arrays are vertex indices, one index or a 1-D array, got shape %s "
                                 "(give xyz positions as floats)" % (name, a.shape))
            vertices = as_index_array(a, name).reshape(-1)
            return vertices, _np.zeros(0, dtype=_np.int64), _np.zeros((0, 3), dtype=_np.float64)
        points = a
    faces, bary = surface_points(points, locate, name)
    return _np.zeros(0, dtype=_np.int64), faces, bary


def one_point(x, locate, name):
    """A vertex index, a (face, barycentric) pair or an xyz position -> (vertex, face, barycentric (1, 3)): the
    vertex, or -1 and the point."""
    if isinstance(x, (bool, _np.bool_)):
        raise TypeError("%s must be a vertex index or a point, got a bool" % name)
    if isinstance(x, (int, _np.integer)):
        return int(x), -1, _np.zeros((1, 3))
    if isinstance(x, tuple) and len(x) == 2 and _np.ndim(x[0]) == 0:
        faces, bary = surface_points((_np.asarray([x[0]]), _np.asarray(x[1], dtype=float).reshape(1, -1)), locate,
                                     name)
    else:
        a = _np.asarray(x)
        if a.ndim == 0 and a.dtype.kind in "iu":
            return int(a), -1, _np.zeros((1, 3))
        faces, bary = surface_points(a, locate, name)
        if faces.shape[0] != 1:
            raise ValueError("%s must be one vertex or one point, got %d points" % (name, faces.shape[0]))
    return -1, int(faces[0]), bary.reshape(1, 3)


def check_float(x, name):
    if isinstance(x, (bool, _np.bool_)):
        raise TypeError("%s must be a number, got a bool" % name)
    try:
        return float(x)
    except (TypeError, ValueError):
        raise TypeError("%s must be a number, got %r" % (name, x)) from None


def check_threads(threads):
    if isinstance(threads, (bool, _np.bool_)) or not isinstance(threads, (int, _np.integer)):
        raise TypeError("threads must be an int, got %r" % (threads,))
    if threads < 0:
        raise ValueError("threads must be >= 0 (0: all cores), got %d" % threads)
    return int(threads)


def check_method(method):
    if not isinstance(method, str):
        raise TypeError("method must be a string (one of %s), got %r" % (", ".join(methods), method))
    return method.lower()


def trace_starts(start, locate):
    """The start(s) of ``trace()`` -> (batch, vertices int64 (n,) (-1: a point), faces int64 (n,), barycentric
    (n, 3)): a vertex index or an array of them, a (face, barycentric) pair or (faces, barycentric) arrays, xyz
    (3,) or (n, 3) (their nearest surface points)."""
    if isinstance(start, (bool, _np.bool_)):
        raise TypeError("start must be a vertex index or a point, got a bool")
    if isinstance(start, tuple) and len(start) == 2:
        batch = _np.ndim(start[0]) > 0
        faces, bary = surface_points(start, locate, "start")
    else:
        a = _np.asarray(start)
        if a.dtype.kind in "iu" and a.dtype != _np.bool_:
            if a.ndim > 1:
                raise ValueError("start: vertex indices must be one index or a 1-D array")
            batch = a.ndim == 1  # (ascontiguousarray makes a scalar 1-D)
            vertices = as_index_array(a, "start").reshape(-1)
            n = vertices.shape[0]
            return batch, vertices, _np.full(n, -1, dtype=_np.int64), _np.zeros((n, 3))
        batch = a.ndim == 2
        faces, bary = surface_points(a, locate, "start")
    n = faces.shape[0]
    return batch, _np.full(n, -1, dtype=_np.int64), faces, bary


def trace_directions(direction, length, n, batch):
    """The directions (n, 2) or (n, 3) and the lengths (n,) of ``trace()``: one direction or length is used for
    every start."""
    d = as_float_array(direction, "direction")
    if d.ndim == 1 and _np.ndim(direction) == 1:
        d = _np.broadcast_to(d, (n, d.shape[0]))
    if d.ndim != 2 or d.shape[0] != n or d.shape[1] not in (2, 3):
        raise ValueError("direction must be a 2D or 3D vector%s, got shape %s"
                         % (" or one per start (n, 2) or (n, 3)" if batch else "", _np.shape(direction)))
    scalar = _np.ndim(length) == 0
    length_array = as_float_array(length, "length")
    if scalar:
        length_array = _np.full(n, float(length_array.reshape(-1)[0]))
    if length_array.shape != (n,):
        raise ValueError("length must be a number%s, got shape %s" % (" or one per start (n,)" if batch else "",
                                                                    length_array.shape))
    return _np.ascontiguousarray(d), length_array


def merge_alias(value, default, alias, name, alias_name):
    """The value of a keyword argument that has an old name kept as an alias (``alias_name``, None when not given):
    the alias's value if it is given (and the new name is not), else ``value``."""
    if alias is None:
        return value
    if value is not default and not (value is None and default is None):
        raise TypeError("%s and its alias %s are both given: give one" % (name, alias_name))
    return alias
