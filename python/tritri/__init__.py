"""tritri: exact triangle-triangle intersection classification and mesh arrangements.

    import numpy as np, tritri
    a = [[0, 0, 0], [2, 0, 0], [0, 2, 0]]
    b = [[0.5, 0.5, -1], [0.5, 0.5, 1], [0.5, -1, 0.5]]
    r = tritri.classify(a, b)
    r.points    # [('EA_CROSS_TB', 0, -1), ('EB_CROSS_TA', 0, -1)]
    r.segments  # [(0, 1)]

Functions (every decision is an exact predicate on the input coordinates, no tolerances):
    classify(a, b)                     -> Result
    self_intersections(V, F)           -> (pairs, results)
    intersections(V1, F1, V2, F2)      -> (pairs, results)
    arrange(V, F, labels=None, classifier="tritri", threads=0, exact_output=None) -> dict
    load_mesh(path, exact=False)       -> dict (V, F)
    boolean(meshes, op="union", exact=None, rounding="nearest", classifier="tritri", threads=0) -> dict
    csg(path, exact=None, rounding="nearest", classifier="tritri", threads=0) -> dict

Arguments are anything numpy.asarray accepts: V as n x 3 real coordinates (any integer or
floating dtype, or Python numbers; converted to float64, except by arrange: below), F as
m x 3 integer vertex indices (any integer dtype). Non-contiguous and Fortran-ordered arrays are fine (copied).

Exact coordinates (exact in, exact out): an exact coordinate is a fractions.Fraction, and
exact vertices are an n x 3 numpy array of dtype object holding Fractions. Fractions are
what Python researchers reach for: the standard library's exact rationals, unlimited in
size (arrangement points have numerators and denominators of hundreds of bits, far beyond
int64 pairs), with exact arithmetic and comparisons that work elementwise on object arrays,
and accepted as they are by sympy, gmpy2 and the statistics module. Vertices in that form:
  - load_mesh(path) returns them as V when the file has rational coordinates that are not
    doubles (as `arrange --exact` writes them, "n/d"); load_mesh(path, exact=True) always;
  - arrange(V, F) takes them: V may hold Fractions, ints and floats in any mix (each
    converted exactly); when some value is not exactly a float64 the exact pipeline runs
    (every point a rational), else the usual double pipeline. The result's "V_exact" holds
    the exact output vertices, for exact input or with exact_output=True.
  - classify, self_intersections and intersections take them too: when some coordinate
    is not exactly a float64 they classify exactly on the rationals (tritri::RationalKernel,
    CGAL's filtered predicates on GMP rationals), so a contact that only exists exactly (a
    vertex at 1/3 on a plane) is found; else the float64 path, as before. Their results
    name points by (type, id0, id1), the same on both paths.

Errors: every refused argument raises ValueError with a message naming the argument and
the entry: wrong shape, NaN or infinite coordinates, a number beyond the float64 range
(e.g. 10**400, or Fraction(10**400, 3): exact coordinates obey the same rule, as the file
loader's rationals do), an index or label out of range, an unknown classifier, threads
outside 0..MAX_THREADS, a mesh the pipeline cannot arrange, an unreadable mesh file. An
argument of the wrong type (threads that is not an integer, a classifier that is not a str,
a path that is not str / bytes / os.PathLike, arrays of bool, complex, str or other
objects, F or labels that are not integers, exact_output that is not None or a bool, exact
that is not a bool) raises ArgumentTypeError, which is both a TypeError (Python's
convention) and a ValueError (so `except ValueError` catches every refused input).
OverflowError and MemoryError are never raised for argument values; only a mesh too large
for the machine's memory can raise MemoryError. The C++ work runs without the GIL.

ThreadError (a RuntimeError): arrange, boolean and csg start their worker threads (threads,
0: one per core) before any work, and raise ThreadError, "cannot start N worker threads:
REASON", when the system refuses them (ulimit -v or -u, a container's pids limit) instead
of the interpreter being killed (SIGABRT in oneTBB); a smaller threads value may succeed.
The command-line tools exit 1 with the same message.

MAX_THREADS (1024): the largest thread count arrange accepts, the same as the command-line
tools' --threads (arrangements/thread_count.h explains why there is a cap).
"""

import math as _math
import numbers as _numbers
import operator as _operator
import sys as _sys
from fractions import Fraction as _Fraction

import numpy as _np

from ._tritri import MAX_THREADS, Result, ThreadError
from ._tritri import arrange as _arrange
from ._tritri import arrange_exact as _arrange_exact
from ._tritri import classify as _classify
from ._tritri import classify_exact as _classify_exact
from ._tritri import intersections as _intersections
from ._tritri import intersections_exact as _intersections_exact
from ._tritri import self_intersections as _self_intersections
from ._tritri import self_intersections_exact as _self_intersections_exact
from ._tritri import _stats_key_list

__all__ = ["Result", "ArgumentTypeError", "ThreadError", "MAX_THREADS", "classify", "self_intersections",
           "intersections", "arrange", "load_mesh", "boolean", "csg", "BOOLEAN_OPS"]
__version__ = "0.1.0"


class ArgumentTypeError(TypeError, ValueError):
    """An argument of the wrong type: both a TypeError and a ValueError."""


def _describe(v):
    """A short description of a value for a message (never fails, never huge)."""
    if isinstance(v, int) and not isinstance(v, bool) and abs(v) >= 10**30:
        return f"{'-' if v < 0 else ''}an integer of {v.bit_length()} bits"
    try:
        text = repr(v)
    except Exception:  # e.g. a broken __repr__
        text = f"a {type(v).__name__}"
    return text if len(text) <= 60 else text[:57] + "..."


def _is_integer(v):
    return isinstance(v, _numbers.Integral) and not isinstance(v, (bool, _np.bool_))


def _as_array(x, name, function, what):
    try:
        return _np.asarray(x)
    except (TypeError, ValueError, OverflowError) as e:  # ragged lists, odd objects
        raise ValueError(f"tritri.{function}: {name} is not an array of {what} ({e})") from None


def _float_array(x, name, function):
    """x as a float64 array: real numbers only (integers and floats of any width)."""
    a = _as_array(x, name, function, "numbers")
    if a.dtype.kind == "O":  # Python objects, e.g. integers beyond int64
        out = _np.empty(a.shape, dtype=_np.float64)
        for index, v in _np.ndenumerate(a):
            if isinstance(v, (bool, _np.bool_)) or not isinstance(v, _numbers.Real):
                raise ArgumentTypeError(f"tritri.{function}: {name}{list(index) if index else ''} is "
                                        f"{_describe(v)}, not a real number")
            try:
                out[index] = float(v)
            except (OverflowError, ValueError, TypeError):
                raise ValueError(f"tritri.{function}: {name}{list(index) if index else ''} = {_describe(v)} "
                                 "is beyond the float64 range") from None
        return out
    if a.dtype.kind not in "iuf":
        raise ArgumentTypeError(f"tritri.{function}: {name} must hold real numbers, got dtype {a.dtype}")
    with _np.errstate(over="ignore"):  # long double beyond float64: inf, refused as not finite
        return a.astype(_np.float64, copy=False)


def _int_array(x, name, function, what):
    """x as an int64 array of integers (any integer dtype; Python ints within int64)."""
    a = _as_array(x, name, function, what)
    if a.size == 0:
        return a.astype(_np.int64)
    if a.dtype.kind == "f" and not isinstance(x, _np.ndarray):  # numpy makes [2**63] float64
        o = _np.asarray(x, dtype=object)
        if o.shape == a.shape and all(_is_integer(v) for v in o.flat):
            a = o
    if a.dtype.kind == "O" and all(_is_integer(v) for v in a.flat):
        try:
            return a.astype(_np.int64)
        except OverflowError:
            raise ValueError(f"tritri.{function}: {name} has a value out of range "
                             f"(beyond int64: {_describe(max(a.flat, key=abs))})") from None
    if a.dtype.kind not in "iu":
        raise ArgumentTypeError(f"tritri.{function}: {name} must hold integer {what}, got dtype {a.dtype}")
    if a.dtype.kind == "u" and a.max() > _np.iinfo(_np.int64).max:
        raise ValueError(f"tritri.{function}: {name} has a value out of range ({a.max()})")
    return a.astype(_np.int64, copy=False)


def _vertices(x, name, function):
    a = _float_array(x, name, function)
    if a.size == 0:
        return _np.zeros((0, 3), dtype=_np.float64)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"tritri.{function}: {name} must be an n x 3 array of vertex coordinates, "
                         f"got shape {a.shape}")
    return _np.ascontiguousarray(a)


def _faces(x, name, function):
    a = _int_array(x, name, function, "vertex indices")
    if a.size == 0:
        return _np.zeros((0, 3), dtype=_np.int64)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"tritri.{function}: {name} must be an m x 3 array of vertex indices, "
                         f"got shape {a.shape}")
    return _np.ascontiguousarray(a)


_DBL_MAX = _Fraction(_sys.float_info.max)


def _coprime_fraction(n, d):
    """Fraction(n, d) for n, d already in lowest terms (d > 0), without the gcd that the
    constructor spends on normalising (quadratic in the digits: minutes for 100,000)."""
    if hasattr(_Fraction, "_from_coprime_ints"):  # Python >= 3.12
        return _Fraction._from_coprime_ints(n, d)
    return _Fraction(n, d, _normalize=False)


def _exact_coordinate(v, where):
    """v as a Fraction, exactly (ints, Fractions, any Rational; floats of any width by
    as_integer_ratio; another Real type by its float()). `where` names the entry."""
    if isinstance(v, (bool, _np.bool_)) or not isinstance(v, _numbers.Real):
        raise ArgumentTypeError(f"{where} is {_describe(v)}, not a real number")
    try:
        if isinstance(v, _numbers.Integral):
            q = _Fraction(_operator.index(v))
        elif type(v) is _Fraction:
            q = v
        elif isinstance(v, _numbers.Rational):  # numerator and denominator in lowest terms
            q = _coprime_fraction(int(v.numerator), int(v.denominator))
        elif hasattr(v, "as_integer_ratio"):  # float, numpy floating of any width
            q = _coprime_fraction(*v.as_integer_ratio())
        else:
            q = _Fraction(float(v))
    except (OverflowError, ValueError):  # NaN, infinity
        raise ValueError(f"{where} = {_describe(v)} is not a finite number") from None
    except TypeError:
        raise ArgumentTypeError(f"{where} is {_describe(v)}, not a real number") from None
    if abs(q) > _DBL_MAX:
        raise ValueError(f"{where} = {_describe(v)} is beyond the float64 range")
    return q


def _is_double(q):
    """The Fraction q (|q| <= DBL_MAX) is exactly a float64."""
    d = q.denominator
    return (d & (d - 1)) == 0 and float(q) == q  # float(q) is correctly rounded


def _coordinates(x, name, function, check_shape):
    """Coordinates for an entry with an exact path: (float64 array, has_fraction) when every
    value is exactly a float64, else (flat list of the Fractions, True). Exact: some value is
    a non-integer Rational (e.g. a Fraction) or not exactly a float64. has_fraction: some
    value is a non-integer Rational. check_shape(shape) raises for a wrong shape."""
    a = _as_array(x, name, function, "numbers")
    if (a.dtype.kind in "iu" and a.dtype.itemsize == 8 and a.size
            and ((a > 2**53).any() or (a < -2**53).any())) or (a.dtype.kind == "f" and a.dtype.itemsize > 8):
        a = a.astype(object)  # int64 beyond 2**53, long double: maybe not doubles, so exactly
    if a.dtype.kind != "O":
        return _float_array(a, name, function), False
    values, all_double, fraction = [], True, False
    for index, v in _np.ndenumerate(a):
        q = _exact_coordinate(v, f"tritri.{function}: {name}{list(index) if index else ''}")
        all_double = all_double and _is_double(q)
        fraction = fraction or (isinstance(v, _numbers.Rational) and not isinstance(v, _numbers.Integral))
        values.append(q)
    if a.size:
        check_shape(a.shape)
    if all_double:
        return _float_array(a, name, function), fraction  # as before: float(v) of each value
    return values, True


def _hex_rationals(values):
    """Coordinates (a float64 array or a list of Fractions) as the hexadecimal "n/d"
    strings of the exact entries, row after row."""
    if isinstance(values, _np.ndarray):
        values = [_Fraction(*float(v).as_integer_ratio()) for v in values.ravel()]
    return [f"{q.numerator:x}/{q.denominator:x}" for q in values]


def _n_by_3(name, function):
    def check(shape):
        if len(shape) != 2 or shape[1] != 3:
            raise ValueError(f"tritri.{function}: {name} must be an n x 3 array of vertex coordinates, "
                             f"got shape {shape}")
    return check


def _mesh_vertices(x, name, function):
    """V of a mesh entry: a contiguous n x 3 float64 array, or a list of Fractions (exact)."""
    values, _ = _coordinates(x, name, function, _n_by_3(name, function))
    return values if isinstance(values, list) else _vertices(values, name, function)


def _fraction_rows(flat):
    """A flat list of 3n Fractions as an n x 3 object array."""
    a = _np.empty(len(flat), dtype=object)
    a[:] = flat
    return a.reshape(-1, 3)


def _thread_count(threads, function="arrange"):
    try:
        if isinstance(threads, (bool, _np.bool_)):
            raise TypeError
        n = _operator.index(threads)  # int, numpy integers; not bool, float, str, None
    except TypeError:
        raise ArgumentTypeError(f"tritri.{function}: threads must be an integer from 0 to {MAX_THREADS}, "
                                f"got {_describe(threads)}") from None
    if not 0 <= n <= MAX_THREADS:
        raise ValueError(f"tritri.{function}: threads must be an integer from 0 to {MAX_THREADS}, "
                         f"got {_describe(n)}")
    return n


def _round_max_move(value, safe, function="arrange"):
    """The keyword arguments that pass round_max_move on: none for None (the C++ default,
    RoundSafeOptions::max_move_relative, applies), else a float above 0 given only with
    rounding="safe"."""
    if value is None:
        return {}
    if not safe:
        raise ValueError(f"tritri.{function}: round_max_move needs rounding='safe'")
    if isinstance(value, (bool, _np.bool_)) or not isinstance(value, _numbers.Real):
        raise ArgumentTypeError(f"tritri.{function}: round_max_move must be a finite number above 0, "
                                f"got {_describe(value)}")
    try:
        x = float(value)
    except OverflowError:  # an int or Fraction beyond the float64 range
        x = _math.inf
    if not (_math.isfinite(x) and x > 0):
        raise ValueError(f"tritri.{function}: round_max_move must be a finite number above 0, "
                         f"got {_describe(value)}")
    return {"round_max_move": x}


def _pipeline_options(function, exact_name, exact, rounding, round_max_move, classifier, threads):
    """The checked arguments that arrange, boolean and csg share: (safe, max_move kwargs,
    threads); exact_name is the name of the caller's exact-output flag."""
    if exact is not None and not isinstance(exact, (bool, _np.bool_)):
        raise ArgumentTypeError(f"tritri.{function}: {exact_name} must be None, True or False, "
                                f"got {_describe(exact)}")
    if not isinstance(classifier, str):
        raise ArgumentTypeError(f"tritri.{function}: classifier must be 'tritri' or 'native', "
                                f"got {_describe(classifier)}")
    if not isinstance(rounding, str):
        raise ArgumentTypeError(f"tritri.{function}: rounding must be 'nearest' or 'safe', got {_describe(rounding)}")
    if rounding not in ("nearest", "safe"):
        raise ValueError(f"tritri.{function}: rounding must be 'nearest' or 'safe', got {rounding!r}")
    safe = rounding == "safe"
    if safe and exact:
        raise ValueError(f"tritri.{function}: {exact_name}=True and rounding='safe' exclude each other "
                         "(the safely rounded mesh is float64)")
    return safe, _round_max_move(round_max_move, safe, function), _thread_count(threads, function)


def classify(a, b):
    """Classifies exactly how triangles a and b intersect.

    a, b: 3 x 3 arrays, one vertex per row (finite; float64 values, or exact ones as for
    arrange's V: if some value is not exactly a float64, both triangles are classified on
    their exact rationals). Returns a Result:
      points     list of (type, id0, id1): every corner of the intersection, named by the
                 two sub-simplices that meet there; type is the C++ enum's name
                 (VA_ON_VB, VA_ON_EB, VB_ON_EA, VA_ON_TB, VB_ON_TA, EA_CROSS_EB,
                 EA_CROSS_TB, EB_CROSS_TA); vertices are 0, 1, 2 (rows), edge k joins
                 vertices k and (k+1)%3, -1 where no id applies; sorted
      segments   list of (p0, p1) indices into points
      coplanar   the triangles lie in one plane
      degenerate a triangle has repeated or collinear vertices and was not classified
      intersects at least one point
    Raises ValueError for a shape other than 3 x 3 or a coordinate that is NaN, infinite or
    beyond the float64 range; ArgumentTypeError for non-numbers (bool, complex, str, ...).
    """
    def three_by_three(name):
        def check(shape):
            if tuple(shape) != (3, 3):
                raise ValueError(f"tritri.classify: {name} must be a 3 x 3 array (one vertex per row), "
                                 f"got shape {tuple(shape)}")
        return check
    (ta, _), (tb, _) = (_coordinates(t, name, "classify", three_by_three(name)) for t, name in ((a, "a"), (b, "b")))
    if isinstance(ta, list) or isinstance(tb, list):  # a value that is not a float64: exactly
        return _classify_exact(_hex_rationals(ta), _hex_rationals(tb))
    for t, name in ((ta, "a"), (tb, "b")):
        three_by_three(name)(t.shape)
    return _classify(_np.ascontiguousarray(ta), _np.ascontiguousarray(tb))


def self_intersections(V, F):
    """Every pair of triangles of one mesh that intersect beyond the vertices they share.

    V: n x 3 coordinates (float64, or exact values as for arrange: then classified on the
    exact rationals); F: m x 3 vertex indices. Returns (pairs, results):
      pairs    k x 2 int64 array of rows (i, j) of F, i < j, sorted
      results  list of k Result, classify(V[F[i]], V[F[j]])
    Vertices are shared by index. A pair is reported when its intersection has a point
    other than a shared vertex (VA_ON_VB of corners with the same index), or when both
    rows have the same three indices (duplicated face). Neighbours that meet only along
    their shared edge or vertex are not reported; corners at equal coordinates with
    different indices touch (reported); degenerate triangles are never reported.
    """
    f = "self_intersections"
    Va, Fa = _mesh_vertices(V, "V", f), _faces(F, "F", f)
    if isinstance(Va, list):
        return _self_intersections_exact(_hex_rationals(Va), Fa)
    return _self_intersections(Va, Fa)


def intersections(V1, F1, V2, F2):
    """Every pair (triangle of mesh 1, triangle of mesh 2) whose closed triangles meet.

    V1, V2: coordinates as for self_intersections (if either holds a value that is not
    exactly a float64, both meshes are classified on their exact rationals).
    Returns (pairs, results): pairs a k x 2 int64 array of (row of F1, row of F2), sorted;
    results the k Result of classify(V1[F1[i]], V2[F2[j]]). Any common point counts;
    degenerate triangles are never reported.
    """
    f = "intersections"
    V1a, F1a, V2a, F2a = _mesh_vertices(V1, "V1", f), _faces(F1, "F1", f), _mesh_vertices(V2, "V2", f), _faces(F2, "F2", f)
    if isinstance(V1a, list) or isinstance(V2a, list):  # both exactly
        return _intersections_exact(_hex_rationals(V1a), F1a, _hex_rationals(V2a), F2a)
    return _intersections(V1a, F1a, V2a, F2a)


def arrange(V, F, labels=None, classifier="tritri", threads=0, exact_output=None, rounding="nearest",
            round_max_move=None):
    """The mesh arrangement: cuts the triangles along all their intersections, exactly.

    V: n x 3 coordinates, float64 or exact (Python ints, fractions.Fraction, floats, in
    any mix; an object array of Fractions as load_mesh returns; see the module's
    documentation); F: m x 3 vertex indices (m >= 1); labels: None (all 0) or m
    integer labels from 0 to 2**31 - 1 (e.g. which input mesh a triangle came from);
    classifier: "tritri" or "native"; threads: worker threads, an integer from 0 (all
    cores, the default) to MAX_THREADS (1024), as `arrange --threads`; exact_output: True
    adds V_exact, False leaves it out, None (default) adds it when V is exact input (holds
    a Fraction or a value that is not exactly a float64); rounding: "nearest" (default:
    V is the arrangement rounded to the nearest doubles, which may self-intersect where
    V_is_exact is False) or "safe" (as `arrange --round safe`, arrangements/round_mesh.h:
    the result describes a float64 mesh that is an arrangement itself, rounded, arranged
    again and rounded until nothing changes; V_is_exact is then all True, there is no
    V_exact, and stats gives round_passes and round_max_move); round_max_move (with
    rounding="safe"): the largest move accepted, as a fraction of the diagonal of the
    arrangement's bounding box (a finite number above 0; None: 1/64), as `arrange
    --round-max-move`: a model only a few hundred ulps wide (tiny and far from the origin)
    settles only with moves of a fifth of its size or more, which 1 accepts.
    Every value of V is converted exactly. When all of them are float64 values, the double
    pipeline runs (new points implicit; with float64 input exactly what earlier versions
    returned); when some value is not, the exact pipeline runs (every point a rational,
    as `arrange` on a file with rational coordinates). Both give the same arrangement of
    the same input, up to the numbering of vertices and the triangulation.
    Returns a dict:
      V           #V x 3 float64: output vertices rounded to the nearest double
      V_is_exact  #V bool: the rounded vertex is the exact one (input vertices that are
                  float64 values always)
      V_exact     (only with exact output, above) #V x 3 object array of
                  fractions.Fraction: the output vertices exactly, rows as in V
      F           #F x 3 int64 triangles, oriented like the input triangle they lie in;
                  they meet only at shared vertices and edges (exactly; the rounded V can
                  differ where V_is_exact is False)
      source      #F int64: the row of the input F each output triangle lies in
      label_set   #F int64: index into label_sets of each triangle's label set
      label_sets  list of distinct tuples: the sorted labels of the input triangles
                  covering a face (face f: label_sets[label_set[f]])
      stats       dict of the pipeline's counts and stage times: exactly the keys and
                  values of `arrange --stats`, in this order (t_load_s is 0 here, nothing
                  is read from a file):
{stats_keys}
    Raises RuntimeError when rounding="safe" does not converge (see round_mesh.h; the
    exact output is always available), ThreadError (a RuntimeError) when the system
    refuses the worker threads (a smaller threads value may succeed), and ValueError for
    refused input (see the module's documentation): an unknown rounding, exact_output=True with rounding="safe", a
    round_max_move that is not a finite number above 0 (or given without rounding="safe"), a threads value
    outside 0..MAX_THREADS, an unknown classifier, an index or label out of range, NaN or
    infinite coordinates, a coordinate beyond the float64 range (also exact ones: |x| >
    the largest float64), nothing left to arrange; ArgumentTypeError (also a ValueError)
    for threads that is not an integer (bool, float, str, None), a round_max_move that is
    not a real number (bool, str, None), a classifier or rounding that is not a str, exact_output that is not None or a bool, arrays of the wrong dtype, or V
    entries that are not real numbers.
    """
    f = "arrange"
    safe, max_move, threads = _pipeline_options(f, "exact_output", exact_output, rounding, round_max_move,
                                                classifier, threads)
    Fa = _faces(F, "F", f)
    la = None
    if labels is not None:
        la = _int_array(labels, "labels", f, "labels")
        if la.size == 0:
            la = la.reshape(0)
        if la.ndim != 1:
            raise ValueError(f"tritri.arrange: labels must be a 1-d integer array (one per row of F), "
                             f"got shape {la.shape}")
        if la.shape[0] != Fa.shape[0]:
            raise ValueError(f"tritri.arrange: labels must have one entry per row of F ({Fa.shape[0]}), "
                             f"got {la.shape[0]}")
        la = _np.ascontiguousarray(la)
    Va, exact_input = _coordinates(V, "V", f, _n_by_3("V", f))
    want_exact = exact_input if exact_output is None else bool(exact_output)
    if isinstance(Va, list):
        out = _arrange_exact(_hex_rationals(Va), Fa, la, classifier, threads, safe, **max_move)
    else:
        out = _arrange(_vertices(Va, "V", f), Fa, la, classifier, threads, want_exact and not safe, safe,
                       **max_move)
    if "V_exact" in out:
        exact = out.pop("V_exact")
        if want_exact:
            out["V_exact"] = _fraction_rows(exact)
    return out


if arrange.__doc__:  # None under python -OO
    # The key list comes from the one table of the statistics (arrangements/arrange_stats.h),
    # indented like the lines around it (the placeholder at column 0 keeps Python >= 3.13
    # from removing the docstring's common indentation).
    arrange.__doc__ = arrange.__doc__.replace("{stats_keys}", _stats_key_list(18, 39, 94).rstrip("\n"))


# load_mesh (_load_mesh.py), boolean and csg (_booleans.py), on the helpers above.
from ._load_mesh import load_mesh  # noqa: E402
from ._booleans import BOOLEAN_OPS, boolean, csg  # noqa: E402
