#!/usr/bin/env python3
"""Our Boolean (`arrange --boolean`, `arrange --csg`) against a baseline build and the peers that
install here (manifold3d, CGAL corefinement), side by side in one run, as a Markdown table.

usage: bench/boolean_bench.py [--arrange build/bin/arrange] [--baseline DIR_OR_ARRANGE]
           [--pairs NAME[,...]] [--ops union,intersection,difference] [--quick] [--threads 1,2]
           [--runs 3] [--peers manifold,cgal-epick,cgal-epeck|none] [--cgal PATH] [--python PATH]
           [--work DIR] [--timeout S] [--no-check] [--md OUT.md] [--json OUT.json]

Workloads: the operand pairs of ../shared/tools/boolean_pairs/make_pairs.py (written once into
--work/pairs, in the order of its pairs.json; the last three have self-intersecting operands)
for each operation of --ops, then QuickCSG's trees organic.csg, T1.csg and H.csg (under
--meshes, thingicsg/QuickCSG; operation "tree"). --quick: only cube-sphere2, t1_0-t1_1 and
sphere1-sphere2, no trees, --runs 1 unless given. --pairs picks workloads by name.

Contestants, one process per run, started through sh (so that a tool's own peak RSS, which it
reports, is its own: see pipeline_bench.py), --runs rounds alternating over all of them so that
all see the same machine load, the least wall time kept (its run's peak memory):
  ours T thr   arrange A B --boolean OP -o OUT.obj --stats --threads T, for each T of --threads
               (stage times: the least of each over the runs)
  base T thr   the same with --baseline (an arrange of another build), when given
  manifold     manifold_boolean.py through --python (PyPI manifold3d, one core): the whole
               Python process, interpreter start-up included, as ../shared/docs/PERFORMANCE.md
  cgal-epick / cgal-epeck   cgal_boolean (bench/cgal_boolean.cpp) with that kernel; it refuses
               self-intersecting operands ("refused"); not run on trees ("–")
All times are whole-process wall seconds, load and output included.

Check (untimed, unless --no-check): ours once more with --exact; bench/mesh_volume.py gives the
exact volume and boundary edges of that output; valid = closed and volume > 0 (= 0 for an empty
result), and where cgal-epeck succeeded, equal to CGAL's exact volume (one more cgal_boolean run
that sums it exactly).

Columns: workload (input triangles), op, ours s per T, ours stage seconds at the first T, base s
per T, each peer's s, ours/exact peer (ours at the first T over the fastest exact peer:
cgal-epeck; cgal-epick and manifold round their constructions), ours/manifold, peak MB of each,
out tris (ours), valid. A failed run shows "failed: <first line of its stderr>".
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
from fractions import Fraction
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for the helpers
from atomic_write import write_atomic  # noqa: E402
from cli_args import MAX_THREADS, Parser, integer, path, seconds, text, thread_list  # noqa: E402
from mesh_files import MeshError  # noqa: E402
from mesh_volume import measure  # noqa: E402
from run_collection import kill_group, parse_tool_json  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
SHARED = REPO.parent / "shared"
OPS = ("union", "intersection", "difference")
TREES = {"organic.csg": "Organic/organic.csg", "T1.csg": "T1/T1.csg", "H.csg": "knots42/H.csg"}
QUICK = ("cube-sphere2", "t1_0-t1_1", "sphere1-sphere2")
PEERS = ("manifold", "cgal-epick", "cgal-epeck")
EXACT_PEERS = ("cgal-epeck",)
STAGES = ("load", "preprocess", "detect", "classify", "triangulate", "winding", "output")


class Missing(Exception):
    """A workload's input that is not there and cannot be built."""


# ---------------------------------------------------------------------------------------------
# Inputs


def pair_list(args):
    """[{name, a, b, kind}] from --work/pairs/pairs.json, written by make_pairs.py once."""
    folder = args.work / "pairs"
    if not (folder / "pairs.json").is_file():
        if not args.make_pairs.is_file():
            raise Missing(f"{args.make_pairs}: no such file")
        tmp = Path(tempfile.mkdtemp(prefix=".pairs-", dir=args.work))
        try:
            print(f"boolean_bench: writing the operand pairs into {folder}", file=sys.stderr)
            p = subprocess.run([args.python, str(args.make_pairs), str(tmp)], capture_output=True, text=True,
                               stdin=subprocess.DEVNULL)
            if p.returncode != 0 or not (tmp / "pairs.json").is_file():
                raise Missing(f"make_pairs.py failed (exit {p.returncode}): {p.stderr.strip()[-300:]}")
            shutil.rmtree(folder, ignore_errors=True)
            os.replace(tmp, folder)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    pairs = json.loads((folder / "pairs.json").read_text(encoding="utf-8"))
    return [dict(p, a=folder / p["a"], b=folder / p["b"]) for p in pairs]


def count_faces(file):
    if file.suffix.lower() == ".off":
        with open(file, encoding="utf-8", errors="replace") as f:
            head = [w for line in f for w in line.split("#", 1)[0].split()][:3]
        return int(head[2] if head[0] == "OFF" else head[1])
    with open(file, encoding="utf-8", errors="replace") as f:
        return sum(line.startswith("f ") for line in f)


def tree_operands(tree):
    names = re.findall(r'import\s*\(\s*file\s*=\s*"([^"]+)"', tree.read_text(encoding="utf-8"))
    return [tree.parent / n for n in names]


def workloads(args):
    """[(name, op, files, tree or None)] in table order; files is Missing when the pairs are."""
    rows = []
    wanted = set(args.pairs) if args.pairs else set(QUICK) if args.quick else None
    try:
        pairs = [] if wanted and wanted <= set(TREES) else pair_list(args)
    except (Missing, OSError, ValueError, KeyError, TypeError) as e:
        pairs = e
    if isinstance(pairs, Exception):
        rows.append(("operand pairs", "", Missing(str(pairs)), None))
    else:
        known = {p["name"] for p in pairs} | set(TREES)
        unknown = sorted((wanted or set()) - known)
        if unknown:
            args.parser.error(f"--pairs: no workload {', '.join(unknown)} (workloads: {', '.join(sorted(known))})")
        rows += [(p["name"], op, [p["a"], p["b"]], None) for p in pairs
                 if wanted is None or p["name"] in wanted for op in args.ops]
    for name, rel in TREES.items():
        if (wanted is None and not args.quick) or (wanted and name in wanted):
            rows.append((name, "tree", [], args.meshes / "thingicsg" / "QuickCSG" / rel))
    return rows


# ---------------------------------------------------------------------------------------------
# Running


def run_process(cmd, timeout):
    """{"wall_s", "json"} of one process, or {"error": "failed: ..." / "refused: ..." /
    "timeout"}; started by sh in its own session (killed as a group at the timeout)."""
    start = time.perf_counter()
    try:
        p = subprocess.Popen(["sh", "-c", '"$@"; exit $?', "sh", *map(str, cmd)], stdin=subprocess.DEVNULL,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace",
                             start_new_session=True)
    except OSError as e:
        return {"error": f"failed: cannot run {cmd[0]}: {e}"}
    try:
        out, err = p.communicate(timeout=timeout or None)
    except subprocess.TimeoutExpired:
        kill_group(p)
        p.communicate()
        return {"error": f"timeout ({timeout:g} s)"}
    except BaseException:  # Ctrl-C: nothing left running
        kill_group(p)
        raise
    wall = time.perf_counter() - start
    first = next((line.strip() for line in err.splitlines() if line.strip()), f"exit {p.returncode}")
    stats = parse_tool_json(out)
    if p.returncode != 0 or stats is None:
        return {"error": first if first.startswith("refused") else f"failed: {first}"}
    return {"wall_s": wall, "json": stats}


def ours_command(binary, files, op, tree, out, threads, exact=False):
    inputs = ["--csg", tree] if tree else [*files, "--boolean", op]
    return [binary, *inputs, "-o", out, "--stats", "--threads", threads] + (["--exact"] if exact else [])


def contestants(args, name, op, files, tree):
    """[(key, command)]: key is the column's label ("ours 1 thr", "manifold", ...)."""
    out = args.work / "out"
    stem = f"{name}-{op}"
    found = []
    for t in args.threads:
        for label, binary in (("ours", args.arrange), ("base", args.baseline)):
            if binary:
                command = ours_command(binary, files, op, tree, out / f"{stem}-{label}{t}.obj", t)
                found.append((f"{label} {t} thr", command))
    if "manifold" in args.peers:
        script = [args.python, REPO / "bench" / "manifold_boolean.py"]
        inputs = ["--csg", tree] if tree else [*files, op]
        found.append(("manifold", script + inputs + [out / f"{stem}-manifold.obj"]))
    for kernel in ("epick", "epeck"):
        if f"cgal-{kernel}" in args.peers and not tree:
            found.append((f"cgal-{kernel}", [args.cgal, *files, op, out / f"{stem}-{kernel}.off", "--kernel", kernel,
                                             "--no-volume"]))
    return found


def summarize(runs, ours):
    """The kept figures of a contestant's successful runs (the run of least wall time)."""
    best = min(runs, key=lambda r: r["wall_s"])
    s = {"wall_s": best["wall_s"], "peak_rss_mb": best["json"].get("peak_rss_mb"),
         "wall_s_runs": [r["wall_s"] for r in runs], "best_run": best["json"]}
    if ours:
        s["t_total_s"] = min(r["json"].get("t_total_s", float("inf")) for r in runs)
        s["stage_min_s"] = {st: min(r["json"].get(f"t_{st}_s", float("nan")) for r in runs) for st in STAGES}
        s["out_triangles"] = best["json"].get("out_triangles")
    else:
        s["triangles"] = best["json"].get("triangles")
    return s


def measure_workload(args, label, name, op, files, tree):
    """{key: summary or {"error": ...}}, runs alternating over the contestants."""
    found = contestants(args, name, op, files, tree)
    runs, errors = {}, {}
    for r in range(1, args.runs + 1):
        for key, cmd in found:
            if key in errors:
                continue
            result = run_process(cmd, args.timeout)
            if "error" in result:
                errors[key] = result["error"]
                note = result["error"]
            else:
                runs.setdefault(key, []).append(result)
                mb = result["json"].get("peak_rss_mb")
                note = f"{result['wall_s']:.3f} s" + (f", {mb:.0f} MB" if isinstance(mb, (int, float)) else "")
            print(f"boolean_bench: {label} {name} {op} run {r}/{args.runs} {key}: {note}", file=sys.stderr)
    return {key: {"error": errors[key]} if key in errors else summarize(runs[key], key.startswith(("ours", "base")))
            for key, _ in found}


def check(args, name, op, files, tree, results):
    """(valid text, record, problem or None): ours with --exact, measured exactly, against CGAL
    Epeck's exact volume when Epeck succeeded."""
    out = args.work / "out" / f"{name}-{op}-exact.obj"
    ran = run_process(ours_command(args.arrange, files, op, tree, out, max(args.threads), exact=True), args.timeout)
    if "error" in ran:
        return ran["error"], {"error": ran["error"]}, f"{name} {op}: the --exact run {ran['error']}"
    try:
        m = measure(out)
    except MeshError as e:
        return f"failed: {e}", {"error": str(e)}, f"{name} {op}: {e}"
    record = {**m, "volume": f"{m['volume'].numerator}/{m['volume'].denominator}"}
    v, why = m["volume"], None
    if not m["closed"]:
        why = f"NO: {m['boundary_edges']} boundary edges"
    elif v < 0 or (v == 0 and m["triangles"]):
        why = f"NO: volume {float(v):.6g}"
    valid = why or "yes"
    if "error" not in results.get("cgal-epeck", {"error": ""}) and not why:
        epeck = run_process([args.cgal, *files, op, args.work / "out" / f"{name}-{op}-epeck-volume.off",
                             "--kernel", "epeck"], args.timeout)
        if "error" in epeck:
            valid += " (epeck volume run: " + epeck["error"] + ")"
        else:
            theirs = Fraction(epeck["json"]["volume"])
            record["cgal_epeck_volume_equal"] = theirs == v
            if theirs == v:
                valid += ", = epeck"
            else:
                rel = float(abs(v - theirs) / abs(theirs)) if theirs else float("inf")
                why = valid = f"NO: volume ≠ CGAL epeck (relative difference {rel:.2g})"
    return valid, record, (f"{name} {op}: {why}" if why else None)


# ---------------------------------------------------------------------------------------------
# Output


def seconds_cell(s):
    if "error" in s:  # a refusal's reason (which operand) is in the JSON
        return "refused" if s["error"].startswith("refused") else s["error"]
    return f"{s['wall_s']:.3f}"


def mb_cell(s):
    mb = None if s is None or "error" in s else s.get("peak_rss_mb")
    return f"{mb:.0f}" if isinstance(mb, (int, float)) else "–"


def ratio(ours, peers):
    times = [p["wall_s"] for p in peers if p is not None and "error" not in p]
    if ours is None or "error" in ours or not times:
        return "–"
    return f"{ours['wall_s'] / min(times):.2f}"


def columns(args):
    t0 = args.threads[0]
    head = ["workload (in tris)", "op"] + [f"ours {t} thr s" for t in args.threads]
    head.append(f"ours {t0} thr stages s ({'/'.join(STAGES)})")
    head += [f"base {t} thr s" for t in args.threads] if args.baseline else []
    head += [f"{p} s" for p in args.peers]
    head += [f"ours/exact peer ({t0} thr)", f"ours/manifold ({t0} thr)"]
    head += [f"ours {t} thr MB" for t in args.threads]
    head += [f"base {t0} thr MB"] if args.baseline else []
    head += [f"{p} MB" for p in args.peers] + ["out tris", "valid"]
    return head


def row(args, title, op, results, valid):
    t0, absent = args.threads[0], {"error": "–"}
    ours = results[f"ours {t0} thr"]
    cells = [title, op] + [seconds_cell(results[f"ours {t} thr"]) for t in args.threads]
    cells.append("/".join(f"{ours['stage_min_s'][s]:.3f}" for s in STAGES) if "error" not in ours else "")
    if args.baseline:
        cells += [seconds_cell(results[f"base {t} thr"]) for t in args.threads]
    cells += [seconds_cell(results.get(p, absent)) for p in args.peers]
    cells += [ratio(ours, [results.get(p) for p in EXACT_PEERS]), ratio(ours, [results.get("manifold")])]
    cells += [mb_cell(results[f"ours {t} thr"]) for t in args.threads]
    cells += [mb_cell(results[f"base {t0} thr"])] if args.baseline else []
    cells += [mb_cell(results.get(p)) for p in args.peers]
    counts = {s.get("out_triangles") for k, s in results.items() if k.startswith("ours") and "error" not in s}
    cells += [" / ".join(f"{c:,}" for c in sorted(counts) if isinstance(c, int)) or "–", valid]
    return cells, len(counts) > 1


# ---------------------------------------------------------------------------------------------
# Command line


def names(allowed=None):
    def parse(value):
        parts = value.split(",")
        if "" in parts or len(set(parts)) != len(parts):
            raise argparse.ArgumentTypeError(f"expected distinct names separated by commas, got {value!r}")
        bad = [p for p in parts if allowed is not None and p not in allowed]
        if bad:
            raise argparse.ArgumentTypeError(f"unknown {', '.join(bad)} (choose from {', '.join(allowed)})")
        return parts
    parse.__name__ = "names"
    return parse


def executable(ap, option, file):
    if not (os.path.isfile(file) and os.access(file, os.X_OK)):
        ap.error(f"{option} {file}: no such executable")
    return str(file)


def parse_args(argv):
    venv = REPO / "build-python" / "venv" / "bin" / "python"
    ap = Parser(prog="boolean_bench.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal digits.\n"
                       "Exit status: 0 all our runs succeeded and are valid; 1 a missing input, a failed or "
                       "invalid run of ours, or\nthread counts that disagree on the output; 2 a bad command line, "
                       "a missing tool, an unwritable file.")
    ap.add_argument("--arrange", type=text, default=str(REPO / "build" / "bin" / "arrange"),
                    help="our arrange binary (default: %(default)s)")
    ap.add_argument("--baseline", type=path, metavar="DIR_OR_ARRANGE",
                    help="an arrange of another build (or its build folder: DIR/bin/arrange), run alternately")
    ap.add_argument("--pairs", type=names(), metavar="NAME[,...]", help="only these pairs and trees")
    ap.add_argument("--ops", type=names(OPS), default=list(OPS), metavar="OP[,...]",
                    help="operations run on the pairs (default: union,intersection,difference)")
    ap.add_argument("--quick", action="store_true", help=f"only {', '.join(QUICK)}; --runs 1 unless given")
    ap.add_argument("--threads", type=thread_list, default=[1, 2], metavar="T[,T...]",
                    help=f"our thread counts, 0 (all cores) to {MAX_THREADS} each (default: 1,2)")
    ap.add_argument("--runs", type=integer(1, 1000), help="rounds of runs, 1 to 1000 (default: 3)")
    ap.add_argument("--peers", type=names(PEERS + ("none",)), default=list(PEERS), metavar="PEER[,...]",
                    help=f"{','.join(PEERS)} or none (default: all)")
    ap.add_argument("--cgal", type=text, help="cgal_boolean (default: beside --arrange)")
    ap.add_argument("--python", type=text, default=str(venv if venv.is_file() else Path(sys.executable)),
                    help="the Python with manifold3d and numpy (default: %(default)s)")
    ap.add_argument("--meshes", type=path, default=SHARED / "meshes", help="shared meshes (default: %(default)s)")
    ap.add_argument("--make-pairs", type=path, default=SHARED / "tools" / "boolean_pairs" / "make_pairs.py",
                    help="the pairs' generator (default: %(default)s)")
    ap.add_argument("--work", type=path, default=Path(tempfile.gettempdir()) / "tritri-boolean-bench",
                    help="operand pairs (reused) and outputs (default: %(default)s)")
    ap.add_argument("--timeout", type=seconds(0, 10**7), default=1800,
                    help="seconds per process, 0 for none (default: 1800)")
    ap.add_argument("--no-check", action="store_true", help="no --exact run, no volume check")
    ap.add_argument("--md", type=path, metavar="OUT.md", help="also write the table here")
    ap.add_argument("--json", type=path, metavar="OUT.json", help="also write every figure here")
    args = ap.parse_args(argv)
    args.parser = ap
    args.runs = args.runs or (1 if args.quick else 3)
    if "none" in args.peers:
        if len(args.peers) > 1:
            ap.error("--peers: none goes alone")
        args.peers = []
    args.arrange = executable(ap, "--arrange", args.arrange)
    if args.baseline is not None:
        base = args.baseline / "bin" / "arrange" if args.baseline.is_dir() else args.baseline
        args.baseline = executable(ap, "--baseline", base)
    cgal = args.cgal or str(Path(args.arrange).parent / "cgal_boolean")
    args.cgal = executable(ap, "--cgal", cgal) if any(p.startswith("cgal") for p in args.peers) else cgal
    args.python = executable(ap, "--python", args.python) if "manifold" in args.peers else args.python
    for option, file in (("--md", args.md), ("--json", args.json)):
        if file is not None and not os.access(file.parent if str(file.parent) else ".", os.W_OK):
            ap.error(f"{option} {file}: cannot write there")
    try:
        (args.work / "out").mkdir(parents=True, exist_ok=True)
    except OSError as e:
        ap.error(f"--work {args.work}: cannot write there ({e.strerror})")
    return args


def main(argv=None):
    args = parse_args(argv)
    head = columns(args)
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    problems, records = [], []
    todo = workloads(args)
    for i, (name, op, files, tree) in enumerate(todo, 1):
        label = f"[{i}/{len(todo)}]"
        try:
            if isinstance(files, Missing):
                raise files
            if tree and not tree.is_file():
                raise Missing(f"{tree}: no such file")
            operands = tree_operands(tree) if tree else files
            title = f"{name} ({sum(count_faces(f) for f in operands):,})"
        except (Missing, OSError, ValueError, IndexError) as e:
            problems.append(f"{name}: MISSING: {e}")
            print(f"boolean_bench: {problems[-1]}", file=sys.stderr)
            lines.append("| " + " | ".join([name, op, "missing"] + [""] * (len(head) - 3)) + " |")
            continue
        results = measure_workload(args, label, name, op, files, tree)
        for key, s in results.items():
            if key.startswith("ours") and "error" in s:
                problems.append(f"{name} {op}: {key}: {s['error']}")
        valid, check_record = "–", None
        if not args.no_check and any("error" not in s for k, s in results.items() if k.startswith("ours")):
            try:
                valid, check_record, problem = check(args, name, op, files, tree, results)
            except (ArithmeticError, ValueError, TypeError, KeyError, OSError) as e:  # never stop the bench
                valid, check_record, problem = f"failed: check: {e}", {"error": str(e)}, f"{name} {op}: check: {e}"
            problems += [problem] if problem else []
        cells, differ = row(args, title, op, results, valid)
        if differ:
            problems.append(f"{name} {op}: the thread counts disagree on out_triangles")
        lines.append("| " + " | ".join(cells) + " |")
        records.append({"workload": name, "op": op, "files": [str(f) for f in files], "tree": tree and str(tree),
                        "results": results, "valid": valid, "check": check_record})
    text_out = "\n".join(lines) + ("\n\n" + "\n".join(f"- {p}" for p in problems) if problems else "") + "\n"
    print(text_out, end="")
    if args.md:
        write_atomic(args.md, lambda f: f.write(text_out.encode()))
    if args.json:
        report = {"arrange": args.arrange, "baseline": args.baseline, "threads": args.threads, "runs": args.runs,
                  "peers": args.peers, "rows": records, "problems": problems}
        write_atomic(args.json, lambda f: f.write(json.dumps(report, indent=1, default=str).encode()))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
