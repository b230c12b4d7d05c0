#!/usr/bin/env python3
"""Per-stage times and peak memory of `arrange --stats`, with 1 and 2 threads, as a
Markdown table (a benchmark, not a test).

usage: bench/stage_table.py [--arrange build/bin/arrange] [--threads 1 2] MESH...

Each mesh runs once per thread count, each run in its own process. Columns: stage
seconds (load, preprocess, candidate pairs, classification, triangulation, output), total,
peak RSS, and the 2-thread speed-up per stage and of the whole run, measured in the same
invocation.
"""
import argparse
import json
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args
from cli_args import MAX_THREADS, Parser, text, thread_count  # noqa: E402  (after the line above)


def run(arrange, mesh, threads):
    out = subprocess.run([arrange, mesh, "--stats", "--threads", str(threads)],
                         capture_output=True, text=True)
    if out.returncode != 0:
        return {"error": out.stderr.strip()}
    return json.loads(out.stdout)


def main(argv=None):
    ap = Parser(prog="stage_table.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal "
                       "digits. Exit status 2 for a bad command line.")
    ap.add_argument("--arrange", type=text, default="build/bin/arrange")
    ap.add_argument("--threads", type=thread_count, nargs="+", default=[1, 2],
                    help=f"thread counts, each 0 (all cores) to {MAX_THREADS}")
    ap.add_argument("meshes", type=text, nargs="+")
    a = ap.parse_args(argv)
    if not os.access(a.arrange, os.X_OK):
        ap.error(f"--arrange {a.arrange}: no such executable")
    print("| mesh | tris | cand. pairs | LPI + TPI | out tris | thr | load s | prep s | cand s | classify s | "
          "triangulate s | output s | total s | peak MB |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for mesh in a.meshes:
        results = {}
        for t in a.threads:
            r = run(a.arrange, mesh, t)
            results[t] = r
            name = os.path.basename(mesh)
            if "error" in r:
                print(f"| {name} | error: {r['error']} |")
                continue
            print(f"| {name} | {r['in_triangles']} | {r['candidate_pairs']} | "
                  f"{r['intersection_points']} + {r['tpi']} | {r['out_triangles']} | {t} | "
                  f"{r['t_load_s']:.3f} | {r['t_preprocess_s']:.3f} | {r['t_detect_s']:.3f} | "
                  f"{r['t_classify_s']:.3f} | {r['t_triangulate_s']:.3f} | {r['t_output_s']:.3f} | "
                  f"{r['t_total_s']:.3f} | {r['peak_rss_mb']:.0f} |")
        if 1 in results and 2 in results and "error" not in results[1] and "error" not in results[2]:
            def up(k):
                return f"{results[1][k] / max(results[2][k], 1e-9):.2f}x"
            print(f"| {os.path.basename(mesh)} | | | | | speed-up | | | {up('t_detect_s')} | "
                  f"{up('t_classify_s')} | {up('t_triangulate_s')} | {up('t_output_s')} | {up('t_total_s')} | |")
    sys.stdout.flush()


if __name__ == "__main__":
    sys.exit(main())
