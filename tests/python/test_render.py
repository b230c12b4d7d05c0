"""bench/render.py: the input readers and the exact "share an input edge" decision, the curve
edges of known cases (two crossing triangles: one chain; make_test_meshes' cube through a cube:
curves whose ends are new points but for the corners in the coplanar contact; a beam through a
cube: only new points), complete PNG files, the input-only picture, and its command line (bad
arguments exit 2, a failing arrange exits 1 and writes nothing).

The cases with arrange run $TRITRI_ARRANGE_BIN (default build/bin/arrange) and
$TRITRI_MAKE_TEST_MESHES_BIN (default build/bin/make_test_meshes); they skip without them,
and fail instead when CI=true.
"""
import os
import struct
from fractions import Fraction
from pathlib import Path

import pytest

import render
from conftest import REPO, run_script

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
ARRANGE = Path(os.environ.get("TRITRI_ARRANGE_BIN", str(REPO / "build" / "bin" / "arrange")))
MAKE_MESHES = Path(os.environ.get("TRITRI_MAKE_TEST_MESHES_BIN",
                                  str(REPO / "build" / "bin" / "make_test_meshes")))
FLAT = ([(0, 0, 0), (4, 0, 0), (0, 4, 0)], [(0, 1, 2)])
STANDING = ([(1, 1, -1), (1, 1, 1), (3, -2, 0)], [(0, 1, 2)])


def need(tool):
    if not os.access(tool, os.X_OK):
        if os.environ.get("CI") == "true":
            pytest.fail(f"no {tool.name} binary at {tool}")
        pytest.skip(f"no {tool.name} binary at {tool}")
    return tool


def write_off(path, mesh):
    V, F = mesh
    path.write_text(f"OFF\n{len(V)} {len(F)} 0\n" + "".join(" ".join(map(str, v)) + "\n" for v in V)
                    + "".join(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in F))
    return path


def box(lo, hi):
    """An axis-aligned box as 12 triangles."""
    V = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return V, [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]


def png_size(path):
    data = Path(path).read_bytes()
    assert data[:8] == PNG_SIGNATURE and data[12:16] == b"IHDR"
    assert data.endswith(b"IEND\xaeB`\x82")  # complete, not a truncated write
    return struct.unpack(">II", data[16:24])


def chains(edges):
    """Connected components of the edges (as vertex pairs)."""
    parent = {}

    def find(v):
        while parent.setdefault(v, v) != v:
            v = parent[v]
        return v
    for a, b in edges:
        parent[find(a)] = find(b)
    return len({find(v) for e in edges for v in e})


def arranged(tmp_path, *inputs):
    """(exact output vertices, triangles, sources, curve edges) of arrange on the inputs."""
    import subprocess
    obj = tmp_path / "out.obj"
    subprocess.run([str(need(ARRANGE)), *map(str, inputs), "-o", str(obj), "--exact"], check=True,
                   capture_output=True)
    V, T = render.read_obj(obj)
    sources, _ = render.read_provenance(Path(f"{obj}.provenance.csv"))
    face_of, corners = render.input_faces(inputs)
    return V, T, sources, render.curve_edges(T, sources, render.sharing(face_of, corners))


# --- the combinatorial part, no arrange --------------------------------------------------------


def test_vertices_merge_when_exactly_equal_across_files_formats_and_fractions(tmp_path):
    a = write_off(tmp_path / "a.off", ([("1/2", 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]))
    b = tmp_path / "b.obj"
    b.write_text("# two triangles\nv 0.5 0 0\nv 1 0 0\nv 0 0 1\nv 0.5000000000000001 0 0\n"
                 "f 1/1 2/2 3/3\nf -1 2 3\n")
    stl = tmp_path / "c.stl"
    stl.write_bytes(b"\0" * 80 + struct.pack("<I", 1) + struct.pack("<12fH", 0, 0, 0, 0.5, 0, 0,
                                                                     1, 0, 0, 0, 0, 2, 0))
    face_of, corners = render.input_faces([a, b, stl])
    assert face_of == [0, 1, 2, 3]
    share = render.sharing(face_of, corners)
    assert share(0, 1) and share(0, 3) and share(1, 3)  # 1/2 == 0.5 (OFF, OBJ, binary STL)
    assert share(1, 2)                                   # (1, 0, 0) and (0, 0, 1)
    assert not share(0, 2) and not share(2, 3)           # 0.5000000000000001 is another point
    assert render.exact_number("1/3") == Fraction(1, 3) and render.exact_number("-0") == 0


def test_a_polygon_face_is_one_face_for_its_n_minus_2_triangles(tmp_path):
    quad = write_off(tmp_path / "q.off", ([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 0)],
                                          [(0, 1, 2, 3), (1, 4, 2)]))
    face_of, corners = render.input_faces([quad])
    assert face_of == [0, 0, 1]
    share = render.sharing(face_of, corners)
    assert share(0, 1) and share(0, 2)


def test_ascii_and_binary_stl_read_alike(tmp_path):
    corners = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
    facets = [(0, 2, 1), (0, 1, 3), (1, 2, 3)]
    text = "solid t\n" + "".join("facet normal 0 0 0\nouter loop\n" + "".join(
        f"vertex {x} {y} {z}\n" for x, y, z in (corners[i] for i in f)) + "endloop\nendfacet\n"
        for f in facets) + "endsolid t\n"
    (tmp_path / "a.stl").write_text(text)
    data = b"solid but binary".ljust(80, b"\0") + struct.pack("<I", len(facets)) + b"".join(
        struct.pack("<12fH", 0, 0, 0, *[c for i in f for c in corners[i]], 0) for f in facets)
    (tmp_path / "b.stl").write_bytes(data)
    assert render.read_stl(tmp_path / "a.stl") == render.read_stl(tmp_path / "b.stl")
    face_of, corners_of = render.input_faces([tmp_path / "a.stl"])
    assert len(set().union(*corners_of)) == 4  # corners merged by position


def test_curve_edges_need_two_input_triangles_without_a_common_input_edge():
    # Output triangles 0-1 share edge (1, 2): sources 0 and 1 share an input edge; 1-2 share
    # edge (2, 3): sources 1 and 2 do not; 3 meets 2 in (3, 4) from the same source.
    triangles = [(0, 1, 2), (1, 3, 2), (2, 3, 4), (3, 5, 4)]
    sources = [0, 1, 2, 2]
    share = lambda s, t: {s, t} == {0, 1}  # noqa: E731
    assert render.curve_edges(triangles, sources, share) == [(2, 3)]
    assert render.curve_edges([], [], share) == []
    # A non-manifold edge: any pair of its triangles counts.
    assert render.curve_edges([(0, 1, 2), (1, 0, 3), (0, 1, 4)], [0, 1, 5], share) == [(0, 1)]


# --- with arrange ------------------------------------------------------------------------------


def test_two_crossing_triangles_give_one_chain(tmp_path):
    a, b = write_off(tmp_path / "a.off", FLAT), write_off(tmp_path / "b.off", STANDING)
    V, _, _, curves = arranged(tmp_path, a, b)
    assert len(curves) >= 1 and chains(curves) == 1
    ends = {V[i] for e in curves for i in e}
    assert (1, 1, 0) in ends  # where the standing triangle's edge pierces the flat one


def test_cube_through_cube_curves_end_in_new_points_or_the_coplanar_contact(tmp_path):
    import subprocess
    subprocess.run([str(need(MAKE_MESHES)), str(tmp_path)], check=True, capture_output=True)
    mesh = tmp_path / "cube_through_cube.off"
    V, T, _, curves = arranged(tmp_path, mesh)
    assert curves
    inputs = set(render.read_off(mesh)[0])
    old = {V[i] for e in curves for i in e if V[i] in inputs}
    # The second box's top lies in the cube's top plane: the cube's corners inside that face
    # are on the curve too; every other curve point is new.
    assert old == {(2, 0, 2), (2, 2, 2)}
    assert len({V[i] for e in curves for i in e}) > len(old)


def test_a_beam_through_a_cube_has_two_closed_curves_of_new_points(tmp_path):
    V0, F0 = box((0, 0, 0), (2, 2, 2))
    V1, F1 = box((0.5, -1, 0.75), (1.25, 3, 1.5))
    mesh = write_off(tmp_path / "beam.off", (V0 + V1, F0 + [tuple(i + 8 for i in f) for f in F1]))
    V, _, _, curves = arranged(tmp_path, mesh)
    inputs = set(V0 + V1)
    ends = {i for e in curves for i in e}
    assert chains(curves) == 2 and all(V[i] not in inputs for i in ends)
    assert {V[i][1] for i in ends} == {0, 2}  # on the cube's faces y = 0 and y = 2


def test_render_writes_a_complete_png_and_a_summary(tmp_path):
    a, b = write_off(tmp_path / "a.off", FLAT), write_off(tmp_path / "b.off", STANDING)
    out = run_script("render.py", a, b, "-o", tmp_path / "p.png", "--size", "200", "--title", "x",
                     "--arrange", need(ARRANGE))
    assert out.returncode == 0, out.stderr
    assert png_size(tmp_path / "p.png") == (200, 200)
    assert "8 triangles (8 drawn), 1 curve edges" in out.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.off", "b.off", "p.png"]
    summary = render.render([a, b], tmp_path / "q.png", ARRANGE, size=120, legend=False,
                            max_faces=3)
    assert summary["drawn_triangles"] == 3 and summary["curve_edges"] == 1  # curves all kept
    assert summary["warning"] is None and png_size(tmp_path / "q.png") == (120, 120)


def test_an_unreadable_format_gives_a_picture_without_curves(tmp_path):
    ply = tmp_path / "t.ply"
    V, F = FLAT[0] + STANDING[0], FLAT[1] + [(3, 4, 5)]
    ply.write_text("ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
                   "end_header\n" + "".join(" ".join(map(str, v)) + "\n" for v in V)
                   + "".join("3 " + " ".join(map(str, f)) + "\n" for f in F))
    summary = render.render([ply], tmp_path / "p.png", need(ARRANGE), size=100)
    assert summary["curve_edges"] == 0 and "cannot read" in summary["warning"]
    png_size(tmp_path / "p.png")


def test_the_input_alone_is_drawn_without_arrange(tmp_path):
    quad = write_off(tmp_path / "q.off", ([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 1)],
                                          [(0, 1, 2, 3)]))
    assert render.draw_inputs([quad], tmp_path / "p.png", size=100) == 2
    png_size(tmp_path / "p.png")
    with pytest.raises(render.RenderError, match="cannot read"):
        render.draw_inputs([tmp_path / "p.png"], tmp_path / "x.png")


def test_a_failing_arrange_exits_one_and_writes_nothing(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    out = run_script("render.py", bad, "-o", tmp_path / "p.png", "--arrange", need(ARRANGE))
    assert out.returncode == 1 and "render.py: arrange exit 1" in out.stderr
    assert not (tmp_path / "p.png").exists() and "Traceback" not in out.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.off"]


@pytest.mark.parametrize("args, message", [
    ([], "required"),
    (["{a}"], "-o/--output"),
    (["{a}", "-o", ""], "-o/--output"),
    (["{a}", "-o", "{d}/p.jpg"], "must end in .png"),
    (["{a}", "-o", "{d}/no/p.png"], "no such folder"),
    (["{d}/none.off", "-o", "{d}/p.png"], "no such input file"),
    (["", "-o", "{d}/p.png"], "INPUT"),
    (["{a}", "-o", "{d}/p.png", "--arrange", "{d}/no_arrange"], "--arrange"),
    (["{a}", "-o", "{d}/p.png", "--size", "0"], "--size"),
    (["{a}", "-o", "{d}/p.png", "--size", "1e3"], "--size"),
    (["{a}", "-o", "{d}/p.png", "--size", "8193"], "--size"),
    (["{a}", "-o", "{d}/p.png", "--title", ""], "--title"),
    (["{a}", "-o", "{d}/p.png", "--timeout", "nan"], "--timeout"),
    (["{a}", "-o", "{d}/p.png", "--size", "100", "--size", "100"], "given twice"),
    (["{a}", "-o", "{d}/p.png", "--bogus"], "unrecognized"),
])
def test_bad_command_lines_exit_two(tmp_path, capsys, args, message):
    a = write_off(tmp_path / "a.off", FLAT)
    argv = [x.format(a=a, d=tmp_path) for x in args]
    with pytest.raises(SystemExit) as e:
        render.main(argv)
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert "render.py: error:" in err and message in err, err
    assert not list(tmp_path.glob("*.png"))


def test_bad_command_line_as_a_process_has_no_traceback(tmp_path):
    out = run_script("render.py", tmp_path / "none.off", "-o", tmp_path / "p.png")
    assert out.returncode == 2 and "no such input file" in out.stderr
    assert "Traceback" not in out.stderr
