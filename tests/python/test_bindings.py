"""Specification of the Python module tritri (python/tritri, python/tritri_module.cpp).

- classify: hand-derived answers (crossing, touching at a vertex / on an edge / in a face,
  coplanar overlap, disjoint, degenerate), and A/B swap symmetry;
- self_intersections / intersections: equal to classify over all pairs with the documented
  rule, on small random meshes with shared and repeated vertices;
- arrange: two crossing cubes (Euler characteristic and areas derived by hand, nothing
  left intersecting in the exactly representable output, provenance and labels), two
  overlapping coplanar squares (label sets and areas by hand), spheres (pairs left in the
  rounded output only involve rounded vertices);
- every refused input raises ValueError (wrong types: ArgumentTypeError, also a TypeError),
  table-driven over every argument of every function with hostile values (huge integers,
  NaN/Inf, wrong shapes and dtypes, out-of-range indices and labels, every kind of bad
  thread count), never OverflowError, MemoryError or a crash;
- the stats dict has exactly the keys of `arrange --stats`, and `arrange --help` and the
  docstring of tritri.arrange list them in the same order (the CLI is run when built:
  $TRITRI_ARRANGE_BIN, default build/bin/arrange).
Run: scripts/test_python.sh (installs the package with pip, then runs pytest).
"""

import fractions
import itertools
import json
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import tritri

# --- helpers -------------------------------------------------------------------------

SWAP = {"VA_ON_VB": "VA_ON_VB", "VA_ON_EB": "VB_ON_EA", "VB_ON_EA": "VA_ON_EB", "VA_ON_TB": "VB_ON_TA",
        "VB_ON_TA": "VA_ON_TB", "EA_CROSS_EB": "EA_CROSS_EB", "EA_CROSS_TB": "EB_CROSS_TA",
        "EB_CROSS_TA": "EA_CROSS_TB"}


TYPES = ["VA_ON_VB", "VA_ON_EB", "VB_ON_EA", "VA_ON_TB", "VB_ON_TA", "EA_CROSS_EB", "EA_CROSS_TB", "EB_CROSS_TA"]



def face_labels(out):
    """Each output face's label set (label_sets[label_set[f]]), checking the two fields."""
    assert out["label_set"].dtype == np.int64 and out["label_set"].shape == (len(out["F"]),)
    assert all(0 <= i < len(out["label_sets"]) for i in out["label_set"])
    return [out["label_sets"][i] for i in out["label_set"]]

def point_order(p):
    """classify's order of points: by (type as in the C++ enum, id0, id1)."""
    return (TYPES.index(p[0]), p[1], p[2])


def swapped_point(p):
    """The name of point p of classify(a, b) in classify(b, a)."""
    t, i, j = p
    if t in ("VA_ON_VB", "EA_CROSS_EB"):
        return (t, j, i)
    return (SWAP[t], i, j)


def segment_set(r, rename=lambda p: p):
    return {frozenset((rename(r.points[s0]), rename(r.points[s1]))) for s0, s1 in r.segments}


def cube(lo, hi):
    """Closed axis-aligned box: 8 vertices, 12 outward-oriented triangles."""
    V = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])], float)
    # vertex index = 4*x + 2*y + z (0: lo, 1: hi)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    F = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return V, np.array(F, dtype=np.int64)


def square(x0, y0, side, z=0.0):
    V = np.array([[x0, y0, z], [x0 + side, y0, z], [x0 + side, y0 + side, z], [x0, y0 + side, z]], float)
    return V, np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64)


def uv_sphere(centre, radius, rings, segments):
    V = [[centre[0], centre[1], centre[2] + radius], [centre[0], centre[1], centre[2] - radius]]
    for r in range(1, rings):
        th = math.pi * r / rings
        for s in range(segments):
            ph = 2 * math.pi * s / segments
            V.append([centre[0] + radius * math.sin(th) * math.cos(ph), centre[1] + radius * math.sin(th) * math.sin(ph),
                      centre[2] + radius * math.cos(th)])
    ring = lambda r, s: 2 + (r - 1) * segments + s % segments  # noqa: E731
    F = []
    for s in range(segments):
        F.append([0, ring(1, s), ring(1, s + 1)])
        F.append([1, ring(rings - 1, s + 1), ring(rings - 1, s)])
        for r in range(1, rings - 1):
            F.append([ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)])
            F.append([ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)])
    return np.array(V), np.array(F, dtype=np.int64)


def join(*meshes):
    """One mesh from several, and the mesh index of each triangle."""
    Vs, Fs, labels, offset = [], [], [], 0
    for k, (V, F) in enumerate(meshes):
        Vs.append(V)
        Fs.append(F + offset)
        labels += [k] * len(F)
        offset += len(V)
    return np.vstack(Vs), np.vstack(Fs), np.array(labels, dtype=np.int64)


def euler_characteristic(F):
    edges = {tuple(sorted(e)) for a, b, c in F for e in ((a, b), (b, c), (c, a))}
    return len(np.unique(F)) - len(edges) + len(F)


def twice_areas(V, F):
    """Twice the area of each triangle (exact for the small integer coordinates used)."""
    return np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)


# --- classify ------------------------------------------------------------------------

A = [[0, 0, 0], [2, 0, 0], [0, 2, 0]]  # in z = 0


def test_classify_crossing():
    # B stands in x = 0.5: its edge 0 pierces A's face at (0.5, 0.5, 0); A's edge 0 (y = 0)
    # crosses B's face at (0.5, 0, 0).
    r = tritri.classify(A, [[0.5, 0.5, -1], [0.5, 0.5, 1], [0.5, -1, 0.5]])
    assert r.points == [("EA_CROSS_TB", 0, -1), ("EB_CROSS_TA", 0, -1)]
    assert r.segments == [(0, 1)]
    assert r.intersects and not r.coplanar and not r.degenerate


def test_classify_touching_at_a_vertex_on_an_edge_and_in_a_face():
    vertex = tritri.classify(A, [[0, 0, 0], [-1, 0, 1], [0, -1, 1]])
    assert vertex.points == [("VA_ON_VB", 0, 0)] and vertex.segments == []
    edge = tritri.classify(A, [[1, 0, 0], [1, -1, 1], [0, -1, 1]])  # B's vertex 0 on A's edge 0
    assert edge.points == [("VB_ON_EA", 0, 0)] and edge.segments == []
    face = tritri.classify(A, [[1, 1, 1], [0.5, 0.5, 0], [0, 1, 1]])  # B's vertex 1 in A's face
    assert face.points == [("VB_ON_TA", 1, -1)] and face.segments == []


def test_classify_coplanar_overlap():
    # B = A shifted by (0.5, 0.5): the overlap is the triangle (0.5, 0.5), (1.5, 0.5),
    # (0.5, 1.5): B's vertex 0 in A's face, and A's edge 1 (x + y = 2) crossing B's
    # edges 0 (y = 0.5) and 2 (x = 0.5).
    r = tritri.classify(A, [[0.5, 0.5, 0], [2.5, 0.5, 0], [0.5, 2.5, 0]])
    assert r.coplanar
    assert r.points == [("VB_ON_TA", 0, -1), ("EA_CROSS_EB", 1, 0), ("EA_CROSS_EB", 1, 2)]
    assert r.segments == [(0, 1), (0, 2), (1, 2)]


def test_classify_disjoint_and_degenerate():
    far = tritri.classify(A, [[0, 0, 1], [1, 0, 1], [0, 1, 1]])
    assert far.points == [] and not far.intersects and not far.coplanar
    degenerate = tritri.classify(A, [[0, 0, 0], [1, 0, 0], [2, 0, 0]])
    assert degenerate.degenerate and degenerate.points == []


def test_classify_is_symmetric_under_swapping_a_and_b():
    rng = np.random.default_rng(7)
    cases = [(A, [[0.5, 0.5, -1], [0.5, 0.5, 1], [0.5, -1, 0.5]]),
             (A, [[0.5, 0.5, 0], [2.5, 0.5, 0], [0.5, 2.5, 0]]),
             (A, [[1, 0, 0], [1, -1, 1], [0, -1, 1]])]
    # Small integer coordinates: many touching, coplanar and edge-on-edge configurations.
    cases += [(rng.integers(0, 3, (3, 3)).astype(float), rng.integers(0, 3, (3, 3)).astype(float))
              for _ in range(400)]
    for a, b in cases:
        ab, ba = tritri.classify(a, b), tritri.classify(b, a)
        if ab.degenerate or ba.degenerate:  # the flag itself is not symmetric (see classify.h)
            assert ab.points == [] and ba.points == []
            continue
        assert sorted((swapped_point(p) for p in ab.points), key=point_order) == ba.points
        assert segment_set(ab, swapped_point) == segment_set(ba)
        assert (ab.coplanar, ab.degenerate) == (ba.coplanar, ba.degenerate)


# --- self_intersections and intersections ---------------------------------------------


def random_mesh(rng, nv, nf):
    return rng.integers(0, 4, (nv, 3)).astype(float), rng.integers(0, nv, (nf, 3))


def test_self_intersections_equals_classify_over_all_pairs():
    rng = np.random.default_rng(1)
    for _ in range(5):
        V, F = random_mesh(rng, 14, 40)
        pairs, results = tritri.self_intersections(V, F)
        expected = []
        for i, j in itertools.combinations(range(len(F)), 2):
            r = tritri.classify(V[F[i]], V[F[j]])
            shared = [p for p in r.points if p[0] == "VA_ON_VB" and F[i][p[1]] == F[j][p[2]]]
            if len(r.points) > len(shared) or len(shared) == 3:
                expected.append(((i, j), r))
        assert pairs.dtype == np.int64 and pairs.shape == (len(expected), 2)
        assert [tuple(p) for p in pairs] == [ij for ij, _ in expected]
        assert results == [r for _, r in expected]


def test_intersections_equals_classify_over_all_pairs():
    rng = np.random.default_rng(2)
    V1, F1 = random_mesh(rng, 10, 25)
    V2, F2 = random_mesh(rng, 10, 25)
    pairs, results = tritri.intersections(V1, F1, V2, F2)
    expected = [((i, j), tritri.classify(V1[F1[i]], V2[F2[j]])) for i in range(len(F1)) for j in range(len(F2))]
    expected = [(ij, r) for ij, r in expected if r.intersects]
    assert len(expected) > 0
    assert [tuple(p) for p in pairs] == [ij for ij, _ in expected]
    assert results == [r for _, r in expected]


def test_self_intersections_of_a_closed_mesh_and_of_empty_input():
    V, F = cube((0, 0, 0), (1, 1, 1))
    pairs, results = tritri.self_intersections(V, F)
    assert pairs.shape == (0, 2) and results == []
    pairs, results = tritri.self_intersections(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int32))
    assert pairs.shape == (0, 2)


def test_calls_from_several_python_threads_agree():
    # The GIL is released during the C++ work: concurrent calls must not interfere.
    from concurrent.futures import ThreadPoolExecutor
    V, F, _ = join(uv_sphere((0, 0, 0), 1.0, 12, 16), uv_sphere((0.5, 0.2, 0.1), 0.8, 10, 14))
    expected = tritri.self_intersections(V, F)
    with ThreadPoolExecutor(4) as pool:
        found = list(pool.map(lambda _: tritri.self_intersections(V, F), range(8)))
    for pairs, results in found:
        assert (pairs == expected[0]).all() and results == expected[1]


# --- arrange -------------------------------------------------------------------------


def test_arrange_two_crossing_cubes():
    # [0,2]^3 and [1,3]^3: the surfaces meet along a closed hexagonal loop (chi 0), so
    # chi(union) = 2 + 2 - 0 = 4. Every new point has integer coordinates: exact.
    V, F, labels = join(cube((0, 0, 0), (2, 2, 2)), cube((1, 1, 1), (3, 3, 3)))
    out = tritri.arrange(V, F, labels=labels)
    Vo, Fo = out["V"], out["F"]
    assert Vo.shape[1] == 3 and Fo.shape[1] == 3 and Fo.dtype == np.int64
    assert out["V_is_exact"].all()
    assert euler_characteristic(Fo) == 4 and out["stats"]["euler"] == 4
    assert out["stats"]["out_triangles"] == len(Fo) and out["stats"]["out_vertices"] == len(Vo)
    assert out["stats"]["in_triangles"] == 24 and out["stats"]["classifier"] == "tritri"
    # Nothing intersects any more beyond shared vertices and edges.
    pairs, _ = tritri.self_intersections(Vo, Fo)
    assert pairs.shape == (0, 2)
    # Provenance: each face lies in its source triangle's plane, with its orientation, and
    # carries its label; each cube keeps its area (6 faces of 4, in twice-areas: 48).
    src = out["source"]
    n_src = np.cross(V[F[src, 1]] - V[F[src, 0]], V[F[src, 2]] - V[F[src, 0]])
    n_out = np.cross(Vo[Fo[:, 1]] - Vo[Fo[:, 0]], Vo[Fo[:, 2]] - Vo[Fo[:, 0]])
    for k in range(3):
        assert (np.einsum("ij,ij->i", Vo[Fo[:, k]] - V[F[src, 0]], n_src) == 0).all()
    assert (np.einsum("ij,ij->i", n_out, n_src) > 0).all()
    assert face_labels(out) == [(int(labels[s]),) for s in src]
    areas = twice_areas(Vo, Fo)
    assert areas[labels[src] == 0].sum() == 48 and areas[labels[src] == 1].sum() == 48
    # The same arrangement with the native classifier and one thread.
    native = tritri.arrange(V, F, labels=labels, classifier="native", threads=1)
    assert native["stats"]["classifier"] == "native"
    assert len(native["F"]) == len(Fo) and euler_characteristic(native["F"]) == 4


def test_arrange_two_overlapping_coplanar_squares():
    # [0,2]^2 and [1,3]^2 in z = 0: the overlap [1,2]^2 (area 1) is covered by both and
    # carries labels (0, 1); the union is a disc (chi 1).
    V, F, labels = join(square(0, 0, 2), square(1, 1, 2))
    out = tritri.arrange(V, F, labels=labels)
    areas = twice_areas(out["V"], out["F"])
    by_labels = {}
    for ls, a in zip(face_labels(out), areas):
        by_labels[ls] = by_labels.get(ls, 0) + a
    assert by_labels == {(0,): 6, (1,): 6, (0, 1): 2}
    assert euler_characteristic(out["F"]) == 1
    assert tritri.self_intersections(out["V"], out["F"])[0].shape == (0, 2)
    # Without labels everything is label 0.
    assert set(face_labels(tritri.arrange(V, F))) == {(0,)}


def test_arrange_spheres_leaves_intersections_only_at_rounded_vertices():
    V, F, labels = join(uv_sphere((0, 0, 0), 1.0, 8, 12), uv_sphere((0.6, 0.25, 0.1), 0.9, 7, 10))
    out = tritri.arrange(V, F, labels=labels, threads=2)
    Vo, Fo, exact = out["V"], out["F"], out["V_is_exact"]
    assert out["stats"]["intersecting_pairs"] > 0 and not exact.all()
    assert len(Fo) > len(F) and Fo.min() >= 0 and Fo.max() < len(Vo)
    pairs, _ = tritri.self_intersections(Vo, Fo)
    for i, j in pairs:  # two faces with exact corners are exact faces of the arrangement
        assert not (exact[Fo[i]].all() and exact[Fo[j]].all())
    assert euler_characteristic(Fo) == out["stats"]["euler"]


# --- refused input -------------------------------------------------------------------

T = np.array(A, dtype=float)
V3, F1 = T.copy(), np.array([[0, 1, 2]])


def with_value(a, index, value):
    b = np.array(a, dtype=float)
    b[index] = value
    return b


BAD_CALLS = {
    "classify a 3x2": lambda: tritri.classify(np.zeros((3, 2)), T),
    "classify b 2x3": lambda: tritri.classify(T, np.zeros((2, 3))),
    "classify b 1-d": lambda: tritri.classify(T, np.zeros(9)),
    "classify NaN": lambda: tritri.classify(with_value(T, (1, 1), np.nan), T),
    "classify Inf": lambda: tritri.classify(T, with_value(T, (2, 0), np.inf)),
    "classify strings": lambda: tritri.classify([["a", "b", "c"]] * 3, T),
    "classify None": lambda: tritri.classify(None, T),
    "self V 2 columns": lambda: tritri.self_intersections(np.zeros((3, 2)), F1),
    "self V 1-d": lambda: tritri.self_intersections(np.zeros(9), F1),
    "self F 4 columns": lambda: tritri.self_intersections(V3, [[0, 1, 2, 0]]),
    "self F float": lambda: tritri.self_intersections(V3, [[0.0, 1.0, 2.0]]),
    "self F out of range": lambda: tritri.self_intersections(V3, [[0, 1, 3]]),
    "self F negative": lambda: tritri.self_intersections(V3, [[0, -1, 2]]),
    "self F huge": lambda: tritri.self_intersections(V3, [[0, 1, 2**40]]),
    "self V NaN": lambda: tritri.self_intersections(with_value(V3, (0, 2), np.nan), F1),
    "self V -Inf": lambda: tritri.self_intersections(with_value(V3, (0, 2), -np.inf), F1),
    "self ragged": lambda: tritri.self_intersections([[0, 0, 0], [1, 0]], F1),
    "two V1 NaN": lambda: tritri.intersections(with_value(V3, (1, 0), np.nan), F1, V3, F1),
    "two F1 range": lambda: tritri.intersections(V3, [[0, 1, 5]], V3, F1),
    "two V2 shape": lambda: tritri.intersections(V3, F1, np.zeros((3, 4)), F1),
    "two F2 shape": lambda: tritri.intersections(V3, F1, V3, [[0, 1]]),
    "two F2 range": lambda: tritri.intersections(V3, F1, V3, [[0, 1, 3]]),
    "arrange classifier": lambda: tritri.arrange(V3, F1, classifier="fast"),
    "arrange classifier type": lambda: tritri.arrange(V3, F1, classifier=1),
    "arrange threads": lambda: tritri.arrange(V3, F1, threads="two"),
    "arrange threads huge": lambda: tritri.arrange(V3, F1, threads=2**40),
    "arrange V NaN": lambda: tritri.arrange(with_value(V3, (2, 1), np.nan), F1),
    "arrange V shape": lambda: tritri.arrange(np.zeros((3, 2)), F1),
    "arrange F range": lambda: tritri.arrange(V3, [[0, 1, 3]]),
    "arrange F huge": lambda: tritri.arrange(V3, [[0, 1, 2**33]]),
    "arrange F float": lambda: tritri.arrange(V3, [[0.0, 1.0, 2.0]]),
    "arrange labels length": lambda: tritri.arrange(V3, F1, labels=[0, 1]),
    "arrange labels negative": lambda: tritri.arrange(V3, F1, labels=[-1]),
    "arrange labels huge": lambda: tritri.arrange(V3, F1, labels=[2**40]),
    "arrange labels float": lambda: tritri.arrange(V3, F1, labels=[0.5]),
    "arrange labels 2-d": lambda: tritri.arrange(V3, F1, labels=[[0]]),
}


@pytest.mark.parametrize("name", sorted(BAD_CALLS))
def test_bad_input_raises_value_error(name):
    with pytest.raises(ValueError) as e:
        BAD_CALLS[name]()
    assert str(e.value)  # a message, not an empty error


def test_bad_input_messages_name_the_argument_and_entry():
    with pytest.raises(ValueError, match=r"F\(0, 2\) = 3 is out of range"):
        tritri.self_intersections(V3, [[0, 1, 3]])
    with pytest.raises(ValueError, match=r"V2\(1, 0\)"):
        tritri.intersections(V3, F1, with_value(V3, (1, 0), np.inf), F1)
    with pytest.raises(ValueError, match="unknown classifier 'fast'"):
        tritri.arrange(V3, F1, classifier="fast")
    with pytest.raises(ValueError, match=r"must be an n x 3 array"):
        tritri.self_intersections(np.zeros((4, 2)), F1)


def test_load_mesh_reads_what_was_written_and_refuses_bad_files(tmp_path):
    # A quad written by hand: two triangles over its corners, tiling it (twice-area 2) with
    # its orientation (+z).
    p = tmp_path / "quad.off"
    p.write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    m = tritri.load_mesh(p)
    np.testing.assert_array_equal(m["V"], [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
    F = m["F"]
    assert F.shape == (2, 3) and set(F.ravel()) == {0, 1, 2, 3}
    n = np.cross(m["V"][F[:, 1]] - m["V"][F[:, 0]], m["V"][F[:, 2]] - m["V"][F[:, 0]])
    assert (n[:, 2] == 1).all()
    assert tritri.load_mesh(str(p).encode())["F"].tolist() == F.tolist()  # bytes paths too
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n")
    for path in (bad, tmp_path / "missing.obj", tmp_path / "x.xyz"):
        with pytest.raises(ValueError):
            tritri.load_mesh(path)


def test_load_mesh_takes_any_path_the_system_takes(tmp_path):
    # Names that are not UTF-8 (bytes, str with surrogate escapes, os.PathLike) are read as
    # the system names them; a refused file's message names it, bytes escaped.
    base = os.fsencode(tmp_path)
    quad = b"OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"
    try:
        os.mkdir(base + b"/d\xff")
        with open(base + b"/d\xff/q\xe9\xfe.off", "wb") as f:
            f.write(quad)
    except (OSError, UnicodeError):
        pytest.skip("the file system refuses names that are not UTF-8")
    raw = base + b"/d\xff/q\xe9\xfe.off"
    for path in (raw, os.fsdecode(raw), pathlib.Path(os.fsdecode(raw))):
        m = tritri.load_mesh(path)
        assert m["V"].shape == (4, 3) and m["F"].shape == (2, 3)
    cwd = os.getcwd()
    try:  # a relative path
        os.chdir(base + b"/d\xff")
        assert tritri.load_mesh(b"q\xe9\xfe.off")["F"].shape == (2, 3)
    finally:
        os.chdir(cwd)
    with open(base + b"/d\xff/bad\xff.obj", "wb") as f:
        f.write(b"v 0 0 0\nv 1 0 0\nv 0 +-1 0\nf 1 2 3\n")
    for name, what in ((b"bad\xff.obj", "line 3: vertex 3: coordinate '+-1' is not a number"),
                       (b"missing\xff.off", "no such file"), (b"x\xff.xyz", "unknown file extension")):
        with pytest.raises(ValueError) as e:
            tritri.load_mesh(base + b"/d\xff/" + name)
        shown = (base + b"/d\xff/" + name).decode("utf-8", "backslashreplace")
        assert shown + ": " in str(e.value) and what in str(e.value), str(e.value)
        assert type(e.value) is ValueError
    assert sorted(os.listdir(base + b"/d\xff")) == [b"bad\xff.obj", b"q\xe9\xfe.off"]


def test_load_mesh_reads_a_file_without_vertices_or_faces_as_an_empty_mesh(tmp_path):
    for name, text in (("e.obj", ""), ("e.off", "OFF\n0 0 0\n"), ("e.stl", "solid e\nendsolid e\n")):
        (tmp_path / name).write_text(text)
        m = tritri.load_mesh(tmp_path / name)
        assert m["V"].shape == (0, 3) and m["F"].shape == (0, 3)
        out = tritri.arrange(m["V"], m["F"])
        assert out["F"].shape == (0, 3)


def test_nothing_to_arrange_gives_an_empty_mesh():
    for V, F in ((V3, np.zeros((0, 3), dtype=int)), (np.zeros((3, 3)), F1)):
        out = tritri.arrange(V, F)
        assert out["V"].shape == (0, 3) and out["F"].shape == (0, 3) and face_labels(out) == []
        assert out["stats"]["out_triangles"] == 0


# --- hostile arguments: ValueError (wrong types: ArgumentTypeError), nothing else ----------

HUGE_INTS = [2**31 - 1, 2**31, 2**63 - 1, 2**63, 2**64, 10**30, 10**400, -2**63, -2**64, -10**400]
THREADS_VALUE = [-1, -2**31, tritri.MAX_THREADS + 1, 4096, 65536, 100000] + HUGE_INTS + [np.int64(2**40)]
THREADS_TYPE = [1.0, 1.5, float("nan"), float("inf"), -float("inf"), "4", "", " 5", "+5", "0x10", None, True,
                False, np.float64(2), np.bool_(True), 2j, [1], b"4"]
A_TYPE = [np.eye(3) * (1 + 1j), np.eye(3, dtype=bool), [["1", "0", "0"]] * 3, [[None] * 3] * 3,
          np.array([[b"x"] * 3] * 3), np.full((3, 3), np.datetime64("2020-01-01")), [[1, 2, "3"]] * 3, "abc"]
A_VALUE = [with_value(T, (0, 0), v) for v in (np.nan, np.inf, -np.inf)] + [
    [[10**400, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 0, 0], [1, 0, 0], [0, -2**1024, 0]],
    np.array([[fractions.Fraction(10**400), 0, 0], [1, 0, 0], [0, 1, 0]], dtype=object),
    np.zeros((3, 3, 1)), np.zeros(9), 5, [[0, 0, 0], [1, 0]]]
A_EMPTY = [[], np.zeros((0,)), np.zeros((0, 3))]  # refused by classify; an empty mesh elsewhere
F_TYPE = [[[0.0, 1.0, 2.0]], [[True, False, True]], [[0, 1, 2j]], [["0", "1", "2"]], [[0, 1, None]],
          np.array([[0, 1, 2]], dtype=object).astype(float)]
F_VALUE = [[[0, 1, v]] for v in HUGE_INTS + [3, -1]] + [np.array([[0, 1, 2**63]], dtype=np.uint64),
                                                        [[0, 1]], [[0, 1, 2, 0]], [0, 1, 2], [[[0, 1, 2]]],
                                                        [[0, 1, 2], [0, 1]]]
LABELS_TYPE = [[0.5], [True], [1j], ["0"], [None]]
LABELS_VALUE = [[v] for v in HUGE_INTS[1:] + [-1]] + [np.array([2**63], dtype=np.uint64), [0, 1], [[0]], [],
                                                   [[0], [1, 2]]]
PATH_TYPE = [None, 5, 1.5, ["a.off"], object()]


def hostile_calls():
    """(name, call, kind): kind 'type' expects ArgumentTypeError, 'value' a plain ValueError."""
    cases = []

    def add(name, values, kind, call):
        for i, v in enumerate(values):
            cases.append(pytest.param(lambda v=v: call(v), kind, id=f"{name}-{i}-{kind}"))

    add("classify a", A_TYPE, "type", lambda v: tritri.classify(v, T))
    add("classify a", A_VALUE + A_EMPTY, "value", lambda v: tritri.classify(v, T))
    add("classify b", A_TYPE, "type", lambda v: tritri.classify(T, v))
    add("classify b", A_VALUE, "value", lambda v: tritri.classify(T, v))
    vertices_value = A_VALUE + [[[0, 0, 0]] * 2]  # two vertices, F1 needs three
    add("self V", A_TYPE, "type", lambda v: tritri.self_intersections(v, F1))
    add("self V", vertices_value, "value", lambda v: tritri.self_intersections(v, F1))
    add("self F", F_TYPE, "type", lambda v: tritri.self_intersections(V3, v))
    add("self F", F_VALUE, "value", lambda v: tritri.self_intersections(V3, v))
    add("two V2", A_TYPE, "type", lambda v: tritri.intersections(V3, F1, v, F1))
    add("two V1", vertices_value, "value", lambda v: tritri.intersections(v, F1, V3, F1))
    add("two F1", F_TYPE, "type", lambda v: tritri.intersections(V3, v, V3, F1))
    add("two F2", F_VALUE, "value", lambda v: tritri.intersections(V3, F1, V3, v))
    add("arrange V", A_TYPE, "type", lambda v: tritri.arrange(v, F1))
    add("arrange V", vertices_value, "value", lambda v: tritri.arrange(v, F1))
    add("arrange F", F_TYPE, "type", lambda v: tritri.arrange(V3, v))
    add("arrange F", F_VALUE, "value", lambda v: tritri.arrange(V3, v))
    add("arrange labels", LABELS_TYPE, "type", lambda v: tritri.arrange(V3, F1, labels=v))
    add("arrange labels", LABELS_VALUE, "value", lambda v: tritri.arrange(V3, F1, labels=v))
    add("arrange threads", THREADS_TYPE, "type", lambda v: tritri.arrange(V3, F1, threads=v))
    add("arrange threads", THREADS_VALUE, "value", lambda v: tritri.arrange(V3, F1, threads=v))
    add("arrange classifier", [None, 1, b"tritri", ["tritri"]], "type",
        lambda v: tritri.arrange(V3, F1, classifier=v))
    add("arrange classifier", ["", "TRITRI", " tritri", "tritri\0", "fast"], "value",
        lambda v: tritri.arrange(V3, F1, classifier=v))
    add("load_mesh", PATH_TYPE, "type", tritri.load_mesh)
    add("load_mesh", ["", "/", "x.off\0", b"x.off\0", "/nonexistent/x.off", "noextension"], "value",
        tritri.load_mesh)
    return cases


@pytest.mark.parametrize("call, kind", hostile_calls())
def test_hostile_arguments_raise_value_error(call, kind):
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value)  # a message
    if kind == "type":
        assert type(e.value) is tritri.ArgumentTypeError and isinstance(e.value, TypeError), repr(e.value)
    else:
        assert not isinstance(e.value, TypeError), repr(e.value)


def test_the_thread_cap_is_documented_and_accepted():
    assert tritri.MAX_THREADS == 1024 and "MAX_THREADS" in tritri.__all__
    assert str(tritri.MAX_THREADS) in tritri.arrange.__doc__ and "ArgumentTypeError" in tritri.arrange.__doc__
    assert issubclass(tritri.ArgumentTypeError, TypeError) and issubclass(tritri.ArgumentTypeError, ValueError)
    V, F, _ = join(cube((0, 0, 0), (2, 2, 2)), cube((1, 1, 1), (3, 3, 3)))
    one = tritri.arrange(V, F, threads=1)
    for t in (0, np.int32(2), np.uint64(3), tritri.MAX_THREADS):
        out = tritri.arrange(V, F, threads=t)
        assert out["F"].tolist() == one["F"].tolist()
        if t:
            assert out["stats"]["threads"] == int(t)
    with pytest.raises(ValueError, match=r"threads must be an integer from 0 to 1024, got 1025"):
        tritri.arrange(V, F, threads=1025)
    from tritri import _tritri  # the extension checks too, for callers that bypass the wrapper
    with pytest.raises(ValueError, match="threads must be an integer from 0 to 1024"):
        _tritri.arrange(V, F, None, "tritri", 100000)


def test_unusual_but_valid_arrays_give_the_same_answers():
    V, F, labels = join(cube((0, 0, 0), (2, 2, 2)), cube((1, 1, 1), (3, 3, 3)))
    expected = tritri.arrange(V, F, labels=labels)
    wide = np.zeros((len(V), 6))
    wide[:, ::2] = V
    variants = [
        (wide[:, ::2], F, labels),                                   # non-contiguous V
        (np.asfortranarray(V), np.asfortranarray(F), labels),        # Fortran order
        (V[::-1][::-1], F[::-1][::-1], labels[::-1][::-1]),          # negative strides
        (V.astype(np.float32), F.astype(np.uint8), labels.astype(np.int8)),
        (V.astype(np.int16), F.astype(np.int32), labels.astype(np.uint16)),
        (V.astype(object), F.astype(object), list(labels)),           # Python numbers
        (V.tolist(), F.tolist(), labels.tolist()),
        (np.array([[fractions.Fraction(int(x)) for x in row] for row in V], dtype=object), F, labels),
    ]
    for Vv, Fv, lv in variants:
        out = tritri.arrange(Vv, Fv, labels=lv)
        assert out["F"].tolist() == expected["F"].tolist() and face_labels(out) == face_labels(expected)
        assert tritri.self_intersections(Vv, Fv)[0].tolist() == tritri.self_intersections(V, F)[0].tolist()
    assert face_labels(tritri.arrange(V3, F1, labels=[2**31 - 1])) == [(2**31 - 1,)]  # the largest label
    r = tritri.classify(np.asfortranarray(T)[:, ::-1][:, ::-1], T.astype(np.float32))
    assert r == tritri.classify(T, T)
    for empty in ([], np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int8)):
        assert tritri.self_intersections(empty, np.zeros((0, 3), dtype=int))[0].shape == (0, 2)
        assert tritri.intersections(V3, F1, empty, [])[0].shape == (0, 2)


def test_extreme_finite_coordinates_are_arranged():
    for s in (1e300, 2.0**-1000, 5e-324):
        V, F, labels = join(cube((0, 0, 0), (2 * s, 2 * s, 2 * s)), cube((s, s, s), (3 * s, 3 * s, 3 * s)))
        out = tritri.arrange(V, F, labels=labels)
        assert out["stats"]["euler"] == 4 and np.isfinite(out["V"]).all()


def test_stats_keys_are_those_of_the_cli(tmp_path):
    """The Python stats dict and `arrange --stats` have the same keys, in the same order, and
    the same counts on the same mesh (t_load_s is 0 in Python: nothing is read)."""
    repo = pathlib.Path(__file__).resolve().parents[2]
    cli = os.environ.get("TRITRI_ARRANGE_BIN", str(repo / "build" / "bin" / "arrange"))
    if not os.access(cli, os.X_OK):
        pytest.skip(f"no arrange binary at {cli} (set TRITRI_ARRANGE_BIN)")
    V, F, _ = join(cube((0, 0, 0), (2, 2, 2)), cube((1, 1, 1), (3, 3, 3)))
    mesh = tmp_path / "cubes.off"
    mesh.write_text(f"OFF\n{len(V)} {len(F)} 0\n" + "".join(f"{x:.17g} {y:.17g} {z:.17g}\n" for x, y, z in V)
                    + "".join(f"3 {a} {b} {c}\n" for a, b, c in F))
    run = subprocess.run([cli, str(mesh), "--stats", "--threads", "1"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    from_cli = json.loads(run.stdout)
    from_python = tritri.arrange(V, F, threads=1)["stats"]
    assert list(from_python) == list(from_cli)
    assert from_python["lpi"] == from_python["intersection_points"] > 0
    for key, value in from_cli.items():
        if not key.startswith("t_") and key != "peak_rss_mb":
            assert from_python[key] == value, key
    assert from_python["t_load_s"] == 0
    # `arrange --help` and the docstring of tritri.arrange list the same keys, in that order
    # (all come from one table, arrangements/arrange_stats.h).
    help_text = subprocess.run([cli, "--help"], capture_output=True, text=True, timeout=60).stdout
    help_lines = help_text.split("JSON keys (--stats)", 1)[1].split("\n\n", 1)[0].splitlines()[1:]
    from_help = [line.split()[0] for line in help_lines if line.startswith("  ") and line[2] != " "]
    assert from_help == list(from_cli)
    doc = tritri.arrange.__doc__
    doc_lines = doc.split("is read from a file):", 1)[1].split("Raises", 1)[0].splitlines()[1:]
    indent = min(len(line) - len(line.lstrip()) for line in doc_lines if line.strip())
    from_doc = [line.split()[0] for line in doc_lines if line.strip() and len(line) - len(line.lstrip()) == indent]
    assert from_doc == list(from_cli)
    over = subprocess.run([cli, str(mesh), "--threads", str(tritri.MAX_THREADS + 1)], capture_output=True, text=True)
    assert over.returncode == 2 and str(tritri.MAX_THREADS) in over.stderr
