#!/usr/bin/env bash
# The main job on a fresh Debian machine: build (build/, Release) and run the classifier
# benchmark. Output: results/bench_classify.json (Google Benchmark JSON).
# (Until the arrangement pipeline exists this is the whole job.)
# Environment: JOBS (parallel build jobs, default: number of cores).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
JOBS=${JOBS:-$(nproc)}

scripts/setup_debian.sh

gen=()
[[ -f build/CMakeCache.txt ]] || gen=(-G Ninja)
cmake -S "$ROOT" -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DTRITRI_BUILD_BENCH=ON

if [[ ! -f bench/bench_classify.cpp ]]; then
  echo "main_job.sh: bench/bench_classify.cpp does not exist yet: nothing to run" >&2
  exit 1
fi
cmake --build build -j "$JOBS" --target bench_classify
if [[ ! -x build/bin/bench_classify ]]; then
  echo "main_job.sh: build/bin/bench_classify was not built" >&2
  exit 1
fi

mkdir -p results
build/bin/bench_classify --benchmark_out=results/bench_classify.json --benchmark_out_format=json
echo "main_job.sh: wrote results/bench_classify.json"
