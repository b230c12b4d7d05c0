#!/usr/bin/env python3
"""Time `arrange --stats` on single large polygon faces (one OFF face with N corners).

Workloads (generated, deterministic): a regular N-gon and a star-shaped N-gon with random
radii, both in the plane z = 0.5, and a comb (a non-convex polygon with N/2 teeth).
Prints one row per workload: corners, output triangles, seconds (min of --runs) and peak
memory (MB), from arrange's own --stats JSON. With --baseline BIN, the older binary runs
alternately in the same invocation and the ratios are printed.

usage: bench/polygon_bench.py --arrange build/bin/arrange [--corners 30000] [--runs 3]
                              [--baseline OLD_ARRANGE] [--json]
"""
import argparse
import json
import math
import os
import random
import sys
import tempfile

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args
from cli_args import Parser, integer, text  # noqa: E402  (after the line above)
from pipeline_bench import run_once  # noqa: E402


def polygon(kind, n):
    rng = random.Random(n)
    if kind == "regular":
        return [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)]
    if kind == "star":
        radii = [0.5 + rng.random() for _ in range(n)]  # star-shaped around the origin: simple
        return [(r * math.cos(2 * math.pi * i / n), r * math.sin(2 * math.pi * i / n)) for i, r in enumerate(radii)]
    # comb: teeth along the x axis, a straight back at y = -1
    teeth = max(1, (n - 2) // 2)
    top = []
    for i in range(teeth):
        x = i / teeth
        top += [(x, 1.0 if i % 2 == 0 else 0.5)]
        top += [(x + 0.5 / teeth, 0.0)]
    pts = [(1.0, -1.0), (0.0, -1.0)] + top
    return pts[:n] if len(pts) >= n else pts


def write_off(path, pts):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(pts)} 1 0\n")
        for x, y in pts:
            f.write(f"{x!r} {y!r} 0.5\n")
        f.write(f"{len(pts)} " + " ".join(map(str, range(len(pts)))) + "\n")


def run(binary, path):
    stats, error = run_once(binary, [path], 0, 0)  # through a shell: an honest peak_rss_mb
    if stats is None:
        raise SystemExit(f"polygon_bench.py: {binary} {path}: {error}")
    return stats


def main(argv=None):
    ap = Parser(prog="polygon_bench.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal "
                       "digits. Exit status 2 for a bad command line.")
    ap.add_argument("--arrange", type=text, required=True, help="the arrange binary to time")
    ap.add_argument("--baseline", type=text, help="an older arrange binary, run alternately")
    ap.add_argument("--corners", type=integer(3, 10_000_000), default=30000, help="3 to 10000000")
    ap.add_argument("--runs", type=integer(1, 1000), default=3, help="1 to 1000")
    ap.add_argument("--json", action="store_true", help="one JSON object per workload")
    ap.add_argument("--kinds", nargs="+", choices=("regular", "star", "comb"), default=("regular", "star", "comb"))
    args = ap.parse_args(argv)
    for option, binary in (("--arrange", args.arrange), ("--baseline", args.baseline)):
        if binary is not None and not os.access(binary, os.X_OK):
            ap.error(f"{option} {binary}: no such executable")
    with tempfile.TemporaryDirectory() as tmp:
        for kind in args.kinds:
            path = os.path.join(tmp, f"{kind}.off")
            pts = polygon(kind, args.corners)
            write_off(path, pts)
            best = {}
            for _ in range(args.runs):
                for name, binary in (("new", args.arrange), ("base", args.baseline)):
                    if not binary:
                        continue
                    s = run(binary, path)
                    if name not in best or s["t_total_s"] < best[name]["t_total_s"]:
                        best[name] = s
            row = {"workload": kind, "corners": len(pts), "out_triangles": best["new"]["out_triangles"],
                   "candidate_pairs": best["new"]["candidate_pairs"], "t_total_s": best["new"]["t_total_s"],
                   "peak_rss_mb": best["new"]["peak_rss_mb"]}
            if "base" in best:
                row["baseline_t_total_s"] = best["base"]["t_total_s"]
                row["baseline_peak_rss_mb"] = best["base"]["peak_rss_mb"]
                row["time_ratio"] = row["t_total_s"] / max(best["base"]["t_total_s"], 1e-9)
            print(json.dumps(row) if args.json else
                  "  ".join(f"{k}={v:.3f}" if isinstance(v, float) else f"{k}={v}" for k, v in row.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
