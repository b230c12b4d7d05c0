#!/usr/bin/env bash
# Fuzzes the mesh and CSG readers with libFuzzer under AddressSanitizer + UBSan
# (tests/fuzz/README.md):
#   scripts/fuzz.sh SECONDS [READER...]    each reader for SECONDS (-max_total_time)
#   scripts/fuzz.sh --runs N [READER...]   each reader for N inputs (-runs; what CI runs)
# READER: obj off stl ply csg (default: all, one after the other). Configures and builds
# build-fuzz/ (clang, -DTRITRI_FUZZ=ON; only the fuzz targets) when needed. Each reader's
# working corpus is build-fuzz/corpus/<reader>/ (kept between runs, new inputs are added
# there), seeded from tests/fuzz/corpus/<reader>/ and from the files of that extension
# under 64 KB in tests/ and ../shared/meshes/. Prints each reader's executions; a finding
# (crash, sanitizer report, exception other than InputError, leak, timeout, out of
# memory) is written to build-fuzz/findings/<reader>/ and makes the exit status 1.
# Environment: JOBS (build jobs, default 1), FUZZ_TIMEOUT (seconds one input may take,
# default 30), FUZZ_MAX_LEN (largest input in bytes, default 65536; 4096 runs about 3x as
# many inputs a second), FUZZ_SANITIZERS (default address,undefined; "undefined" alone runs about 3x
# as many inputs a second, for long campaigns), FUZZ_BUILD (build dir, default build-fuzz,
# or build-fuzz-<sanitizers> when FUZZ_SANITIZERS is set).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
SANITIZERS=${FUZZ_SANITIZERS:-address,undefined}
[[ $SANITIZERS =~ ^[a-z,]+$ ]] || { echo "fuzz.sh: FUZZ_SANITIZERS must be a -fsanitize= list such as address,undefined" >&2; exit 2; }
if [[ -n ${FUZZ_SANITIZERS:-} ]]; then default_build=build-fuzz-${SANITIZERS//,/-}; else default_build=build-fuzz; fi
BUILD=${FUZZ_BUILD:-$default_build}
ALL_READERS=(obj off stl ply csg)

usage() { echo "usage: scripts/fuzz.sh SECONDS [READER...] | --runs N [READER...]   (READER: ${ALL_READERS[*]})" >&2; exit 2; }
(($# >= 1)) || usage
if [[ $1 == --runs ]]; then
  (($# >= 2)) && [[ $2 =~ ^[0-9]+$ ]] || usage
  limit=(-runs="$2"); shift 2
else
  [[ $1 =~ ^[0-9]+$ ]] || usage
  limit=(-max_total_time="$1"); shift
fi
readers=("$@")
((${#readers[@]})) || readers=("${ALL_READERS[@]}")
for r in "${readers[@]}"; do
  [[ " ${ALL_READERS[*]} " == *" $r "* ]] || usage
done

if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ not found (scripts/setup_debian.sh installs clang and libclang-rt-dev)" >&2; exit 1
fi
if [[ ! -f $BUILD/CMakeCache.txt ]]; then
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DTRITRI_FUZZ=ON -DTRITRI_FUZZ_SANITIZERS="$SANITIZERS" -DTRITRI_BUILD_TESTS=OFF -DTRITRI_BUILD_BENCH=OFF >/dev/null
fi
start=$SECONDS
if ! cmake --build "$BUILD" -j "${JOBS:-1}" --target "${readers[@]/#/fuzz_}" >"$BUILD/build.log" 2>&1; then
  tail -40 "$BUILD/build.log" >&2
  echo "fuzz.sh: the build of the fuzz targets failed (log $BUILD/build.log)" >&2; exit 1
fi
echo "fuzz.sh: fuzz targets built in $((SECONDS - start)) s"

# Seeds: copies named by content hash (no duplicates, no name clashes).
seed() {
  local reader=$1 dir=$2 f
  rm -rf "$dir"; mkdir -p "$dir"
  {
    [[ -d tests/fuzz/corpus/$reader ]] && find tests/fuzz/corpus/"$reader" -type f -print0
    find tests -path tests/fuzz/corpus -prune -o -type f -iname "*.$reader" -size -64k -print0
    [[ -d ../shared/meshes ]] && find ../shared/meshes -type f -iname "*.$reader" -size -64k -print0
  } | while IFS= read -r -d '' f; do
    cp "$f" "$dir/$(sha1sum <"$f" | cut -c1-40)"
  done
}

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
failed=()
for r in "${readers[@]}"; do
  corpus=$BUILD/corpus/$r seeds=$BUILD/seeds/$r findings=$BUILD/findings/$r log=$BUILD/logs/fuzz_$r.log
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  seed "$r" "$seeds"
  status=0
  "$BUILD/bin/fuzz_$r" "$corpus" "$seeds" "${limit[@]}" -rss_limit_mb=2048 -max_len="${FUZZ_MAX_LEN:-65536}" \
    -timeout="${FUZZ_TIMEOUT:-30}" -print_final_stats=1 -artifact_prefix="$findings/" >"$log" 2>&1 || status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
  echo "fuzz_$r: ${runs:-?} executions in ${secs:-?} s (${cov:-cov: ?}, corpus $(find "$corpus" -type f | wc -l) files), exit $status"
  if ((status != 0)); then
    failed+=("$r")
    echo "fuzz_$r: FINDING (log $log):" >&2
    grep -E 'ERROR|SUMMARY|terminate|uncaught|deadly|Test unit written' "$log" | head -20 >&2 || true
  fi
done
if ((${#failed[@]})); then
  echo "fuzz.sh: findings in: ${failed[*]} (reproducers in $BUILD/findings/)" >&2
  exit 1
fi
echo "fuzz.sh: no findings"
