"""Command-line arguments of the bench scripts: every hostile value of every option is a usage
error (exit status 2 and a message naming the option), never a traceback or a hang.

Table-driven over run_collection.py, report.py, compare_upstream.py, python_vs_cli.py,
stage_table.py, polygon_bench.py, pipeline_bench.py and round_safe_sweep.py: empty values, signs, spaces,
prefixes, fractions, NaN/Inf, numbers beyond every range (2^31 - 1, 2^63, 10^30), missing values, an option given twice, unknown
options. Most cases call the scripts' main(argv) in this process (argparse's SystemExit
carries the exit status); a sample runs them as processes. The shared rules and the thread
cap come from bench/cli_args.py, which reads the cap from the C++ header.
"""
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

import cli_args
import compare_upstream
import pipeline_bench
import polygon_bench
import python_vs_cli
import report
import round_safe_sweep
import run_collection
import stage_table
from conftest import BENCH, REPO, make_meshes

BAD_INTEGERS = ["", "-1", "-0", "+5", " 5", "5 ", "5x", "0x10", "1e3", "1.5", "nan", "inf", "-inf", "two",
                "\u0665", "2147483647", "9223372036854775808", "1" + "0" * 30]
BAD_SECONDS = ["", "-1", "nan", "inf", "-inf", "NaN", "1e3", "1e400", " 5", "+5", "5x", "0x10", "1_0",
               "10000001", "1" + "0" * 30]


@pytest.fixture
def setup(tmp_path):
    """Valid arguments for every script; hostile cases change one option at a time."""
    meshes = make_meshes(tmp_path / "meshes", ["a.off", "b.obj"])
    results = tmp_path / "results.jsonl"
    results.write_text('{"model": "a.off", "status": "agree", "wall_s": 1.0}\n')
    reference = tmp_path / "reference"
    reference.mkdir()
    (reference / "upstream_reference.jsonl").write_text("")
    tool = tmp_path / "tool.sh"
    tool.write_text("#!/bin/sh\nexit 2\n")
    tool.chmod(0o755)
    return {
        "run_collection": (run_collection.main, [str(meshes), "--out", str(tmp_path / "r.jsonl"), "--list"]),
        "report": (report.main, [str(results), "--out", str(tmp_path / "report")]),
        "compare_upstream": (compare_upstream.main, ["--meshes", str(reference), "--arrange", str(tool)]),
        "python_vs_cli": (python_vs_cli.main, [str(tmp_path / "meshes"), "--arrange", str(tool)]),
        "stage_table": (stage_table.main, ["--arrange", str(tool), str(meshes / "a.off")]),
        "polygon_bench": (polygon_bench.main, ["--arrange", str(tool)]),
        "pipeline_bench": (pipeline_bench.main, ["--arrange", str(tool), "--meshes", str(reference)]),
        "round_safe_sweep": (round_safe_sweep.main, [str(meshes), "--out", str(tmp_path / "s.jsonl"),
                                                     "--arrange", str(tool)]),
    }


# (script, option, hostile values, a valid value): every option that takes a value.
OPTIONS = [
    ("run_collection", "--jobs", BAD_INTEGERS + ["0", "1025"], "1"),
    ("run_collection", "--timeout", BAD_SECONDS, "1"),
    ("run_collection", "--shard", ["", "0/1", "2/1", "1/0", "1/1000001", "+1/2", "1 /2", "a/b", "1/2/3"], "1/2"),
    ("run_collection", "--out", [""], "x.jsonl"),
    ("run_collection", "--tool", [""], "tool"),
    ("run_collection", "--tool-arg", [""], None),  # repeatable
    ("run_collection", "--pattern", ["", ",", " "], "*.off"),
    ("run_collection", "--pairs-dir", [""], "pairs"),
    ("run_collection", "--retry", ["", "agreed", "CRASH"], "crash"),
    ("report", "--out", [""], "out"),
    ("report", "--title", [""], "title"),
    ("report", "--thumbnails", ["", "/nonexistent/meshes"], "m"),
    ("report", "--arrange", [""], "a"),
    ("report", "--thumb-timeout", BAD_SECONDS, "1"),
    ("compare_upstream", "--threads", BAD_INTEGERS + [str(cli_args.MAX_THREADS + 1), "100000"], "1"),
    ("compare_upstream", "--timeout", BAD_SECONDS, "1"),
    ("compare_upstream", "--classifier", ["", "magic", "TRITRI"], "native"),
    ("compare_upstream", "--meshes", [""], "m"),
    ("compare_upstream", "--arrange", [""], "a"),
    ("compare_upstream", "--only", [""], "x"),
    ("compare_upstream", "--ember-dir", [""], "d"),
    ("compare_upstream", "--json", [""], "j.jsonl"),
    ("python_vs_cli", "--threads", BAD_INTEGERS + [str(cli_args.MAX_THREADS + 1)], "1"),
    ("python_vs_cli", "--repeat", BAD_INTEGERS + ["0", "1001"], "1"),
    ("python_vs_cli", "--largest", BAD_INTEGERS + ["1000001"], "1"),
    ("python_vs_cli", "--arrange", [""], "a"),
    ("stage_table", "--threads", BAD_INTEGERS + [str(cli_args.MAX_THREADS + 1)], "1"),
    ("stage_table", "--arrange", [""], "a"),
    ("polygon_bench", "--corners", BAD_INTEGERS + ["0", "2", "10000001"], "3"),
    ("polygon_bench", "--runs", BAD_INTEGERS + ["0", "1001"], "1"),
    ("polygon_bench", "--arrange", [""], "a"),
    ("polygon_bench", "--baseline", [""], "a"),
    ("polygon_bench", "--kinds", ["", "square"], "star"),
    ("pipeline_bench", "--threads", BAD_INTEGERS + [str(cli_args.MAX_THREADS + 1), "1,", ",1", "1,,2", "1,1",
                                                    "1;2", "1 2", "1,-2", "1,2x"], "1,2"),
    ("pipeline_bench", "--runs", BAD_INTEGERS + ["0", "1001"], "1"),
    ("pipeline_bench", "--timeout", BAD_SECONDS, "1"),
    ("pipeline_bench", "--only", ["", ",", "box,", ",box", "box,,ogre", "no-such-workload"], "box"),
    ("pipeline_bench", "--arrange", ["", "/nonexistent/arrange"], "a"),
    ("pipeline_bench", "--baseline", ["", "/nonexistent/arrange"], "a"),
    ("pipeline_bench", "--meshes", [""], "m"),
    ("pipeline_bench", "--work", [""], "w"),
    ("pipeline_bench", "--json", [""], "j.jsonl"),
    ("pipeline_bench", "--reference-omc", [""], "p.md"),  # its value is optional
    ("round_safe_sweep", "--out", [""], "x.jsonl"),
    ("round_safe_sweep", "--arrange", ["", "/nonexistent/arrange"], "a"),
    ("round_safe_sweep", "--variants", ["", ",", "rot2,", ",rot2", "rot2,,shift", "rot2,rot2", "ROT2", "rot4",
                                        "rot2 shift", "rot2;shift", "all"], "rot2"),
    ("round_safe_sweep", "--max-triangles", BAD_INTEGERS + ["0", "1000000001"], "1"),
    ("round_safe_sweep", "--seed", BAD_INTEGERS + ["1000000001"], "1"),
    ("round_safe_sweep", "--threads", BAD_INTEGERS + [str(cli_args.MAX_THREADS + 1)], "1"),
    ("round_safe_sweep", "--timeout", BAD_SECONDS, "1"),
    ("round_safe_sweep", "--round-max-move", ["", "0", "0.0", "-1", "+1", " 1", "1 ", "1x", "nan", "inf", "1e400",
                                              "1e-400", "0x10", "1/64", "1_0"], "0.5"),
    ("round_safe_sweep", "--work", [""], "w"),
]
OPTIONAL_VALUE = {("pipeline_bench", "--reference-omc")}


def hostile_cases():
    for script, option, values, valid in OPTIONS:
        for i, v in enumerate(values):
            yield pytest.param(script, lambda base, o=option, v=v: base + [o, v], option, id=f"{script}{option}-{i}")
        if (script, option) not in OPTIONAL_VALUE:
            yield pytest.param(script, lambda base, o=option: base + [o], option, id=f"{script}{option}-missing")
        if valid is not None:
            yield pytest.param(script, lambda base, o=option, v=valid: base + [o, v, o, v], option,
                               id=f"{script}{option}-twice")
    for script in ("run_collection", "report", "compare_upstream", "python_vs_cli", "stage_table", "polygon_bench",
                   "pipeline_bench", "round_safe_sweep"):
        for i, opt in enumerate(["--bogus", "-x", "--threads=", "---"]):
            if script in ("compare_upstream", "python_vs_cli", "stage_table", "pipeline_bench",
                          "round_safe_sweep") and opt == "--threads=":
                continue  # covered above as an empty value
            yield pytest.param(script, lambda base, o=opt: base + [o], None, id=f"{script}-unknown-{i}")
    # Empty positional arguments.
    yield pytest.param("run_collection", lambda base: [""] + base[1:], "input", id="run_collection-empty-input")
    yield pytest.param("report", lambda base: [""] + base[1:], "results", id="report-empty-results")
    yield pytest.param("python_vs_cli", lambda base: [""] + base[1:], "meshes", id="python_vs_cli-empty-meshes")
    yield pytest.param("stage_table", lambda base: base[:-1] + [""], "meshes", id="stage_table-empty-mesh")
    yield pytest.param("round_safe_sweep", lambda base: [""] + base[1:], "INPUT", id="round_safe_sweep-empty-input")
    yield pytest.param("round_safe_sweep", lambda base: ["/nonexistent/mesh.off"] + base[1:], "input",
                       id="round_safe_sweep-missing-input")
    yield pytest.param("round_safe_sweep", lambda base: [str(Path(base[0]).parent / "results.jsonl")] + base[1:],
                       "input", id="round_safe_sweep-not-a-mesh")
    yield pytest.param("round_safe_sweep", lambda base: base[3:], "--out", id="round_safe_sweep-no-out")
    yield pytest.param("run_collection", lambda base: base[1:], None, id="run_collection-no-input")
    yield pytest.param("report", lambda base: base[:1], "--out", id="report-no-out")


@pytest.mark.parametrize("script, make_args, option", list(hostile_cases()))
def test_hostile_option_values_exit_with_two(setup, capsys, script, make_args, option):
    main, base = setup[script]
    with pytest.raises(SystemExit) as e:
        main(make_args(list(base)))
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert f"{script}.py: error:" in err
    if option:
        assert option.split("/")[0] in err, err


@pytest.mark.parametrize("script, extra", [
    ("run_collection", ["--jobs", "1024", "--timeout", "0", "--shard", "1/1000000"]),
    ("run_collection", ["--timeout", "0.5", "--tool-arg=--repeat", "--tool-arg=2", "--pattern", "*.off,*.obj"]),
    ("compare_upstream", ["--threads", str(cli_args.MAX_THREADS), "--timeout", "0", "--classifier", "native"]),
    ("compare_upstream", ["--threads", "0", "--only", "x", "--timeout", "10.25"]),
])
def test_values_at_the_limits_are_accepted(setup, capsys, script, extra):
    main, base = setup[script]
    assert main(base + extra) == 0
    assert "error" not in capsys.readouterr().err


def test_run_time_problems_are_messages_not_tracebacks(setup, tmp_path, capsys):
    # A missing reference file, a missing --arrange, a --json in a missing folder, a
    # --meshes that is not a folder, an --out that is a file: exit 2 with a message.
    cu, cu_base = setup["compare_upstream"]
    assert cu(["--meshes", str(tmp_path / "none"), "--arrange", cu_base[-1]]) == 2
    assert cu(cu_base[:2] + ["--arrange", str(tmp_path / "no_tool")]) == 2
    assert cu(cu_base + ["--json", str(tmp_path / "no" / "dir.jsonl")]) == 2
    rep, rep_base = setup["report"]
    (tmp_path / "file").write_text("")
    assert rep(rep_base[:1] + ["--out", str(tmp_path / "file")]) == 2
    err = capsys.readouterr().err
    assert "upstream_reference.jsonl" in err and "no_tool" in err and "dir.jsonl" in err and "--out" in err
    for script, args in (("python_vs_cli", [str(tmp_path / "file")]),
                         ("python_vs_cli", [str(tmp_path), "--arrange", str(tmp_path / "no_tool")]),
                         ("stage_table", ["--arrange", str(tmp_path / "no_tool"), "m.off"])):
        main, _ = setup[script]
        with pytest.raises(SystemExit) as e:
            main(args)
        assert e.value.code == 2


@pytest.mark.parametrize("args", [
    ["run_collection.py", "meshes", "--out", "r.jsonl", "--jobs", "9223372036854775808"],
    ["run_collection.py", "meshes", "--out", "r.jsonl", "--timeout", "nan"],
    ["run_collection.py", "", "--out", "r.jsonl"],
    ["report.py", "r.jsonl", "--out", "", "--title", "t"],
    ["compare_upstream.py", "--threads", "100000"],
    ["compare_upstream.py", "--meshes", "/nonexistent"],
    ["python_vs_cli.py", ".", "--threads", "-1"],
    ["stage_table.py", "--threads", "1", "--threads", "2", "m.off"],
    ["polygon_bench.py", "--arrange", "/nonexistent/arrange"],
    ["pipeline_bench.py", "--arrange", "/nonexistent/arrange"],
    ["pipeline_bench.py", "--threads", "1,1", "--runs", "1"],
    ["pipeline_bench.py", "--runs", "1", "--runs", "1"],
    ["round_safe_sweep.py", "--out", "o.jsonl", "--arrange", "/nonexistent/arrange"],
    ["round_safe_sweep.py", "--out", "o.jsonl", "--variants", "rot4"],
    ["round_safe_sweep.py", "--out", "o.jsonl", "--max-triangles", "-5"],
])
def test_as_processes_exit_two_without_a_traceback(tmp_path, args):
    p = subprocess.run([sys.executable, str(BENCH / args[0]), *args[1:]], capture_output=True, text=True,
                       timeout=60, cwd=tmp_path)
    assert p.returncode == 2, p.stderr
    assert "Traceback" not in p.stderr and p.stderr.strip()
    assert not (BENCH / "__pycache__").exists()


def test_the_thread_cap_is_the_cxx_one():
    header = (REPO / "arrangements" / "include" / "arrangements" / "thread_count.h").read_text()
    assert cli_args.MAX_THREADS == int(re.search(r"#define ARRANGEMENTS_MAX_THREADS (\d+)", header).group(1))
    assert cli_args.thread_count("0") == 0 and cli_args.thread_count(str(cli_args.MAX_THREADS)) == 1024
    try:
        import tritri
    except ImportError:
        return
    if getattr(tritri, "__file__", None) is None:  # the checkout's tritri/ folder, not the module
        return
    assert tritri.MAX_THREADS == cli_args.MAX_THREADS


def test_help_names_the_limits(capsys):
    for main in (run_collection.main, compare_upstream.main, python_vs_cli.main, stage_table.main, polygon_bench.main,
                 pipeline_bench.main, round_safe_sweep.main):
        with pytest.raises(SystemExit) as e:
            main(["--help"])
        assert e.value.code == 0
    out = capsys.readouterr().out
    assert out.count(f"0 (all cores) to {cli_args.MAX_THREADS}") == 5
    assert "models run at once, 1 to 1024" in out and out.count("given once") == 7


def test_pipeline_bench_limits_missing_inputs_and_run_time_problems(tmp_path, capsys):
    # A fake arrange printing --stats JSON, a cached generated mesh: values at the limits run
    # (exit 0); a missing workload or reference table is reported, exit 1; an unwritable
    # --json or --work exits 2 with a message.
    stats = {"in_triangles": 4, "lpi": 2, "tpi": 1, "out_vertices": 9, "out_triangles": 12,
             "intersecting_pairs": 3, "peak_rss_mb": 5.0,
             **{f"t_{s}_s": 0.01 for s in ("load", "preprocess", "detect", "classify", "triangulate", "output",
                                           "total")}}
    arrange = tmp_path / "arrange"
    arrange.write_text(f"#!/bin/sh\necho '{json.dumps(stats)}'\n")
    arrange.chmod(0o755)
    work = tmp_path / "work"
    make_meshes(work / "generated", ["two_spheres.off"])
    table = tmp_path / "PERFORMANCE.md"
    table.write_text("| workload | OMC 1 thr s | OMC 2 thr s |\n|---|---|---|\n| generated two_spheres | 0.02 | > 600 |\n")
    base = ["--arrange", str(arrange), "--work", str(work), "--meshes", str(tmp_path / "no_meshes")]
    out = tmp_path / "out.jsonl"
    assert pipeline_bench.main(base + ["--only", "two_spheres", "--threads", f"0,1,2,{cli_args.MAX_THREADS}",
                                       "--runs", "1", "--timeout", "0", "--baseline", str(arrange),
                                       "--json", str(out), "--reference-omc", str(table)]) == 0
    text = capsys.readouterr().out
    assert "| two_spheres | 4 | 3 | 0.010 |" in text and "1 thr ours/OMC" in text and "2 thr ours/OMC" in text
    assert len(out.read_text().splitlines()) == 8  # 4 thread counts x 2 binaries
    assert pipeline_bench.main(base + ["--only", "two_spheres,40509", "--runs", "1", "--threads", "1",
                                       "--reference-omc", str(tmp_path / "none.md")]) == 1
    text = capsys.readouterr().out
    assert "| thingi10k/40509.stl | missing |" in text and "MISSING" in text and "none.md" in text
    assert pipeline_bench.main(base + ["--only", "two", "--json", str(tmp_path / "no" / "o.jsonl")]) == 2
    (tmp_path / "file").write_text("")
    assert pipeline_bench.main(base[:2] + ["--only", "two", "--work", str(tmp_path / "file" / "w")]) == 2
    err = capsys.readouterr().err
    assert "o.jsonl" in err and "file" in err and "Traceback" not in err
