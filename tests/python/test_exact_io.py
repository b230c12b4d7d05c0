"""Exact coordinates through the Python module (issue 14: exact in, exact out):

- arrange with fractions.Fraction input (thirds): the exact pipeline; the counts, the two
  new points and the tiling derived by hand, exactly;
- the double pipeline is unchanged for float64 input (no V_exact unless asked for), and
  exact_output=True gives its output vertices exactly;
- load_mesh reads rational files (written by hand, and by `arrange --exact`) as Fraction
  arrays, double files as float64 (Fractions with exact=True); the exact output of a
  double arrangement equals the Fractions of the file `arrange --exact` writes, and
  arranging that file again finds nothing new;
- refusals: values beyond the float64 range (exact ones too), NaN and infinite floats
  (ValueError), non-numbers and wrong flag types (ArgumentTypeError).
The CLI test runs $TRITRI_ARRANGE_BIN (default build/bin/arrange) and skips without it.
Run: scripts/test_python.sh.
"""

import decimal
import os
import pathlib
import subprocess
import sys
from fractions import Fraction as Fr

import numpy as np
import pytest

import tritri

T = Fr(1, 3)
# A = (0,0,0), (1,0,0), (0,1,0) in z = 0; B in the plane x = 1/3 with corners (1/3,1/3,-1),
# (1/3,1/3,1), (1/3,-1,1/3). B's vertical edge crosses A's interior at (1/3,1/3,0); its
# edge from (1/3,-1,1/3) to (1/3,1/3,-1) meets z = 0 at y = -2/3, outside A; the third edge
# stays above z = 0. So B meets A along x = 1/3, z = 0 from y = 1/3 down to A's edge y = 0,
# where that edge crosses B's interior at (1/3,0,0). Each triangle then has 4 boundary
# points and 1 interior point: 4 triangles, 8 edges; they share one edge. V 8, E 15, F 8.
THIRDS_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [T, T, -1], [T, T, 1], [T, -1, T]]
THIRDS_F = [[0, 1, 2], [3, 4, 5]]
THIRDS_NEW = {(T, T, 0), (T, 0, 0)}


def rows(V):
    return [tuple(Fr(x) for x in row) for row in V]


def vector_area(p, q, r):
    """Twice the vector area of triangle pqr, exactly."""
    u = [q[k] - p[k] for k in range(3)]
    v = [r[k] - p[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def expect_tiling(out, V, F):
    """The output triangles of each source add up to its input triangle's vector area, exactly
    (every piece lies in its source's plane with its orientation, and none is missing)."""
    P = rows(out["V_exact"])
    total = {s: (Fr(0),) * 3 for s in range(len(F))}
    for f, s in zip(out["F"].tolist(), out["source"].tolist()):
        a = vector_area(*(P[i] for i in f))
        assert a != (0, 0, 0), "a degenerate output triangle"
        total[s] = tuple(x + y for x, y in zip(total[s], a))
    for s, (i, j, k) in enumerate(F):
        assert total[s] == vector_area(*(tuple(map(Fr, V[i])), tuple(map(Fr, V[j])), tuple(map(Fr, V[k]))))


def arrange_cli():
    repo = pathlib.Path(__file__).resolve().parents[2]
    cli = os.environ.get("TRITRI_ARRANGE_BIN", str(repo / "build" / "bin" / "arrange"))
    if not os.access(cli, os.X_OK):
        pytest.skip(f"no arrange binary at {cli} (set TRITRI_ARRANGE_BIN)")
    return cli


# --- arrange: exact input -------------------------------------------------------------------

def test_thirds_crossing_by_hand():
    V = np.array(THIRDS_V, dtype=object)
    out = tritri.arrange(V, THIRDS_F, labels=[0, 5], threads=1)
    s = out["stats"]
    assert (s["out_vertices"], s["out_edges"], s["out_triangles"], s["euler"]) == (8, 15, 8, 1)
    assert s["intersection_points"] == 2 and s["tpi"] == 0
    VE = out["V_exact"]
    assert VE.dtype == object and VE.shape == (8, 3) and all(type(x) is Fr for x in VE.flat)
    assert set(rows(VE)) == set(rows(THIRDS_V)) | THIRDS_NEW
    # V is V_exact rounded to the nearest double; exact where every coordinate is a double.
    assert out["V"].dtype == np.float64 and out["V"].tolist() == [[float(x) for x in r] for r in VE]
    assert out["V_is_exact"].tolist() == [all(Fr(float(x)) == x for x in r) for r in VE]
    assert sorted(out["source"].tolist()) == [0] * 4 + [1] * 4
    assert [out["label_sets"][i] for i in out["label_set"]] == [(0,) if t == 0 else (5,) for t in out["source"]]
    expect_tiling(out, THIRDS_V, THIRDS_F)


def test_exact_input_in_any_form_gives_the_same_arrangement():
    expected = tritri.arrange(np.array(THIRDS_V, dtype=object), THIRDS_F, threads=1)
    as_floats = [[float(x) if not isinstance(x, Fr) else x for x in r] for r in THIRDS_V]  # floats, Fractions
    for V in (THIRDS_V, as_floats, np.array(THIRDS_V, dtype=object).T.copy().T):
        out = tritri.arrange(V, THIRDS_F, threads=1)
        assert rows(out["V_exact"]) == rows(expected["V_exact"]) and out["F"].tolist() == expected["F"].tolist()
    native = tritri.arrange(THIRDS_V, THIRDS_F, classifier="native", threads=2)
    assert set(rows(native["V_exact"])) == set(rows(expected["V_exact"]))
    plain = tritri.arrange(THIRDS_V, THIRDS_F, threads=1, exact_output=False)  # exact path, no V_exact
    assert "V_exact" not in plain and plain["V"].tolist() == expected["V"].tolist()


def test_integers_beyond_two_to_the_53_are_exact():
    big = 2**53 + 1  # not a double: the exact pipeline keeps it
    V = [[0, 0, 0], [big, 0, 0], [0, big, 0]]
    for Vv in (V, np.array(V, dtype=np.int64)):
        out = tritri.arrange(Vv, [[0, 1, 2]])
        assert set(rows(out["V_exact"])) == set(rows(V))
        assert sorted(out["V_is_exact"].tolist()) == [False, False, True]
    out = tritri.arrange([[0, 0, 0], [2**60, 0, 0], [0, 1, 0]], [[0, 1, 2]])  # a double: as before
    assert "V_exact" not in out and out["V"].dtype == np.float64


def test_fractions_that_are_doubles_take_the_double_pipeline():
    """Backward compatibility: float64 input returns what it returned before; Fractions
    that are all doubles give the same arrangement, plus V_exact."""
    V = [[0, 0, 0], [4, 0, 0], [0, 4, 0], [1, 1, -1], [3, 1, -1], [1, 1, 1.5]]
    F = [[0, 1, 2], [3, 4, 5]]
    before = tritri.arrange(np.array(V), F)
    assert list(before) == ["V", "F", "source", "label_set", "label_sets", "V_is_exact", "stats"]
    exact = tritri.arrange(np.array(V), F, exact_output=True)
    fractions = tritri.arrange(np.array([[Fr(x) for x in r] for r in V], dtype=object), F)
    for out in (exact, fractions):
        for key in before:
            if key != "stats":
                assert np.array_equal(np.asarray(out[key], dtype=object), np.asarray(before[key], dtype=object)), key
        VE = out["V_exact"]
        assert [all(Fr(float(a)) == b for a, b in zip(r, e)) for r, e in zip(out["V"], VE)] == \
            out["V_is_exact"].tolist()
    expect_tiling(exact, V, F)


# --- load_mesh --------------------------------------------------------------------------------

def test_load_mesh_reads_rationals_exactly(tmp_path):
    p = tmp_path / "thirds.obj"
    p.write_text("".join(f"v {' '.join(str(Fr(x)) for x in r)}\n" for r in THIRDS_V)
                 + "f 1 2 3\nf 4 5 6\n")
    m = tritri.load_mesh(p)
    assert list(m) == ["V", "F"] and m["V"].dtype == object and m["V"].shape == (6, 3)
    assert rows(m["V"]) == rows(THIRDS_V) and m["F"].tolist() == THIRDS_F
    assert all(type(x) is Fr for x in m["V"].flat)
    out = tritri.arrange(m["V"], m["F"], threads=1)  # exact in, exact out
    assert set(rows(out["V_exact"])) == set(rows(THIRDS_V)) | THIRDS_NEW
    # "2/6" is 1/3; a file whose rationals are all doubles reads as float64.
    q = tmp_path / "mixed.off"
    q.write_text("OFF\n3 1 0\n2/6 0 0\n1/4 1 0\n0 0.1 -3/1\n3 0 1 2\n")
    assert rows(tritri.load_mesh(q)["V"]) == [(T, 0, 0), (Fr(1, 4), 1, 0), (0, Fr(0.1), -3)]
    d = tmp_path / "doubles.off"
    d.write_text("OFF\n3 1 0\n1/4 0 0\n1 1e-300 0\n0 0.1 -0\n3 0 1 2\n")
    m = tritri.load_mesh(d)
    assert m["V"].dtype == np.float64 and m["V"].tolist() == [[0.25, 0, 0], [1, 1e-300, 0], [0, 0.1, 0]]
    e = tritri.load_mesh(d, exact=True)
    assert e["V"].dtype == object and all(type(x) is Fr for x in e["V"].flat)
    assert rows(e["V"]) == [(Fr(1, 4), 0, 0), (1, Fr(1e-300), 0), (0, Fr(3602879701896397, 2**55), 0)]
    assert e["F"].tolist() == m["F"].tolist()


def test_cli_exact_file_equals_the_exact_output_and_arranges_to_itself(tmp_path):
    cli = arrange_cli()
    # Two crossing tetrahedra; some of their intersection points are not doubles.
    V = [[0, 0, 0], [3, 0, 0], [0, 3, 0], [0, 0, 3], [1, 1, -1], [2, 1, 2], [1, 2, 2], [-1, 1, 1]]
    F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [4, 6, 5], [4, 5, 7], [4, 7, 6], [5, 6, 7]]
    src = tmp_path / "in.off"
    src.write_text(f"OFF\n{len(V)} {len(F)} 0\n" + "".join(f"{x} {y} {z}\n" for x, y, z in V)
                   + "".join(f"3 {a} {b} {c}\n" for a, b, c in F))
    written = tmp_path / "out.obj"
    run = subprocess.run([cli, str(src), "-o", str(written), "--exact", "--threads", "1"], capture_output=True,
                         text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    out = tritri.arrange(np.array(V, dtype=float), F, threads=1, exact_output=True)
    assert not out["V_is_exact"].all()  # some new points are not doubles
    m = tritri.load_mesh(written)
    assert m["V"].dtype == object
    assert rows(m["V"]) == rows(out["V_exact"]) and m["F"].tolist() == out["F"].tolist()
    expect_tiling(out, V, F)
    again = tritri.arrange(m["V"], m["F"], threads=1)
    assert again["stats"]["intersection_points"] == 0 and again["stats"]["tpi"] == 0
    assert set(rows(again["V_exact"])) == set(rows(m["V"])) and len(again["F"]) == len(m["F"])


# --- refusals ---------------------------------------------------------------------------------

BIG = Fr(sys.float_info.max)


def with_value(v):
    V = np.array(THIRDS_V, dtype=object)
    V[1, 0] = v
    return V


@pytest.mark.parametrize("v", [Fr(10**400, 3), BIG + Fr(1, 3), -BIG - 1, 2**1024, float("nan"), float("inf"),
                               -float("inf"), np.float64("nan")])
def test_values_beyond_the_float64_range_or_not_finite_are_refused(v):
    with pytest.raises(ValueError, match=r"V\[1, 0\]") as e:
        tritri.arrange(with_value(v), THIRDS_F)
    assert not isinstance(e.value, TypeError)


def test_the_largest_double_and_tiny_rationals_are_accepted():
    V = [[0, 0, 0], [BIG - Fr(1, 3), 0, 0], [0, -BIG, Fr(1, 10**400)]]
    out = tritri.arrange(V, [[0, 1, 2]])
    assert set(rows(out["V_exact"])) == set(rows(V)) and out["V"][np.isfinite(out["V"])].size == 9


@pytest.mark.parametrize("call", [
    lambda: tritri.arrange(with_value("1/3"), THIRDS_F),
    lambda: tritri.arrange(with_value(None), THIRDS_F),
    lambda: tritri.arrange(with_value(1j), THIRDS_F),
    lambda: tritri.arrange(with_value(True), THIRDS_F),
    lambda: tritri.arrange(with_value(decimal.Decimal(1)), THIRDS_F),
    lambda: tritri.arrange(THIRDS_V, THIRDS_F, exact_output="yes"),
    lambda: tritri.arrange(THIRDS_V, THIRDS_F, exact_output=1),
    lambda: tritri.load_mesh("x.obj", exact=None),
    lambda: tritri.load_mesh("x.obj", exact="yes"),
])
def test_wrong_types_raise_argument_type_error(call):
    with pytest.raises(tritri.ArgumentTypeError):
        call()


@pytest.mark.parametrize("text", ["v 1/0 0 0", "v 1e400/3 0 0", f"v -{2**1024}/1 0 0", f"v {2**1026}/3 0 0",
                                  "v 1/3/3 0 0", "v -1/ 0 0"])
def test_bad_rational_files_are_refused(tmp_path, text):
    p = tmp_path / "bad.obj"
    p.write_text(f"{text}\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(ValueError, match="bad.obj"):
        tritri.load_mesh(p, exact=True)


def test_the_extension_checks_exact_strings_too():
    from tritri import _tritri  # for callers that bypass the wrapper
    F = np.array([[0, 1, 2]], dtype=np.int64)
    good = ["0/1", "1/1", "0/1"] * 3
    third = ["0/1", "1/1", "0/1", "1/3", "0/1", "0/1", "0/1", "0/1", "1/1"]  # (0,1,0), (1/3,0,0), (0,0,1)
    assert len(_tritri.arrange_exact(third, F, None, "tritri", 1)["F"]) == 1
    for bad in (good[:8], ["1/0"] + good[1:], ["x/1"] + good[1:], ["1"] + good[1:], ["1/-3"] + good[1:]):
        with pytest.raises(ValueError):
            _tritri.arrange_exact(bad, F, None, "tritri", 1)


def test_huge_fractions_are_not_normalised_again(monkeypatch):
    """Issue 36: the exact pipeline's rationals are in lowest terms; building the Fractions
    of its input and output must not run the gcd of their normalisation (quadratic in the
    digits: 29 s of a 34 s call for 30,000-digit input). Counted, not timed: math.gcd as the
    fractions module sees it."""
    import fractions
    import math

    big = Fr(10**3000 + 1, 10**3000)  # in lowest terms, just above 1
    V = [[0, 0, 0], [big, 0, 0], [0, 1, 0], [T, T, -1], [T, T, 1], [T, -1, T]]
    calls = []
    real_gcd = math.gcd

    def counting_gcd(*args):
        calls.append(max(abs(a).bit_length() for a in args))
        return real_gcd(*args)

    monkeypatch.setattr(fractions.math, "gcd", counting_gcd)
    out = tritri.arrange(V, THIRDS_F)
    monkeypatch.setattr(fractions.math, "gcd", real_gcd)
    assert big in set(out["V_exact"].ravel())
    assert not [bits for bits in calls if bits > 1000], "huge Fractions were normalised again"
