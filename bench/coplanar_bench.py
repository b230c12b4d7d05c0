#!/usr/bin/env python3
"""How the arrangement's time grows with the size of coplanar overlaps: `arrange --stats` on
pairs of cylinders whose caps lie in common planes, as a Markdown table (and a log-log chart).

usage: bench/coplanar_bench.py [--arrange build/bin/arrange] [--baseline OLD_ARRANGE]
           [--families sheets,fans,strips] [--sheet-sizes 10,30,...] [--sizes 100,300,...]
           [--strip-sizes 100,200,...] [--wedge-sizes 20,40,...]
           [--max-strip-n 1600] [--threads 1,2] [--runs 3] [--timeout 600] [--work DIR]
           [--json OUT.jsonl] [--chart OUT.png]

Inputs (generated here, deterministic, pure Python; written as OFF into --work):
  sheets  two flat square sheets of side 60 in z = 0, n x n cells of two triangles each, B
          turned by 12 degrees and moved by a fraction of a cell: every triangle overlaps O(1)
          triangles of the other sheet, and no vertex is shared, so candidates, output and
          time should all grow linearly in the 2 n^2 triangles (--sheet-sizes).
and two closed
cylinders of radius 30 and height 1 with n segments, axes parallel to z, like QuickCSG's
TwoCylinders: A centred at (0, 0), B at (10, 10) and turned by 12 degrees. Both have their
caps exactly in z = 0 and z = 1, so every cap triangle of A is coplanar with B's cap triangles.
  fans    each cap is a fan around an apex vertex at (5, 5), the midpoint of the two axes
          (inside both caps): 2n + 2 vertices and 4n triangles per cylinder. Both fans share
          the apex, so their spokes never cross and each cap wedge overlaps O(1) wedges of the
          other cap: the output grows linearly in n. (Fans around each cylinder's own axis
          would not do: spokes from two different points cross about 0.2 n^2 times per cap,
          as many as strips.)
  strips  each cap is a fan from rim vertex 0, exactly as QuickCSG's TwoCylinders is built
          (long thin triangles across the disk): 2n vertices and 4n - 4 triangles per
          cylinder; the output grows quadratically in n (n = 200 is TwoCylinders itself:
          37,408 output triangles). Only small n: at most --max-strip-n (default 1600).
  wedges  hostile input (issue 36): n thin wedges in z = 0 whose edges all pass through two
          points near the origin, wedge i from (-1, y) to (1, -y +- d), y = -1 + 2 (i + 1/2) / n,
          d = 1 / (2n) (as in tests/test_hostile_polygons.cpp); the even wedges are A, the odd
          ones B. Rounded to doubles, the edges miss the two points, and their O(n^2)
          crossings form clouds within about 1e-17 of them, where every predicate is exact
          (--wedge-sizes).

Every (family, n) runs `arrange A.off B.off --stats --threads T` for each T of --threads, --runs
times, one process per run (through sh, so that peak_rss_mb is the process's own); with
--baseline the older binary runs alternately (new, base, new, base, ...). Kept per (family,
n, binary, T): the run of least t_total_s with its stages (t_detect_s, t_classify_s,
t_triangulate_s), peak_rss_mb, out_triangles, out_vertices and coplanar_pairs. The counts
out_triangles and out_vertices must be the same in every run of a (family, n) (both binaries,
every T); a difference is flagged on stderr and below the table. A run that exceeds --timeout
is killed and reported as timeout (not as a failure); the larger sizes of that family are then
skipped for that binary (shown as skipped).

Columns: family, n (segments per cylinder), in tris (input triangles of both cylinders), out
tris (output triangles), coplanar pairs, candidate pairs (pairs of overlapping bounding boxes:
quadratic in n for both families, since every cap triangle is long and thin), then per thread
count T: total s (t_total_s), detect/classify/triangulate s (t_detect_s, t_classify_s,
t_triangulate_s), µs/out tri (t_total_s in microseconds per output triangle: flat when the
time grows linearly with the output), peak MB; with --baseline, new/base (the ratio of total s;
below 1 the new binary is faster). Below the table: the log-log slope of
total s against out tris per family, binary and T (least squares over the sizes whose total
exceeds 0.01 s; 1 = linear). --chart draws those curves on log-log axes, each with a dashed
line of slope 1 through its smallest point. --json writes one object per (family, n, binary,
T). Progress goes to stderr.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args, run_collection
from cli_args import MAX_THREADS, Parser, integer, path, seconds, text, thread_count, thread_list  # noqa: E402
from run_collection import kill_group, parse_tool_json  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
RADIUS, HEIGHT = 30.0, 1.0
OFFSET, TURN_DEGREES = (10.0, 10.0), 12.0  # cylinder B against A, as in QuickCSG's TwoCylinders
APEX = (5.0, 5.0)  # the fans' common apex: the midpoint of the two axes
FAMILIES = ("sheets", "fans", "strips", "wedges")
STAGES = ("detect", "classify", "triangulate")
COUNTS = ("out_vertices", "out_triangles")
KEPT = ("t_total_s",) + tuple(f"t_{s}_s" for s in STAGES) + ("peak_rss_mb", "in_triangles", "out_triangles",
                                                             "out_vertices", "coplanar_pairs", "candidate_pairs")
MIN_FIT_SECONDS = 0.01
MAX_N = 10**7

# ---------------------------------------------------------------------------------------------
# Meshes


def cylinder(family, n, centre, turn):
    """(vertices, triangles) of one closed cylinder, outward oriented: rim vertex i at angle
    turn + 2 pi i / n, i in the bottom ring (z = 0) and n + i in the top ring (z = 1); fans add
    the apex vertices 2n (bottom) and 2n + 1 (top)."""
    cx, cy = centre
    ring = [(cx + RADIUS * math.cos(turn + 2 * math.pi * i / n), cy + RADIUS * math.sin(turn + 2 * math.pi * i / n))
            for i in range(n)]
    vertices = [(x, y, 0.0) for x, y in ring] + [(x, y, HEIGHT) for x, y in ring]
    triangles = []
    for i in range(n):
        j = (i + 1) % n
        triangles += [(i, j, n + j), (i, n + j, n + i)]
    if family == "fans":
        b = len(vertices)
        vertices += [(APEX[0], APEX[1], 0.0), (APEX[0], APEX[1], HEIGHT)]
        for i in range(n):
            j = (i + 1) % n
            triangles += [(b, j, i), (b + 1, n + i, n + j)]
    else:
        for i in range(1, n - 1):
            triangles += [(0, i + 1, i), (n, n + i, n + i + 1)]
    return vertices, triangles


def sheet(n, turn, shift):
    """(vertices, triangles) of a square sheet of side 2 RADIUS in z = 0, n x n cells of two
    triangles each, turned by `turn` about the origin and moved by `shift`."""
    c, s = math.cos(turn), math.sin(turn)
    vertices = []
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = -RADIUS + 2 * RADIUS * i / n, -RADIUS + 2 * RADIUS * j / n
            vertices.append((c * x - s * y + shift[0], s * x + c * y + shift[1], 0.0))
    triangles = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            triangles += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    return vertices, triangles


def wedges(n, parity):
    """(vertices, triangles) of the wedges i = parity, parity + 2, ... of n (see the top)."""
    vertices, triangles = [], []
    for i in range(parity, n, 2):
        y, d = -1 + 2 * (i + 0.5) / n, 0.5 / n
        triangles.append((len(vertices), len(vertices) + 1, len(vertices) + 2))
        vertices += [(-1.0, y, 0.0), (1.0, -y + d, 0.0), (1.0, -y - d, 0.0)]
    return vertices, triangles


def cylinder_pair(family, n):
    """The meshes A and B of one workload."""
    if family == "wedges" and n >= 2:
        return wedges(n, 0), wedges(n, 1)
    if family == "sheets" and n >= 1:
        return sheet(n, 0.0, (0.0, 0.0)), sheet(n, math.radians(TURN_DEGREES), (0.37 * RADIUS / n, 0.21 * RADIUS / n))
    if family not in FAMILIES or n < 3:
        raise ValueError(f"no {family} cylinders with {n} segments")
    return (cylinder(family, n, (0.0, 0.0), 0.0),
            cylinder(family, n, OFFSET, math.radians(TURN_DEGREES)))


def write_off(file, mesh):
    """An OFF file with exact (repr) doubles, written atomically: temporary file + rename."""
    vertices, triangles = mesh
    tmp = file.with_name(f".{file.name}.{os.getpid()}.tmp")
    try:
        with open(tmp, "w", encoding="ascii") as f:
            f.write(f"OFF\n{len(vertices)} {len(triangles)} 0\n")
            f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in vertices)
            f.writelines(f"3 {a} {b} {c}\n" for a, b, c in triangles)
        os.replace(tmp, file)
    finally:
        if tmp.exists():
            tmp.unlink()


def write_pair(work, family, n):
    """([A.off, B.off], input triangles of both) in work."""
    files, triangles = [], 0
    for name, mesh in zip("AB", cylinder_pair(family, n)):
        files.append(work / f"{family}-n{n}-{name}.off")
        write_off(files[-1], mesh)
        triangles += len(mesh[1])
    return files, triangles


# ---------------------------------------------------------------------------------------------
# Running


def run_once(binary, files, threads, timeout):
    """("ok", stats), ("timeout", message) or ("failed", message) of one `arrange --stats`
    process, forked by sh (Linux keeps the largest RSS across exec: a direct child of Python
    would report at least Python's RSS) in a new session, killed as a group at the timeout."""
    cmd = ["sh", "-c", '"$@"; exit $?', "sh", binary, *map(str, files), "--stats", "--threads", str(threads)]
    try:
        p = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, errors="replace", start_new_session=True)
    except OSError as e:
        return "failed", f"cannot run {binary}: {e}"
    try:
        out, err = p.communicate(timeout=timeout or None)
    except subprocess.TimeoutExpired:
        kill_group(p)
        p.communicate()
        return "timeout", f"timed out after {timeout:g} s"
    except BaseException:  # Ctrl-C: no arrange left behind
        kill_group(p)
        raise
    stats = parse_tool_json(out) if p.returncode == 0 else None
    if stats is None or any(not isinstance(stats.get(k), (int, float)) for k in KEPT):
        return "failed", f"exit {p.returncode}, no --stats JSON with {', '.join(KEPT)}: {err.strip()[-300:]}"
    return "ok", stats


def measure(label_n, files, binaries, args, problems):
    """{(binary label, T): summary} of one workload, runs alternating between the binaries.
    A summary has "status" ok, timeout or failed; failures and count differences go to
    problems."""
    runs, ended, reference, differ = {}, {}, None, False
    for t in args.threads:
        for r in range(1, args.runs + 1):
            for label, binary in binaries:
                key = (label, t)
                if key in ended:
                    continue
                status, value = run_once(binary, files, t, args.timeout)
                if status != "ok":
                    ended[key] = {"status": status, "error": value}
                    if status == "failed":
                        problems.append(f"{label_n}: {label} binary, {t} thr: FAILED: {value}")
                    print(f"coplanar_bench: {label_n}: {label} binary, {t} thr: {value}", file=sys.stderr)
                    continue
                print(f"coplanar_bench: {label_n}: {t} thr run {r}/{args.runs} {label}: "
                      f"{value['t_total_s']:.3f} s, {value['out_triangles']:,} out tris, "
                      f"{value['peak_rss_mb']:.0f} MB", file=sys.stderr)
                counts = {k: value[k] for k in COUNTS}
                if reference is None:
                    reference = (counts, f"{label} {t} thr")
                elif counts != reference[0]:
                    differ = True
                    diff = ", ".join(f"{k} {counts[k]} vs {reference[0][k]}" for k in COUNTS
                                     if counts[k] != reference[0][k])
                    problems.append(f"{label_n}: COUNTS DIFFER: {label} {t} thr run {r}: {diff} ({reference[1]})")
                    print(f"coplanar_bench: *** {problems[-1]} ***", file=sys.stderr)
                runs.setdefault(key, []).append(value)
    result = {}
    for t in args.threads:
        for label, _ in binaries:
            key = (label, t)
            if key in ended and key not in runs:
                result[key] = ended[key]
            else:  # a timeout after some good runs still keeps them, but counts as a timeout
                best = min(runs[key], key=lambda s: s["t_total_s"])
                result[key] = {"status": "ok", **ended.get(key, {}), **{k: best[k] for k in KEPT},
                               "t_total_s_runs": [s["t_total_s"] for s in runs[key]], "best_run": best}
    return result, differ


def fit_slope(points):
    """The least-squares slope of log(seconds) against log(output triangles) over the points
    (out_triangles, seconds) with seconds > MIN_FIT_SECONDS; None for fewer than two."""
    xy = [(math.log(n), math.log(s)) for n, s in points if s > MIN_FIT_SECONDS and n > 0]
    if len({x for x, _ in xy}) < 2:
        return None
    mx, my = sum(x for x, _ in xy) / len(xy), sum(y for _, y in xy) / len(xy)
    return sum((x - mx) * (y - my) for x, y in xy) / sum((x - mx) ** 2 for x, _ in xy)


# ---------------------------------------------------------------------------------------------
# Output


def columns(threads, baseline):
    head = ["family", "n", "in tris", "out tris", "coplanar pairs", "candidate pairs"]
    for t in threads:
        head += [f"{t} thr total s", f"{t} thr {'/'.join(STAGES)} s", f"{t} thr µs/out tri", f"{t} thr peak MB"]
        if baseline:
            head += [f"{t} thr new/base"]
    return head


def row(family, n, in_tris, result, threads, baseline):
    good = [s for s in result.values() if s["status"] == "ok"]
    cells = [family, str(n), f"{in_tris:,}", f"{good[0]['out_triangles']:,}" if good else "–",
             f"{good[0]['coplanar_pairs']:,}" if good else "–", f"{good[0]['candidate_pairs']:,}" if good else "–"]
    for t in threads:
        new = result[("new", t)]
        if new["status"] != "ok":
            cells += [new["status"], "", "", ""]
        else:
            per = f"{1e6 * new['t_total_s'] / new['out_triangles']:.2f}" if new["out_triangles"] else "–"
            cells += [f"{new['t_total_s']:.3f}", "/".join(f"{new[f't_{s}_s']:.3f}" for s in STAGES), per,
                      f"{new['peak_rss_mb']:.0f}"]
        if baseline:
            base = result[("base", t)]
            ok = new["status"] == base["status"] == "ok" and base["t_total_s"] > 0
            cells += [f"{new['t_total_s'] / base['t_total_s']:.2f}" if ok else "–"]
    return cells


def draw_chart(file, curves):
    """Log-log total seconds against output triangles, one curve per (family, binary, T), each
    with a dashed slope-1 line through its smallest point; written atomically."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 6))
    for i, ((family, label, t), points) in enumerate(sorted(curves.items())):
        points = sorted(p for p in points if p[0] > 0 and p[1] > 0)
        if not points:
            continue
        color = f"C{i % 10}"
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        ax.plot(xs, ys, "o-" if label == "new" else "s:", color=color,
                label=f"{family}, {t} thr" + ("" if label == "new" else f" ({label})"))
        x0, y0 = points[0]
        ax.plot([x0, xs[-1]], [y0, y0 * xs[-1] / x0], "--", color=color, alpha=0.5, linewidth=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("output triangles")
    ax.set_ylabel("t_total_s (s)")
    ax.set_title("arrange on coplanar cylinder caps (dashed: slope 1, linear)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    tmp = file.with_name(f".{file.name}.{os.getpid()}.tmp")
    try:
        fig.savefig(tmp, format="png", dpi=110)
        os.replace(tmp, file)
    finally:
        plt.close(fig)
        if tmp.exists():
            tmp.unlink()


# ---------------------------------------------------------------------------------------------
# Command line


def int_list(lo, hi):
    one = integer(lo, hi)

    def parse(value):
        values = [one(v) for v in value.split(",")]
        if len(set(values)) != len(values):
            raise argparse.ArgumentTypeError(f"a value given twice in {value!r}")
        return values
    parse.__name__ = "list"
    return parse


def family_list(value):
    names = value.split(",")
    if any(f not in FAMILIES for f in names) or len(set(names)) != len(names):
        raise argparse.ArgumentTypeError(f"expected distinct families from {','.join(FAMILIES)}, got {value!r}")
    return [f for f in FAMILIES if f in names]


def parse_args(argv):
    ap = Parser(prog="coplanar_bench.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal digits.\n"
                       "Exit status: 0 every run ended (ran or timed out) with equal counts; 1 a failed run "
                       "or a\ncount difference; 2 a bad command line, --arrange/--baseline not executable, "
                       "or\n--work/--json/--chart not writable.")
    ap.add_argument("--arrange", type=text, default=str(REPO / "build" / "bin" / "arrange"),
                    help="the arrange binary to time (default: %(default)s)")
    ap.add_argument("--baseline", type=text, help="an older arrange binary, run alternately with --arrange")
    ap.add_argument("--families", type=family_list, default=list(FAMILIES), metavar="F[,F...]",
                    help="sheets, fans, strips, wedges or several (default: all four)")
    ap.add_argument("--sheet-sizes", type=int_list(3, MAX_N), default=[10, 30, 100, 300],
                    metavar="N[,N...]", help="cells per side of sheets, 3 to %d each (default: 10,30,100,300)" % MAX_N)
    ap.add_argument("--sizes", type=int_list(3, MAX_N), default=[100, 300, 1000, 3000, 10000],
                    metavar="N[,N...]", help=f"segments per cylinder of fans, 3 to {MAX_N} each "
                                             "(default: 100,300,1000,3000,10000; their box pairs grow as n^2: "
                                             "n = 10000 takes about a minute)")
    ap.add_argument("--strip-sizes", type=int_list(3, MAX_N), default=[100, 200, 400, 800, 1600],
                    metavar="N[,N...]", help="segments per cylinder of strips, 3 to --max-strip-n each "
                                             "(default: 100,200,400,800,1600)")
    ap.add_argument("--wedge-sizes", type=int_list(3, MAX_N), default=[20, 40, 60],
                    metavar="N[,N...]",
                    help="wedges, 3 to %d each (default: 20,40,60; 180 take seconds, more are refused)" % MAX_N)
    ap.add_argument("--max-strip-n", type=integer(3, MAX_N), default=1600,
                    help="the largest strips size accepted: their output is quadratic (default: 1600)")
    ap.add_argument("--threads", type=thread_list, default=[1, 2], metavar="T[,T...]",
                    help=f"0 (all cores) to {MAX_THREADS} each, comma-separated (default: 1,2)")
    ap.add_argument("--runs", type=integer(1, 1000), default=3,
                    help="runs per size, thread count and binary, 1 to 1000 (default: 3)")
    ap.add_argument("--timeout", type=seconds(0, 10**7), default=600,
                    help="seconds per arrange process, 0 for none (default: 600)")
    ap.add_argument("--work", type=path, default=Path(tempfile.gettempdir()) / "tritri-coplanar-bench",
                    help="where the OFF files are written (default: %(default)s)")
    ap.add_argument("--json", type=path, metavar="OUT.jsonl",
                    help="also write one JSON object per (family, n, binary, threads) here")
    ap.add_argument("--chart", type=path, metavar="OUT.png", help="also draw the log-log chart here (matplotlib)")
    args = ap.parse_args(argv)
    for option, binary in (("--arrange", args.arrange), ("--baseline", args.baseline)):
        if binary is not None and not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            ap.error(f"{option} {binary}: no such executable")
    over = [n for n in args.strip_sizes if n > args.max_strip_n]
    if "strips" in args.families and over:
        ap.error(f"--strip-sizes: {','.join(map(str, over))} above --max-strip-n {args.max_strip_n} "
                 "(strips' output grows quadratically; raise --max-strip-n to run them)")
    return args


def main(argv=None):
    args = parse_args(argv)
    binaries = [("new", args.arrange)] + ([("base", args.baseline)] if args.baseline else [])
    problems, notes, records, curves, stopped = [], [], [], {}, {}
    try:
        args.work.mkdir(parents=True, exist_ok=True)
        out = open(f"{args.json}.tmp", "w", encoding="utf-8") if args.json else None
        if args.chart:
            with open(f"{args.chart}.tmp", "w"):
                pass
            os.unlink(f"{args.chart}.tmp")
    except OSError as e:
        print(f"coplanar_bench.py: {e.filename}: cannot write ({e.strerror})", file=sys.stderr)
        return 2
    head = columns(args.threads, args.baseline)
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for family in args.families:
        sizes = {"sheets": args.sheet_sizes, "fans": args.sizes, "strips": args.strip_sizes,
                 "wedges": args.wedge_sizes}[family]
        for n in sizes:
            label_n = f"{family} n={n}"
            active = [(label, b) for label, b in binaries if (family, label) not in stopped]
            try:
                files, in_tris = write_pair(args.work, family, n)
            except OSError as e:
                print(f"coplanar_bench.py: {e.filename}: cannot write ({e.strerror})", file=sys.stderr)
                return 2
            print(f"coplanar_bench: {label_n}: {in_tris:,} input triangles", file=sys.stderr)
            result, differ = measure(label_n, files, active, args, problems) if active else ({}, False)
            for label, _ in binaries:
                for t in args.threads:
                    if (label, t) not in result:
                        result[(label, t)] = {"status": "skipped", "error": stopped[(family, label)]}
                    s = result[(label, t)]
                    if s["status"] == "timeout" and (family, label) not in stopped:
                        stopped[(family, label)] = f"after the timeout at n={n}"
                        notes.append(f"{label_n}: {label} binary, {t} thr: {s['error']}; larger {family} "
                                     f"sizes skipped for the {label} binary")
                    if s["status"] == "ok":
                        curves.setdefault((family, label, t), []).append((s["out_triangles"], s["t_total_s"]))
                    records.append({"family": family, "n": n, "files": [str(f) for f in files], "binary": label,
                                    "arrange": dict(binaries)[label], "threads": t, "runs": args.runs,
                                    "input_triangles": in_tris, **s})
            cells = row(family, n, in_tris, result, args.threads, args.baseline)
            if differ:
                cells[0] += " **COUNTS DIFFER**"
            lines.append("| " + " | ".join(cells) + " |")
            if out:
                out.writelines(json.dumps(r) + "\n" for r in records)
                out.flush()
                records.clear()
    if out:
        out.close()
        os.replace(f"{args.json}.tmp", args.json)
    order = sorted(curves, key=lambda k: (FAMILIES.index(k[0]), k[1] != "new", k[2]))
    for family, label, t in order:
        slope = fit_slope(curves[(family, label, t)])
        notes.append(f"slope {family} {t} thr{'' if label == 'new' else ' ' + label}: "
                     + (f"{slope:.2f}" if slope is not None else
                        f"n/a (fewer than 2 sizes above {MIN_FIT_SECONDS} s)")
                     + " (log total s against log out tris; 1 = linear)")
    if args.chart:
        try:
            draw_chart(args.chart, curves)
            notes.append(f"chart: {args.chart}")
        except ImportError as e:
            problems.append(f"--chart {args.chart}: no chart ({e}); install matplotlib")
        except OSError as e:
            print(f"coplanar_bench.py: {args.chart}: cannot write ({e.strerror})", file=sys.stderr)
            return 2
    print("\n".join(lines))
    print("\n" + "\n".join(f"- {line}" for line in notes + problems))
    sys.stdout.flush()
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
