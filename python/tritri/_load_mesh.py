"""tritri.load_mesh: a mesh file read by the pipeline's loader, on the helpers of
tritri/__init__.py (which imports this module once those are defined)."""

import os as _os
from fractions import Fraction as _Fraction

import numpy as _np

from . import ArgumentTypeError, _describe, _fraction_rows  # noqa: F401
from ._load_path import load_mesh_file as _load_mesh_file
from ._tritri import load_mesh as _load_mesh


def load_mesh(path, exact=False):
    """Reads a mesh file with the pipeline's loader (the same one `arrange` uses).

    path: an .obj, .off, .stl or .ply file (ASCII or binary). Polygons are triangulated as
    by the loader (in their plane when simple, else the fan from the first corner);
    vertices are not merged (arrange merges them exactly). OBJ and OFF coordinates may be
    rationals "n/d" (as `arrange --exact` writes them), read exactly.
    exact: False (default) or True.
    Returns a dict with V and F (m x 3 int64). V is n x 3 float64 when every coordinate is
    a float64 and exact is False; otherwise an n x 3 object array of fractions.Fraction,
    every coordinate exactly (decimals as their correctly rounded float64, rationals as
    written). Either V goes to arrange as it is (exact V runs the exact pipeline).
    Any path the system takes is read (also names that are not UTF-8: bytes, os.fsdecode's str).
    A missing, unreadable or malformed file, NaN/Inf coordinates, rationals beyond the
    float64 range or with a zero denominator, or out-of-range indices raise ValueError; a
    path that is not str, bytes or os.PathLike, or exact that is not a bool, raises
    ArgumentTypeError.
    """
    try:
        raw = _os.fsencode(path)  # str, bytes or os.PathLike: the bytes the system takes
    except TypeError:
        raise ArgumentTypeError(f"tritri.load_mesh: path must be a str, bytes or os.PathLike, "
                                f"got {_describe(path)}") from None
    if not isinstance(exact, (bool, _np.bool_)):
        raise ArgumentTypeError(f"tritri.load_mesh: exact must be True or False, got {_describe(exact)}")
    if b"\0" in raw:
        raise ValueError("tritri.load_mesh: the path contains a NUL character")
    out = _load_mesh_file(raw, _load_mesh)
    if "V_exact" in out:
        V = _fraction_rows(out["V_exact"])
    elif exact:
        V = _fraction_rows([_Fraction(x) for x in out["V"].ravel().tolist()])
    else:
        V = out["V"]
    return {"V": V, "F": out["F"]}
