#!/usr/bin/env python3
"""How often `arrange --round safe` settles on generated hard inputs, and at what cost.

usage: build-python/venv/bin/python bench/round_safe_sweep.py [INPUT ...] --out RESULTS.jsonl
           [--arrange build/bin/arrange] [--variants rot2,rot3,shift,scaled] [--max-triangles 20000]
           [--seed 1] [--threads 1] [--timeout 300] [--work DIR] [--round-max-move F]

A measurement, not a test: every outcome is recorded, none is a failure of the script.

Inputs: mesh files (.obj .off .stl .ply), folders (searched recursively for those) and
manifest CSVs (column `file`: paths relative to the CSV's folder; column `triangles`, when
present, is used as the mesh's triangle count without loading it). Default:
../shared/meshes/manifest.csv beside the checkout. Meshes with more than --max-triangles
triangles (as arrange counts them: an n-gon is n - 2) are left out. Meshes are read with
tritri.load_mesh, the loader of arrange (so run this with the Python that has the tritri
module, e.g. build-python/venv/bin/python); a mesh it cannot read gives `error` rows;
rational coordinates (n/d) are rounded to the nearest double.

Variants, written as OFF files into --work (every coordinate as Python's repr() of a float64,
which arrange reads back exactly). For a mesh M with bounding-box centre c and diagonal d:
  rot2    M and a copy of M rotated by pi about an axis through c
  rot3    M and two copies rotated by 2 pi / 3 and 4 pi / 3 about an axis through c
  shift   M and a copy rotated by 1e-7 rad about an axis through c, then translated by 1e-9 d
  scaled  rot2 with every coordinate x replaced by x * 2^-30 + 1e6 (magnitude and offset)
The axes and the direction are pseudo-random unit vectors fixed by --seed and the variant
(the same for every mesh). The copy at angle 0 is M itself, coordinates untouched.

Runs: `arrange VARIANT.off -o OUT.obj --round safe --stats --threads T` (with
`--round-max-move F` when given), one process per
variant, started through `sh` (so that peak_rss_mb is arrange's own), killed as a group
after --timeout. OUT.obj is deleted after the run; the variant files stay in --work (a temp
folder, removed at the end, unless --work is given).
Status: settled (exit 0 with --stats JSON), refused (exit 4: safe rounding did not settle),
timeout, error (any other exit, exit 0 without JSON, or an unreadable mesh).

Output: --out gets one JSON object per run: mesh (id: path relative to its folder or
manifest), variant, file (the variant OFF), in_triangles (of the variant), status,
exit_code, message (the first stderr line when not settled), wall_s (the process), and
round_passes, round_max_move_rel, round_rerouted, round_merged_input,
round_snapped_vertices, round_nudged, out_triangles (of the exact arrangement), t_total_s, peak_rss_mb (null when
arrange printed no --stats), and rounded_triangles (faces of the written mesh; null unless settled). Rows go to
RESULTS.jsonl.partial as runs finish (flushed), renamed to RESULTS.jsonl when the sweep is
done; an interrupted sweep leaves the .partial file. Progress on stderr. On stdout, a
Markdown summary per variant: counts per status; median and max of round_passes,
round_max_move_rel and t_total_s over settled runs; how many settled runs needed rerouting,
merged input vertices, snapped nearly coplanar faces or nudged vertices; max peak MB; then the
refused, timed-out and failed runs.
"""
import argparse
import csv
import json
import math
import os
import random
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args, run_collection
from cli_args import MAX_THREADS, Parser, integer, path, positive_number, seconds, text, thread_count  # noqa: E402
from run_collection import Progress, kill_group, parse_tool_json  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
DEFAULT_MANIFEST = REPO.parent / "shared" / "meshes" / "manifest.csv"
MESH_SUFFIXES = (".obj", ".off", ".stl", ".ply")
VARIANTS = ("rot2", "rot3", "shift", "scaled")
STATUSES = ("settled", "refused", "timeout", "error")
STAT_KEYS = ("round_passes", "round_max_move_rel", "round_rerouted", "round_merged_input",
             "round_snapped_vertices", "round_nudged", "out_triangles", "t_total_s", "peak_rss_mb", "rounded_triangles")
REFUSED_EXIT = 4
SCALE, OFFSET = 2.0 ** -30, 1e6
SHIFT_ANGLE, SHIFT_DISTANCE = 1e-7, 1e-9


class InputError(Exception):
    """An input that stops the sweep before it starts."""


# ---------------------------------------------------------------------------------------------
# Inputs


def manifest_rows(csv_path):
    """[(id, path, triangles or None)] of the mesh files a manifest lists."""
    with open(csv_path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        if "file" not in (reader.fieldnames or []):
            raise InputError(f"{csv_path}: a manifest needs a column named 'file'")
        rows = []
        for row in reader:
            name = (row.get("file") or "").strip()
            if not name.lower().endswith(MESH_SUFFIXES):
                continue
            count = (row.get("triangles") or "").strip()
            rows.append((name, csv_path.parent / name, int(count) if count.isdigit() else None))
    return rows


def collect(inputs):
    """[(id, path, triangles or None)] of every input mesh, sorted by id, each file once."""
    found, seen = {}, set()
    for source in inputs:
        if source.is_dir():
            rows = [(f.relative_to(source).as_posix(), f, None) for f in source.rglob("*")
                    if f.is_file() and f.name.lower().endswith(MESH_SUFFIXES)]
        elif source.is_file() and source.suffix.lower() == ".csv":
            rows = manifest_rows(source)
        elif source.is_file() and source.name.lower().endswith(MESH_SUFFIXES):
            rows = [(source.as_posix(), source, None)]
        else:
            raise InputError(f"{source}: not a mesh file ({' '.join(MESH_SUFFIXES)}), folder or manifest .csv")
        for mesh_id, file, count in rows:
            key = file.resolve()
            if key in seen:
                continue
            if not file.is_file():
                raise InputError(f"{file}: no such file (listed in {source})")
            seen.add(key)
            found[mesh_id if mesh_id not in found else file.as_posix()] = (file, count)
    return [(mesh_id, *found[mesh_id]) for mesh_id in sorted(found)]


def load(tritri, file):
    """(vertices as float tuples, triangles as index tuples) of a mesh; raises ValueError."""
    mesh = tritri.load_mesh(str(file))
    return [tuple(map(float, v)) for v in mesh["V"].tolist()], [tuple(t) for t in mesh["F"].tolist()]


# ---------------------------------------------------------------------------------------------
# Variants


def unit_vector(seed, name):
    """A pseudo-random unit vector fixed by the seed and a name."""
    rng = random.Random(f"round_safe_sweep/{seed}/{name}")
    while True:
        v = [rng.gauss(0.0, 1.0) for _ in range(3)]
        n = math.hypot(*v)
        if n > 1e-3:
            return [x / n for x in v]


def rotation(axis, angle):
    """The 3 x 3 matrix of the rotation by angle about a unit axis (Rodrigues)."""
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    t = 1.0 - c
    return ((c + x * x * t, x * y * t - z * s, x * z * t + y * s),
            (y * x * t + z * s, c + y * y * t, y * z * t - x * s),
            (z * x * t - y * s, z * y * t + x * s, c + z * z * t))


def moved(V, centre, R, shift=(0.0, 0.0, 0.0)):
    """V rotated by R about centre, then translated by shift."""
    cx, cy, cz = centre
    out = []
    for x, y, z in V:
        d = (x - cx, y - cy, z - cz)
        out.append(tuple(c + r[0] * d[0] + r[1] * d[1] + r[2] * d[2] + s
                         for c, r, s in zip(centre, R, shift)))
    return out


def variant_copies(V, names, seed):
    """{variant: [vertex list of each copy]}; every copy has the triangles of the mesh."""
    lo = [min(p[i] for p in V) for i in range(3)]
    hi = [max(p[i] for p in V) for i in range(3)]
    centre, diagonal = [(a + b) / 2 for a, b in zip(lo, hi)], math.dist(lo, hi)
    copies = {}
    if "rot2" in names or "scaled" in names:
        copies["rot2"] = [V, moved(V, centre, rotation(unit_vector(seed, "rot2"), math.pi))]
    if "rot3" in names:
        axis = unit_vector(seed, "rot3")
        copies["rot3"] = [V] + [moved(V, centre, rotation(axis, 2 * math.pi * k / 3)) for k in (1, 2)]
    if "shift" in names:
        step = [SHIFT_DISTANCE * diagonal * c for c in unit_vector(seed, "shift/direction")]
        copies["shift"] = [V, moved(V, centre, rotation(unit_vector(seed, "shift/axis"), SHIFT_ANGLE), step)]
    if "scaled" in names:
        copies["scaled"] = [[tuple(c * SCALE + OFFSET for c in p) for p in copy] for copy in copies["rot2"]]
    return {name: copies[name] for name in names}


def write_off(file, copies, F):
    """An OFF file of every copy with the triangles F, coordinates as repr() (exact)."""
    n = len(copies[0])
    lines = ["OFF", f"{n * len(copies)} {len(F) * len(copies)} 0"]
    for copy in copies:
        lines += [f"{x!r} {y!r} {z!r}" for x, y, z in copy]
    for k in range(len(copies)):
        lines += [f"3 {a + k * n} {b + k * n} {c + k * n}" for a, b, c in F]
    tmp = file.with_name(file.name + ".tmp")
    tmp.write_text("\n".join(lines) + "\n", encoding="ascii")
    os.replace(tmp, file)


# ---------------------------------------------------------------------------------------------
# Running


def first_line(stderr):
    return next((line.strip() for line in stderr.splitlines() if line.strip()), "")


def count_faces(obj):
    """The faces of a written OBJ file (its 'f' lines), or None when it cannot be read."""
    try:
        with open(obj, encoding="ascii", errors="replace") as f:
            return sum(1 for line in f if line.startswith("f "))
    except OSError:
        return None


def run_arrange(binary, file, out, threads, timeout, max_move=None, without=None):
    """(status, exit code, message, stats or None, wall seconds) of one arrange process; `without`:
    the --round-without steps (comma-separated), if any."""
    cmd = ["sh", "-c", '"$@"; exit $?', "sh", str(binary), str(file), "-o", str(out), "--round", "safe",
           "--stats", "--threads", str(threads)]
    if max_move is not None:
        cmd += ["--round-max-move", repr(max_move)]
    if without:
        cmd += ["--round-without", without]
    start = time.monotonic()
    try:
        p = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, errors="replace", start_new_session=True)
    except OSError as e:
        return "error", None, f"cannot run {binary}: {e}", None, 0.0
    try:
        stdout, stderr = p.communicate(timeout=timeout or None)
    except subprocess.TimeoutExpired:
        kill_group(p)
        try:
            p.communicate(timeout=10)
        except subprocess.TimeoutExpired:  # a descendant escaped the group, holding the pipes
            p.kill()
        return "timeout", None, f"timed out after {timeout:g} s", None, time.monotonic() - start
    except BaseException:  # Ctrl-C: no arrange left behind
        kill_group(p)
        raise
    wall = time.monotonic() - start
    stats = parse_tool_json(stdout)
    if p.returncode == 0 and stats is not None:
        stats["rounded_triangles"] = count_faces(out)
        return "settled", 0, None, stats, wall
    if p.returncode == REFUSED_EXIT:
        return "refused", p.returncode, first_line(stderr), stats, wall
    message = first_line(stderr) or (f"exit {p.returncode}" + (", no --stats JSON" if p.returncode == 0 else ""))
    return "error", p.returncode, message, stats, wall


def record(mesh_id, variant, file, triangles, status, code, message, stats, wall):
    rec = {"mesh": mesh_id, "variant": variant, "file": str(file) if file else None, "in_triangles": triangles,
           "status": status, "exit_code": code, "message": message, "wall_s": round(wall, 6)}
    rec.update({k: (stats or {}).get(k) for k in STAT_KEYS})
    return rec


class SweepProgress(Progress):
    """run_collection's progress line, counting this script's statuses."""

    def __init__(self, total):
        super().__init__(total, stream=sys.stderr)
        self.counts = dict.fromkeys(STATUSES, 0)

    def update(self, rec):
        self.done += 1
        self.counts[rec["status"]] += 1
        if rec["status"] != "settled":
            self.note(f"{rec['status']}: {rec['mesh']} {rec['variant']}: {rec['message']}")
        self.show()


def sweep_mesh(tritri, mesh_id, file, index, args, emit):
    """Generates the variants of one mesh and runs arrange on each; emit(record) per run."""
    try:
        V, F = load(tritri, file)
    except ValueError as e:
        for variant in args.variants:
            emit(record(mesh_id, variant, None, None, "error", None, f"cannot read {file}: {e}", None, 0.0))
        return
    folder = args.work / f"{index:04d}_{''.join(c if c.isalnum() or c in '.-' else '_' for c in mesh_id)}"
    folder.mkdir(parents=True, exist_ok=True)
    for variant, copies in variant_copies(V, args.variants, args.seed).items():
        off = folder / f"{variant}.off"
        write_off(off, copies, F)
        out = folder / f"{variant}.out.obj"
        result = run_arrange(args.arrange, off, out, args.threads, args.timeout, args.round_max_move)
        for leftover in (out, out.with_name(out.name + ".provenance.csv")):
            leftover.unlink(missing_ok=True)
        emit(record(mesh_id, variant, off, len(F) * len(copies), *result))


# ---------------------------------------------------------------------------------------------
# Summary


def fmt(values, spec):
    return (format(statistics.median(values), spec), format(max(values), spec)) if values else ("–", "–")


def shorten(message, width=110):
    return message if len(message) <= width else message[:width - 1] + "…"


def summary(rows, args, meshes):
    lines = [f"arrange --round safe on {meshes} meshes of at most {args.max_triangles:,} triangles; seed "
             f"{args.seed}, {args.threads} thread(s), timeout {args.timeout:g} s"
             + (f", --round-max-move {args.round_max_move:g}" if args.round_max_move else "")
             + f"; {args.arrange}", "",
             "| variant | runs | settled | refused | timeout | error | passes median | passes max "
             "| max move rel median | max move rel max | total s median | total s max | rerouted | merged input "
             "| snapped | nudged | peak MB max |", "|---|" + "---:|" * 16]
    for variant in args.variants:
        runs = [r for r in rows if r["variant"] == variant]
        ok = [r for r in runs if r["status"] == "settled"]
        counts = [str(sum(r["status"] == s for r in runs)) for s in STATUSES]
        used = [str(sum((r[k] or 0) > 0 for r in ok))
                for k in ("round_rerouted", "round_merged_input", "round_snapped_vertices", "round_nudged")]
        peak = [r["peak_rss_mb"] for r in ok if r["peak_rss_mb"] is not None]
        cells = [variant, str(len(runs)), *counts, *fmt([r["round_passes"] for r in ok], "g"),
                 *fmt([r["round_max_move_rel"] for r in ok], ".2e"), *fmt([r["t_total_s"] for r in ok], ".3f"),
                 *used, f"{max(peak):.0f}" if peak else "–"]
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("\nrerouted / merged input / snapped / nudged: settled runs whose last resort "
                 "rerouted vertices, merged input vertices, snapped nearly coplanar faces "
                 "or nudged vertices "
                 "(round_* > 0). Messages are cut; --out has them whole.")
    for status, title in (("refused", "Refused"), ("timeout", "Timed out"), ("error", "Errors")):
        bad = [r for r in rows if r["status"] == status]
        lines.append(f"\n{title} ({len(bad)}):" + ("" if bad else " none"))
        lines += [f"- {r['variant']} {r['mesh']} ({r['in_triangles']} triangles): {shorten(r['message'])}"
                  for r in bad]
    return "\n".join(lines)


# ---------------------------------------------------------------------------------------------
# Command line


def variant_list(value):
    names = value.split(",")
    unknown = [n for n in names if n not in VARIANTS]
    if unknown:
        raise argparse.ArgumentTypeError(f"unknown variant {unknown[0]!r} in {value!r} (variants: "
                                         f"{', '.join(VARIANTS)})")
    if len(set(names)) != len(names):
        raise argparse.ArgumentTypeError(f"a variant given twice in {value!r}")
    return [v for v in VARIANTS if v in names]


def parse_args(argv):
    ap = Parser(prog="round_safe_sweep.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter,
                epilog="An option that takes a value may be given once; numbers are plain decimal digits.\n"
                       "Exit status: 0 the sweep ran (whatever the statuses of the runs); 1 a file could not be "
                       "written\nmid-sweep; 2 a bad command line, a missing input, --arrange not executable, "
                       "no tritri module,\n--out or --work not writable; 130 interrupted (the finished runs are in "
                       "RESULTS.jsonl.partial).")
    ap.add_argument("input", type=path, nargs="*", metavar="INPUT",
                    help=f"mesh files, folders or manifest CSVs (default: {DEFAULT_MANIFEST})")
    ap.add_argument("--out", type=path, required=True, metavar="RESULTS.jsonl",
                    help="one JSON object per run (replaced at the end)")
    ap.add_argument("--arrange", type=text, default=str(REPO / "build" / "bin" / "arrange"),
                    help="the arrange binary (default: %(default)s)")
    ap.add_argument("--variants", type=variant_list, default=list(VARIANTS), metavar="NAME[,NAME...]",
                    help=f"a comma-separated subset of {','.join(VARIANTS)} (default: all)")
    ap.add_argument("--max-triangles", type=integer(1, 10**9), default=20000, metavar="N",
                    help="leave out meshes with more triangles, 1 to 1000000000 (default: 20000)")
    ap.add_argument("--seed", type=integer(0, 10**9), default=1,
                    help="fixes the rotation axes and the shift direction, 0 to 1000000000 (default: 1)")
    ap.add_argument("--threads", type=thread_count, default=1,
                    help=f"arrange --threads: 0 (all cores) to {MAX_THREADS} (default: 1)")
    ap.add_argument("--timeout", type=seconds(0, 10**7), default=300,
                    help="seconds per arrange process, 0 for none (default: 300)")
    ap.add_argument("--work", type=path, help="keep the variant files here (default: a temp folder, removed)")
    ap.add_argument("--round-max-move", type=positive_number, metavar="F",
                    help="arrange --round-max-move: the largest move accepted, a fraction of the diagonal "
                         "(default: arrange's, a 64th)")
    args = ap.parse_args(argv)
    if not (os.path.isfile(args.arrange) and os.access(args.arrange, os.X_OK)):
        ap.error(f"--arrange {args.arrange}: no such executable")
    try:
        args.meshes = collect(args.input or [DEFAULT_MANIFEST])
    except (InputError, OSError, UnicodeDecodeError) as e:
        ap.error(f"input: {e}")
    return args, ap


def main(argv=None):
    args, ap = parse_args(argv)
    try:
        import tritri
        tritri.load_mesh  # a folder named tritri (the checkout's headers) is not the module
    except (ImportError, AttributeError) as e:
        ap.error(f"cannot import tritri.load_mesh ({e}): run with build-python/venv/bin/python or "
                 "pip install . first")
    selected = []
    for mesh_id, file, count in args.meshes:
        if count is None:
            try:
                count = len(load(tritri, file)[1])
            except ValueError:
                count = 0  # kept: its rows say why it cannot be read
        if count <= args.max_triangles:
            selected.append((mesh_id, file))
    temporary = args.work is None
    partial = Path(f"{args.out}.partial")
    try:
        args.work = Path(tempfile.mkdtemp(prefix="round-safe-sweep-")) if temporary else args.work
        args.work.mkdir(parents=True, exist_ok=True)
        out = open(partial, "w", encoding="utf-8")
    except OSError as e:
        print(f"round_safe_sweep.py: {e.filename}: cannot write ({e.strerror})", file=sys.stderr)
        return 2
    rows, progress = [], SweepProgress(len(selected) * len(args.variants))
    print(f"round_safe_sweep: {len(selected)} of {len(args.meshes)} meshes (at most {args.max_triangles} "
          f"triangles) x {len(args.variants)} variants; variant files in {args.work}", file=sys.stderr)

    def emit(rec):
        rows.append(rec)
        out.write(json.dumps(rec) + "\n")
        out.flush()
        progress.update(rec)

    previous_term = signal.signal(signal.SIGTERM, raise_interrupt)
    try:
        for i, (mesh_id, file) in enumerate(selected):
            sweep_mesh(tritri, mesh_id, file, i, args, emit)
        out.close()
        os.replace(partial, args.out)
        status = 0
    except KeyboardInterrupt:
        out.close()
        progress.note(f"round_safe_sweep: interrupted after {progress.done} of {progress.total} runs; "
                      f"they are in {partial}")
        status = 130
    except OSError as e:  # the work folder or the results file, mid-sweep
        out.close()
        progress.note(f"round_safe_sweep: {e.filename or args.work}: cannot write ({e.strerror}); "
                      f"the finished runs are in {partial}")
        status = 1
    finally:
        signal.signal(signal.SIGTERM, previous_term)
        progress.finish()
        if temporary:
            shutil.rmtree(args.work, ignore_errors=True)
    print(summary(rows, args, len(selected)))
    sys.stdout.flush()
    return status


def raise_interrupt(signum, frame):
    raise KeyboardInterrupt


if __name__ == "__main__":
    sys.exit(main())
