"""Safe rounding through the Python module (issue 14; arrangements/round_mesh.h):
tritri.arrange(..., rounding="safe") returns a float64 mesh that is itself an arrangement.

- two copies of a UV sphere, the second turned by pi about the z axis (two layers about
  1e-16 apart, since sin(pi) is not 0 in float64, crossing everywhere):
  rounded to nearest, the mesh arranged again has intersecting pairs (so the test can tell
  the two apart); rounded safely, arranging it again finds nothing (no new point, no
  intersecting pair, nothing merged or removed, the same triangles), every row of V is
  exact, sources are those of the exact arrangement (the two layers merge into one with
  both labels), stats report the
  passes and a displacement bound;
- two and three copies of a sphere with 19 meridians turned about its box centre (grazing
  crossings) need rerouting in cycles of arranging again: stats report round_rerouted > 0
  (none without --round safe);
- three copies of a 12 x 24 sphere turned by 2 pi / 3 (the copies' vertices a few ulps
  apart, the layers crossing wherever the rounding errors change sign) settle only by
  the last resort that merges input vertices: stats report round_merged_input > 0, and
  the result is about one sphere, most of its area with all three labels;
- exact input (Fractions) takes the exact path and rounds safely the same way;
- the move limit: two crossing spheres scaled by 2^-28 and moved to 1e6 (about 120 ulps
  wide) are refused within the default (RuntimeError) and settle with round_max_move=1,
  moving a vertex by more than a 64th of the diagonal and less than all of it;
- refusals: an unknown rounding (ValueError), a rounding that is not a str
  (ArgumentTypeError), exact_output=True with rounding="safe" (ValueError), a
  round_max_move that is not a finite number above 0 or given without rounding="safe"
  (ValueError), or that is not a real number (ArgumentTypeError).
Run: scripts/test_python.sh.
"""

import math
from fractions import Fraction as Fr

import numpy as np
import pytest

import tritri


def uv_sphere(centre, radius, rings, segments):
    V = [(centre[0], centre[1], centre[2] + radius)]
    for i in range(1, rings):
        t = math.pi * i / rings
        for j in range(segments):
            p = 2 * math.pi * j / segments
            V.append((centre[0] + radius * math.sin(t) * math.cos(p),
                      centre[1] + radius * math.sin(t) * math.sin(p), centre[2] + radius * math.cos(t)))
    V.append((centre[0], centre[1], centre[2] - radius))
    F = [(0, 1 + j, 1 + (j + 1) % segments) for j in range(segments)]
    for i in range(rings - 2):
        for j in range(segments):
            a, b = 1 + i * segments + j, 1 + i * segments + (j + 1) % segments
            F += [(a, a + segments, b + segments), (a, b + segments, b)]
    last = len(V) - 1
    base = 1 + (rings - 2) * segments
    F += [(last, base + (j + 1) % segments, base + j) for j in range(segments)]
    return np.array(V), np.array(F, dtype=np.int64)


def rotated_copies(V, F, k, centre):
    Vs, Fs = [], []
    for i in range(k):
        a = 2 * math.pi * i / k
        c, s = math.cos(a), math.sin(a)
        x, y = V[:, 0] - centre[0], V[:, 1] - centre[1]
        Vs.append(np.column_stack([centre[0] + c * x - s * y, centre[1] + s * x + c * y, V[:, 2]]))
        Fs.append(F + i * len(V))
    return np.vstack(Vs), np.vstack(Fs)


@pytest.fixture(scope="module")
def copies():
    V, F = uv_sphere((0.1, 0.2, 0.3), 1.0, 10, 20)
    return rotated_copies(V, F, 2, (0.1, 0.2, 0.3))


def assert_is_arrangement(out):
    again = tritri.arrange(out["V"], out["F"])["stats"]
    assert again["lpi"] == 0 and again["tpi"] == 0 and again["intersecting_pairs"] == 0
    assert again["merged_vertices"] == again["removed_degenerate"] == again["removed_duplicate"] == 0
    assert again["out_triangles"] == len(out["F"])


def test_safe_rounding_is_an_arrangement_and_nearest_is_not(copies):
    V, F = copies
    labels = np.repeat(np.arange(2), len(F) // 2)
    near = tritri.arrange(V, F, labels)
    assert not near["V_is_exact"].all()
    assert tritri.arrange(near["V"], near["F"])["stats"]["intersecting_pairs"] > 0
    safe = tritri.arrange(V, F, labels, rounding="safe")
    assert_is_arrangement(safe)
    assert safe["V"].dtype == np.float64 and safe["V_is_exact"].all() and "V_exact" not in safe
    s = safe["stats"]
    assert s["round_passes"] > 1 and 0 < s["round_max_move_rel"] < 1e-6
    assert near["stats"]["round_passes"] == 0
    # Sources of the exact arrangement; layers merged by rounding carry the union of labels.
    exact_sources = set(near["source"].tolist())
    assert set(safe["source"].tolist()) <= exact_sources
    for ls in safe["label_set"]:
        assert set(safe["label_sets"][ls]) <= {0, 1}


@pytest.mark.parametrize("k", [2, 3])
def test_grazing_copies_settle_by_rerouting_in_cycles(k):
    # An odd number of meridians: the copies turned about the box's centre (not the axis)
    # cross at grazing angles, where rounding and re-arranging keep making new crossings;
    # rerouting, with its best mesh arranged again while few conflicts are left, settles
    # it with every vertex at a nearest double, a few ulps per round off.
    V, F = uv_sphere((0.0, 0.0, 0.0), 1.0, 10, 19)
    centre = 0.5 * (V.min(axis=0) + V.max(axis=0))  # turned about its box's centre
    V2, F2 = rotated_copies(V, F, k, centre)
    out = tritri.arrange(V2, F2, rounding="safe")
    assert_is_arrangement(out)
    s = out["stats"]
    assert s["round_rerouted"] > 0
    assert 0 < s["round_max_move_rel"] < 1e-12
    plain = tritri.arrange(V2, F2)["stats"]
    assert plain["round_rerouted"] == 0


def test_nearly_coincident_copies_merge_at_their_input_vertices():
    V, F = uv_sphere((0.1, 0.2, 0.3), 1.0, 12, 24)
    V3, F3 = rotated_copies(V, F, 3, (0.1, 0.2, 0.3))
    labels = np.repeat(np.arange(3), len(F))
    out = tritri.arrange(V3, F3, labels, rounding="safe")
    assert_is_arrangement(out)
    s = out["stats"]
    assert s["round_merged_input"] > 0 and 0 < s["round_max_move_rel"] < 1e-14

    def area(W, G):
        a, b, c = W[G[:, 0]], W[G[:, 1]], W[G[:, 2]]
        return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)

    one_sphere = area(V, F).sum()
    faces = area(out["V"], out["F"])
    assert one_sphere * (1 - 1e-9) < faces.sum() < 1.1 * one_sphere
    shared = np.array([len(out["label_sets"][ls]) == 3 for ls in out["label_set"]])
    assert faces[shared].sum() > 0.9 * faces.sum()
    assert tritri.arrange(V3, F3)["stats"]["round_merged_input"] == 0


def test_exact_input_rounds_safely():
    # Two triangles of thirds crossing, plus a sliver of sevenths through both.
    T, S = Fr(1, 3), Fr(1, 7)
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [T, T, -1], [T, T, 1], [T, -1, T], [S, 0, -S], [S, 1, S], [2 * S, T, 0]]
    F = [[0, 1, 2], [3, 4, 5], [6, 7, 8]]
    out = tritri.arrange(np.array(V, dtype=object), np.array(F), rounding="safe")
    assert_is_arrangement(out)
    assert out["stats"]["lpi"] > 0 and out["stats"]["round_passes"] >= 1


def test_bad_rounding_is_refused(copies):
    V, F = copies
    with pytest.raises(ValueError):
        tritri.arrange(V, F, rounding="magic")
    with pytest.raises(tritri.ArgumentTypeError):
        tritri.arrange(V, F, rounding=1)
    with pytest.raises(ValueError):
        tritri.arrange(V, F, rounding="safe", exact_output=True)


def tiny_spheres_far_out(e):
    V1, F1 = uv_sphere((0.0, 0.0, 0.0), 1.0, 12, 24)
    V2, F2 = uv_sphere((0.6, 0.25, 0.15), 0.8, 12, 24)
    return np.vstack([V1, V2]) * 2.0**-e + 1e6, np.vstack([F1, F2 + len(V1)])


def test_a_larger_move_limit_settles_a_model_a_hundred_ulps_wide():
    V, F = tiny_spheres_far_out(28)
    with pytest.raises(RuntimeError):
        tritri.arrange(V, F, rounding="safe")
    out = tritri.arrange(V, F, rounding="safe", round_max_move=1)
    assert_is_arrangement(out)
    assert 1 / 64 < out["stats"]["round_max_move_rel"] <= 1


def test_bad_move_limits_are_refused():
    V, F = tiny_spheres_far_out(22)
    for bad in (0, -1, 0.0, math.nan, math.inf, 10**400, Fr(-1, 3)):
        with pytest.raises(ValueError):
            tritri.arrange(V, F, rounding="safe", round_max_move=bad)
    for bad in ("0.5", True, [0.5]):
        with pytest.raises(tritri.ArgumentTypeError):
            tritri.arrange(V, F, rounding="safe", round_max_move=bad)
    with pytest.raises(ValueError):
        tritri.arrange(V, F, round_max_move=0.5)  # rounding to nearest moves nothing beyond an ulp
    out = tritri.arrange(V, F, rounding="safe", round_max_move=Fr(1, 2))
    assert_is_arrangement(out)
