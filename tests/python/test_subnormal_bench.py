"""bench/subnormal_bench.py: the two models, the command line and the runner.

Models: the default parameters give, byte for byte, the files of the generator issue 36's
first figures came from (transcribed below as the reference); for any parameters both models
have the same faces and vertices except exactly --subnormals z values, +-5e-324 in one and
0.0 in the other. Runner: a fake `arrange` written to tmp_path logs its command lines (the
runs alternate zeros / subnormal and new / base, both modes, --check in one); a failing one
exits 1 naming the command; bad command lines exit 2. Last, a quick run of the real binary,
$TRITRI_ARRANGE_BIN (default build/bin/arrange): skipped without it, failed instead when
CI=true.
"""
import json
import os
import random
import sys
from pathlib import Path

import pytest

import subnormal_bench as sb
from conftest import REPO, run_script

ARRANGE = Path(os.environ.get("TRITRI_ARRANGE_BIN", str(REPO / "build" / "bin" / "arrange")))


def need(ok, reason):
    """Skip without a prerequisite; in CI (CI=true) its absence is a failure."""
    if not ok:
        if os.environ.get("CI") == "true":
            pytest.fail(reason)
        pytest.skip(reason)


def reference(subnormal, seed=1, n=12, boxes=40, k=180):
    """The generator as given in issue 36 (only 180 made a parameter k), as text."""
    rng = random.Random(seed)
    V = []
    F = []

    def v(x, y, z):
        V.append([x, y, z])
        return len(V) - 1
    ids = [[v(10 * i / n, 10 * j / n, 0.0) for j in range(n + 1)] for i in range(n + 1)]
    for i in range(n):
        for j in range(n):
            a, b, c, d = ids[i][j], ids[i + 1][j], ids[i + 1][j + 1], ids[i][j + 1]
            F.append((a, b, c))
            F.append((a, c, d))
    for _ in range(boxes):
        x0 = rng.uniform(0, 8)
        y0 = rng.uniform(0, 8)
        w = rng.uniform(0.5, 2)
        h = rng.uniform(0.5, 2)
        t = rng.uniform(0.3, 2)
        P = [v(x0 + dx * w, y0 + dy * h, dz * t) for dz in (0, 1) for dy in (0, 1) for dx in (0, 1)]
        q = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
        for a, b, c, d in q:
            F.append((P[a], P[b], P[c]))
            F.append((P[a], P[c], P[d]))
    zero = [i for i, p in enumerate(V) if p[2] == 0.0]
    rng2 = random.Random(seed + 7)
    pick = rng2.sample(zero, min(k, len(zero)))
    for i in pick:
        V[i][2] = rng2.choice((5e-324, -5e-324)) if subnormal else 0.0
    text = ""
    for p in V:
        text += "v %r %r %r\n" % tuple(p)
    for t in F:
        text += "f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1)
    return text


def parse_obj(file):
    lines = Path(file).read_text().splitlines()
    vertices = [tuple(float(c) for c in line.split()[1:]) for line in lines if line.startswith("v ")]
    faces = [tuple(int(c) for c in line.split()[1:]) for line in lines if line.startswith("f ")]
    assert len(vertices) + len(faces) == len(lines)
    return vertices, faces


def test_default_models_are_the_reference_byte_for_byte(tmp_path):
    zeros, subnormal = sb.make_models(tmp_path)
    assert zeros.read_bytes() == reference(False).encode()
    assert subnormal.read_bytes() == reference(True).encode()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["subnormal.obj", "zeros.obj"]  # no temporaries
    assert sb.make_models(tmp_path, 1, 12, 40, 180) == (zeros, subnormal)
    assert subnormal.read_bytes() == reference(True).encode()


@pytest.mark.parametrize("seed,grid,boxes,subnormals", [(1, 12, 40, 180), (3, 5, 7, 20), (2, 1, 0, 2), (1, 4, 5, 10)])
def test_models_differ_exactly_in_the_subnormal_z(tmp_path, seed, grid, boxes, subnormals):
    zeros, subnormal = sb.make_models(tmp_path, seed, grid, boxes, subnormals)
    assert subnormal.read_text() == reference(True, seed, grid, boxes, subnormals)
    (vz, fz), (vs, fs) = parse_obj(zeros), parse_obj(subnormal)
    assert fz == fs and len(fz) == 2 * grid * grid + 12 * boxes
    assert len(vz) == len(vs) == (grid + 1) ** 2 + 8 * boxes
    differ = [i for i, (a, b) in enumerate(zip(vz, vs)) if a != b]
    assert len(differ) == subnormals
    for i in differ:
        assert vz[i][:2] == vs[i][:2] and vz[i][2] == 0.0 and abs(vs[i][2]) == 5e-324
    if subnormals >= 10:
        assert {vs[i][2] for i in differ} == {5e-324, -5e-324}  # both signs
    assert all(v[2] == 0.0 or v[2] >= 0.3 for v in vz)  # floor and box bottoms, tops


# A fake arrange: appends its command line to LOG, writes the -o file, exits FAIL.
FAKE = """#!{python}
import json, sys
with open({log!r}, "a") as f:
    f.write(json.dumps(sys.argv) + "\\n")
open(sys.argv[sys.argv.index("-o") + 1], "w").write("")
sys.exit({fail})
"""


def fake_arrange(tmp_path, name, fail=0):
    tool = tmp_path / name
    tool.write_text(FAKE.format(python=sys.executable, log=str(tmp_path / "log.jsonl"), fail=fail))
    tool.chmod(0o755)
    return tool


def run_main(capsys, argv):
    code = sb.main([str(a) for a in argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def table(out):
    lines = [line.strip("|").split("|") for line in out.splitlines() if line.startswith("| ")]
    head = [c.strip() for c in lines[0]]
    return [dict(zip(head, (c.strip() for c in r))) for r in lines[1:]]


def test_runs_alternate_and_json_rows(tmp_path, capsys):
    new, base = fake_arrange(tmp_path, "arrange"), fake_arrange(tmp_path, "arrange-base")
    work = tmp_path / "w"
    code, out, err = run_main(capsys, ["--arrange", new, "--baseline", base, "--runs", "2", "--threads", "2",
                                       "--boxes", "3", "--grid", "2", "--subnormals", "5", "--work", work, "--json"])
    assert code == 0, err
    rows = [json.loads(line) for line in out.splitlines()]
    assert [(r["binary"], r["mode"]) for r in rows] == [("new", "arrangement"), ("new", "check"),
                                                        ("base", "arrangement"), ("base", "check")]
    assert all(r["cpu_ratio"] is None or r["cpu_ratio"] == pytest.approx(r["subnormal_cpu_s"] / r["zeros_cpu_s"])
               for r in rows)
    assert rows[0]["subnormals"] == 5 and rows[0]["threads"] == 2 and rows[0]["runs"] == 2
    calls = [json.loads(line) for line in (tmp_path / "log.jsonl").read_text().splitlines()]
    order = [(Path(c[0]).name, Path(c[1]).name, "--check" in c) for c in calls]
    one_round = [(b, m) for b in ("arrange", "arrange-base") for m in ("zeros.obj", "subnormal.obj")]
    assert order == [(b, m, check) for check in (False, True) for _ in range(2) for b, m in one_round]
    assert all(c[2] == "-o" and c[4:6] == ["--threads", "2"] and c[1].startswith(str(work)) for c in calls)
    assert (work / "zeros.obj").is_file() and (work / "subnormal.obj").is_file()


def test_markdown_table_and_temporary_work(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(sb.tempfile, "tempdir", str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    code, out, err = run_main(capsys, ["--arrange", fake_arrange(tmp_path, "arrange"), "--runs", "1"])
    assert code == 0, err
    rows = table(out)
    assert list(rows[0]) == ["binary", "mode", "zeros cpu s", "subnormal cpu s", "ratio subnormal/zeros (cpu)",
                             "zeros wall s", "subnormal wall s", "ratio (wall)"]
    assert [(r["binary"], r["mode"]) for r in rows] == [("new", "arrangement"), ("new", "check")]
    assert list((tmp_path / "tmp").iterdir()) == []  # the temporary work folder is gone


def test_failed_arrange_exits_1_with_the_command(tmp_path, capsys):
    tool = fake_arrange(tmp_path, "arrange", fail=3)
    code, out, err = run_main(capsys, ["--arrange", tool, "--runs", "1", "--work", tmp_path / "w"])
    assert code == 1 and out == ""
    assert f"exit status 3 of {tool} {tmp_path / 'w' / 'zeros.obj'} -o " in err


BAD = [["--runs", "0"], ["--runs", "1.5"], ["--runs", "-1"], ["--boxes", "x"], ["--grid", "0"], ["--seed", "1e3"],
       ["--subnormals", ""], ["--threads", "-1"], ["--work", ""], ["--runs", "1", "--runs", "2"], ["--unknown"],
       ["positional"], ["--baseline", "/nonexistent/arrange"], ["--json", "x"]]


@pytest.mark.parametrize("extra", BAD, ids=" ".join)
def test_bad_arguments_exit_2(tmp_path, capsys, extra):
    with pytest.raises(SystemExit) as e:
        sb.main(["--arrange", str(fake_arrange(tmp_path, "arrange"))] + extra)
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert "usage:" in err and "error:" in err
    assert not (tmp_path / "log.jsonl").exists()


@pytest.mark.parametrize("argv", [[], ["--arrange", "/nonexistent/arrange"], ["--arrange", ""]], ids=str)
def test_missing_arrange_exits_2(capsys, argv):
    with pytest.raises(SystemExit) as e:
        sb.main(argv)
    assert e.value.code == 2 and "--arrange" in capsys.readouterr().err


def test_script_runs_as_process(tmp_path):
    p = run_script("subnormal_bench.py", "--boxes", "x", "--arrange", fake_arrange(tmp_path, "arrange"))
    assert p.returncode == 2 and "--boxes" in p.stderr and "Traceback" not in p.stderr
    p = run_script("subnormal_bench.py", "--help")
    assert p.returncode == 0 and "issue 36" in p.stdout and "--subnormals" in p.stdout


def test_quick_run_of_the_real_arrange(tmp_path):
    need(os.access(ARRANGE, os.X_OK), f"no arrange binary at {ARRANGE} (set TRITRI_ARRANGE_BIN)")
    p = run_script("subnormal_bench.py", "--arrange", ARRANGE, "--runs", "1", "--boxes", "5", "--grid", "4",
                   "--subnormals", "10", "--work", tmp_path, timeout=300)
    assert p.returncode == 0, p.stderr
    rows = table(p.stdout)
    assert [(r["binary"], r["mode"]) for r in rows] == [("new", "arrangement"), ("new", "check")]
    assert all(float(r["zeros wall s"]) > 0 and float(r["subnormal wall s"]) > 0 for r in rows)
    assert (tmp_path / "out-new-check-subnormal.obj").stat().st_size > 0
