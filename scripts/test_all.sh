#!/usr/bin/env bash
# Runs every test on a fresh Debian machine:
#   1. build/       Release: all tests (ctest)
#   2. build-asan/  RelWithDebInfo + AddressSanitizer/UBSan: all tests at TRITRI_TEST_SCALE=0.1
#   3. install build/ to a temporary prefix and build + run tests/consumer against it
# Environment: JOBS (parallel build jobs, default: number of cores).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
JOBS=${JOBS:-$(nproc)}

scripts/setup_debian.sh

# Configure a build dir; pick Ninja only when the dir is new (an existing cache keeps its
# generator).
configure() {
  local dir=$1; shift
  local gen=()
  [[ -f $dir/CMakeCache.txt ]] || gen=(-G Ninja)
  cmake -S "$ROOT" -B "$dir" "${gen[@]}" "$@"
}

echo "=== [1/3] Release build and tests (build/)"
configure build -DCMAKE_BUILD_TYPE=Release -DTRITRI_BUILD_TESTS=ON -DTRITRI_BUILD_BENCH=ON
cmake --build build -j "$JOBS"
ctest --test-dir build --output-on-failure --no-tests=error -j2

echo "=== [2/3] Sanitizer build and tests (build-asan/)"
configure build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRITRI_SANITIZE=ON \
  -DTRITRI_BUILD_TESTS=ON -DTRITRI_BUILD_BENCH=OFF
cmake --build build-asan -j "$JOBS"
TRITRI_TEST_SCALE=0.1 ctest --test-dir build-asan --output-on-failure --no-tests=error -j2

echo "=== [3/3] Install and build tests/consumer against the install"
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install build --prefix "$prefix/install"
cmake -S tests/consumer -B "$prefix/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix/install"
cmake --build "$prefix/consumer" -j "$JOBS"
"$prefix/consumer/tritri_consumer"

echo "=== all tests passed"
