"""tritri.boolean and tritri.csg (python/tritri/__init__.py over arrangements/boolean_eigen.h
and load_csg.h): two cubes [0,2]^3 and [1,3]^3 have union volume 15, intersection 1,
difference 7 and xor 14, exactly; the output is closed and oriented outwards; bad op,
empty input, bad shapes and open operands raise ValueError; a .csg file importing two OFF
files gives the same result."""

from collections import Counter
from fractions import Fraction

import numpy as np
import pytest

import tritri

CUBE_F = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                   [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
VOLUMES = {"union": 15, "intersection": 1, "difference": 7, "xor": 14}


def cube(lo, hi):
    V = [[hi if i & 1 else lo, hi if i & 2 else lo, hi if i & 4 else lo] for i in range(8)]
    return np.array(V, dtype=float), CUBE_F.copy()


def volume(V, F):
    """The signed volume, exactly (Fractions of the given coordinates)."""
    total = Fraction(0)
    for a, b, c in F:
        p, q, r = ([Fraction(x) for x in V[k]] for k in (a, b, c))
        total += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                  + p[2] * (q[0] * r[1] - q[1] * r[0]))
    return total / 6


def assert_closed(F):
    directed = Counter((int(t[i]), int(t[(i + 1) % 3])) for t in F for i in range(3))
    for (a, b), n in directed.items():
        assert directed[(b, a)] == n, (a, b)


@pytest.mark.parametrize("op", sorted(VOLUMES))
def test_two_cubes(op):
    out = tritri.boolean([cube(0, 2), cube(1, 3)], op)
    assert set(out) >= {"V", "V_is_exact", "F", "source", "label_set", "label_sets", "stats"}
    assert "V_exact" not in out
    assert out["V"].dtype == np.float64 and out["F"].dtype == np.int64
    assert out["V_is_exact"].all()
    assert volume(out["V"], out["F"]) == VOLUMES[op]
    assert_closed(out["F"])
    assert len(out["source"]) == len(out["F"]) == len(out["label_set"])
    for f, s in enumerate(out["source"]):
        assert (0 if s < 12 else 1) in out["label_sets"][out["label_set"][f]]
    assert isinstance(out["stats"], dict)


@pytest.mark.parametrize("op", sorted(VOLUMES))
def test_two_cubes_exact(op):
    out = tritri.boolean([cube(0, 2), cube(1, 3)], op, exact=True)
    Vq = out["V_exact"]
    assert Vq.dtype == object and all(isinstance(x, Fraction) for x in Vq.flat)
    assert volume(Vq, out["F"]) == VOLUMES[op]
    # Exact input (Fractions) runs the exact pipeline and returns V_exact by default.
    Va, Fa = cube(0, 2)
    Vb, Fb = cube(1, 3)
    frac = np.array([[Fraction(x) for x in row] for row in Vb], dtype=object)
    out2 = tritri.boolean([(Va, Fa), (frac, Fb)], op)
    assert volume(out2["V_exact"], out2["F"]) == VOLUMES[op]
    assert_closed(out2["F"])


def test_thirds_exact():
    # A cube at non-dyadic coordinates: only exact Fractions describe it.
    Va, Fa = cube(0, 2)
    third = np.array([[Fraction(1, 3) + Fraction(int(x)) for x in row] for row in cube(0, 2)[0]], dtype=object)
    out = tritri.boolean([(Va, Fa), (third, Fa)], "intersection")
    assert volume(out["V_exact"], out["F"]) == Fraction(5, 3) ** 3


def test_safe_rounding():
    out = tritri.boolean([cube(0, 2), cube(1, 3)], "union", rounding="safe")
    assert volume(out["V"], out["F"]) == 15
    assert_closed(out["F"])


def test_errors():
    meshes = [cube(0, 2), cube(1, 3)]
    with pytest.raises(ValueError, match="op must be one of"):
        tritri.boolean(meshes, "subtract")
    with pytest.raises(ValueError, match="empty"):
        tritri.boolean([], "union")
    with pytest.raises(ValueError, match=r"meshes\[1\] V must be an n x 3"):
        tritri.boolean([cube(0, 2), (np.zeros((4, 2)), CUBE_F)], "union")
    with pytest.raises(ValueError, match=r"meshes\[0\] F must be an m x 3"):
        tritri.boolean([(cube(0, 2)[0], np.zeros((3, 4), dtype=int))], "union")
    with pytest.raises(ValueError, match=r"meshes\[0\] must be a \(V, F\) pair"):
        tritri.boolean([cube(0, 2)[0]], "union")
    with pytest.raises(ValueError, match="index|out of range|not a row"):
        tritri.boolean([(cube(0, 2)[0], CUBE_F + 8), cube(1, 3)], "union")
    with pytest.raises(ValueError, match="threads"):
        tritri.boolean(meshes, "union", threads=-1)
    with pytest.raises(TypeError):
        tritri.boolean(meshes, 3)
    Vb, Fb = cube(1, 3)
    with pytest.raises(ValueError, match="operand 1 is not closed"):
        tritri.boolean([cube(0, 2), (Vb, Fb[:-1])], "union")


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        for v in V:
            f.write(" ".join(repr(float(x)) for x in v) + "\n")
        for t in F:
            f.write("3 " + " ".join(str(int(i)) for i in t) + "\n")


def test_csg(tmp_path):
    write_off(tmp_path / "a.off", *cube(0, 2))
    write_off(tmp_path / "b.off", *cube(0, 2))
    # b moved by (1, 1, 1): the second cube [1,3]^3.
    (tmp_path / "scene.csg").write_text(
        'difference() {\n  import(file = "a.off");\n'
        '  multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1], [0, 0, 0, 1]]) import("b.off");\n}\n')
    out = tritri.csg(tmp_path / "scene.csg")
    assert volume(out["V"], out["F"]) == 7
    assert_closed(out["F"])
    assert "V_exact" not in out
    out = tritri.csg(str(tmp_path / "scene.csg"), exact=True)
    assert volume(out["V_exact"], out["F"]) == 7
    # A translation by 1/10 makes the operand exact: V_exact by default.
    (tmp_path / "tenth.csg").write_text(
        'union() { import("a.off"); multmatrix([[1,0,0,0.1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) import("b.off"); }')
    out = tritri.csg(tmp_path / "tenth.csg")
    assert volume(out["V_exact"], out["F"]) == 8 + Fraction(1, 10) * 4
    (tmp_path / "bad.csg").write_text('union() { import("missing.off"); }')
    with pytest.raises(ValueError, match="missing.off"):
        tritri.csg(tmp_path / "bad.csg")
    write_off(tmp_path / "open.off", cube(0, 2)[0], CUBE_F[:-1])
    (tmp_path / "open.csg").write_text('union() { import("a.off"); import("open.off"); }')
    with pytest.raises(ValueError, match="operand 1 is not closed"):
        tritri.csg(tmp_path / "open.csg")
