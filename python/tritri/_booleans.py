"""tritri.boolean and tritri.csg (exact Booleans and CSG files, arrangements/boolean.h,
arrangements/load_csg.h): their argument checks and the shaping of their results, on the
helpers of tritri/__init__.py (which imports this module once those are defined)."""

import os as _os

from . import (ArgumentTypeError, _coordinates, _describe, _faces, _fraction_rows,  # noqa: F401
               _hex_rationals, _n_by_3, _pipeline_options, _vertices)
from ._tritri import boolean as _boolean
from ._tritri import boolean_exact as _boolean_exact
from ._tritri import csg as _csg


BOOLEAN_OPS = ("union", "intersection", "difference", "xor")


def _shape_exact(out, want_exact):
    """out with V_exact as an n x 3 Fraction array when want_exact, else without it."""
    if "V_exact" in out:
        exact = out.pop("V_exact")
        if want_exact:
            out["V_exact"] = _fraction_rows(exact)
    return out


def boolean(meshes, op="union", *, exact=None, rounding="nearest", round_max_move=None, classifier="tritri",
            threads=0):
    """The exact Boolean of closed meshes (arrangements/boolean.h): their arrangement, then
    the triangles bounding the result, oriented outwards.

    meshes: a non-empty list (or tuple) of (V, F) pairs, operand i = meshes[i] (label i);
    V and F as for arrange (V float64 or exact values; F m x 3 vertex indices into that
    operand's V). Every operand must be closed (each edge used as often in one direction
    as in the other); a point is inside operand i where its winding number is not zero.
    op: "union", "intersection", "difference" (the first minus all others) or "xor"
    (inside an odd number), over the operands in order.
    exact, rounding, round_max_move, classifier, threads: as arrange's exact_output,
    rounding, round_max_move, classifier and threads (exact=None: V_exact when some
    operand is exact input; when some value is not exactly a float64, the exact pipeline
    runs). rounding="safe" keeps the result closed (a step of safe rounding whose result
    would be open is not taken; docs/BOOLEANS.md).
    Returns the dict of arrange for the boundary of the result: V, V_is_exact, (V_exact),
    F, source (the row of the concatenation of the operands' F, operand 0's rows first),
    label_set / label_sets (the operands covering each triangle), stats. An empty result
    (e.g. disjoint operands intersected) has no triangle.
    Raises ValueError for an op not in BOOLEAN_OPS, no operand, an entry that is not a
    (V, F) pair, refused arrays (as arrange, the message naming meshes[i]), and an operand
    that is not closed ("... operand 1 is not closed: ..."); RuntimeError when
    rounding="safe" does not converge to a closed result; ThreadError (a RuntimeError) when the system refuses
    the worker threads; ArgumentTypeError for arguments of the wrong type.
    """
    f = "boolean"
    if not isinstance(op, str):
        raise ArgumentTypeError(f"tritri.boolean: op must be one of {', '.join(BOOLEAN_OPS)}, got {_describe(op)}")
    if op not in BOOLEAN_OPS:
        raise ValueError(f"tritri.boolean: op must be one of {', '.join(BOOLEAN_OPS)}, got {op!r}")
    safe, max_move, threads = _pipeline_options(f, "exact", exact, rounding, round_max_move, classifier, threads)
    if isinstance(meshes, (str, bytes, dict)) or not hasattr(meshes, "__len__"):
        raise ArgumentTypeError(f"tritri.boolean: meshes must be a list of (V, F) pairs, got {_describe(meshes)}")
    meshes = list(meshes)
    if not meshes:
        raise ValueError("tritri.boolean: meshes is empty (no operand)")
    Vs, Fs, exact_input = [], [], False
    for i, mesh in enumerate(meshes):
        try:
            V, F = mesh
        except (TypeError, ValueError):
            raise ValueError(f"tritri.boolean: meshes[{i}] must be a (V, F) pair, got {_describe(mesh)}") from None
        name = f"meshes[{i}] V"
        values, fraction = _coordinates(V, name, f, _n_by_3(name, f))
        exact_input = exact_input or fraction or isinstance(values, list)
        Vs.append(values if isinstance(values, list) else _vertices(values, name, f))
        Fs.append(_faces(F, f"meshes[{i}] F", f))
    want_exact = exact_input if exact is None else bool(exact)
    if any(isinstance(V, list) for V in Vs):
        out = _boolean_exact([_hex_rationals(V) for V in Vs], Fs, op, classifier, threads, safe, **max_move)
    else:
        out = _boolean(Vs, Fs, op, classifier, threads, want_exact and not safe, safe, **max_move)
    return _shape_exact(out, want_exact)


def csg(path, *, exact=None, rounding="nearest", round_max_move=None, classifier="tritri", threads=0):
    """Evaluates an OpenSCAD .csg file over mesh files exactly (arrangements/load_csg.h: the
    subset of union, difference, intersection, group, multmatrix and import; operand i is
    the i-th import, transforms applied in rational arithmetic) with boolean's rules.

    path: a str, bytes or os.PathLike; exact, rounding, round_max_move, classifier,
    threads: as for boolean (exact=None: V_exact when some transformed coordinate is not a
    float64, then the exact pipeline runs). Returns boolean's dict.
    Raises ValueError for an unreadable or malformed .csg file or operand (the message
    names the file and line) and for an operand that is not closed; the rest as boolean.
    """
    f = "csg"
    try:
        raw = _os.fsencode(path)
    except TypeError:
        raise ArgumentTypeError(f"tritri.csg: path must be a str, bytes or os.PathLike, "
                                f"got {_describe(path)}") from None
    safe, max_move, threads = _pipeline_options(f, "exact", exact, rounding, round_max_move, classifier, threads)
    if b"\0" in raw:
        raise ValueError("tritri.csg: the path contains a NUL character")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise ValueError("tritri.csg: the path is not UTF-8 (not supported for .csg files)") from None
    out = _csg(text, classifier, threads, bool(exact) and not safe, safe, **max_move)
    return _shape_exact(out, bool(exact) or (exact is None and "V_exact" in out))
