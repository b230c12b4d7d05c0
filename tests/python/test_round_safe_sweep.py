"""bench/round_safe_sweep.py on two tiny meshes (a tetrahedron and an octahedron written here):
with --variants rot2,shift it writes one JSON row per (mesh, variant) with the documented keys,
statuses from the allowed set, round_passes >= 1 where settled, variant OFF files of exactly
twice the input triangles whose first copy is the input, untouched; --max-triangles leaves
out the larger mesh; --round-max-move is passed on to arrange. Runs the real arrange:
$TRITRI_ARRANGE_BIN, default build/bin/arrange; the test fails (does not skip) when it is
missing. Needs the tritri module (load_mesh).
"""
import json
import os
from pathlib import Path

import round_safe_sweep
from conftest import REPO

ARRANGE = Path(os.environ.get("TRITRI_ARRANGE_BIN", str(REPO / "build" / "bin" / "arrange")))
KEYS = {"mesh", "variant", "file", "in_triangles", "status", "exit_code", "message", "wall_s", "round_passes",
        "round_max_move_rel", "round_rerouted", "round_merged_input", "round_snapped_vertices",
        "round_nudged", "out_triangles", "t_total_s", "peak_rss_mb", "rounded_triangles"}
TETRAHEDRON = ([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.1, 0.2, 1.0)],
               [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])
OCTAHEDRON = ([(1.5, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.25, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0),
               (0.0, 0.0, -0.75)],
              [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)])


def write_off(file, mesh):
    V, F = mesh
    file.write_text(f"OFF\n{len(V)} {len(F)} 0\n" + "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in V)
                    + "".join(f"3 {a} {b} {c}\n" for a, b, c in F))


def read_off(file):
    lines = file.read_text().split("\n")
    assert lines[0] == "OFF"
    nv, nf, _ = map(int, lines[1].split())
    V = [tuple(map(float, line.split())) for line in lines[2:2 + nv]]
    F = [tuple(map(int, line.split())) for line in lines[2 + nv:2 + nv + nf]]
    assert all(len(f) == 4 and f[0] == 3 for f in F)
    return V, [f[1:] for f in F]


def sweep(tmp_path, capsys, *extra):
    assert os.access(ARRANGE, os.X_OK), f"no arrange binary at {ARRANGE} (build it or set TRITRI_ARRANGE_BIN)"
    meshes = tmp_path / "meshes"
    meshes.mkdir(exist_ok=True)
    write_off(meshes / "tetrahedron.off", TETRAHEDRON)
    write_off(meshes / "octahedron.off", OCTAHEDRON)
    out = tmp_path / "sweep.jsonl"
    argv = [str(meshes), "--variants", "rot2,shift", "--arrange", str(ARRANGE), "--out", str(out),
            "--work", str(tmp_path / "work"), "--timeout", "120", *extra]
    assert round_safe_sweep.main(argv) == 0
    assert not Path(f"{out}.partial").exists()
    return [json.loads(line) for line in out.read_text().splitlines()], capsys.readouterr().out


def test_rows_and_variant_files(tmp_path, capsys):
    rows, summary = sweep(tmp_path, capsys)
    assert len(rows) == 4
    assert {(r["mesh"], r["variant"]) for r in rows} == {(m, v) for m in ("tetrahedron.off", "octahedron.off")
                                                       for v in ("rot2", "shift")}
    inputs = {"tetrahedron.off": TETRAHEDRON, "octahedron.off": OCTAHEDRON}
    for r in rows:
        assert set(r) == KEYS, r
        assert r["status"] in ("settled", "refused", "timeout", "error"), r
        if r["status"] == "settled":
            assert r["exit_code"] == 0 and r["message"] is None
            assert r["round_passes"] >= 1 and r["out_triangles"] > 0 and r["round_max_move_rel"] >= 0, r
            assert r["rounded_triangles"] > 0, r
        else:
            assert r["rounded_triangles"] is None, r
        V0, F0 = inputs[r["mesh"]]
        V, F = read_off(Path(r["file"]))
        assert len(F) == 2 * len(F0) == r["in_triangles"]
        assert len(V) == 2 * len(V0) and V[:len(V0)] == V0  # the first copy is the input itself
        assert F == F0 + [tuple(i + len(V0) for i in f) for f in F0]
        assert V[len(V0):] != V0  # the second copy moved
    for variant in ("rot2", "shift"):
        assert f"| {variant} | 2 |" in summary
    assert "| rot3 |" not in summary and "| scaled |" not in summary


def test_max_triangles_leaves_out_larger_meshes(tmp_path, capsys):
    rows, summary = sweep(tmp_path, capsys, "--max-triangles", "4")
    assert sorted((r["mesh"], r["variant"]) for r in rows) == [("tetrahedron.off", "rot2"),
                                                               ("tetrahedron.off", "shift")]
    assert "on 1 meshes of at most 4 triangles" in summary


def test_round_max_move_reaches_arrange(tmp_path, capsys):
    # arrange refuses a malformed --round-max-move with exit status 2 (an `error` row).
    rows, summary = sweep(tmp_path, capsys, "--round-max-move", "0.5")
    assert len(rows) == 4 and all(r["status"] == "settled" for r in rows), rows
    assert "--round-max-move 0.5;" in summary
