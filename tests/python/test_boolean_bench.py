"""bench/mesh_volume.py and bench/boolean_bench.py.

mesh_volume: exact volumes of hand-made meshes (the unit cube is exactly 1, a cube with
rational "N/D" coordinates exactly its rational volume, decimals at their exact double value,
an inside-out cube negative), boundary edges of an open mesh and of a flipped triangle, the
command line. boolean_bench: bad command lines exit 2; a fake `arrange --boolean` (writes the
exact box of two overlapping boxes) on a hand-made pair in --work/pairs gives the table, the
Markdown and JSON files and a valid result; a failing or an open result exits 1 with
"failed: <first stderr line>" or "NO: ..." in the table; with the real cgal_boolean, the fake's
exact volume equals CGAL Epeck's. Last, a --quick run of the real tools on cube-sphere2.

The cases with real tools run $TRITRI_ARRANGE_BIN (default build/bin/arrange, with --boolean)
and build/bin/cgal_boolean, and the shared meshes; they skip without them, and fail instead
when CI=true.
"""
import json
import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

import boolean_bench as bb
import mesh_volume as mv
from conftest import REPO, run_script

ARRANGE = Path(os.environ.get("TRITRI_ARRANGE_BIN", str(REPO / "build" / "bin" / "arrange")))
CGAL = REPO / "build" / "bin" / "cgal_boolean"
QUADS = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
CUBE_TRIANGLES = [t for a, b, c, d in QUADS for t in ((a, b, c), (a, c, d))]  # outwards


def need(ok, reason):
    """Skip without a prerequisite; in CI (CI=true) its absence is a failure."""
    if not ok:
        if os.environ.get("CI") == "true":
            pytest.fail(reason)
        pytest.skip(reason)


def built(tool):
    need(os.access(tool, os.X_OK), f"no {tool.name} binary at {tool}")
    return tool


def box_corners(lo, hi):
    return [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]


def write_obj(path, corners, triangles=CUBE_TRIANGLES):
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in corners)
                    + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles))
    return path


# ---------------------------------------------------------------------------------------------
# mesh_volume.py


def test_unit_cube_is_exactly_one(tmp_path):
    m = mv.measure(write_obj(tmp_path / "cube.obj", box_corners((0, 0, 0), (1, 1, 1))))
    assert m["volume"] == 1 and type(m["volume"]) is Fraction
    assert m["closed"] and m["boundary_edges"] == 0 and m["non_manifold_edges"] == 0
    assert m["triangles"] == 12 and m["vertices"] == 8


def test_rational_coordinates_exact(tmp_path):
    corners = [tuple(f"{c}" for c in p) for p in box_corners(("-1/3", "2/7", "5"), ("1/6", "9/7", "16/3"))]
    m = mv.measure(write_obj(tmp_path / "r.obj", corners))
    assert m["volume"] == Fraction(1, 2) * 1 * Fraction(1, 3)


def test_decimals_are_their_exact_doubles(tmp_path):
    m = mv.measure(write_obj(tmp_path / "d.obj", box_corners((0, 0, 0), (0.1, 0.1, 0.1))))
    assert m["volume"] == Fraction(0.1) ** 3 and m["volume"] != Fraction(1, 1000)


def test_off_and_polygons(tmp_path):
    corners = box_corners((0, 0, 0), (2, 1, 1))
    off = tmp_path / "q.off"
    off.write_text(f"OFF\n8 6 0\n" + "".join(f"{x} {y} {z}\n" for x, y, z in corners)
                   + "".join(f"4 {a} {b} {c} {d}\n" for a, b, c, d in QUADS))
    m = mv.measure(off)
    assert m["volume"] == 2 and m["closed"] and m["triangles"] == 12


def test_inside_out_cube_is_negative(tmp_path):
    flipped = [(a, c, b) for a, b, c in CUBE_TRIANGLES]
    m = mv.measure(write_obj(tmp_path / "in.obj", box_corners((0, 0, 0), (1, 1, 1)), flipped))
    assert m["volume"] == -1 and m["closed"]


def test_open_mesh_and_flipped_triangle_report_boundary_edges(tmp_path):
    corners = box_corners((0, 0, 0), (1, 1, 1))
    m = mv.measure(write_obj(tmp_path / "open.obj", corners, CUBE_TRIANGLES[1:]))
    assert m["boundary_edges"] == 3 and not m["closed"]
    (a, b, c), rest = CUBE_TRIANGLES[0], CUBE_TRIANGLES[1:]
    m = mv.measure(write_obj(tmp_path / "flip.obj", corners, [(a, c, b)] + rest))
    assert m["boundary_edges"] == 3 and not m["closed"]


def test_duplicate_vertices_are_merged(tmp_path):
    corners = box_corners((0, 0, 0), (1, 1, 1))
    triangles = [(a + 8 * (i % 2), b, c) for i, (a, b, c) in enumerate(CUBE_TRIANGLES)]
    m = mv.measure(write_obj(tmp_path / "dup.obj", corners + corners, triangles))
    assert m["closed"] and m["volume"] == 1 and m["vertices"] == 8


def test_mesh_volume_command_line(tmp_path):
    cube = write_obj(tmp_path / "cube.obj", box_corners((0, 0, 0), ("1/3", 1, 1)))
    p = run_script("mesh_volume.py", cube, "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["volume"] == "1/3" and out["closed"] is True and out["boundary_edges"] == 0
    p = run_script("mesh_volume.py", cube)
    assert p.returncode == 0 and p.stdout.startswith("volume 1/3 ")
    p = run_script("mesh_volume.py", tmp_path / "missing.obj")
    assert p.returncode == 1 and "missing.obj" in p.stderr and "Traceback" not in p.stderr
    for bad in ([], [cube, "--bogus"], [""], [cube, cube]):
        p = run_script("mesh_volume.py", *bad)
        assert p.returncode == 2 and "usage:" in p.stderr


# ---------------------------------------------------------------------------------------------
# boolean_bench.py with a fake arrange

FAKE = """#!{python}
import json, sys
args = sys.argv[1:]
{failure}
out = args[args.index("-o") + 1]
files = [a for i, a in enumerate(args) if a.endswith(".obj") and args[i - 1] != "-o"]
op = args[args.index("--boolean") + 1]
def box(f):
    v = [tuple(float(w) for w in l.split()[1:]) for l in open(f) if l.startswith("v ")]
    return [min(p[i] for p in v) for i in range(3)], [max(p[i] for p in v) for i in range(3)]
(alo, ahi), (blo, bhi) = box(files[0]), box(files[1])
x = {{"union": (alo[0], bhi[0]), "intersection": (blo[0], ahi[0]), "difference": (alo[0], blo[0])}}[op]
V = [(a, b, c) for a in x for b in (alo[1], ahi[1]) for c in (alo[2], ahi[2])]
with open(out, "w") as f:
    f.writelines(f"v {{a}} {{b}} {{c}}\\n" for a, b, c in V)
    f.writelines(f"f {{a + 1}} {{b + 1}} {{c + 1}}\\n" for a, b, c in {triangles})
stats = {{f"t_{{s}}_s": 0.001 for s in {stages}}}
print(json.dumps({{**stats, "t_total_s": 0.007, "peak_rss_mb": 5.0, "out_triangles": 12}}))
"""


def fake_arrange(tmp_path, failure="", triangles=CUBE_TRIANGLES):
    tool = tmp_path / "arrange"
    tool.write_text(FAKE.format(python=sys.executable, failure=failure, triangles=triangles, stages=bb.STAGES))
    tool.chmod(0o755)
    return tool


def box_pair(work):
    """work/pairs: the boxes [0,1]^3 and [1/2,3/2]x[0,1]^2: union 3/2, intersection and difference 1/2."""
    folder = work / "pairs"
    folder.mkdir(parents=True)
    write_obj(folder / "a.obj", box_corners((0, 0, 0), (1, 1, 1)))
    write_obj(folder / "b.obj", box_corners((0.5, 0, 0), (1.5, 1, 1)))
    (folder / "pairs.json").write_text(json.dumps([{"name": "boxes", "a": "a.obj", "b": "b.obj", "kind": "valid"}]))
    return work


def table(out):
    rows = [line.strip("|").split("|") for line in out.splitlines() if line.startswith("| ") and "---" not in line]
    head = [c.strip() for c in rows[0]]
    return [dict(zip(head, (c.strip() for c in r))) for r in rows[1:]]


def run_bench(capsys, argv):
    code = bb.main([str(a) for a in argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_fake_run_table_files_and_validity(tmp_path, capsys):
    work = box_pair(tmp_path / "w")
    code, out, err = run_bench(capsys, ["--arrange", fake_arrange(tmp_path), "--work", work, "--pairs", "boxes",
                                        "--peers", "none", "--runs", "2", "--md", tmp_path / "t.md",
                                        "--json", tmp_path / "t.json"])
    assert code == 0, out + err
    rows = table(out)
    assert [(r["workload (in tris)"], r["op"]) for r in rows] == [("boxes (24)", op) for op in bb.OPS]
    assert all(r["valid"] == "yes" and r["out tris"] == "12" and r["ours 1 thr MB"] == "5" for r in rows)
    assert rows[0][f"ours 1 thr stages s ({'/'.join(bb.STAGES)})"] == "/".join(["0.001"] * len(bb.STAGES))
    assert "boxes union run 2/2 ours 2 thr:" in err
    assert (tmp_path / "t.md").read_text() == out
    report = json.loads((tmp_path / "t.json").read_text())
    checks = [r["check"] for r in report["rows"]]
    assert [c["volume"] for c in checks] == ["3/2", "1/2", "1/2"] and report["problems"] == []
    assert len(report["rows"][0]["results"]["ours 1 thr"]["wall_s_runs"]) == 2


def test_failed_and_open_results_exit_1(tmp_path, capsys):
    work = box_pair(tmp_path / "w")
    argv = ["--work", work, "--pairs", "boxes", "--ops", "union", "--peers", "none", "--runs", "1", "--threads", "1"]
    failing = fake_arrange(tmp_path, failure='print("arrange: cannot read the operands", file=sys.stderr)\n'
                                             'print("second line", file=sys.stderr); sys.exit(2)')
    code, out, _ = run_bench(capsys, ["--arrange", failing] + argv)
    assert code == 1 and table(out)[0]["ours 1 thr s"] == "failed: arrange: cannot read the operands"
    assert table(out)[0]["valid"] == "–"
    code, out, _ = run_bench(capsys, ["--arrange", fake_arrange(tmp_path, triangles=CUBE_TRIANGLES[2:])] + argv)
    assert code == 1 and table(out)[0]["valid"] == "NO: 4 boundary edges"  # a whole square face missing


def test_baseline_folder_and_timeout(tmp_path, capsys):
    work = box_pair(tmp_path / "w")
    base = tmp_path / "build-base" / "bin"
    base.mkdir(parents=True)
    fake_arrange(base)
    slow = tmp_path / "slow"
    slow.mkdir()
    argv = ["--work", work, "--pairs", "boxes", "--ops", "union", "--peers", "none", "--runs", "2", "--threads", "1"]
    code, out, err = run_bench(capsys, ["--arrange", fake_arrange(tmp_path), "--baseline", base.parent] + argv)
    assert code == 0, out + err
    r = table(out)[0]
    assert r["base 1 thr s"][0].isdigit() and r["base 1 thr MB"] == "5" and "run 2/2 base 1 thr" in err
    sleeper = fake_arrange(slow, failure="import time; time.sleep(30)")
    code, out, err = run_bench(capsys, ["--arrange", sleeper, "--timeout", "0.5"] + argv)
    assert code == 1 and table(out)[0]["ours 1 thr s"] == "timeout (0.5 s)"
    assert "run 2/2" not in err  # a contestant that failed is not run again


def test_exact_volume_equals_cgal_epeck(tmp_path, capsys):
    built(CGAL)
    work = box_pair(tmp_path / "w")
    code, out, err = run_bench(capsys, ["--arrange", fake_arrange(tmp_path), "--cgal", CGAL, "--work", work,
                                        "--pairs", "boxes", "--peers", "cgal-epick,cgal-epeck", "--runs", "1",
                                        "--threads", "1"])
    assert code == 0, out + err
    rows = table(out)
    assert all(r["valid"] == "yes, = epeck" and r["cgal-epeck s"][0].isdigit() for r in rows)
    assert all(r["ours/exact peer (1 thr)"] not in ("", "–") for r in rows)


def test_manifold_peer_on_boxes(tmp_path):
    python = REPO / "build-python" / "venv" / "bin" / "python"
    python = python if python.is_file() else Path(sys.executable)
    has = subprocess.run([str(python), "-c", "import manifold3d, numpy"], capture_output=True).returncode == 0
    need(has, f"no manifold3d for {python} (pip install manifold3d)")
    pairs = box_pair(tmp_path / "w") / "pairs"
    script = REPO / "bench" / "manifold_boolean.py"
    for op, volume in (("union", 1.5), ("intersection", 0.5), ("difference", 0.5)):
        out = tmp_path / f"{op}.obj"
        p = subprocess.run([str(python), str(script), pairs / "a.obj", pairs / "b.obj", op, out],
                           capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        assert json.loads(p.stdout)["volume"] == pytest.approx(volume)
        m = mv.measure(out)
        assert m["closed"] and m["volume"] == Fraction(volume)
    tree = tmp_path / "t.csg"
    tree.write_text(f'difference() {{ import(file="{pairs / "a.obj"}"); import(file="{pairs / "b.obj"}"); }}')
    p = subprocess.run([str(python), str(script), "--csg", tree, tmp_path / "t.obj"], capture_output=True, text=True)
    assert p.returncode == 0 and mv.measure(tmp_path / "t.obj")["volume"] == Fraction(1, 2)
    p = subprocess.run([str(python), str(script), "a.obj", "b.obj", "xor", "o.obj"], capture_output=True, text=True)
    assert p.returncode == 2 and "usage:" in p.stderr


BAD = [["--runs", "0"], ["--runs", "1.5"], ["--ops", "xor"], ["--ops", "union,union"], ["--ops", ""],
       ["--pairs", ""], ["--pairs", "a,,b"], ["--peers", "none,manifold"], ["--peers", "cork"],
       ["--threads", "1,1"], ["--threads", "-1"], ["--timeout", "nan"], ["--baseline", "/nonexistent/arrange"],
       ["--cgal", "/nonexistent/cgal_boolean"], ["--md", "/nonexistent/dir/t.md"], ["--json", ""],
       ["--runs", "1", "--runs", "2"], ["--unknown"], ["positional"], ["--arrange", "/nonexistent/arrange"],
       ["--pairs", "no-such-pair"]]


@pytest.mark.parametrize("extra", BAD, ids=" ".join)
def test_bad_arguments_exit_2(tmp_path, capsys, extra):
    work = box_pair(tmp_path / "w")
    argv = ([] if "--arrange" in extra else ["--arrange", str(fake_arrange(tmp_path))])
    argv += [] if "--cgal" in extra or "--peers" in extra else ["--peers", "none"]
    with pytest.raises(SystemExit) as e:
        bb.main(argv + ["--work", str(work)] + extra)
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert "usage:" in err and "boolean_bench.py: error:" in err


def test_help_and_process_exit_status(tmp_path):
    p = run_script("boolean_bench.py", "--help")
    assert p.returncode == 0 and "--baseline" in p.stdout and "--quick" in p.stdout
    p = run_script("boolean_bench.py", "--ops", "xor")
    assert p.returncode == 2 and "--ops" in p.stderr and "Traceback" not in p.stderr


# ---------------------------------------------------------------------------------------------
# The real tools


def test_quick_run_of_the_real_tools(tmp_path, capsys):
    built(ARRANGE)
    built(CGAL)
    helptext = subprocess.run([str(ARRANGE), "--help"], capture_output=True, text=True).stdout
    need("--boolean" in helptext, f"{ARRANGE} --help does not mention --boolean")
    make_pairs = REPO.parent / "shared" / "tools" / "boolean_pairs" / "make_pairs.py"
    need(make_pairs.is_file(), f"no {make_pairs}")
    code, out, err = run_bench(capsys, ["--arrange", ARRANGE, "--cgal", CGAL, "--quick", "--pairs", "cube-sphere2",
                                        "--threads", "1", "--peers", "cgal-epick,cgal-epeck",
                                        "--work", tmp_path / "w"])
    assert code == 0, out + err
    rows = table(out)
    assert [r["op"] for r in rows] == list(bb.OPS)
    assert all(r["valid"] == "yes, = epeck" for r in rows), out
    assert all(r["workload (in tris)"] == "cube-sphere2 (2,892)" for r in rows)
