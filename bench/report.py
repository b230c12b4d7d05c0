#!/usr/bin/env python3
"""Report of a collection run: a Markdown (and HTML) table per model, two PNG charts, pictures.

usage: bench/report.py RESULTS.jsonl [MORE.jsonl ...] --out DIR [--title TEXT]
           [--thumbnails MESHES [--arrange PATH] [--thumb-timeout SECONDS]]

Reads the JSON lines written by run_collection.py (several files, e.g. one per shard, are
merged; when a model appears more than once the last line wins) and writes, each atomically:
  DIR/report.md          per-model table (input vertices, intersection points, classification
                         and total time of tritri and native, tritri/native ratios, result),
                         totals, and the lists of disagreements, errors, crashes and time-outs
  DIR/time_classes.png   models per time class, tritri and native side by side
  DIR/times_sorted.png   both classifiers' times, log scale, models sorted by tritri time
  DIR/report.html        the same as report.md, a static page (no server, no script)
  DIR/thumbs/MODEL.png   with --thumbnails: a picture per model (bench/render.py: the
                         arrangement shaded per input file, intersection curves in red), shown
                         in report.md's section "Models", disagreements and failures first,
                         then the slowest; the timing table becomes "Times per model". MESHES
                         is the folder or manifest CSV given to run_collection.py (the root
                         of the records' relative `files`). A model arrange fails on, or that
                         timed out, is drawn from its input alone; a picture that cannot be
                         made is a note in the report, never a failure of the report.
Exit status: 0 on success, 2 for a bad command line (an empty value, an option given twice)
or a missing or malformed results file (with its line number), a missing MESHES or arrange,
1 when the charts could not be drawn (report.md is still written).
"""
import json
import os
import re
import statistics
import sys
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args
from atomic_write import write_atomic  # noqa: E402
from cli_args import Parser, path, seconds, text  # noqa: E402  (after the line above)
from report_html import markdown_to_html  # noqa: E402

DEFAULT_ARRANGE = Path(__file__).resolve().parent.parent / "build" / "bin" / "arrange"

STATUSES = ("agree", "disagree", "error", "crash", "timeout")
CLASSIFIERS = ("tritri", "native")
STAGES = (("t_classify_s", "classification"), ("t_total_s", "total"))
# Upper bounds (seconds) of the time classes; the last class is open.
CLASS_EDGES = (0.01, 0.1, 1, 10, 60)
CLASS_LABELS = ("<0.01 s", "0.01–0.1 s", "0.1–1 s", "1–10 s", "10–60 s", ">60 s")
COLORS = {"tritri": "tab:blue", "native": "tab:orange"}
THUMB_SIZE, THUMB_MAX_FACES = 320, 50_000
# The order of the section "Models": disagreements and failures first.
STATUS_ORDER = {"disagree": 0, "crash": 1, "error": 2, "timeout": 3, "agree": 4}


class ResultsError(Exception):
    pass


# ---------------------------------------------------------------------------------------------
# Reading


def read_results(paths):
    """{model: record}, the last line of a model winning."""
    records = {}
    for path in paths:
        try:
            text = Path(path).read_text(encoding="utf-8")
        except FileNotFoundError:
            raise ResultsError(f"{path}: no such results file") from None
        except (OSError, UnicodeDecodeError) as e:
            raise ResultsError(f"{path}: cannot read: {e}") from None
        for number, line in enumerate(text.splitlines(), 1):
            if not line.strip():
                continue
            rec = parse_line(line, f"{path}:{number}")
            records[rec["model"]] = rec
    return records


def parse_line(line, where):
    try:
        rec = json.loads(line)
    except ValueError as e:
        raise ResultsError(f"{where}: malformed results line: {e}") from None
    if not isinstance(rec, dict):
        raise ResultsError(f"{where}: malformed results line: not a JSON object")
    if not isinstance(rec.get("model"), str):
        raise ResultsError(f"{where}: malformed results line: no 'model' string")
    if rec.get("status") not in STATUSES:
        raise ResultsError(f"{where}: malformed results line: 'status' is "
                           f"{rec.get('status')!r}, expected one of {', '.join(STATUSES)}")
    return rec


def stage_time(rec, classifier, key):
    value = (rec.get(classifier) or {}).get(key)
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else None


def times(rec, key):
    """(tritri, native) seconds of one stage, or None unless both are known."""
    t, n = (stage_time(rec, c, key) for c in CLASSIFIERS)
    return (t, n) if t is not None and n is not None else None


# ---------------------------------------------------------------------------------------------
# Markdown


def fmt_s(t):
    if t is None:
        return "–"
    return f"{t:.0f}" if t >= 100 else f"{t:#.3g}"  # three significant digits, zeros kept


def fmt_ratio(pair):
    if pair is None or pair[1] <= 0:
        return "–"
    return f"{pair[0] / pair[1]:.2f}"


def fmt_int(value):
    return str(value) if isinstance(value, int) and not isinstance(value, bool) else "–"


def md_cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def result_cell(rec):
    status = rec["status"]
    if status == "disagree":
        return "**disagree**"
    if status == "crash":
        return f"crash ({rec.get('signal', 'signal')})"
    if status == "timeout":
        return f"time-out ({fmt_s(rec.get('timeout_s') or rec.get('wall_s'))} s)"
    if status == "error":
        return f"error (exit {rec.get('exit_code')})"
    return status


def model_row(rec):
    cls, tot = times(rec, "t_classify_s"), times(rec, "t_total_s")
    cells = [rec["model"], fmt_int(rec.get("in_vertices")), fmt_int(rec.get("intersection_points")),
             fmt_s(cls and cls[0]), fmt_s(cls and cls[1]), fmt_ratio(cls),
             fmt_s(tot and tot[0]), fmt_s(tot and tot[1]), fmt_ratio(tot), result_cell(rec)]
    return "| " + " | ".join(md_cell(c) for c in cells) + " |"


MODEL_HEADER = ("| model | input vertices | intersection points | tritri classify (s) "
                "| native classify (s) | ratio | tritri total (s) | native total (s) "
                "| ratio total | result |")


def totals(records):
    counts = {s: sum(1 for r in records if r["status"] == s) for s in STATUSES}
    sums = {}
    for key, _ in STAGES:
        pairs = [p for p in (times(r, key) for r in records) if p is not None]
        ratios = [t / n for t, n in pairs if n > 0]
        sums[key] = {"models": len(pairs), "tritri": sum(t for t, _ in pairs),
                     "native": sum(n for _, n in pairs),
                     "median_ratio": statistics.median(ratios) if ratios else None}
    return counts, sums


def last_line(text):
    lines = [l for l in (text or "").strip().splitlines() if l.strip()]
    return lines[-1].strip() if lines else ""


def problem_lists(records):
    out = []
    sections = (("disagree", "Disagreements"), ("error", "Errors"), ("crash", "Crashes"),
                ("timeout", "Time-outs"))
    for status, title in sections:
        bad = [r for r in records if r["status"] == status]
        if not bad:
            continue
        out += ["", f"## {title} ({len(bad)})", ""]
        for r in bad:
            if status == "disagree":
                diffs = r.get("differences") or ["(no differences listed)"]
                out.append(f"- `{r['model']}`")
                out += [f"  - {md_cell(d)}" for d in diffs]
            elif status == "timeout":
                out.append(f"- `{r['model']}`: killed after {fmt_s(r.get('wall_s'))} s")
            else:
                what = (r.get("signal") if status == "crash" else f"exit code {r.get('exit_code')}")
                detail = r.get("note") or last_line(r.get("stderr_tail"))
                out.append(f"- `{r['model']}`: {what}" + (f": {md_cell(detail)}" if detail else ""))
    return out


def render_markdown(records, sources, title, charts, thumbs=None):
    counts, sums = totals(records)
    lines = [f"# {title}", "",
             f"From {', '.join(f'`{s}`' for s in sources)}. Times are seconds; ratio = tritri "
             "time / native time (below 1: tritri is faster). Classification is the "
             "classification stage alone; total is the whole pipeline run.", "",
             "## Totals", "",
             "| models | agree | disagree | errors | crashes | time-outs |",
             "|---:|---:|---:|---:|---:|---:|",
             f"| {len(records)} | " + " | ".join(str(counts[s]) for s in STATUSES) + " |", "",
             "| stage | models timed | tritri (s) | native (s) | ratio of sums | median ratio |",
             "|---|---:|---:|---:|---:|---:|"]
    for key, name in STAGES:
        s = sums[key]
        median = "–" if s["median_ratio"] is None else f"{s['median_ratio']:.2f}"
        lines.append(f"| {name} | {s['models']} | {fmt_s(s['tritri'])} | {fmt_s(s['native'])} "
                     f"| {fmt_ratio((s['tritri'], s['native']))} | {median} |")
    if charts:
        lines += ["", "## Charts", ""] + [f"![{alt}]({name})" for name, alt in charts]
    if thumbs is not None:
        lines += gallery(records, thumbs)
    lines += ["", "## Times per model" if thumbs is not None else "## Models", "", MODEL_HEADER,
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    lines += [model_row(r) for r in records]
    lines += problem_lists(records)
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# Thumbnails


GALLERY_HEADER = ("| picture | model | result | input vertices | intersection points "
                  "| output triangles | curve edges | time (s) | note |")


def total_time(rec):
    t = stage_time(rec, "tritri", "t_total_s")
    if t is None and isinstance(rec.get("wall_s"), (int, float)):
        t = float(rec["wall_s"])
    return t


def gallery_order(records):
    """Disagreements and failures first, then the slowest first, then by name."""
    return sorted(records, key=lambda r: (STATUS_ORDER[r["status"]], -(total_time(r) or 0),
                                          r["model"]))


def gallery(records, thumbs):
    lines = ["", "## Models", "",
             "One picture per model (`bench/render.py`): the arrangement shaded per input file, "
             "intersection curves in red (thin and faint where hidden). Disagreements and "
             "failures first, then the slowest. Time: tritri's total time, or the run's wall "
             "time when it failed.", "",
             GALLERY_HEADER, "|---|---|---|---:|---:|---:|---:|---:|---|"]
    for r in gallery_order(records):
        t = thumbs.get(r["model"], {})
        alt = re.sub(r"[\[\]]", "", r["model"])
        pic = f"[![{alt}](thumbs/{t['file']})](thumbs/{t['file']})" if t.get("file") else "–"
        cells = [pic, f"`{r['model']}`", result_cell(r), fmt_int(r.get("in_vertices")),
                 fmt_int(r.get("intersection_points")), fmt_int(t.get("out_triangles")),
                 fmt_int(t.get("curve_edges")), fmt_s(total_time(r)), t.get("note", "")]
        lines.append("| " + " | ".join(md_cell(c) for c in cells) + " |")
    return lines


def thumb_name(model, taken):
    """A file name for the model's picture: its id with every other character than letters,
    digits, '.', '-' and '_' made '_', unique within the report."""
    name = re.sub(r"[^A-Za-z0-9._-]+", "_", model).strip("._") or "model"
    candidate, n = name, 1
    while candidate.lower() in taken:
        n += 1
        candidate = f"{name}-{n}"
    taken.add(candidate.lower())
    return candidate + ".png"


def model_files(rec, root):
    files = rec.get("files")
    if not isinstance(files, list) or not files or not all(isinstance(f, str) and f for f in files):
        return None
    return [Path(f) if Path(f).is_absolute() else root / f for f in files]


def make_thumbnails(records, root, folder, arrange, timeout, log=sys.stderr):
    """{model: {"file", "out_triangles", "curve_edges", "note"}}; files in folder; stale
    pictures of earlier runs removed. Never raises for one model's failure."""
    import render  # numpy and matplotlib: only when pictures are wanted
    folder.mkdir(exist_ok=True)
    thumbs, taken, start = {}, set(), time.monotonic()
    for number, r in enumerate(records, 1):
        files = model_files(r, root)
        missing = [f for f in files or [] if not f.is_file()]
        if files is None or missing:
            info = {"note": "no picture: the record names no files" if files is None else
                    f"no picture: no such file {', '.join(map(str, missing))}"}
        else:
            try:
                info = thumbnail(render, r, files, folder, thumb_name(r["model"], taken),
                                 arrange, timeout)
            except ImportError:
                raise
            except Exception as e:  # noqa: BLE001  one model's picture never fails the report
                info = {"note": f"no picture: {type(e).__name__}: {e}"}
        info["note"] = info.get("note", "").replace(f"{root}{os.sep}", "")  # shorter
        thumbs[r["model"]] = info
        if number % 100 == 0:
            print(f"report.py: pictures of {number} of {len(records)} models", file=log)
    made = {t["file"] for t in thumbs.values() if t.get("file")}
    for old in folder.glob("*.png"):
        if old.name not in made:
            old.unlink()
    failed = sum(1 for t in thumbs.values() if not t.get("file"))
    print(f"report.py: {len(made)} pictures in {folder} ({time.monotonic() - start:.1f} s)"
          + (f", {failed} models without one (see the report)" if failed else ""), file=log)
    return thumbs


def thumbnail(render, rec, files, folder, name, arrange, timeout):
    """One model's picture: the arrangement, or its input alone when arrange fails or the run
    timed out. Its gallery entry."""
    try:
        if rec["status"] == "timeout":
            raise render.ArrangeError("the run timed out")
        summary = render.render(files, folder / name, arrange, THUMB_SIZE, timeout=timeout,
                                legend=False, max_faces=THUMB_MAX_FACES)
        return {"file": name, "out_triangles": summary["out_triangles"],
                "curve_edges": summary["curve_edges"], "note": summary["warning"] or ""}
    except render.ArrangeError as e:
        try:
            render.draw_inputs(files, folder / name, THUMB_SIZE, legend=False,
                               max_faces=THUMB_MAX_FACES)
            return {"file": name, "note": f"input only: {e}"}
        except render.RenderError as e2:
            return {"note": f"no picture: {e} (nor of the input alone: {e2})"}
    except render.RenderError as e:
        return {"note": f"no picture: {e}"}


# ---------------------------------------------------------------------------------------------
# Charts


def time_class(t):
    for i, edge in enumerate(CLASS_EDGES):
        if t < edge:
            return i
    return len(CLASS_EDGES)


def class_counts(records, classifier, key):
    counts = [0] * len(CLASS_LABELS)
    for r in records:
        t = stage_time(r, classifier, key)
        if t is not None:
            counts[time_class(t)] += 1
    return counts


def plot_time_classes(plt, records, path):
    fig, axes = plt.subplots(1, len(STAGES), figsize=(12, 4.5), sharey=True)
    width = 0.4
    for ax, (key, name) in zip(axes, STAGES):
        xs = range(len(CLASS_LABELS))
        for i, c in enumerate(CLASSIFIERS):
            counts = class_counts(records, c, key)
            bars = ax.bar([x + (i - 0.5) * width for x in xs], counts, width, label=c,
                          color=COLORS[c])
            ax.bar_label(bars, labels=[str(n) if n else "" for n in counts], fontsize=8)
        ax.set_xticks(list(xs), CLASS_LABELS, rotation=20)
        ax.set_title(f"{name} time")
        ax.set_xlabel("time class")
    axes[0].set_ylabel("models")
    axes[0].legend()
    fig.suptitle(f"Models per time class ({len(records)} models; failed runs have no time)")
    fig.tight_layout()
    save_atomic(fig, path)
    plt.close(fig)


def plot_sorted_times(plt, records, path):
    from matplotlib.ticker import MaxNLocator
    fig, axes = plt.subplots(1, len(STAGES), figsize=(12, 4.5))
    for ax, (key, name) in zip(axes, STAGES):
        pairs = sorted(p for p in (times(r, key) for r in records) if p is not None)
        floor = 1e-7  # a zero time cannot be drawn on a log scale
        xs = range(1, len(pairs) + 1)
        marker = "o" if len(pairs) <= 50 else None
        for i, c in enumerate(CLASSIFIERS):
            ax.plot(xs, [max(p[i], floor) for p in pairs], label=c, color=COLORS[c],
                    marker=marker, markersize=3, linewidth=1.2)
        ax.set_yscale("log")
        ax.xaxis.set_major_locator(MaxNLocator(integer=True))
        ax.set_xlabel("models, sorted by tritri time")
        ax.set_ylabel("seconds (log scale)")
        ax.set_title(f"{name} time ({len(pairs)} models)")
        ax.grid(True, which="both", alpha=0.3)
        if pairs:
            ax.legend()
    fig.tight_layout()
    save_atomic(fig, path)
    plt.close(fig)


def save_atomic(fig, path):
    write_atomic(path, lambda f: fig.savefig(f, format="png", dpi=110))


# ---------------------------------------------------------------------------------------------


def main(argv=None):
    ap = Parser(prog="report.py", description=__doc__.split("\n\n")[0],
                epilog="An option that takes a value may be given once; exit status 2 for a bad "
                       "command line or results file.")
    ap.add_argument("results", nargs="+", type=text, help="JSON-lines files written by run_collection.py")
    ap.add_argument("--out", required=True, type=path, help="output folder (created)")
    ap.add_argument("--title", type=text, default="tritri vs native: collection report")
    ap.add_argument("--thumbnails", type=path, metavar="MESHES",
                    help="draw a picture per model into DIR/thumbs/; MESHES is the folder or "
                         "manifest CSV given to run_collection.py")
    ap.add_argument("--arrange", type=path, default=DEFAULT_ARRANGE,
                    help="the arrange tool for the pictures (default: %(default)s)")
    ap.add_argument("--thumb-timeout", type=seconds(0, 10**7), default=120,
                    help="seconds arrange may take per picture, 0 for none (default: 120)")
    args = ap.parse_args(argv)
    if args.thumbnails is not None:
        if not args.thumbnails.exists():
            ap.error(f"--thumbnails {args.thumbnails}: no such folder or manifest")
        if not os.access(args.arrange, os.X_OK) or args.arrange.is_dir():
            ap.error(f"--arrange {args.arrange}: no such executable (build it: cmake --build "
                     "build --target arrange)")
    try:
        records = sorted(read_results(args.results).values(), key=lambda r: r["model"])
    except ResultsError as e:
        print(f"report.py: {e}", file=sys.stderr)
        return 2
    try:
        args.out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        print(f"report.py: --out {args.out}: cannot create the folder ({e})", file=sys.stderr)
        return 2

    charts, status = [], 0
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        plot_time_classes(plt, records, args.out / "time_classes.png")
        plot_sorted_times(plt, records, args.out / "times_sorted.png")
        charts = [("time_classes.png", "models per time class"),
                  ("times_sorted.png", "sorted times, log scale")]
    except ImportError as e:
        print(f"report.py: no charts ({e}); install matplotlib: python3 -m pip install "
              "matplotlib", file=sys.stderr)
        status = 1

    thumbs = None
    if args.thumbnails is not None:
        root = args.thumbnails if args.thumbnails.is_dir() else args.thumbnails.parent
        try:
            thumbs = make_thumbnails(records, root, args.out / "thumbs", args.arrange,
                                     args.thumb_timeout)
        except ImportError as e:
            print(f"report.py: no pictures ({e}); install matplotlib", file=sys.stderr)
            thumbs, status = {}, 1

    markdown = render_markdown(records, args.results, args.title, charts, thumbs)
    write_atomic(args.out / "report.md", lambda f: f.write(markdown.encode("utf-8")))
    page = markdown_to_html(markdown, args.title)
    write_atomic(args.out / "report.html", lambda f: f.write(page.encode("utf-8")))
    counts, _ = totals(records)
    print(f"report.py: wrote {args.out / 'report.md'} and report.html: {len(records)} models, "
          + ", ".join(f"{n} {s}" for s, n in counts.items()))
    return status


if __name__ == "__main__":
    sys.exit(main())
