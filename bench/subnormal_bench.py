#!/usr/bin/env python3
"""Subnormal coordinates against zeros (issue 36: "subnormal input within 3x of the same input
with zeros"): the CPU and wall time of `arrange` on two models that differ only in some z.

usage: bench/subnormal_bench.py --arrange BIN [--baseline OLD_BIN] [--runs 3] [--threads 1]
           [--seed 1] [--boxes 40] [--grid 12] [--subnormals 180] [--work DIR] [--json]

Models (generated, deterministic, written as OBJ into --work, or a temporary folder removed at
the end): a floor of --grid x --grid cells in [0,10]^2 at z = 0 (two triangles per cell) with
--boxes random axis-aligned boxes standing on it (corner x0, y0 uniform in [0,8], width and
depth in [0.5,2], height in [0.3,2]; 12 triangles each). Then --subnormals of the vertices
with z = 0.0 (floor and box bottoms) are picked: in subnormal.obj their z is +5e-324 or
-5e-324 (random sign), in zeros.obj it stays 0.0. Same faces, same other vertices.

For each mode, arrangement and check (`--check` added), `BIN MODEL -o OUT.obj --threads T`
runs --runs rounds, alternating zeros / subnormal (and new / base with --baseline), one
process per run. Kept per (binary, mode, model): the least CPU time (user + sys of the child,
from getrusage(RUSAGE_CHILDREN)) and the least wall time, each over the runs.

Output: a Markdown table with columns binary (new / base), mode, zeros cpu s, subnormal cpu s,
ratio subnormal/zeros (cpu), zeros wall s, subnormal wall s, ratio (wall); with --json one
JSON object per row instead. Progress goes to stderr.
"""
import argparse
import json
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args, atomic_write
from atomic_write import write_atomic  # noqa: E402
from cli_args import Parser, integer, path, text, thread_count  # noqa: E402

MODELS = ("zeros", "subnormal")
MODES = ("arrangement", "check")
SUBNORMAL = 5e-324  # the smallest positive double


class BenchError(Exception):
    pass


def model_text(subnormal, seed=1, n=12, boxes=40, subnormals=180):
    """The OBJ text of one model. The RNG calls and their order are those of the generator
    the first figures of issue 36 were taken with: keep them, or the figures are not comparable."""
    rng = random.Random(seed)
    vertices, faces = [], []

    def vertex(x, y, z):
        vertices.append([x, y, z])
        return len(vertices) - 1
    ids = [[vertex(10 * i / n, 10 * j / n, 0.0) for j in range(n + 1)] for i in range(n + 1)]
    for i in range(n):
        for j in range(n):
            a, b, c, d = ids[i][j], ids[i + 1][j], ids[i + 1][j + 1], ids[i][j + 1]
            faces += [(a, b, c), (a, c, d)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    for _ in range(boxes):
        x0, y0 = rng.uniform(0, 8), rng.uniform(0, 8)
        w, h, t = rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.3, 2)
        p = [vertex(x0 + dx * w, y0 + dy * h, dz * t) for dz in (0, 1) for dy in (0, 1) for dx in (0, 1)]
        for a, b, c, d in quads:
            faces += [(p[a], p[b], p[c]), (p[a], p[c], p[d])]
    zero = [i for i, v in enumerate(vertices) if v[2] == 0.0]
    rng2 = random.Random(seed + 7)
    for i in rng2.sample(zero, min(subnormals, len(zero))):
        # choice() only for the subnormal model, as in the original generator
        vertices[i][2] = rng2.choice((SUBNORMAL, -SUBNORMAL)) if subnormal else 0.0
    return ("".join("v %r %r %r\n" % tuple(v) for v in vertices)
            + "".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in faces))


def make_models(folder, seed=1, grid=12, boxes=40, subnormals=180):
    """(zeros.obj, subnormal.obj) in folder, each written atomically."""
    files = []
    for name in MODELS:
        file = Path(folder) / f"{name}.obj"
        data = model_text(name == "subnormal", seed, grid, boxes, subnormals).encode("ascii")
        write_atomic(file, lambda f: f.write(data))
        files.append(file)
    return tuple(files)


def run_once(command):
    """(cpu s, wall s) of one process; BenchError if it cannot start or exits non-zero."""
    shown = " ".join(map(str, command))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    try:
        p = subprocess.run(command, stdin=subprocess.DEVNULL, capture_output=True, text=True, errors="replace")
    except OSError as e:
        raise BenchError(f"cannot run {shown}: {e}") from None
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)  # the child is waited for: counted here
    if p.returncode != 0:
        raise BenchError(f"exit status {p.returncode} of {shown}: {p.stderr.strip()[-500:]}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), wall


def measure(binaries, files, work, args):
    """{(binary label, mode): {model: (least cpu s, least wall s)}}."""
    best = {}
    for mode in MODES:
        for r in range(1, args.runs + 1):
            for label, binary in binaries:
                for model, file in zip(MODELS, files):
                    out = work / f"out-{label}-{mode}-{model}.obj"
                    command = [binary, str(file), "-o", str(out), "--threads", str(args.threads)]
                    cpu, wall = run_once(command + (["--check"] if mode == "check" else []))
                    print(f"subnormal_bench: {mode} run {r}/{args.runs} {label} {model}: "
                          f"{cpu:.3f} s cpu, {wall:.3f} s wall", file=sys.stderr)
                    old = best.setdefault((label, mode), {}).get(model, (cpu, wall))
                    best[(label, mode)][model] = (min(old[0], cpu), min(old[1], wall))
    return best


def ratio(a, b):
    return a / b if b > 0 else None  # a tiny run may show 0 s of CPU


def rows(best, args):
    for (label, mode), times in sorted(best.items(), key=lambda kv: (kv[0][0] != "new", MODES.index(kv[0][1]))):
        (zc, zw), (sc, sw) = times["zeros"], times["subnormal"]
        yield {"binary": label, "mode": mode, "zeros_cpu_s": zc, "subnormal_cpu_s": sc, "cpu_ratio": ratio(sc, zc),
               "zeros_wall_s": zw, "subnormal_wall_s": sw, "wall_ratio": ratio(sw, zw), "threads": args.threads,
               "runs": args.runs, "seed": args.seed, "grid": args.grid, "boxes": args.boxes,
               "subnormals": args.subnormals}


def markdown(records):
    head = ["binary", "mode", "zeros cpu s", "subnormal cpu s", "ratio subnormal/zeros (cpu)",
            "zeros wall s", "subnormal wall s", "ratio (wall)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in records:
        cells = [r["binary"], r["mode"]]
        for kind in ("cpu", "wall"):
            cells += [f"{r[f'zeros_{kind}_s']:.3f}", f"{r[f'subnormal_{kind}_s']:.3f}",
                      "–" if r[f"{kind}_ratio"] is None else f"{r[f'{kind}_ratio']:.2f}"]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def parse_args(argv):
    ap = Parser(prog="subnormal_bench.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal digits.\n"
                       "Exit status: 0 done; 1 an arrange run failed (or could not start); 2 a bad command "
                       "line,\n--arrange/--baseline not executable, or --work not writable.")
    ap.add_argument("--arrange", type=text, required=True, help="the arrange binary to time")
    ap.add_argument("--baseline", type=text, help="an older arrange binary, run alternately with --arrange")
    ap.add_argument("--runs", type=integer(1, 1000), default=3, help="rounds, 1 to 1000 (default: 3)")
    ap.add_argument("--threads", type=thread_count, default=1, help="arrange --threads (default: 1)")
    ap.add_argument("--seed", type=integer(0, 2**31), default=1, help="the models' seed (default: 1)")
    ap.add_argument("--boxes", type=integer(0, 100_000), default=40, help="boxes on the floor (default: 40)")
    ap.add_argument("--grid", type=integer(1, 2000), default=12, help="floor cells per side (default: 12)")
    ap.add_argument("--subnormals", type=integer(0, 10**7), default=180,
                    help="z = 0 vertices made +-5e-324 (at most all of them; default: 180)")
    ap.add_argument("--work", type=path, help="where the models and outputs go (default: a temporary folder)")
    ap.add_argument("--json", action="store_true", help="one JSON object per row instead of the table")
    args = ap.parse_args(argv)
    for option, binary in (("--arrange", args.arrange), ("--baseline", args.baseline)):
        if binary is not None and not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            ap.error(f"{option} {binary}: no such executable")
    return args


def main(argv=None):
    args = parse_args(argv)
    binaries = [("new", args.arrange)] + ([("base", args.baseline)] if args.baseline else [])
    work = args.work or Path(tempfile.mkdtemp(prefix="tritri-subnormal-bench."))
    try:
        try:
            work.mkdir(parents=True, exist_ok=True)
            files = make_models(work, args.seed, args.grid, args.boxes, args.subnormals)
        except OSError as e:
            print(f"subnormal_bench.py: {e.filename or work}: cannot write ({e.strerror})", file=sys.stderr)
            return 2
        try:
            best = measure(binaries, files, work, args)
        except BenchError as e:
            print(f"subnormal_bench.py: {e}", file=sys.stderr)
            return 1
    finally:
        if args.work is None:
            shutil.rmtree(work, ignore_errors=True)
    records = list(rows(best, args))
    print("\n".join(map(json.dumps, records)) if args.json else markdown(records))
    return 0


if __name__ == "__main__":
    sys.exit(main())
