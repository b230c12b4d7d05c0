#!/usr/bin/env python3
"""What each step of `arrange --round safe` settles that no other step does.

usage: python3 bench/round_steps_study.py SWEEP.jsonl --out STUDY.jsonl [--arrange build/bin/arrange]
           [--steps NAME[,NAME...]] [--jobs N] [--timeout S]

A measurement, not a test. SWEEP.jsonl is the output of bench/round_safe_sweep.py run with
--work (its variant files must still exist) and with the same arrange. Every run that it
records as settled after more than one pass (rounding to nearest alone did not settle it, so
the ladder's steps ran) is run again once per step, with `--round-without STEP`
(docs/ROUNDING.md lists the steps), at 1 thread and the default move limit (the sweep's
defaults: a sweep run otherwise is not comparable), --jobs at once. Leaving out a step that
was tried and failed frees its passes for the later steps, which can also change a run. Leaving out a step that the
run never reached, or that failed on it, gives the same result; a run where the step settled
comes out different: settled by a later step (another step settles it too) or not at all
(refused, timed out: only this step settles it). "Same" compares the output:
round_max_move_rel and rounded_triangles (a step that was tried and failed still spent
passes, so round_passes may differ where the output does not).

Output: --out gets one JSON object per run (step, mesh, variant, file, status, the sweep's and
this run's wall_s, round_passes, round_max_move_rel, rounded_triangles, same), written as they
finish to STUDY.jsonl.partial and renamed at the end. On stdout, a Markdown table per step:
runs re-run, unchanged, settled another way, refused, timed out or failed (what only this
step settles), and the seconds of the changed runs with the step and without it.
"""
import argparse
import json
import os
import re
import sys
import tempfile
import threading
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__
from cli_args import Parser, integer, path, seconds, text  # noqa: E402
from round_safe_sweep import run_arrange  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
ROUND_MESH_H = REPO / "arrangements" / "include" / "arrangements" / "round_mesh.h"


def round_steps():
    """The names `arrange --round-without` takes, in the ladder's order: kRoundStepNames of
    round_mesh.h (defined once; empty when the header is not beside the script)."""
    try:
        m = re.search(r"kRoundStepNames = \{([^}]*)\}", ROUND_MESH_H.read_text())
    except OSError:
        m = None
    return tuple(re.findall(r'"([^"]+)"', m.group(1))) if m else ()


STEPS = round_steps()
COMPARED = ("round_max_move_rel", "rounded_triangles")


def step_list(value):
    names = value.split(",")
    unknown = [n for n in names if n not in STEPS]
    if unknown:
        raise argparse.ArgumentTypeError(f"unknown step {unknown[0]!r} (known: {', '.join(STEPS)})")
    if len(set(names)) != len(names):
        raise argparse.ArgumentTypeError(f"a step given twice in {value!r}")
    return names


def parse_args(argv):
    ap = Parser(prog="round_steps_study.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="Exit status: 0 the study ran (whatever the statuses of the runs); 1 SWEEP.jsonl unreadable, "
                       "a variant file gone,\nor --out not writable; 2 a bad command line or --arrange not executable.")
    ap.add_argument("sweep", type=path, metavar="SWEEP.jsonl", help="round_safe_sweep.py's --out, run with --work")
    ap.add_argument("--out", type=path, required=True, metavar="STUDY.jsonl", help="one JSON object per run")
    ap.add_argument("--arrange", type=text, default=str(REPO / "build" / "bin" / "arrange"),
                    help="the arrange binary (default: build/bin/arrange)")
    ap.add_argument("--steps", type=step_list, default=list(STEPS), metavar="NAME[,NAME...]",
                    help="the steps to leave out, one at a time (default: all)")
    ap.add_argument("--jobs", type=integer(1, 256), default=1, help="runs at once (default 1)")
    ap.add_argument("--timeout", type=seconds(0, 10**7), default=120, help="per run (default 120 s; 0: none)")
    args = ap.parse_args(argv)
    if not STEPS:
        ap.error(f"cannot read the step names (kRoundStepNames) from {ROUND_MESH_H}")
    if not (os.path.isfile(args.arrange) and os.access(args.arrange, os.X_OK)):
        ap.error(f"--arrange {args.arrange}: no such executable")
    return args, ap


def load_sweep(file):
    """The sweep's settled runs that needed more than one pass."""
    rows = []
    with open(file, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            try:
                rows.append(json.loads(line))
            except json.JSONDecodeError as e:
                raise ValueError(f"{file}:{number}: not a JSON line ({e.msg})") from None
    runs = [r for r in rows if r.get("status") == "settled" and (r.get("round_passes") or 0) > 1]
    for r in runs:
        if not r.get("file") or not Path(r["file"]).is_file():
            raise ValueError(f"{file}: the variant file {r.get('file')!r} is gone (run the sweep with --work)")
    return runs


def study_run(args, step, sweep_row, scratch):
    out = Path(scratch) / f"{threading.get_ident()}.obj"
    status, _, message, stats, wall = run_arrange(args.arrange, sweep_row["file"], out, 1, args.timeout,
                                                  without=step)
    for leftover in (out, out.with_name(out.name + ".provenance.csv")):
        leftover.unlink(missing_ok=True)
    rec = {"step": step, "mesh": sweep_row["mesh"], "variant": sweep_row["variant"], "file": sweep_row["file"],
           "status": status, "message": message, "sweep_wall_s": sweep_row["wall_s"], "wall_s": round(wall, 6)}
    rec.update({k: (stats or {}).get(k) for k in ("round_passes",) + COMPARED})
    rec["same"] = status == "settled" and all(rec[k] == sweep_row.get(k) for k in COMPARED)
    return rec


def summary(records, steps, runs):
    lines = [f"{runs} settled runs of more than one pass, each with one step left out", "",
             "| step left out | unchanged | settled by another step | refused | timed out | failed "
             "| changed runs: s with the step | s without |", "|---|" + "---:|" * 7]
    for step in steps:
        mine = [r for r in records if r["step"] == step]
        changed = [r for r in mine if not r["same"]]
        count = [sum(r["status"] == s for r in changed) for s in ("settled", "refused", "timeout", "error")]
        with_s = sum(r["sweep_wall_s"] for r in changed)
        without_s = sum(r["wall_s"] for r in changed)
        lines.append(f"| {step} | {len(mine) - len(changed)} | " + " | ".join(map(str, count))
                     + f" | {with_s:.1f} | {without_s:.1f} |")
    lines.append("\nrefused, timed out, failed: runs that only this step settles in the sweep.")
    return "\n".join(lines)


def main(argv=None):
    args, ap = parse_args(argv)
    try:
        runs = load_sweep(args.sweep)
    except (OSError, ValueError) as e:
        print(f"round_steps_study.py: {e}", file=sys.stderr)
        return 1
    partial = Path(f"{args.out}.partial")
    records, lock = [], threading.Lock()
    total = len(runs) * len(args.steps)
    try:
        out = open(partial, "w", encoding="utf-8")
    except OSError as e:
        print(f"round_steps_study.py: {e.filename}: cannot write ({e.strerror})", file=sys.stderr)
        return 1
    with out, tempfile.TemporaryDirectory() as scratch:
        def one(job):
            rec = study_run(args, job[0], job[1], scratch)
            with lock:
                records.append(rec)
                out.write(json.dumps(rec) + "\n")
                out.flush()
                print(f"\r{len(records)}/{total} runs", end="", file=sys.stderr, flush=True)
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            list(pool.map(one, [(s, r) for s in args.steps for r in runs]))
    print(file=sys.stderr)
    os.replace(partial, args.out)
    print(summary(records, args.steps, len(runs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
