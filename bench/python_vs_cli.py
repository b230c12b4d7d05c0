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

import tritri


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshes")
    ap.add_argument("--arrange", default=os.path.join(here, "..", "build", "bin", "arrange"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--largest", type=int, default=3)
    ap.add_argument("--threads", type=int, default=0)
    a = ap.parse_args()
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
