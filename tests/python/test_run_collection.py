"""bench/run_collection.py: every outcome recorded, never fatal; resumable; shards partition."""
import contextlib
import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import run_collection
from conftest import BENCH, make_meshes, run_script


def read_lines(path):
    return [json.loads(line) for line in Path(path).read_text().splitlines() if line.strip()]


def by_model(path):
    return {r["model"]: r for r in read_lines(path)}


def logged(log, event):
    """Model names of the fake tool's log lines of one event ('start' or 'done')."""
    if not log.exists():
        return []
    return [" ".join(l.split()[2:]) for l in log.read_text().splitlines() if l.split()[1] == event]


def listed(*args):
    """The models run_collection.py selects (its --list output), run in-process for speed."""
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        assert run_collection.main([*map(str, args), "--list"]) == 0
    return stdout.getvalue().splitlines()


def test_crash_timeout_error_and_disagreement_are_recorded_and_the_run_goes_on(tmp_path, fake_tool):
    meshes = make_meshes(tmp_path / "m", ["a.off", "sub/b.stl", "crash.off", "error.ply",
                                          "disagree.obj", "nojson.off", "sleep.off", "notes.txt"])
    results = tmp_path / "out" / "results.jsonl"
    out = run_script("run_collection.py", meshes, "--out", results, "--tool", fake_tool,
                     "--timeout", 1, "--jobs", 2)
    assert out.returncode == 0, out.stderr
    recs = by_model(results)
    assert len(read_lines(results)) == len(recs) == 7  # notes.txt is not a mesh
    assert {m: r["status"] for m, r in recs.items()} == {
        "a.off": "agree", "sub/b.stl": "agree", "crash.off": "crash", "error.ply": "error",
        "disagree.obj": "disagree", "nojson.off": "error", "sleep.off": "timeout"}

    crash = recs["crash.off"]
    assert crash["exit_code"] == -signal.SIGSEGV and crash["signal"] == "SIGSEGV"
    assert "about to crash" in crash["stderr_tail"]
    error = recs["error.ply"]
    assert error["exit_code"] == 2 and "bad header" in error["stderr_tail"]
    assert recs["nojson.off"]["exit_code"] == 0 and "no JSON" in recs["nojson.off"]["note"]
    timeout = recs["sleep.off"]
    # The tool's own child (sleep 60) holds the pipes: only killing the group ends it quickly.
    assert timeout["timeout_s"] == 1 and 1 <= timeout["wall_s"] < 5
    disagree = recs["disagree.obj"]
    assert disagree["exit_code"] == 1 and disagree["differences"] and disagree["agree"] is False

    agree = recs["sub/b.stl"]
    assert agree["files"] == ["sub/b.stl"] and agree["exit_code"] == 0
    assert agree["tritri"]["t_classify_s"] > 0 and agree["in_vertices"] > 0
    assert "stderr_tail" not in agree and "signal" not in agree
    assert "[7/7] agree 2 disagree 1 error 2 crash 1 timeout 1" in out.stderr


def test_rerun_skips_recorded_models_and_drops_an_incomplete_last_line(tmp_path, fake_tool):
    meshes = make_meshes(tmp_path / "m", ["a.off", "b.off", "c.off", "d.off", "e.off"])
    results = tmp_path / "results.jsonl"
    prefilled = ('{"model": "a.off", "status": "agree"}\n'
                 '{"model": "b.off", "status": "crash"}\n')
    results.write_text(prefilled + '{"model": "c.off", "sta')  # killed while writing c
    log = tmp_path / "tool.log"
    out = run_script("run_collection.py", meshes, "--out", results, "--tool", fake_tool,
                     env={"FAKE_LOG": str(log)})
    assert out.returncode == 0, out.stderr
    assert sorted(logged(log, "start")) == ["c.off", "d.off", "e.off"]
    assert results.read_text().startswith(prefilled)
    models = [r["model"] for r in read_lines(results)]
    assert sorted(models) == ["a.off", "b.off", "c.off", "d.off", "e.off"]

    # --retry reruns the models recorded with the given statuses, and only those.
    out = run_script("run_collection.py", meshes, "--out", results, "--tool", fake_tool,
                     "--retry", "crash", env={"FAKE_LOG": str(log)})
    assert out.returncode == 0, out.stderr
    assert logged(log, "start")[3:] == ["b.off"]
    assert [r["model"] for r in read_lines(results)][5:] == ["b.off"]


def process_gone(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] == "Z"  # a zombie is dead
    except FileNotFoundError:
        return True


def test_interrupted_run_keeps_finished_models_and_resumes_without_duplicates(tmp_path, fake_tool):
    names = [f"m{i}.off" for i in range(6)]
    meshes = make_meshes(tmp_path / "m", names)
    results, log = tmp_path / "results.jsonl", tmp_path / "tool.log"
    env = dict(os.environ, FAKE_LOG=str(log), FAKE_DELAY="0.4")
    cmd = [sys.executable, str(BENCH / "run_collection.py"), str(meshes), "--out", str(results),
           "--tool", str(fake_tool), "--jobs", "1"]
    runner = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 20
    while not (results.exists() and results.read_text().count("\n") >= 2):
        assert time.monotonic() < deadline and runner.poll() is None, "runner made no progress"
        time.sleep(0.05)
    runner.send_signal(signal.SIGTERM)
    _, err = runner.communicate(timeout=20)
    assert runner.returncode == 130, err
    finished = [r["model"] for r in read_lines(results)]
    assert 2 <= len(finished) < 6
    started_pids = [int(l.split()[0]) for l in log.read_text().splitlines() if " start " in l]
    assert all(process_gone(pid) for pid in started_pids), "a tool process outlived the runner"

    out = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=30)
    assert out.returncode == 0, out.stderr
    models = [r["model"] for r in read_lines(results)]
    assert models[:len(finished)] == finished
    assert sorted(models) == names  # each model exactly once
    assert sorted(logged(log, "done")) == names  # no finished model ran twice


@pytest.mark.parametrize("n", [1, 2, 3, 8])
def test_shards_partition_the_sorted_models(tmp_path, n):
    meshes = make_meshes(tmp_path / "m", [f"d{i % 2}/m{i}.off" for i in range(7)])
    everything = listed(meshes, "--out", tmp_path / "r.jsonl")
    assert everything == sorted(everything) and len(everything) == 7
    shards = [listed(meshes, "--out", tmp_path / "r.jsonl", "--shard", f"{k}/{n}")
              for k in range(1, n + 1)]
    assert sorted(m for s in shards for m in s) == everything  # union = all, no model twice
    for k, shard in enumerate(shards, 1):
        assert shard == everything[k - 1::n]


def test_a_shard_runs_only_its_models(tmp_path, fake_tool):
    meshes = make_meshes(tmp_path / "m", [f"m{i}.off" for i in range(5)])
    results = tmp_path / "r.jsonl"
    out = run_script("run_collection.py", meshes, "--out", results, "--tool", fake_tool,
                     "--shard", "2/2")
    assert out.returncode == 0, out.stderr
    assert sorted(by_model(results)) == ["m1.off", "m3.off"]


@pytest.mark.parametrize("shard", ["0/2", "3/2", "2", "a/b"])
def test_a_bad_shard_is_a_usage_error(tmp_path, shard):
    out = run_script("run_collection.py", tmp_path, "--out", tmp_path / "r.jsonl", "--shard", shard)
    assert out.returncode == 2 and "K/N" in out.stderr


def test_pairs_make_one_model_of_an_mcut_pair_and_add_the_ember_pairs(tmp_path, fake_tool):
    meshes = make_meshes(tmp_path / "m", ["mcut/src-mesh000.off", "mcut/cut-mesh000.off",
                                          "mcut/src-mesh001.off", "x.off"])
    (meshes / "thingi").mkdir()
    (meshes / "thingi" / "ember_cases_subset.json").write_text(
        json.dumps([{"id_a": 7, "id_b": 3, "transform_a": {}, "transform_b": {}}]))
    plain = listed(meshes, "--out", tmp_path / "r.jsonl")
    assert plain == ["mcut/cut-mesh000.off", "mcut/src-mesh000.off", "mcut/src-mesh001.off",
                     "x.off"]
    assert listed(meshes, "--out", tmp_path / "r.jsonl", "--pairs") == [
        "mcut/src-mesh000.off + mcut/cut-mesh000.off", "mcut/src-mesh001.off",
        "pairs/ember-7-3.off", "x.off"]

    (meshes / "thingi" / "ember_cases_subset.json").unlink()
    results = tmp_path / "r.jsonl"
    out = run_script("run_collection.py", meshes, "--out", results, "--tool", fake_tool, "--pairs")
    assert out.returncode == 0, out.stderr
    pair = by_model(results)["mcut/src-mesh000.off + mcut/cut-mesh000.off"]
    assert pair["files"] == ["mcut/src-mesh000.off", "mcut/cut-mesh000.off"]
    assert pair["file"].split(",") == [str(meshes / f) for f in pair["files"]]  # both, in order


def test_a_manifest_lists_models_relative_to_its_folder(tmp_path):
    meshes = make_meshes(tmp_path / "m", ["a/one.off", "b/two.STL", "c/three.ply", "readme.txt"])
    manifest = meshes / "manifest.csv"
    manifest.write_text("file,source\nb/two.STL,x\na/one.off,y\nreadme.txt,z\n")
    assert listed(manifest, "--out", tmp_path / "r.jsonl") == ["a/one.off", "b/two.STL"]
    assert listed(manifest, "--out", tmp_path / "r.jsonl", "--pattern", "*.stl") == ["b/two.STL"]

    manifest.write_text("path\na/one.off\n")
    out = run_script("run_collection.py", manifest, "--out", tmp_path / "r.jsonl")
    assert out.returncode == 2 and "column named 'file'" in out.stderr


def test_a_malformed_results_line_stops_the_run_with_its_line_number(tmp_path, fake_tool):
    meshes = make_meshes(tmp_path / "m", ["a.off"])
    results = tmp_path / "r.jsonl"
    results.write_text('{"model": "x.off", "status": "agree"}\nnot json\n')
    out = run_script("run_collection.py", meshes, "--out", results, "--tool", fake_tool)
    assert out.returncode == 2 and f"{results}:2: malformed results line" in out.stderr


def test_a_missing_tool_is_reported_before_anything_runs(tmp_path):
    meshes = make_meshes(tmp_path / "m", ["a.off"])
    out = run_script("run_collection.py", meshes, "--out", tmp_path / "r.jsonl",
                     "--tool", tmp_path / "nope")
    assert out.returncode == 2 and "no such executable" in out.stderr
    assert not (tmp_path / "r.jsonl").exists()
