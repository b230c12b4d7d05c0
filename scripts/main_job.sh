#!/usr/bin/env bash
# The main job on a fresh Debian machine: build tritri-compare (build/, Release), run it on every
# model of a collection (native vs tritri classifier) and write the report.
#   default collection: the generated meshes of build/bin/make_test_meshes -> results/default_meshes
#   results/results.jsonl   one JSON line per model (bench/run_collection.py)
#   results/report/         report.md + report.html + time_classes.png + times_sorted.png +
#                           thumbs/ (a picture per model: bench/render.py) (bench/report.py)
# See bench/README.md ("Collection runs") for the two Python tools and a cluster job array.
#
# usage: scripts/main_job.sh [--meshes DIR_OR_CSV] [--resume] [--jobs N] [--timeout SECONDS]
#                            [--pairs] [--rotated-copies K]
#   --meshes DIR_OR_CSV  run on this folder or manifest CSV instead (e.g. ../shared/meshes)
#   --resume             keep results/results.jsonl and run only the models missing from it
#                        (default: start afresh)
#   --jobs N             models run at once (default 2); --timeout: seconds per model (900)
#   --pairs              MCUT/EMBER pairs as one model each (see bench/README.md)
#   --rotated-copies K   also generate sphere_copies_K.off (large: K = 8 gives ~1M points)
# Environment: JOBS (parallel build jobs, default: number of cores).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
JOBS=${JOBS:-$(nproc)}

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; }
die() { echo "main_job.sh: $*" >&2; exit 2; }

meshes="" resume=0 copies="" runner_args=()
while (($#)); do
  case $1 in
    --meshes) (($# > 1)) || die "--meshes needs a folder or a CSV"; meshes=$2; shift ;;
    --resume) resume=1 ;;
    --jobs | --timeout) (($# > 1)) || die "$1 needs a value"; runner_args+=("$1" "$2"); shift ;;
    --pairs) runner_args+=(--pairs) ;;
    --rotated-copies) (($# > 1)) || die "$1 needs a value"; copies=$2; shift ;;
    -h | --help) usage; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
  shift
done
if [[ -n $meshes ]]; then
  [[ -e $meshes ]] || die "$meshes: no such folder or file"
  meshes=$(realpath "$meshes")
fi

scripts/setup_debian.sh
# report.py needs matplotlib (setup_debian.sh only warns when it cannot install it).
if ! python3 -c 'import matplotlib' 2>/dev/null; then
  python3 -m pip install -q matplotlib || python3 -m pip install -q --break-system-packages matplotlib
fi

[[ -f arrangements/tools/tritri_compare.cpp ]] ||
  die "arrangements/tools/tritri_compare.cpp does not exist yet: nothing to compare with"
gen=()
[[ -f build/CMakeCache.txt ]] || gen=(-G Ninja)
cmake -S "$ROOT" -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$JOBS" --target tritri-compare make_test_meshes arrange

mkdir -p results
if [[ -z $meshes ]]; then
  meshes=results/default_meshes
  build/bin/make_test_meshes "$meshes" ${copies:+--rotated-copies "$copies"}
fi

if ((!resume)); then
  rm -f results/results.jsonl
  rm -rf results/report
fi
# A time-out, crash or disagreement is a result, not a failure: the runner exits 0 for them.
python3 bench/run_collection.py "$meshes" --out results/results.jsonl "${runner_args[@]}"
# The pictures (results/report/thumbs/) run arrange on each model again; the report reads
# the models' files relative to the collection's root, as the runner recorded them.
python3 bench/report.py results/results.jsonl --out results/report --thumbnails "$meshes"
echo "main_job.sh: wrote results/results.jsonl and results/report/report.md (and report.html)"
