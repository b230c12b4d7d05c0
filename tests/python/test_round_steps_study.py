"""bench/round_steps_study.py on one run that needs the ladder: a 10 x 19 UV sphere and its copy
turned by pi about the vertical axis through its box centre, which rounding to nearest does not
settle and rerouting does (asserted first, from arrange's own --stats). With the steps
rerouting and level-1: leaving out level-1 (never reached) gives the same run; leaving
out rerouting changes it (settled by a later step with nothing rerouted, or refused). The
sweep rows are written here from the real arrange ($TRITRI_ARRANGE_BIN, default
build/bin/arrange; the test fails, not skips, when it is missing). Also: a row whose variant
file is gone is an error (exit 1), an unknown step a usage error (exit 2).
"""
import json
import math
import os
import subprocess
from pathlib import Path

import pytest

import round_steps_study
from conftest import REPO

ARRANGE = Path(os.environ.get("TRITRI_ARRANGE_BIN", str(REPO / "build" / "bin" / "arrange")))


def turned_spheres(rings=10, segments=19):
    """The sphere and its copy turned by pi about the z axis, as one OFF text."""
    V = [(0.0, 0.0, 1.0)]
    for i in range(1, rings):
        theta = math.pi * i / rings
        V += [(math.sin(theta) * math.cos(2 * math.pi * j / segments),
               math.sin(theta) * math.sin(2 * math.pi * j / segments), math.cos(theta)) for j in range(segments)]
    V.append((0.0, 0.0, -1.0))
    ring = lambda i, j: 1 + (i - 1) * segments + j % segments  # noqa: E731
    F = [(0, ring(1, j), ring(1, j + 1)) for j in range(segments)]
    for i in range(1, rings - 1):
        for j in range(segments):
            F += [(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)), (ring(i, j), ring(i + 1, j + 1), ring(i, j + 1))]
    F += [(len(V) - 1, ring(rings - 1, j + 1), ring(rings - 1, j)) for j in range(segments)]
    # Turned by pi about the vertical line through the box centre, as make_test_meshes does
    # (sin(pi) is 1.2e-16, not 0: the copy's vertices land an ulp off the exact turn).
    cx = (min(v[0] for v in V) + max(v[0] for v in V)) / 2
    cy = (min(v[1] for v in V) + max(v[1] for v in V)) / 2
    ca, sa = math.cos(math.pi), math.sin(math.pi)
    turned = [(cx + ca * (x - cx) - sa * (y - cy), cy + sa * (x - cx) + ca * (y - cy), z) for x, y, z in V]
    both_V, n = V + turned, len(V)
    both_F = F + [(a + n, b + n, c + n) for a, b, c in F]
    return (f"OFF\n{len(both_V)} {len(both_F)} 0\n" + "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in both_V)
            + "".join(f"3 {a} {b} {c}\n" for a, b, c in both_F))


def sweep_row(tmp_path):
    assert os.access(ARRANGE, os.X_OK), f"no arrange binary at {ARRANGE} (build it or set TRITRI_ARRANGE_BIN)"
    off = tmp_path / "spheres.off"
    off.write_text(turned_spheres())
    status, _, message, stats, wall = round_steps_study.run_arrange(ARRANGE, off, tmp_path / "o.obj", 1, 120)
    assert status == "settled", message
    assert stats["round_passes"] > 1 and stats["round_rerouted"] > 0 and stats["round_nudged"] == 0, stats
    row = {"mesh": "spheres.off", "variant": "rot2", "file": str(off), "status": "settled", "wall_s": wall}
    row.update({k: stats[k] for k in ("round_passes",) + round_steps_study.COMPARED})
    sweep = tmp_path / "sweep.jsonl"
    sweep.write_text(json.dumps(row) + "\n")
    return sweep


def test_a_step_not_reached_changes_nothing_the_settling_one_does(tmp_path, capsys):
    sweep = sweep_row(tmp_path)
    out = tmp_path / "study.jsonl"
    argv = [str(sweep), "--out", str(out), "--arrange", str(ARRANGE), "--steps", "rerouting,level-1",
            "--jobs", "2"]
    assert round_steps_study.main(argv) == 0
    assert not Path(f"{out}.partial").exists()
    rows = {r["step"]: r for r in map(json.loads, out.read_text().splitlines())}
    assert set(rows) == {"rerouting", "level-1"}
    assert rows["level-1"]["same"] and rows["level-1"]["status"] == "settled"
    assert not rows["rerouting"]["same"]
    assert rows["rerouting"]["status"] in ("settled", "refused")
    table = capsys.readouterr().out
    assert "| level-1 | 1 | 0 | 0 | 0 | 0 |" in table
    assert "| rerouting | 0 |" in table


def test_a_missing_variant_file_is_an_error(tmp_path, capsys):
    sweep = tmp_path / "sweep.jsonl"
    sweep.write_text(json.dumps({"mesh": "m", "variant": "rot2", "file": str(tmp_path / "gone.off"),
                                 "status": "settled", "round_passes": 3, "wall_s": 1.0}) + "\n")
    assert round_steps_study.main([str(sweep), "--out", str(tmp_path / "s.jsonl"), "--arrange", str(ARRANGE)]) == 1
    assert "gone.off" in capsys.readouterr().err


def test_an_unknown_step_is_a_usage_error(tmp_path):
    p = subprocess.run(["python3", str(REPO / "bench" / "round_steps_study.py"), "x.jsonl", "--out",
                        str(tmp_path / "s.jsonl"), "--steps", "rerouting,bogus"], capture_output=True, text=True)
    assert p.returncode == 2
    assert "unknown step 'bogus'" in p.stderr
    with pytest.raises(SystemExit):
        round_steps_study.parse_args(["x.jsonl", "--out", "s.jsonl", "--steps", "nudging,nudging"])
