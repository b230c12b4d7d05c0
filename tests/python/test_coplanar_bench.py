"""bench/coplanar_bench.py: the cylinder generator and the runner, without the real arrange.

Generator: both families give closed, consistently oriented meshes (every undirected edge in
exactly two triangles, every directed edge in one, outward: positive volume), caps exactly
in z = 0 and z = 1 (every vertex is at one of them), the documented vertex and triangle counts,
B offset by (10, 10) and turned by 12 degrees, fans sharing their apex (5, 5), strips as
QuickCSG's TwoCylinders; OFF files round-trip exactly. Runner: a fake `arrange` written to
tmp_path prints a --stats JSON line (its counts from the OFF headers); sizes above a threshold
sleep past --timeout (reported as timeout, larger sizes skipped, exit 0); --baseline gives the
ratio of the totals and a count difference exits 1. Bad command lines exit 2.
"""
import json
import math
import sys
from collections import Counter
from fractions import Fraction

import pytest

import coplanar_bench as cb

# The fake arrange: the JSON of `arrange --stats`, out_triangles 3 x and t_total_s proportional
# to the input triangles times FACTOR; sleeps 30 s when the input has more than SLEEP_ABOVE.
FAKE = """#!{python}
import json, sys, time
files = [a for a in sys.argv[1:] if a.endswith(".off")]
threads = int(sys.argv[sys.argv.index("--threads") + 1])
tris = sum(int(open(f).read().split("\\n")[1].split()[1]) for f in files)
if tris > {sleep_above}:
    time.sleep(30)
t = {factor} * tris * 1e-4
print("loading...")
print(json.dumps({{"in_triangles": tris, "out_triangles": {out} * tris, "out_vertices": tris,
                  "coplanar_pairs": tris // 2, "candidate_pairs": tris * 5, "threads": threads,
                  "t_load_s": 0.001, "t_preprocess_s": 0.0, "t_detect_s": t / 4, "t_classify_s": t / 4,
                  "t_triangulate_s": t / 2, "t_output_s": 0.0, "t_total_s": t, "peak_rss_mb": 12.5}}))
"""


def fake_arrange(tmp_path, name, factor=1.0, out=3, sleep_above=10**9):
    tool = tmp_path / name
    tool.write_text(FAKE.format(python=sys.executable, factor=factor, out=out, sleep_above=sleep_above))
    tool.chmod(0o755)
    return tool


def check_closed_oriented(vertices, triangles):
    directed = Counter((t[i], t[(i + 1) % 3]) for t in triangles for i in range(3))
    assert max(directed.values()) == 1, "a directed edge used twice: inconsistent orientation"
    undirected = Counter(frozenset(e) for e in directed.elements())
    assert set(undirected.values()) == {2}, "an edge not in exactly two triangles: not closed"
    assert all(len(set(t)) == 3 for t in triangles)
    assert {v for t in triangles for v in t} == set(range(len(vertices)))
    volume = sum(a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                 + a[2] * (b[0] * c[1] - b[1] * c[0]) for a, b, c in
                 ([vertices[i] for i in t] for t in triangles)) / 6
    return volume


@pytest.mark.parametrize("family", ["fans", "strips"])
@pytest.mark.parametrize("n", [3, 4, 7, 100, 1000])
def test_closed_oriented_caps_exact(family, n):
    for mesh in cb.cylinder_pair(family, n):
        vertices, triangles = mesh
        volume = check_closed_oriented(vertices, triangles)
        assert volume > 0, "inward orientation"
        # the prism over a regular n-gon inscribed in the radius-30 circle, height 1
        assert volume == pytest.approx(n / 2 * 30 ** 2 * math.sin(2 * math.pi / n), rel=1e-9)
        assert {v[2] for v in vertices} == {0.0, 1.0}
        assert all(type(c) is float for v in vertices for c in v)
        caps = [t for t in triangles if len({vertices[i][2] for i in t}) == 1]
        assert len(caps) == (2 * n if family == "fans" else 2 * n - 4)
        if family == "fans":
            assert len(vertices) == 2 * n + 2 and len(triangles) == 4 * n
            assert vertices[2 * n] == (5.0, 5.0, 0.0) and vertices[2 * n + 1] == (5.0, 5.0, 1.0)
            assert all(2 * n in t or 2 * n + 1 in t for t in caps)
        else:
            assert len(vertices) == 2 * n and len(triangles) == 4 * n - 4
            assert all(0 in t or n in t for t in caps)


@pytest.mark.parametrize("n", [1, 3, 10])
def test_sheets_flat_grids_that_overlap(n):
    a, b = cb.cylinder_pair("sheets", n)
    for vertices, triangles in (a, b):
        assert len(vertices) == (n + 1) ** 2 and len(triangles) == 2 * n * n
        assert {v[2] for v in vertices} == {0.0}
        # every triangle counterclockwise seen from +z, total area the square's
        area = 0
        for t in triangles:
            (x0, y0, _), (x1, y1, _), (x2, y2, _) = (vertices[i] for i in t)
            twice = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
            assert twice > 0
            area += twice / 2
        assert area == pytest.approx(60.0 ** 2, rel=1e-12)
    assert a[0] != b[0]  # B is turned and moved: no vertex in common at the corner
    assert not set(a[0]) & set(b[0])


def test_placement_like_two_cylinders():
    (va, _), (vb, _) = cb.cylinder_pair("strips", 200)
    assert va[0] == (30.0, 0.0, 0.0) and va[200] == (30.0, 0.0, 1.0)
    turn = math.radians(12)
    assert vb[0] == (10 + 30 * math.cos(turn), 10 + 30 * math.sin(turn), 0.0)
    # QuickCSG's cyl2.off starts with 39.3444 16.2374 0 and 39.134 17.156 0
    assert vb[0][:2] == pytest.approx((39.3444, 16.2374), abs=1e-4)
    assert vb[1][:2] == pytest.approx((39.134, 17.156), abs=1e-4)
    for x, y, _ in vb[:200]:
        assert math.hypot(x - 10, y - 10) == pytest.approx(30, rel=1e-12)


@pytest.mark.parametrize("n", [3, 4, 40, 101])
def test_wedges_concurrent_in_exact_arithmetic(n):
    a, b = cb.cylinder_pair("wedges", n)
    assert [len(a[1]), len(b[1])] == [(n + 1) // 2, n // 2]
    d = Fraction(1, 2 * n)
    hubs = set()
    for k, (vertices, triangles) in enumerate((a, b)):
        assert all(type(c) is float and (j != 2 or c == 0.0) for v in vertices for j, c in enumerate(v))
        for w, t in enumerate(triangles):
            i = 2 * w + k
            p, q, r = (tuple(map(Fraction, vertices[c][:2])) for c in t)
            assert p[0] == -1 and q[0] == r[0] == 1 and q[1] - r[1] > 0  # a proper wedge
            # In exact arithmetic its edges meet x = 0 at the two hubs (0, +-d / 2); the doubles
            # miss them by rounding only (the clouds of crossings the family is for).
            y = -1 + Fraction(2 * i + 1, n)
            for (x0, y0), (x1, y1), hub in ((p, q, d / 2), (p, r, -d / 2)):
                at0 = y0 + (y1 - y0) * (0 - x0) / (x1 - x0)
                assert abs(at0 - hub) < Fraction(1, 10**14) and abs(y0 - y) < Fraction(1, 10**15)
                hubs.add(at0 == hub)
    if n == 101:
        assert False in hubs  # rounding moved some edges off the hubs


def test_deterministic_and_off_round_trip(tmp_path):
    files, tris = cb.write_pair(tmp_path, "fans", 50)
    assert tris == 400 and [f.name for f in files] == ["fans-n50-A.off", "fans-n50-B.off"]
    first = [f.read_bytes() for f in files]
    cb.write_pair(tmp_path, "fans", 50)
    assert [f.read_bytes() for f in files] == first
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fans-n50-A.off", "fans-n50-B.off"]  # no temporaries
    lines = files[1].read_text().splitlines()
    vertices, triangles = cb.cylinder_pair("fans", 50)[1]
    assert lines[0] == "OFF" and lines[1] == f"{len(vertices)} {len(triangles)} 0"
    assert [tuple(map(float, line.split())) for line in lines[2:2 + len(vertices)]] == vertices
    assert [tuple(map(int, line.split()[1:])) for line in lines[2 + len(vertices):]] == triangles


def test_fit_slope():
    assert cb.fit_slope([(10, 0.02), (100, 0.2), (1000, 2.0)]) == pytest.approx(1.0)
    assert cb.fit_slope([(10, 0.001), (100, 0.04), (1000, 4.0)]) == pytest.approx(2.0)  # first point < 0.01 s
    assert cb.fit_slope([(10, 0.001), (100, 0.5)]) is None
    assert cb.fit_slope([]) is None


def run_main(capsys, argv):
    code = cb.main(argv)
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def table(out):
    rows = [line.strip("|").split("|") for line in out.splitlines() if line.startswith("| ") and "---" not in line]
    head = [c.strip() for c in rows[0]]
    return [dict(zip(head, (c.strip() for c in r))) for r in rows[1:]]


def test_runner_end_to_end(tmp_path, capsys):
    new = fake_arrange(tmp_path, "arrange")
    chart = tmp_path / "c.png"
    pytest.importorskip("matplotlib")
    code, out, err = run_main(capsys, ["--arrange", str(new), "--families", "fans,strips", "--sizes", "10,20,40",
                                       "--strip-sizes", "5,10",
                                       "--threads", "1,2", "--runs", "2", "--work", str(tmp_path / "w"),
                                       "--json", str(tmp_path / "r.jsonl"), "--chart", str(chart)])
    assert code == 0, err
    rows = table(out)
    assert [(r["family"], r["n"]) for r in rows] == [("fans", "10"), ("fans", "20"), ("fans", "40"),
                                                 ("strips", "5"), ("strips", "10")]
    assert rows[1]["in tris"] == "160" and rows[1]["out tris"] == "480" and rows[1]["candidate pairs"] == "800"
    assert rows[1]["2 thr total s"] == "0.016" and rows[1]["2 thr detect/classify/triangulate s"] == "0.004/0.004/0.008"
    assert rows[1]["1 thr µs/out tri"] == "33.33" and rows[1]["1 thr peak MB"] == "12"
    assert rows[4]["in tris"] == "72"
    assert "slope fans 1 thr: 1.00" in out and "slope strips 2 thr: n/a" in out
    records = [json.loads(line) for line in (tmp_path / "r.jsonl").read_text().splitlines()]
    assert len(records) == 10 and all(r["status"] == "ok" and len(r["t_total_s_runs"]) == 2 for r in records)
    assert chart.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["arrange", "c.png", "r.jsonl", "w"]


def test_timeout_skips_larger_sizes(tmp_path, capsys):
    new = fake_arrange(tmp_path, "arrange", sleep_above=200)  # fans n=20: 160 tris; n=30: 240
    code, out, err = run_main(capsys, ["--arrange", str(new), "--families", "fans", "--sizes", "20,30,40",
                                       "--threads", "1,2", "--runs", "3", "--timeout", "0.5",
                                       "--work", str(tmp_path / "w"), "--json", str(tmp_path / "r.jsonl")])
    assert code == 0, err
    rows = table(out)
    assert rows[0]["1 thr total s"] == "0.016"
    assert rows[1]["1 thr total s"] == "timeout" and rows[1]["2 thr total s"] == "timeout"
    assert rows[2]["1 thr total s"] == "skipped" and rows[2]["out tris"] == "–"
    assert "timed out after 0.5 s; larger fans sizes skipped" in out
    records = [json.loads(line) for line in (tmp_path / "r.jsonl").read_text().splitlines()]
    assert [r["status"] for r in records] == ["ok", "ok", "timeout", "timeout", "skipped", "skipped"]


def test_baseline_ratio_and_count_difference(tmp_path, capsys):
    new = fake_arrange(tmp_path, "arrange")
    base = fake_arrange(tmp_path, "arrange-base", factor=2.0)
    argv = ["--arrange", str(new), "--families", "strips", "--strip-sizes", "50", "--threads", "1",
            "--runs", "1", "--work", str(tmp_path / "w")]
    code, out, err = run_main(capsys, argv + ["--baseline", str(base)])
    assert code == 0, err
    assert table(out)[0]["1 thr new/base"] == "0.50"
    other = fake_arrange(tmp_path, "arrange-other", out=4)
    code, out, err = run_main(capsys, argv + ["--baseline", str(other)])
    assert code == 1
    assert "COUNTS DIFFER" in err and "COUNTS DIFFER" in out and "out_triangles 1568 vs 1176" in out


def test_failed_run_exits_1(tmp_path, capsys):
    tool = tmp_path / "arrange"
    tool.write_text("#!/bin/sh\necho 'arrange: cannot read' >&2\nexit 2\n")
    tool.chmod(0o755)
    code, out, err = run_main(capsys, ["--arrange", str(tool), "--families", "fans", "--sizes", "5",
                                       "--threads", "1", "--runs", "1", "--work", str(tmp_path / "w")])
    assert code == 1 and "FAILED: exit 2" in out and "| fans | 5 | 40 | – |" in out


BAD = [["--sizes", "0"], ["--sizes", "2"], ["--sizes", "-5"], ["--sizes", "1e3"], ["--sizes", "10,,20"],
       ["--sizes", "10,10"], ["--sizes", ""], ["--strip-sizes", "1601"], ["--strip-sizes", "100,2000"],
       ["--max-strip-n", "0"], ["--threads", "abc"], ["--threads", "-1"], ["--threads", "1,1"],
       ["--threads", str(cb.MAX_THREADS + 1)], ["--runs", "0"], ["--runs", "1.5"], ["--timeout", "-1"],
       ["--timeout", "nan"], ["--families", "cubes"], ["--families", "fans,fans"], ["--families", ""],
       ["--json", ""], ["--chart", ""], ["--work", ""], ["--runs", "1", "--runs", "2"], ["--unknown"],
       ["positional"], ["--arrange", "/nonexistent/arrange"]]


@pytest.mark.parametrize("extra", BAD, ids=" ".join)
def test_bad_arguments_exit_2(tmp_path, capsys, extra):
    new = fake_arrange(tmp_path, "arrange")
    argv = (["--arrange", str(new)] if "--arrange" not in extra else []) + extra
    with pytest.raises(SystemExit) as e:
        cb.main(argv + ["--work", str(tmp_path / "w")] if "--work" not in extra else argv)
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert "usage:" in err and "error:" in err


def test_strip_cap_can_be_raised_and_ignored_without_strips(tmp_path):
    new = str(fake_arrange(tmp_path, "arrange"))
    assert cb.parse_args(["--arrange", new, "--strip-sizes", "2000", "--max-strip-n", "2000"]).strip_sizes == [2000]
    assert cb.parse_args(["--arrange", new, "--strip-sizes", "2000", "--families", "fans"]).families == ["fans"]
    args = cb.parse_args(["--arrange", new])
    assert args.sizes == [100, 300, 1000, 3000, 10000] and args.strip_sizes == [100, 200, 400, 800, 1600]
    assert args.sheet_sizes == [10, 30, 100, 300] and args.families == ["sheets", "fans", "strips", "wedges"]
    assert args.wedge_sizes == [20, 40, 60]
    assert args.threads == [1, 2] and args.runs == 3 and args.timeout == 600


def test_unwritable_json_exits_2(tmp_path, capsys):
    new = fake_arrange(tmp_path, "arrange")
    code, _, err = run_main(capsys, ["--arrange", str(new), "--json", str(tmp_path / "missing" / "r.jsonl"),
                                     "--work", str(tmp_path / "w")])
    assert code == 2 and "cannot write" in err


def test_script_runs_as_process(tmp_path):
    from conftest import run_script
    p = run_script("coplanar_bench.py", "--sizes", "0")
    assert p.returncode == 2 and "--sizes" in p.stderr and "Traceback" not in p.stderr
    new = fake_arrange(tmp_path, "arrange")
    p = run_script("coplanar_bench.py", "--arrange", new, "--sizes", "10", "--strip-sizes", "10", "--runs", "1",
                   "--threads", "1", "--work", tmp_path / "w")
    assert p.returncode == 0, p.stderr
    assert "| fans | 10 | 80 | 240 |" in p.stdout and "| strips | 10 | 72 | 216 |" in p.stdout
