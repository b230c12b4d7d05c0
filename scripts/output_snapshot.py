#!/usr/bin/env python3
"""Write every output of `arrange` for every mesh of a folder into one snapshot folder, so
that two builds (before and after a refactoring) can be compared byte for byte with `diff -r`.

usage: scripts/output_snapshot.py MESH_DIR SNAPSHOT_DIR [--arrange PATH] [--jobs N]
           [--threads N] [--pattern GLOB ...]

Per mesh (relative path P, '/' replaced by '__'): P.obj + P.obj.provenance.csv (rounded),
P.off + P.off.provenance.csv (--exact), P.ply, P.stats.json (--stats with the timings and the
peak memory removed), P.native.stats.json (the same with --classifier native), P.compare.json (tritri-compare
--json, with predicate counts, timings removed) and P.exit
(exit codes and the stderr of every run), so refusals and messages are compared as well.
"""
import argparse
import concurrent.futures
import json
import subprocess
import sys
from pathlib import Path

PATTERNS = ["*.obj", "*.off", "*.stl", "*.ply"]
VOLATILE = ("t_", "peak_rss_mb")  # stats that differ from run to run


def run(cmd):
    proc = subprocess.run(cmd, capture_output=True, text=True)
    return proc.returncode, proc.stdout, proc.stderr


def stable(value):
    if isinstance(value, dict):
        return {k: stable(v) for k, v in value.items() if not k.startswith(VOLATILE + ("ratio_",))}
    return value


def stable_stats(stdout):
    try:
        stats = json.loads(stdout)
    except json.JSONDecodeError:
        return stdout
    return json.dumps(stable(stats), indent=1, sort_keys=False) + "\n"


def snapshot(mesh, root, out, arrange, threads):
    name = str(mesh.relative_to(root)).replace("/", "__")
    base = out / name
    common = [arrange, str(mesh), "--threads", str(threads)]
    compare = str(Path(arrange).with_name("tritri-compare"))
    log = []
    runs = [
        ("obj", common + ["-o", f"{base}.obj", "--stats"], f"{base}.stats.json"),
        ("off", common + ["--exact", "-o", f"{base}.off"], None),
        ("ply", common + ["-o", f"{base}.ply"], None),
        ("native", common + ["--classifier", "native", "--stats"], f"{base}.native.stats.json"),
        ("compare", [compare, str(mesh), "--threads", str(threads), "--json"], f"{base}.compare.json"),
    ]
    for tag, cmd, stats_path in runs:
        code, stdout, stderr = run(cmd)
        log.append(f"{tag}: exit {code}\n{stderr}")
        if stats_path:
            Path(stats_path).write_text(stable_stats(stdout))
    Path(f"{base}.exit").write_text("".join(log))
    return name


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh_dir", type=Path)
    parser.add_argument("snapshot_dir", type=Path)
    parser.add_argument("--arrange", default=str(Path(__file__).resolve().parent.parent
                                                 / "build" / "bin" / "arrange"))
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--pattern", nargs="+", default=PATTERNS)
    args = parser.parse_args()
    if not args.mesh_dir.is_dir():
        parser.error(f"{args.mesh_dir} is not a folder")
    meshes = sorted({p for pat in args.pattern for p in args.mesh_dir.rglob(pat) if p.is_file()})
    args.snapshot_dir.mkdir(parents=True, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        jobs = [pool.submit(snapshot, m, args.mesh_dir, args.snapshot_dir, args.arrange,
                            args.threads) for m in meshes]
        for i, job in enumerate(concurrent.futures.as_completed(jobs), 1):
            print(f"\r{i}/{len(meshes)} {job.result()[:60]:60}", end="", file=sys.stderr)
    print(file=sys.stderr)


if __name__ == "__main__":
    main()
