#!/usr/bin/env python3
"""Compare `arrange --stats` with the upstream 2020 pipeline's counts (upstream_reference.jsonl).

usage: compare_upstream.py [--arrange build/bin/arrange] [--meshes ../shared/meshes]
                           [--classifier tritri|native] [--threads N] [--only SUBSTRING]
                           [--ember-dir DIR] [--json OUT.jsonl]

For every record with status "ok" it runs the pipeline on the same file (records of
fan-triangulated variants: our loader fan-triangulates too; pairs/ember-*: built with
../tools/make_ember_pairs.py into --ember-dir when given, skipped otherwise) and compares
lpi, tpi, referenced output vertices, edges, triangles and the Euler characteristic.
Prints one line per mismatch and a summary; exit status 1 if anything differs.
"""
import argparse
import json
import os
import subprocess
import sys

KEYS = [("intersection_points", "lpi_points"), ("tpi", "tpi_points"),
        ("out_vertices", "out_verts_referenced"), ("out_edges", "out_edges"),
        ("out_triangles", "out_tris"), ("euler", "euler")]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--arrange", default=os.path.join(here, "..", "build", "bin", "arrange"))
    ap.add_argument("--meshes", default=os.path.join(here, "..", "..", "shared", "meshes"))
    ap.add_argument("--classifier", default="tritri")
    ap.add_argument("--threads", default="0")
    ap.add_argument("--only", default="")
    ap.add_argument("--ember-dir", default="")
    ap.add_argument("--json", default="")
    ap.add_argument("--timeout", type=float, default=600)
    a = ap.parse_args()
    records = [json.loads(l) for l in open(os.path.join(a.meshes, "upstream_reference.jsonl"))]
    same = differ = skipped = failed = 0
    out = open(a.json + ".tmp", "w") if a.json else None
    for r in records:
        f = r["file"]
        if r.get("status") != "ok" or a.only not in f:
            continue
        # Upstream's loader does not triangulate polygons: only its fan-triangulated
        # variant of such a file is comparable (see the meshes' README).
        if (r.get("input_non_tri_faces") or 0) > 0 and r.get("variant") != "fan_triangulated":
            continue
        path = os.path.join(a.meshes, f)
        if f.startswith("pairs/ember"):
            path = os.path.join(a.ember_dir, os.path.basename(f)) if a.ember_dir else ""
        if not path or not os.path.exists(path):
            skipped += 1
            continue
        cmd = [a.arrange, path, "--stats", "--classifier", a.classifier, "--threads", a.threads]
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=a.timeout)
        except subprocess.TimeoutExpired:
            print(f"TIMEOUT {f}")
            failed += 1
            continue
        if p.returncode != 0:
            print(f"FAILED {f}: exit {p.returncode}: {p.stderr.strip()[:300]}")
            failed += 1
            continue
        d = json.loads(p.stdout)
        diffs = [f"{ours}={d[ours]} upstream={r.get(theirs)}" for ours, theirs in KEYS if d[ours] != r.get(theirs)]
        if out:
            out.write(json.dumps({"file": f, "ours": d, "upstream": {t: r.get(t) for _, t in KEYS},
                                  "same": not diffs}) + "\n")
        if diffs:
            differ += 1
            print(f"DIFF {f}: " + ", ".join(diffs))
        else:
            same += 1
    if out:
        out.close()
        os.replace(a.json + ".tmp", a.json)
    print(f"same {same}, differ {differ}, failed {failed}, skipped {skipped}")
    return 1 if differ or failed else 0


if __name__ == "__main__":
    sys.exit(main())
