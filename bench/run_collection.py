#!/usr/bin/env python3
"""Run tritri-compare on every model of a collection, one process per model, and append one
JSON line per model to a results file (see bench/README.md, "Collection runs").

usage: bench/run_collection.py DIR_OR_MANIFEST --out results.jsonl [--tool PATH] [--jobs N]
           [--timeout SECONDS] [--shard K/N] [--pattern GLOB ...] [--pairs] [--pairs-dir DIR]
           [--retry STATUS ...] [--list]

Input: a folder (searched recursively) or a manifest CSV whose column `file` holds paths
relative to the CSV's folder. A model is one file; with --pairs, MCUT pairs
(src-meshNNN.off + cut-meshNNN.off in one folder) are one model of two files, and the EMBER
pairs of an ember_cases_subset.json found in the input are built (by make_ember_pairs.py)
into --pairs-dir and added as models `pairs/ember-A-B.off`.

Each line is the tool's JSON plus: model (stable id: path(s) relative to the input root,
joined by " + "), files, status (agree, disagree, error, crash, timeout), exit_code, signal
(crash only), wall_s, stderr_tail (when not agree). A crash or a time-out is recorded, never
fatal. Models already in --out are skipped, so an interrupted run resumes where it stopped.
--shard K/N keeps the models whose index i in the sorted list has i % N == K - 1.

Exit status: 0 when every selected model has a line in --out, 2 for a usage or input error,
130 when interrupted (finished models are kept).
"""
import argparse
import concurrent.futures
import csv
import fnmatch
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path

sys.dont_write_bytecode = True  # no bench/__pycache__ for cli_args
from cli_args import Parser, integer, path, seconds, text  # noqa: E402  (after the line above)

REPO_ROOT = Path(__file__).resolve().parent.parent
DEFAULT_TOOL = REPO_ROOT / "build" / "bin" / "tritri-compare"
DEFAULT_PATTERNS = ["*.obj", "*.off", "*.stl", "*.ply"]
STATUSES = ("agree", "disagree", "error", "crash", "timeout")
STDERR_TAIL_CHARS = 2000
MAX_JOBS, MAX_SHARDS, MAX_TIMEOUT_S = 1024, 1000000, 10**7
MCUT_NAME = re.compile(r"^(src|cut)-mesh(\d+)\.off$", re.IGNORECASE)
EMBER_CASES = "ember_cases_subset.json"
EMBER_ID_DIR = "pairs"  # the folder upstream_reference.jsonl uses for combined pairs


class InputError(Exception):
    """A problem with the command line or the input that stops the run before it starts."""


@dataclass(frozen=True)
class Model:
    id: str                  # stable: path(s) relative to the input root
    files: tuple             # Paths passed to the tool, in order
    ember_cases: Path = None  # set for EMBER pairs: built on demand from this file


# ---------------------------------------------------------------------------------------------
# Collection: files -> models


def relative_id(path, root):
    return Path(os.path.relpath(path, root)).as_posix()


def file_label(path, root):
    """A file as recorded: relative to the input root, absolute when outside it (EMBER pairs)."""
    rel = relative_id(path, root)
    return str(Path(path).resolve()) if rel.startswith("../") else rel


def matches(name, patterns):
    return any(fnmatch.fnmatch(name.lower(), p.lower()) for p in patterns)


def list_input_files(source, exclude=None):
    """(root, every file of the input, sorted). Files under `exclude` are left out."""
    source = Path(source)
    if source.is_dir():
        files = [p for p in source.rglob("*") if p.is_file()]
        if exclude is not None:
            exclude = exclude.resolve()
            files = [p for p in files if exclude not in p.resolve().parents]
        return source, sorted(files, key=lambda p: relative_id(p, source))
    if source.is_file() and source.suffix.lower() == ".csv":
        root = source.parent
        with open(source, newline="") as f:
            reader = csv.DictReader(f)
            if "file" not in (reader.fieldnames or []):
                raise InputError(f"{source}: a manifest needs a column named 'file'")
            names = [row["file"].strip() for row in reader if (row.get("file") or "").strip()]
        return root, sorted({root / n for n in names}, key=lambda p: relative_id(p, root))
    raise InputError(f"{source}: neither a folder nor a manifest .csv file")


def ember_models(cases_json, pairs_dir):
    """The EMBER pairs of a cases file, as models whose file is built later into pairs_dir."""
    try:
        names = [f"ember-{c['id_a']}-{c['id_b']}.off" for c in json.loads(cases_json.read_text())]
    except (ValueError, KeyError, TypeError) as e:
        raise InputError(f"{cases_json}: not a list of EMBER cases ({e!r})") from e
    return [Model(f"{EMBER_ID_DIR}/{n}", (pairs_dir / n,), cases_json) for n in names]


def collect_models(source, patterns, pairs=False, pairs_dir=None):
    """The sorted list of models of a folder or manifest."""
    root, files = list_input_files(source, exclude=pairs_dir if pairs else None)
    singles, mcut = [], {}
    for f in files:
        if not matches(f.name, patterns):
            continue
        m = MCUT_NAME.match(f.name) if pairs else None
        if m:
            mcut.setdefault((f.parent, m.group(2)), {})[m.group(1).lower()] = f
        else:
            singles.append(f)
    models = [Model(relative_id(f, root), (f,)) for f in singles]
    for group in mcut.values():
        if "src" in group and "cut" in group:
            ids = [relative_id(group[k], root) for k in ("src", "cut")]
            models.append(Model(" + ".join(ids), (group["src"], group["cut"])))
        else:  # a lone half of a pair is an ordinary model
            models += [Model(relative_id(f, root), (f,)) for f in group.values()]
    if pairs:
        known = {m.id for m in models}
        for cases in (f for f in files if f.name == EMBER_CASES):
            models += [m for m in ember_models(cases, pairs_dir) if m.id not in known]
    return sorted(models, key=lambda m: m.id)


def select_shard(models, shard):
    k, n = shard
    return [m for i, m in enumerate(models) if i % n == k - 1]


def parse_shard(value):
    m = re.fullmatch(r"([0-9]+)/([0-9]+)", value)
    if not m or not 1 <= int(m.group(1)) <= int(m.group(2)) <= MAX_SHARDS:
        raise argparse.ArgumentTypeError(f"expected K/N with 1 <= K <= N <= {MAX_SHARDS}, got '{value}'")
    return int(m.group(1)), int(m.group(2))


def build_ember_pairs(cases_json, pairs_dir, names):
    """Runs make_ember_pairs.py (found beside the meshes folder) into pairs_dir unless every
    file is already there. Files are moved in complete, so concurrent shards are safe."""
    if all((pairs_dir / n).is_file() for n in names):
        return
    script = cases_json.resolve().parent.parent.parent / "tools" / "make_ember_pairs.py"
    reads_from = script.parent.parent / "meshes" / "thingi10k"
    if not script.is_file() or reads_from.resolve() != cases_json.resolve().parent:
        raise InputError(f"{cases_json}: cannot build the EMBER pairs: expected "
                         f"{script} (which reads ../meshes/thingi10k)")
    print(f"run_collection: building the EMBER pairs of {cases_json} into {pairs_dir}",
          file=sys.stderr)
    pairs_dir.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=".building-", dir=pairs_dir))
    try:
        subprocess.run([sys.executable, str(script), str(tmp)], check=True,
                       stdout=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
        for n in names:
            os.replace(tmp / n, pairs_dir / n)
    except (OSError, subprocess.CalledProcessError) as e:
        raise InputError(f"building the EMBER pairs into {pairs_dir} failed: {e}") from e
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


# ---------------------------------------------------------------------------------------------
# Running one model


class LiveProcesses:
    """The tool processes currently running, so that an interrupt can kill them all."""

    def __init__(self):
        self._lock = threading.Lock()
        self._procs = set()
        self.stopping = False

    def add(self, proc):
        with self._lock:
            if not self.stopping:
                self._procs.add(proc)
                return True
        kill_group(proc)
        return False

    def discard(self, proc):
        with self._lock:
            self._procs.discard(proc)

    def kill_all(self):
        with self._lock:
            self.stopping = True
            procs = list(self._procs)
        for p in procs:
            kill_group(p)


def kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)  # start_new_session: the group id is the pid
    except (ProcessLookupError, PermissionError):
        pass


def parse_tool_json(stdout):
    """The JSON object printed by the tool, or None. Tolerates log lines before it."""
    text = stdout.strip()
    for candidate in (text, text.rsplit("\n", 1)[-1]):
        try:
            value = json.loads(candidate)
        except ValueError:
            continue
        if isinstance(value, dict):
            return value
    return None


def classify_outcome(returncode, timed_out, tool_json):
    """(status, note) from how the process ended."""
    if timed_out:
        return "timeout", None
    if returncode < 0:
        return "crash", None
    if returncode in (0, 1):
        if tool_json is None:
            return "error", f"exit code {returncode} but no JSON object on stdout"
        return ("agree" if returncode == 0 else "disagree"), None
    if returncode == 2:
        return "error", None
    return "error", f"unexpected exit code {returncode}"


def run_model(model, root, tool, timeout, live, tool_args=()):
    """Runs the tool on one model; the result line as a dict, or None when interrupted."""
    cmd = [str(tool), *(str(f) for f in model.files), "--json", *tool_args]
    start = time.monotonic()
    try:
        proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, start_new_session=True,
                                text=True, errors="replace")
    except OSError as e:
        return make_record(model, root, "error", None, time.monotonic() - start, None,
                           f"cannot start {tool}: {e}", None)
    if not live.add(proc):
        proc.communicate()
        return None
    timed_out = False
    try:
        try:
            out, err = proc.communicate(timeout=timeout or None)
        except subprocess.TimeoutExpired:
            timed_out = True
            kill_group(proc)
            try:
                out, err = proc.communicate(timeout=10)
            except subprocess.TimeoutExpired:  # a descendant escaped the group, holding the pipes
                proc.kill()
                out, err = "", "(output lost: a descendant kept the pipes open)"
    finally:
        live.discard(proc)
    wall = time.monotonic() - start
    if live.stopping:
        return None  # killed by the interrupt: not an outcome of the model
    tool_json = parse_tool_json(out)
    status, note = classify_outcome(proc.returncode, timed_out, tool_json)
    return make_record(model, root, status, proc.returncode, wall, tool_json, err, note,
                       timeout=timeout if timed_out else None)


def make_record(model, root, status, returncode, wall, tool_json, stderr, note, timeout=None):
    rec = {"model": model.id, "status": status}
    for key, value in (tool_json or {}).items():
        rec.setdefault(key, value)
    rec["files"] = [file_label(f, root) for f in model.files]
    rec["exit_code"] = returncode
    if returncode is not None and returncode < 0:
        try:
            rec["signal"] = signal.Signals(-returncode).name
        except ValueError:
            rec["signal"] = f"signal {-returncode}"
    rec["wall_s"] = round(wall, 6)
    if timeout is not None:
        rec["timeout_s"] = timeout
    if note:
        rec["note"] = note
    if status != "agree" and stderr and stderr.strip():
        rec["stderr_tail"] = stderr.strip()[-STDERR_TAIL_CHARS:]
    return rec


# ---------------------------------------------------------------------------------------------
# Results file and progress


def read_recorded(out_path):
    """{model: last recorded status} of an existing results file. An incomplete last line
    (the run was killed while writing it) is cut off; any other malformed line is an error."""
    if not out_path.exists():
        return {}
    data = out_path.read_bytes()
    if data and not data.endswith(b"\n"):
        keep = data.rfind(b"\n") + 1
        print(f"run_collection: {out_path}: dropping an incomplete last line", file=sys.stderr)
        with open(out_path, "r+b") as f:
            f.truncate(keep)
        data = data[:keep]
    recorded = {}
    for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
        if not line.strip():
            continue
        try:
            rec = json.loads(line)
            recorded[rec["model"]] = rec["status"]
        except (ValueError, KeyError, TypeError) as e:
            raise InputError(f"{out_path}:{number}: malformed results line ({e}); "
                             "fix or delete that line, then rerun") from e
    return recorded


def format_duration(seconds):
    seconds = int(seconds)
    h, rest = divmod(seconds, 3600)
    return f"{h}:{rest // 60:02d}:{rest % 60:02d}" if h else f"{rest // 60}:{rest % 60:02d}"


class Progress:
    """A one-line plain-text progress bar on stderr: rewritten with \\r on a terminal, one line
    per finished model otherwise (batch logs)."""

    def __init__(self, total, stream=sys.stderr):
        self.total, self.done, self.stream = total, 0, stream
        self.counts = dict.fromkeys(STATUSES, 0)
        self.start = time.monotonic()
        self.tty = stream.isatty()
        self.width = 0

    def line(self):
        elapsed = time.monotonic() - self.start
        eta = (format_duration(elapsed / self.done * (self.total - self.done))
               if self.done else "?")
        counts = " ".join(f"{s} {n}" for s, n in self.counts.items())
        return (f"[{self.done}/{self.total}] {counts} | elapsed {format_duration(elapsed)}"
                f" | ETA {eta}")

    def update(self, rec):
        self.done += 1
        self.counts[rec["status"]] += 1
        if rec["status"] != "agree":
            self.note(f"{rec['status']}: {rec['model']}")
        self.show()

    def show(self):
        text = self.line()
        if self.tty:
            self.write("\r" + text.ljust(self.width))
            self.width = len(text)
        else:
            self.write(text + "\n")

    def note(self, text):
        if self.tty and self.width:
            self.write("\r" + " " * self.width + "\r")
            self.width = 0
        self.write(text + "\n")

    def finish(self):
        if self.tty and self.width:
            self.write("\n")

    def write(self, text):
        if self.stream is None:
            return
        try:
            self.stream.write(text)
            self.stream.flush()
        except OSError:  # e.g. a closed pipe: the run matters more than its progress bar
            self.stream = None


# ---------------------------------------------------------------------------------------------


def parse_args(argv):
    ap = Parser(prog="run_collection.py", description=__doc__.split("\n\n")[0],
                epilog="An option that takes a value may be given once; numbers are plain decimal "
                       "digits. See bench/README.md for an sbatch job-array example.")
    ap.add_argument("input", type=path, help="a folder of meshes or a manifest CSV (column 'file')")
    ap.add_argument("--out", required=True, type=path, help="results file (JSON lines), appended")
    ap.add_argument("--tool", type=path, default=DEFAULT_TOOL,
                    help="the per-model tool (default: %(default)s)")
    ap.add_argument("--jobs", type=integer(1, MAX_JOBS), default=2,
                    help=f"models run at once, 1 to {MAX_JOBS} (default: 2)")
    ap.add_argument("--tool-arg", dest="tool_args", action="append", default=[], metavar="ARG", type=text,
                    help="an extra argument for the tool, e.g. --tool-arg=--repeat --tool-arg=3 "
                         "(repeatable)")
    ap.add_argument("--timeout", type=seconds(0, MAX_TIMEOUT_S), default=900,
                    help="seconds per model, 0 for none (default: 900)")
    ap.add_argument("--shard", type=parse_shard, default=(1, 1), metavar="K/N",
                    help="run the K-th of N interleaved parts (1-based)")
    ap.add_argument("--pattern", nargs="+", default=DEFAULT_PATTERNS, metavar="GLOB", type=text,
                    help="file name globs, case-insensitive (default: %(default)s)")
    ap.add_argument("--pairs", action="store_true",
                    help="group MCUT src/cut pairs into one model and add the EMBER pairs")
    ap.add_argument("--pairs-dir", type=path,
                    help="where the EMBER pairs are built (default: ember_pairs/ beside --out)")
    ap.add_argument("--retry", nargs="+", default=[], choices=STATUSES, metavar="STATUS",
                    help="also rerun models recorded with these statuses (a new line is "
                         "appended; report.py keeps the last line of a model)")
    ap.add_argument("--list", action="store_true",
                    help="print the selected models (after --shard) and exit")
    args = ap.parse_args(argv)
    args.pattern = [p for item in args.pattern for p in re.split(r"[\s,]+", item) if p]
    if not args.pattern:
        ap.error("--pattern needs at least one glob")
    if args.pairs_dir is None:
        args.pairs_dir = args.out.parent / "ember_pairs"
    return args


def main(argv=None):
    args = parse_args(argv)
    try:
        models = select_shard(collect_models(args.input, args.pattern, args.pairs,
                                             args.pairs_dir), args.shard)
        if args.list:
            for m in models:
                print(m.id)
            return 0
        recorded = read_recorded(args.out)
        todo = [m for m in models if m.id not in recorded or recorded[m.id] in args.retry]
        if todo and not os.access(args.tool, os.X_OK):
            raise InputError(f"{args.tool}: no such executable (build it: cmake --build build "
                             "--target tritri-compare)")
        for cases in sorted({m.ember_cases for m in todo if m.ember_cases}):
            build_ember_pairs(cases, args.pairs_dir, [m.files[0].name for m in todo if m.ember_cases == cases])
    except (InputError, OSError, ValueError) as e:
        print(f"run_collection: {e}", file=sys.stderr)
        return 2

    k, n = args.shard
    print(f"run_collection: {len(models)} models" + (f" in shard {k}/{n}" if n > 1 else "")
          + f", {len(models) - len(todo)} already in {args.out}, {len(todo)} to run"
          + f" ({args.jobs} at once, time limit {args.timeout:g} s)", file=sys.stderr)
    return run_all(todo, root_of(args.input), args)


def root_of(source):
    source = Path(source)
    return source if source.is_dir() else source.parent


def run_all(todo, root, args):
    args.out.parent.mkdir(parents=True, exist_ok=True)
    live = LiveProcesses()
    progress = Progress(len(todo))
    previous_term = signal.signal(signal.SIGTERM, raise_interrupt)
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs)
    try:
        with open(args.out, "a", encoding="utf-8") as out:
            futures = [pool.submit(run_model, m, root, args.tool, args.timeout, live, args.tool_args)
                       for m in todo]
            for future in concurrent.futures.as_completed(futures):
                rec = future.result()
                if rec is None:
                    continue
                out.write(json.dumps(rec) + "\n")
                out.flush()
                os.fsync(out.fileno())
                progress.update(rec)
        progress.finish()
        return 0
    except KeyboardInterrupt:
        live.kill_all()
        pool.shutdown(wait=False, cancel_futures=True)
        progress.finish()
        progress.note(f"run_collection: interrupted after {progress.done} of {len(todo)} "
                      "models; rerun the same command to continue")
        return 130
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
        signal.signal(signal.SIGTERM, previous_term)


def raise_interrupt(signum, frame):
    raise KeyboardInterrupt


if __name__ == "__main__":
    sys.exit(main())
