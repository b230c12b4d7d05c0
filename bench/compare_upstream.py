#!/usr/bin/env python3
"""Compare `arrange --stats` with the upstream 2020 pipeline's counts (upstream_reference.jsonl).

usage: compare_upstream.py [--arrange build/bin/arrange] [--meshes ../shared/meshes]
                           [--classifier tritri|native] [--threads N] [--only SUBSTRING]
                           [--ember-dir DIR] [--json OUT.jsonl]

For every record with status "ok" it runs the pipeline on the same file (records of
fan-triangulated variants: the file with each polygon split into a fan, as upstream was
given it; pairs/ember-*: built with ../tools/make_ember_pairs.py into --ember-dir when
given, skipped otherwise) and compares
lpi, tpi, referenced output vertices, edges, triangles and the Euler characteristic.
Prints one line per mismatch and a summary; exit status 1 if anything differs.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args
from cli_args import MAX_THREADS, Parser, seconds, text, thread_count  # noqa: E402  (after the line above)

KEYS = [("intersection_points", "lpi_points"), ("tpi", "tpi_points"),
        ("out_vertices", "out_verts_referenced"), ("out_edges", "out_edges"),
        ("out_triangles", "out_tris"), ("euler", "euler")]


def fan_triangulated_off(path, out):
    """Write OFF `path` to `out` with every polygon split into the fan (v0, vi, vi+1), as the
    reference's fan_triangulated variants were made. Our loader triangulates a non-convex
    polygon without overlaps; a fan may overlap itself, which is what upstream measured."""
    with open(path) as f:
        words = [w for line in f for w in line.split("#", 1)[0].split()]
    if not words or words[0] != "OFF":
        raise ValueError(f"{path}: fan_triangulated records are only made for OFF files")
    nv, nf = int(words[1]), int(words[2])
    at = 4 + 3 * nv
    tris = []
    for _ in range(nf):
        k = int(words[at])
        face = words[at + 1:at + 1 + k]
        at += 1 + k
        tris += [(face[0], face[i], face[i + 1]) for i in range(1, k - 1)]
    with open(out, "w") as f:
        f.write(f"OFF\n{nv} {len(tris)} 0\n")
        for i in range(nv):
            f.write(" ".join(words[4 + 3 * i:7 + 3 * i]) + "\n")
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in tris)


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = Parser(prog="compare_upstream.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal "
                       "digits. Exit status 2 for a bad command line or a missing reference file.")
    ap.add_argument("--arrange", type=text, default=os.path.join(here, "..", "build", "bin", "arrange"))
    ap.add_argument("--meshes", type=text, default=os.path.join(here, "..", "..", "shared", "meshes"))
    ap.add_argument("--classifier", choices=("tritri", "native"), default="tritri")
    ap.add_argument("--threads", type=thread_count, default=0, help=f"0 (all cores) to {MAX_THREADS}")
    ap.add_argument("--only", type=text, help="only records whose file contains this")
    ap.add_argument("--ember-dir", type=text)
    ap.add_argument("--json", type=text, help="also write one JSON line per mesh here")
    ap.add_argument("--timeout", type=seconds(0, 10**7), default=600, help="seconds per mesh, 0 for none")
    a = ap.parse_args(argv)
    reference = os.path.join(a.meshes, "upstream_reference.jsonl")
    try:
        with open(reference) as f:
            records = [json.loads(line) for line in f if line.strip()]
    except (OSError, ValueError) as e:
        print(f"compare_upstream.py: {reference}: cannot read the reference counts ({e})", file=sys.stderr)
        return 2
    if not os.access(a.arrange, os.X_OK):
        print(f"compare_upstream.py: {a.arrange}: no such executable (--arrange)", file=sys.stderr)
        return 2
    same = differ = skipped = failed = 0
    try:
        out = open(a.json + ".tmp", "w") if a.json else None
    except OSError as e:
        print(f"compare_upstream.py: --json {a.json}: cannot write ({e})", file=sys.stderr)
        return 2
    scratch = tempfile.TemporaryDirectory(prefix="compare_upstream.")
    for r in records:
        f = r["file"]
        if r.get("status") != "ok" or (a.only or "") not in f:
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
        if r.get("variant") == "fan_triangulated":
            fanned = os.path.join(scratch.name, "fanned.off")
            fan_triangulated_off(path, fanned)
            path = fanned
        cmd = [a.arrange, path, "--stats", "--classifier", a.classifier, "--threads", str(a.threads)]
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=a.timeout or None)
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
    scratch.cleanup()
    if out:
        out.close()
        os.replace(a.json + ".tmp", a.json)
    print(f"same {same}, differ {differ}, failed {failed}, skipped {skipped}")
    return 1 if differ or failed else 0


if __name__ == "__main__":
    sys.exit(main())
