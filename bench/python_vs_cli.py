#!/usr/bin/env python3
"""tritri.arrange from Python against `arrange --stats` on a folder of meshes.

usage: python_vs_cli.py MESH_DIR [--arrange build/bin/arrange] [--repeat 3] [--largest 3]
                        [--threads N]

For every mesh file (recursively) that the command-line tool handles, loads it with
tritri.load_mesh, runs tritri.arrange and compares out_vertices, out_triangles and euler with
the CLI's JSON. For the `--largest` meshes with the most triangles, it times both (best of
--repeat): the whole CLI process (load included, wall clock) against load_mesh + arrange in
this interpreter. Exit status 1 if any mesh differs.
"""
import argparse
import json
import os
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args
from cli_args import MAX_THREADS, Parser, integer, text, thread_count  # noqa: E402  (after the line above)


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = Parser(prog="python_vs_cli.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal "
                       "digits. Exit status 2 for a bad command line.")
    ap.add_argument("meshes", type=text, help="a folder of meshes (searched recursively)")
    ap.add_argument("--arrange", type=text, default=os.path.join(here, "..", "build", "bin", "arrange"))
    ap.add_argument("--repeat", type=integer(1, 1000), default=3, help="timing runs, 1 to 1000")
    ap.add_argument("--largest", type=integer(0, 1000000), default=3, help="meshes timed, 0 to 1000000")
    ap.add_argument("--threads", type=thread_count, default=0, help=f"0 (all cores) to {MAX_THREADS}")
    a = ap.parse_args(argv)
    if not os.path.isdir(a.meshes):
        ap.error(f"{a.meshes}: not a folder")
    if not os.access(a.arrange, os.X_OK):
        ap.error(f"--arrange {a.arrange}: no such executable")
    try:
        import tritri
    except ImportError as e:
        ap.error(f"cannot import tritri ({e}): pip install . first")
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.meshes) for f in fs
                   if f.lower().endswith((".obj", ".off", ".stl", ".ply")))
    same = differ = refused = 0
    sizes = []
    for path in files:
        p = subprocess.run([a.arrange, path, "--stats", "--threads", str(a.threads)], capture_output=True, text=True)
        if p.returncode != 0:
            refused += 1
            continue
        cli = json.loads(p.stdout)
        m = tritri.load_mesh(path)
        r = tritri.arrange(m["V"], m["F"], threads=a.threads)["stats"]
        keys = ("out_vertices", "out_triangles", "euler")
        if all(r[k] == cli[k] for k in keys):
            same += 1
        else:
            differ += 1
            print(f"DIFF {path}: python {[r[k] for k in keys]} cli {[cli[k] for k in keys]}")
        sizes.append((cli["in_triangles"], path))
    print(f"python == cli on {same} meshes, differ {differ}, refused by both {refused}")
    print("| mesh | triangles | CLI process s | Python load_mesh + arrange s | ratio |")
    print("|---|---:|---:|---:|---:|")
    for n, path in sorted(sizes, reverse=True)[: a.largest]:
        cli_t = py_t = float("inf")
        for _ in range(a.repeat):
            t0 = time.perf_counter()
            subprocess.run([a.arrange, path, "--threads", str(a.threads)], check=True, capture_output=True)
            cli_t = min(cli_t, time.perf_counter() - t0)
            t0 = time.perf_counter()
            m = tritri.load_mesh(path)
            tritri.arrange(m["V"], m["F"], threads=a.threads)
            py_t = min(py_t, time.perf_counter() - t0)
        print(f"| {os.path.relpath(path, a.meshes)} | {n} | {cli_t:.3f} | {py_t:.3f} | {py_t / cli_t:.2f} |")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
