"""tritri.classify, self_intersections and intersections on exact coordinates (Fractions):
when some value is not exactly a float64 they classify on the rationals
(tritri::RationalKernel), else on float64 as before.

- a contact that only exists exactly: triangle B's corner at the centroid (1/3, 1/3, 1/3)
  of triangle A in the plane x + y + z = 1 (checked here with Fractions: on the plane,
  inside A) is one point VB_ON_TA; with the coordinates rounded to float64 the answer
  differs;
- Fractions that are float64 values give exactly the float64 path's results;
- an exact arrangement's own vertices (V_exact of two copies of a sphere a rotation by pi
  apart, layers 1e-16 apart that cross everywhere) have no self-intersection, while the
  same mesh rounded to nearest has many: self_intersections sees the difference;
- intersections with one exact mesh and one float64 mesh classifies both exactly, the same
  as with both given as Fractions;
- refusals: a Fraction beyond the float64 range (ValueError), wrong shapes (ValueError),
  non-numbers (ArgumentTypeError).
Run: scripts/test_python.sh.
"""

import math
from fractions import Fraction as Fr

import numpy as np
import pytest

import tritri

from test_round_safe import rotated_copies, uv_sphere

THIRD = Fr(1, 3)
A = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
B = [[THIRD, THIRD, THIRD], [1, 1, 1], [2, 1, 1]]


def objects(rows):
    a = np.empty((len(rows), 3), dtype=object)
    a[:] = rows
    return a


def test_a_contact_that_only_exists_exactly():
    # The reference, with Fractions: B's first corner is on A's plane, inside A, and B's
    # other corners are strictly above it.
    assert sum(B[0]) == 1 and all(c > 0 for c in B[0])
    assert sum(B[1]) > 1 and sum(B[2]) > 1
    r = tritri.classify(A, objects(B))
    assert r.intersects and not r.coplanar
    assert [(t, i) for t, i, _ in r.points] == [("VB_ON_TA", 0)]
    rounded = tritri.classify(A, [[float(c) for c in row] for row in B])
    assert rounded.points != r.points
    # Both argument orders, and as meshes: the same contact.
    swapped = tritri.classify(objects(B), A)
    assert [(t, i) for t, i, _ in swapped.points] == [("VA_ON_TB", 0)]
    F = np.array([[0, 1, 2]])
    pairs, results = tritri.intersections(A, F, objects(B), F)
    assert pairs.tolist() == [[0, 0]] and results[0] == r
    pairs, results = tritri.self_intersections(objects(A + B), [[0, 1, 2], [3, 4, 5]])
    assert pairs.tolist() == [[0, 1]] and results[0] == r


def test_fractions_that_are_doubles_give_the_float64_results():
    V, F = uv_sphere((0.0, 0.0, 0.0), 1.0, 6, 8)
    W = V * 0.75 + 0.5
    V2 = np.vstack([V, W])
    F2 = np.vstack([F, F + len(V)])
    exact = objects([[Fr(c) for c in row] for row in V2])
    p_float, r_float = tritri.self_intersections(V2, F2)
    p_exact, r_exact = tritri.self_intersections(exact, F2)
    assert len(p_float) > 10
    assert p_exact.tolist() == p_float.tolist() and r_exact == r_float
    assert tritri.classify(exact[F2[0]], exact[F2[len(F)]]) == tritri.classify(V2[F2[0]], V2[F2[len(F)]])


def test_an_exact_arrangement_has_no_self_intersection_and_its_rounding_has():
    V, F = uv_sphere((0.1, 0.2, 0.3), 1.0, 10, 20)
    V, F = rotated_copies(V, F, 2, (0.1, 0.2, 0.3))
    out = tritri.arrange(V, F, exact_output=True)
    assert not out["V_is_exact"].all()
    pairs, _ = tritri.self_intersections(out["V"], out["F"])
    assert len(pairs) > 0
    pairs, _ = tritri.self_intersections(out["V_exact"], out["F"])
    assert len(pairs) == 0


def test_intersections_with_one_exact_mesh_classifies_both_exactly():
    V1, F1 = uv_sphere((0.0, 0.0, 0.0), 1.0, 6, 8)
    V2 = objects([[Fr(1, 3) + Fr(1, 7) * i, Fr(-2, 3) + Fr(2, 7) * j, Fr(1, 21)] for i in range(4) for j in range(4)])
    F2 = np.array([[4 * i + j, 4 * i + j + 4, 4 * i + j + 1] for i in range(3) for j in range(3)] +
                  [[4 * i + j + 1, 4 * i + j + 4, 4 * i + j + 5] for i in range(3) for j in range(3)])
    mixed = tritri.intersections(V1, F1, V2, F2)
    both = tritri.intersections(objects([[Fr(c) for c in row] for row in V1]), F1, V2, F2)
    assert len(mixed[0]) > 0
    assert mixed[0].tolist() == both[0].tolist() and mixed[1] == both[1]


@pytest.mark.parametrize("value", [Fr(10**400, 3), -Fr(2**1024 + 1)])
def test_coordinates_beyond_float64_are_refused(value):
    b = objects(B)
    b[1, 1] = value
    with pytest.raises(ValueError, match=r"tritri.classify: b\[1, 1\] = .* beyond the float64 range"):
        tritri.classify(A, b)
    with pytest.raises(ValueError, match=r"tritri.self_intersections: V\[1, 1\]"):
        tritri.self_intersections(b, [[0, 1, 2]])


def test_wrong_shapes_and_types_are_refused():
    with pytest.raises(ValueError, match=r"a must be a 3 x 3 array"):
        tritri.classify(objects(B)[:2], A)
    with pytest.raises(ValueError, match=r"V1 must be an n x 3 array"):
        tritri.intersections(objects(B).reshape(1, 9), [[0, 1, 2]], A, [[0, 1, 2]])
    b = objects(B)
    b[0, 0] = "1/3"
    with pytest.raises(tritri.ArgumentTypeError):
        tritri.classify(A, b)
    assert math.isclose(float(THIRD), 1 / 3)
