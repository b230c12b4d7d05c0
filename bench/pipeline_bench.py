#!/usr/bin/env python3
"""End-to-end benchmark of `arrange --stats` on a fixed list of workloads, as a Markdown table.

usage: bench/pipeline_bench.py [--arrange build/bin/arrange] [--baseline OLD_ARRANGE]
           [--threads 1,2] [--runs 3] [--only SUBSTRING[,...]] [--meshes ../shared/meshes]
           [--work DIR] [--timeout S] [--json OUT.jsonl] [--reference-omc [PERFORMANCE.md]]

Workloads (always the same, in this order): the shared models thingi10k/40509.stl,
trimesh/box.STL, common3d/ogre.obj, and two clean meshes with no intersection,
thingi10k/1063852.stl and cgal_data/bunny00.off (relative to --meshes); the generated meshes
coplanar_grids, two_spheres, grid_through_sphere, sphere_copies_4 and sphere_copies_8
(make_test_meshes, found beside --arrange); the EMBER pairs ember-79741-65004,
ember-88566-58011 and ember-1063852-72214 (../tools/make_ember_pairs.py beside --meshes); QuickCSG's TwoCylinders (the two .off files
of thingicsg/QuickCSG/TwoCylinders under --meshes, caps overlapping in common planes).
Generated meshes and EMBER pairs are built once into --work and reused from there.

Every workload runs `arrange FILES --stats --threads T` for each T of --threads, --runs
times, one process per run; with --baseline the older binary runs alternately (new, base,
new, base, ...). Kept per (workload, binary, T): the run of least t_total_s and its peak
memory, the least time of every stage over the runs, and the least wall time of the process.
The counts out_vertices, out_triangles, lpi, tpi and intersecting_pairs must be the same in
every run (both binaries, every thread count); a difference is flagged on stderr and
below the table.

Columns: tris (input triangles), new points (lpi + tpi), then per thread count T: total s
(t_total_s), wall s (the whole process), the stages load/detect/classify/triangulate/output
in seconds, detect/load (issue 37's target: at most 3 on meshes with few intersections),
peak MB; with --baseline the ratios new/base of the total, of each stage and of
the peak memory (below 1: the new binary is faster / smaller); with --reference-omc, for
T = 1 and 2, ours/OMC: our wall s over OpenMeshCraft's wall seconds from the table of
../shared/docs/PERFORMANCE.md (whole process, as measured there; the target is at most 0.5, issue 37).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args, run_collection
from cli_args import MAX_THREADS, Parser, integer, path, seconds, text, thread_count, thread_list  # noqa: E402
from run_collection import (EMBER_CASES, InputError, build_ember_pairs, ember_models,  # noqa: E402
                            kill_group, parse_tool_json)

REPO = Path(__file__).resolve().parent.parent
SHARED = REPO.parent / "shared"
STAGES = ("load", "detect", "classify", "triangulate", "output")  # shown; the JSON has all
ALL_STAGES = ("load", "preprocess", "detect", "classify", "triangulate", "output")
COUNTS = ("out_vertices", "out_triangles", "lpi", "tpi", "intersecting_pairs")
OMC_TARGET = 0.5  # issue 37: twice as fast as OpenMeshCraft everywhere (was 0.8)
# (name, kind): "shared" = a file under --meshes, "generated" = make_test_meshes output,
# "ember" = a pair built by make_ember_pairs.py. Names match PERFORMANCE.md's rows.
WORKLOADS = [("thingi10k/40509.stl", "shared"), ("trimesh/box.STL", "shared"),
             ("common3d/ogre.obj", "shared"), ("thingi10k/1063852.stl", "shared"),
             ("cgal_data/bunny00.off", "shared"), ("coplanar_grids", "generated"),
             ("two_spheres", "generated"), ("grid_through_sphere", "generated"),
             ("sphere_copies_4", "generated"), ("sphere_copies_8", "generated"),
             ("ember-79741-65004", "ember"), ("ember-88566-58011", "ember"),
             ("ember-1063852-72214", "ember"),
             ("thingicsg/QuickCSG/TwoCylinders", "shared-folder")]


class Missing(Exception):
    """A workload's input that is not there and cannot be built."""


# ---------------------------------------------------------------------------------------------
# Inputs


def generated_input(tool, work, name):
    """work/generated/NAME.off, written by make_test_meshes once (moved in complete)."""
    target = work / "generated" / f"{name}.off"
    if target.is_file():
        return target
    if not os.access(tool, os.X_OK):
        raise Missing(f"{tool}: no such executable (build it: cmake --build build --target make_test_meshes)")
    m = re.fullmatch(r"sphere_copies_(\d+)", name)
    target.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=".building-", dir=target.parent))
    try:
        print(f"pipeline_bench: generating {name} into {target.parent}", file=sys.stderr)
        p = subprocess.run([str(tool), str(tmp)] + (["--rotated-copies", m.group(1)] if m else []),
                           capture_output=True, text=True, stdin=subprocess.DEVNULL)
        if p.returncode != 0 or not (tmp / target.name).is_file():
            raise Missing(f"make_test_meshes failed (exit {p.returncode}): {p.stderr.strip()[-300:]}")
        for f in tmp.iterdir():  # keep the other meshes of the set as well
            if not (target.parent / f.name).exists():
                os.replace(f, target.parent / f.name)
        return target
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def ember_input(meshes, work, name):
    """work/ember/NAME.off, built with make_ember_pairs.py (all pairs of the cases file, once)."""
    cases = meshes / "thingi10k" / EMBER_CASES
    target = work / "ember" / f"{name}.off"
    if target.is_file():
        return target
    if not cases.is_file():
        raise Missing(f"{cases}: no such file (the EMBER cases)")
    try:
        names = [m.files[0].name for m in ember_models(cases, target.parent)]
        if target.name not in names:
            raise Missing(f"{cases} does not list {name}")
        build_ember_pairs(cases, target.parent, names)
    except InputError as e:
        raise Missing(str(e)) from e
    return target


def prepare(name, kind, args):
    """The files of one workload; raises Missing."""
    try:
        if kind == "generated":
            return [generated_input(Path(args.arrange).parent / "make_test_meshes", args.work, name)]
        if kind == "ember":
            return [ember_input(args.meshes, args.work, name)]
    except OSError as e:
        raise Missing(f"cannot build it in {args.work}: {e}") from e
    f = args.meshes / name
    if kind == "shared-folder":  # every mesh of the folder, in name order, as one input
        files = sorted(p for p in f.glob("*.off")) if f.is_dir() else []
        if not files:
            raise Missing(f"{f}: no .off files")
        return files
    if not f.is_file():
        raise Missing(f"{f}: no such file")
    return [f]


# ---------------------------------------------------------------------------------------------
# OpenMeshCraft's reference times


def read_omc(file):
    """{workload: {threads: seconds}} from the Markdown table of PERFORMANCE.md: the columns
    'OMC T thr s'; rows named as our workloads (a 'generated ' or 'pairs ' prefix dropped).
    Cells that are not plain numbers ('> 600', '-') are left out."""
    columns, omc = None, {}
    for line in file.read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")] if line.lstrip().startswith("|") else None
        if not cells:
            columns = None
        elif columns is None:
            columns = {i: int(m.group(1)) for i, c in enumerate(cells)
                       if (m := re.fullmatch(r"OMC (\d+) thr s", c))}
        elif not set("".join(cells)) <= set("-: "):
            name = re.sub(r"^(generated|pairs)\s+", "", cells[0])
            for i, t in columns.items():
                value = cells[i].replace(",", "") if i < len(cells) else ""
                if re.fullmatch(r"[0-9]+(\.[0-9]*)?", value):
                    omc.setdefault(name, {})[t] = float(value)
    return omc


# ---------------------------------------------------------------------------------------------
# Running


def run_once(binary, files, threads, timeout):
    """(stats, wall seconds) of one `arrange --stats` process, or (None, error message).
    arrange is forked by a shell, not by Python: Linux keeps the largest RSS of a process
    across exec, so a child of this Python process would report at least Python's RSS as
    its peak_rss_mb. The shell runs it in a new session, killed as a group at the timeout."""
    cmd = ["sh", "-c", '"$@"; exit $?', "sh", binary, *map(str, files), "--stats", "--threads", str(threads)]
    start = time.perf_counter()
    try:
        p = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, errors="replace", start_new_session=True)
    except OSError as e:
        return None, f"cannot run {binary}: {e}"
    try:
        out, err = p.communicate(timeout=timeout or None)
    except subprocess.TimeoutExpired:
        kill_group(p)
        p.communicate()
        return None, f"timed out after {timeout:g} s"
    except BaseException:  # Ctrl-C: no arrange left behind
        kill_group(p)
        raise
    wall = time.perf_counter() - start
    stats = parse_tool_json(out) if p.returncode == 0 else None
    if stats is None or any(f"t_{s}_s" not in stats for s in ALL_STAGES + ("total",)):
        return None, f"exit {p.returncode}, no --stats JSON: {err.strip()[-300:]}"
    return stats, wall


def summarize(runs):
    """The kept figures of a list of (stats, wall) runs."""
    best = min(runs, key=lambda r: r[0]["t_total_s"])[0]
    return {"t_total_s": best["t_total_s"], "wall_s": min(w for _, w in runs),
            "stage_min_s": {s: min(r[0][f"t_{s}_s"] for r in runs) for s in ALL_STAGES},
            "peak_rss_mb": best["peak_rss_mb"], "best_run": best,
            "t_total_s_runs": [r[0]["t_total_s"] for r in runs]}


def measure(name, files, binaries, args, problems):
    """({(binary, threads): summary or {"error": message}}, counts differ) for one workload,
    runs alternating between the binaries; count differences and failures go to problems."""
    runs, errors, reference, differ = {}, {}, None, False
    for t in args.threads:
        for r in range(1, args.runs + 1):
            for label, binary in binaries:
                key = (label, t)
                if key in errors:
                    continue
                stats, wall = run_once(binary, files, t, args.timeout)  # wall: the error if failed
                if stats is None:
                    errors[key] = wall
                    problems.append(f"{name}: {label} binary, {t} thr: FAILED: {wall}")
                    print(f"pipeline_bench: {problems[-1]}", file=sys.stderr)
                    continue
                print(f"pipeline_bench: {name}: {t} thr run {r}/{args.runs} {label}: "
                      f"{stats['t_total_s']:.3f} s, {stats['peak_rss_mb']:.0f} MB", file=sys.stderr)
                counts = {k: stats.get(k) for k in COUNTS}
                if reference is None:
                    reference = (counts, f"{label} {t} thr")
                elif counts != reference[0]:
                    differ = True
                    diff = ", ".join(f"{k} {counts[k]} vs {reference[0][k]}" for k in COUNTS
                                     if counts[k] != reference[0][k])
                    problems.append(f"{name}: COUNTS DIFFER: {label} {t} thr run {r}: {diff} "
                                    f"({reference[1]})")
                    print(f"pipeline_bench: *** {problems[-1]} ***", file=sys.stderr)
                runs.setdefault(key, []).append((stats, wall))
    return {key: ({"error": errors[key]} if key in errors else summarize(runs[key]))
            for key in ((label, t) for t in args.threads for label, _ in binaries)}, differ


# ---------------------------------------------------------------------------------------------
# Output


def ratio(new, base):
    return f"{new / base:.2f}" if base > 0 else "–"


def columns(threads, baseline, omc):
    head = ["workload", "tris", "new points"]
    for t in threads:
        head += [f"{t} thr total s", f"{t} thr wall s", f"{t} thr {'/'.join(STAGES)} s", f"{t} thr detect/load",
                 f"{t} thr peak MB"]
        if baseline:
            head += [f"{t} thr new/base total", f"{t} thr new/base stages", f"{t} thr new/base MB"]
        if omc is not None and t in (1, 2):
            head += [f"{t} thr ours/OMC"]
    return head


def row(name, result, threads, baseline, omc, compared):
    """The cells of one workload's row; compared collects (workload and threads, ours/OMC)."""
    first = next((s for s in result.values() if "error" not in s), None)
    if first is None:
        return [name, "failed"]
    b = first["best_run"]
    cells = [name, f"{b['in_triangles']:,}", f"{b['lpi'] + b['tpi']:,}"]
    for t in threads:
        new, base = result[("new", t)], result.get(("base", t))
        if "error" in new:
            cells += ["failed", "", "", "", ""]
        else:
            cells += [f"{new['t_total_s']:.3f}", f"{new['wall_s']:.3f}",
                      "/".join(f"{new['stage_min_s'][s]:.3f}" for s in STAGES),
                      ratio(new["stage_min_s"]["detect"], new["stage_min_s"]["load"]), f"{new['peak_rss_mb']:.0f}"]
        if baseline:
            if "error" in new or "error" in base:
                cells += ["failed", "", ""]
            else:
                cells += [ratio(new["t_total_s"], base["t_total_s"]),
                          "/".join(ratio(new["stage_min_s"][s], base["stage_min_s"][s]) for s in STAGES),
                          ratio(new["peak_rss_mb"], base["peak_rss_mb"])]
        if omc is not None and t in (1, 2):
            ref = new.get("omc_wall_s")
            cells += [ratio(new["wall_s"], ref) if ref else ""]
            if ref:
                compared.append((f"{name} {t} thr", new["wall_s"] / ref))
    return cells


def write_json(out, name, files, result, binaries, runs):
    paths = dict(binaries)
    for (label, t), summary in result.items():
        out.write(json.dumps({"workload": name, "files": [str(f) for f in files], "binary": label,
                              "arrange": paths[label], "threads": t, "runs": runs, **summary}) + "\n")


# ---------------------------------------------------------------------------------------------
# Command line


def substrings(value):
    parts = value.split(",")
    if "" in parts:
        raise argparse.ArgumentTypeError(f"expected non-empty substrings separated by commas, got {value!r}")
    return parts


def add_run_options(ap, default_timeout, work_help):
    """The options of a benchmark over a fixed workload list (this one, round_bench.py):
    --arrange, --baseline, --threads, --runs, --only, --meshes, --work, --timeout, --json."""
    ap.add_argument("--arrange", type=text, default=str(REPO / "build" / "bin" / "arrange"),
                    help="the arrange binary to time; make_test_meshes is taken from its folder "
                         "(default: %(default)s)")
    ap.add_argument("--baseline", type=text, help="an older arrange binary, run alternately with --arrange")
    ap.add_argument("--threads", type=thread_list, default=[1, 2], metavar="T[,T...]",
                    help=f"0 (all cores) to {MAX_THREADS} each, comma-separated (default: 1,2)")
    ap.add_argument("--runs", type=integer(1, 1000), default=3,
                    help="runs per workload, thread count and binary, 1 to 1000 (default: 3)")
    ap.add_argument("--only", type=substrings, metavar="SUBSTRING[,...]",
                    help="only the workloads whose name contains one of these")
    ap.add_argument("--meshes", type=path, default=SHARED / "meshes",
                    help="the shared meshes folder (default: %(default)s)")
    ap.add_argument("--work", type=path, default=Path(tempfile.gettempdir()) / "tritri-pipeline-bench",
                    help=work_help + " (default: %(default)s)")
    ap.add_argument("--timeout", type=seconds(0, 10**7), default=default_timeout,
                    help=f"seconds per arrange process, 0 for none (default: {default_timeout})")
    ap.add_argument("--json", type=path, metavar="OUT.jsonl",
                    help="also write one JSON object per (workload, threads, binary) here")


def check_run_options(ap, args, workloads):
    """Usage errors for add_run_options' binaries; args.selected: the workloads --only keeps;
    args.binaries: [(label, binary)], "new" then "base" when --baseline is given."""
    for option, binary in (("--arrange", args.arrange), ("--baseline", args.baseline)):
        if binary is not None and not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            ap.error(f"{option} {binary}: no such executable")
    args.selected = [(n, k) for n, k in workloads if not args.only or any(s in n for s in args.only)]
    if not args.selected:
        ap.error(f"--only {','.join(args.only)}: no workload matches (workloads: "
                 + ", ".join(n for n, _ in workloads) + ")")
    args.binaries = [("new", args.arrange)] + ([("base", args.baseline)] if args.baseline else [])


def parse_args(argv):
    ap = Parser(prog="pipeline_bench.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="workloads: " + ", ".join(n for n, _ in WORKLOADS) + "\n\n"
                       "An option that takes a value may be given once; numbers are plain decimal "
                       "digits.\nExit status: 0 every workload ran with equal counts; 1 a workload "
                       "missing, a failed run, a count\ndifference or a missing --reference-omc "
                       "file; 2 a bad command line, --arrange/--baseline not\nexecutable, or "
                       "--work/--json not writable.")
    add_run_options(ap, default_timeout=1800,
                    work_help="cache of the generated meshes and EMBER pairs, reused when present")
    ap.add_argument("--reference-omc", type=path, nargs="?", const=SHARED / "docs" / "PERFORMANCE.md",
                    metavar="PERFORMANCE.md",
                    help="add ours/OMC columns (1 and 2 threads) from this table (default file: "
                         f"{SHARED / 'docs' / 'PERFORMANCE.md'})")
    args = ap.parse_args(argv)
    check_run_options(ap, args, WORKLOADS)
    return args


def main(argv=None):
    args = parse_args(argv)
    binaries = args.binaries
    problems, notes, omc = [], [], None
    if args.reference_omc is not None:
        try:
            omc = read_omc(args.reference_omc) or None
            why = None if omc else "no table with a column 'OMC 1 thr s' or 'OMC 2 thr s'"
        except (OSError, UnicodeDecodeError) as e:
            why = f"cannot read it ({e.strerror or e})"
        if why:
            problems.append(f"--reference-omc {args.reference_omc}: {why}; no ours/OMC columns")
            print(f"pipeline_bench: {problems[-1]}", file=sys.stderr)
    try:
        args.work.mkdir(parents=True, exist_ok=True)
        out = open(f"{args.json}.tmp", "w", encoding="utf-8") if args.json else None
    except OSError as e:
        print(f"pipeline_bench.py: {e.filename}: cannot write ({e.strerror})", file=sys.stderr)
        return 2
    head = columns(args.threads, args.baseline, omc)
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    compared = []
    for i, (name, kind) in enumerate(args.selected, 1):
        print(f"pipeline_bench: [{i}/{len(args.selected)}] {name}", file=sys.stderr)
        try:
            files = prepare(name, kind, args)
        except Missing as e:
            problems.append(f"{name}: MISSING: {e}")
            print(f"pipeline_bench: {problems[-1]}", file=sys.stderr)
            lines.append("| " + " | ".join([name, "missing"] + [""] * (len(head) - 2)) + " |")
            continue
        result, differ = measure(name, files, binaries, args, problems)
        for t, summary in ((t, result[("new", t)]) for t in args.threads):
            if omc is not None and t in (1, 2) and t in omc.get(name, {}) and "error" not in summary:
                summary["omc_wall_s"] = omc[name][t]
        cells = row(name, result, args.threads, args.baseline, omc, compared)
        if differ:
            cells[0] += " **COUNTS DIFFER**"
        lines.append("| " + " | ".join(cells + [""] * (len(head) - len(cells))) + " |")
        if out:
            write_json(out, name, files, result, binaries, args.runs)
            out.flush()
    if out:
        out.close()
        os.replace(f"{args.json}.tmp", args.json)
    if omc is not None:
        over = [w for w, r in compared if r > OMC_TARGET]
        notes.append(f"ours/OMC: our wall s over OpenMeshCraft's (from {args.reference_omc}); target at most "
                     f"{OMC_TARGET}: " + ("no OMC time for the workloads and thread counts run" if not compared
                                          else f"over it: {', '.join(over)}" if over
                                          else f"met on all {len(compared)} compared"))
    print("\n".join(lines))
    if notes or problems:
        print("\n" + "\n".join(f"- {line}" for line in notes + problems))
    sys.stdout.flush()
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
