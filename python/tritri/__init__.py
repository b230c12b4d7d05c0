"""tritri: exact triangle-triangle intersection classification and mesh arrangements.

    import numpy as np, tritri
    a = [[0, 0, 0], [2, 0, 0], [0, 2, 0]]
    b = [[0.5, 0.5, -1], [0.5, 0.5, 1], [0.5, -1, 0.5]]
    r = tritri.classify(a, b)
    r.points    # [('EA_CROSS_TB', 0, -1), ('EB_CROSS_TA', 0, -1)]
    r.segments  # [(0, 1)]

Functions (every decision is an exact predicate on the input doubles, no tolerances):
    classify(a, b)                     -> Result
    self_intersections(V, F)           -> (pairs, results)
    intersections(V1, F1, V2, F2)      -> (pairs, results)
    arrange(V, F, labels=None, classifier="tritri", threads=0) -> dict

Arguments are anything numpy.asarray accepts: V as n x 3 coordinates (converted to
float64), F as m x 3 integer vertex indices (any integer dtype). Refused input (wrong
shape, NaN or infinite coordinates, an index out of range, an unknown classifier, a mesh
the pipeline cannot arrange) raises ValueError with a message naming the argument and the
entry. The C++ work runs without the GIL.
"""

import numpy as _np

from ._tritri import Result
from ._tritri import arrange as _arrange
from ._tritri import classify as _classify
from ._tritri import intersections as _intersections
from ._tritri import load_mesh as _load_mesh
from ._tritri import self_intersections as _self_intersections

__all__ = ["Result", "classify", "self_intersections", "intersections", "arrange", "load_mesh"]
__version__ = "0.1.0"


def _float_array(x, name, function):
    try:
        a = _np.asarray(x, dtype=_np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"tritri.{function}: {name} is not an array of numbers ({e})") from None
    return a


def _vertices(x, name, function):
    a = _float_array(x, name, function)
    if a.size == 0:
        return _np.zeros((0, 3), dtype=_np.float64)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"tritri.{function}: {name} must be an n x 3 array of vertex coordinates, "
                         f"got shape {a.shape}")
    return _np.ascontiguousarray(a)


def _faces(x, name, function):
    try:
        a = _np.asarray(x)
    except (TypeError, ValueError) as e:
        raise ValueError(f"tritri.{function}: {name} is not an array of indices ({e})") from None
    if a.size == 0:
        return _np.zeros((0, 3), dtype=_np.int64)
    if a.dtype.kind not in "iu":
        raise ValueError(f"tritri.{function}: {name} must hold integer vertex indices, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"tritri.{function}: {name} must be an m x 3 array of vertex indices, "
                         f"got shape {a.shape}")
    if a.dtype.kind == "u" and a.max() > _np.iinfo(_np.int64).max:
        raise ValueError(f"tritri.{function}: {name} has an index out of range ({a.max()})")
    return _np.ascontiguousarray(a, dtype=_np.int64)


def classify(a, b):
    """Classifies exactly how triangles a and b intersect.

    a, b: 3 x 3 arrays, one vertex per row (finite). Returns a Result:
      points     list of (type, id0, id1): every corner of the intersection, named by the
                 two sub-simplices that meet there; type is the C++ enum's name
                 (VA_ON_VB, VA_ON_EB, VB_ON_EA, VA_ON_TB, VB_ON_TA, EA_CROSS_EB,
                 EA_CROSS_TB, EB_CROSS_TA); vertices are 0, 1, 2 (rows), edge k joins
                 vertices k and (k+1)%3, -1 where no id applies; sorted
      segments   list of (p0, p1) indices into points
      coplanar   the triangles lie in one plane
      degenerate a triangle has repeated or collinear vertices and was not classified
      intersects at least one point
    """
    ta, tb = _float_array(a, "a", "classify"), _float_array(b, "b", "classify")
    for t, name in ((ta, "a"), (tb, "b")):
        if t.shape != (3, 3):
            raise ValueError(f"tritri.classify: {name} must be a 3 x 3 array (one vertex per row), "
                             f"got shape {t.shape}")
    return _classify(_np.ascontiguousarray(ta), _np.ascontiguousarray(tb))


def self_intersections(V, F):
    """Every pair of triangles of one mesh that intersect beyond the vertices they share.

    V: n x 3 coordinates; F: m x 3 vertex indices. Returns (pairs, results):
      pairs    k x 2 int64 array of rows (i, j) of F, i < j, sorted
      results  list of k Result, classify(V[F[i]], V[F[j]])
    Vertices are shared by index. A pair is reported when its intersection has a point
    other than a shared vertex (VA_ON_VB of corners with the same index), or when both
    rows have the same three indices (duplicated face). Neighbours that meet only along
    their shared edge or vertex are not reported; corners at equal coordinates with
    different indices touch (reported); degenerate triangles are never reported.
    """
    return _self_intersections(_vertices(V, "V", "self_intersections"),
                               _faces(F, "F", "self_intersections"))


def intersections(V1, F1, V2, F2):
    """Every pair (triangle of mesh 1, triangle of mesh 2) whose closed triangles meet.

    Returns (pairs, results): pairs a k x 2 int64 array of (row of F1, row of F2), sorted;
    results the k Result of classify(V1[F1[i]], V2[F2[j]]). Any common point counts;
    degenerate triangles are never reported.
    """
    f = "intersections"
    return _intersections(_vertices(V1, "V1", f), _faces(F1, "F1", f),
                          _vertices(V2, "V2", f), _faces(F2, "F2", f))


def arrange(V, F, labels=None, classifier="tritri", threads=0):
    """The mesh arrangement: cuts the triangles along all their intersections, exactly.

    V: n x 3 coordinates; F: m x 3 vertex indices (m >= 1); labels: None (all 0) or m
    integer labels >= 0 (e.g. which input mesh a triangle came from); classifier:
    "tritri" or "native"; threads: worker threads (<= 0: all cores).
    Returns a dict:
      V           #V x 3 float64: output vertices rounded to the nearest double
      V_is_exact  #V bool: the rounded vertex is the exact one (input vertices always)
      F           #F x 3 int64 triangles, oriented like the input triangle they lie in;
                  they meet only at shared vertices and edges (exactly; the rounded V can
                  differ where V_is_exact is False)
      source      #F int64: the row of the input F each output triangle lies in
      labels      #F tuples: the sorted labels of the input triangles covering each one
      stats       dict of the pipeline's counts and stage times (ArrangeStats)
    """
    f = "arrange"
    if not isinstance(classifier, str):
        raise ValueError(f"tritri.arrange: classifier must be 'tritri' or 'native', got {classifier!r}")
    try:
        threads = int(threads)
    except (TypeError, ValueError):
        raise ValueError(f"tritri.arrange: threads must be an integer, got {threads!r}") from None
    if not -2**31 <= threads < 2**31:
        raise ValueError(f"tritri.arrange: threads out of range ({threads})")
    Fa = _faces(F, "F", f)
    la = None
    if labels is not None:
        try:
            la = _np.asarray(labels)
        except (TypeError, ValueError) as e:
            raise ValueError(f"tritri.arrange: labels is not an array of integers ({e})") from None
        if la.size == 0:
            la = la.reshape(0).astype(_np.int64)
        if la.dtype.kind not in "iu" or la.ndim != 1:
            raise ValueError(f"tritri.arrange: labels must be a 1-d integer array (one per row of F), "
                             f"got dtype {la.dtype} shape {la.shape}")
        if la.shape[0] != Fa.shape[0]:
            raise ValueError(f"tritri.arrange: labels must have one entry per row of F ({Fa.shape[0]}), "
                             f"got {la.shape[0]}")
        if la.size and la.dtype.kind == "u" and la.max() > _np.iinfo(_np.int64).max:
            raise ValueError(f"tritri.arrange: labels has a value out of range ({la.max()})")
        la = _np.ascontiguousarray(la, dtype=_np.int64)
    return _arrange(_vertices(V, "V", f), Fa, la, classifier, threads)


def load_mesh(path):
    """Reads a mesh file with the pipeline's loader (the same one `arrange` uses).

    path: an .obj, .off, .stl or .ply file (ASCII or binary). Polygons are fan-triangulated
    from their first corner; vertices are not merged (arrange merges them exactly).
    Returns a dict with V (n x 3 float64) and F (m x 3 int64). A missing, unreadable or
    malformed file, NaN/Inf coordinates or out-of-range indices raise ValueError.
    """
    return _load_mesh(str(path))
