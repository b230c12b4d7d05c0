#!/usr/bin/env bash
# Builds and installs the Python package with `pip install .` (scikit-build-core and
# nanobind come from PyPI) into a virtual environment, then runs the binding tests
# (tests/python/test_bindings.py, test_exact_io.py, test_round_safe.py,
# test_exact_classify.py, test_boolean_bindings.py, test_thread_failure.py) and the Python
# example.
# Environment: JOBS (parallel compile jobs, default: number of cores), PYTHON (interpreter
# for the venv, default python3), TRITRI_PY_VENV (venv, default build-python/venv),
# TRITRI_PREFIX (an install prefix of a Release build of this checkout, as
# `cmake --install build --prefix DIR`: the module then links that installed arrangements
# library instead of compiling it again, CMake's TRITRI_PYTHON_PREBUILT; unset: everything
# is built from source, as a user's `pip install .`).
# The CMake build directory build-python/wheel is kept, so a rerun recompiles only what
# changed. Needs the Debian packages of scripts/setup_debian.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
JOBS=${JOBS:-$(nproc)}
PYTHON=${PYTHON:-python3}
VENV=${TRITRI_PY_VENV:-$ROOT/build-python/venv}

mkdir -p "$ROOT/build-python"
[[ -x $VENV/bin/python ]] || "$PYTHON" -m venv "$VENV"
"$VENV/bin/python" -m pip install -q numpy pytest

# Passed even when empty: the kept build dir's cache would otherwise keep an earlier prefix.
echo "=== pip install . (build dir build-python/wheel${TRITRI_PREFIX:+, arrangements from $TRITRI_PREFIX})"
start=$SECONDS
CMAKE_BUILD_PARALLEL_LEVEL=$JOBS "$VENV/bin/python" -m pip install -q "$ROOT" \
  --config-settings=build-dir="$ROOT/build-python/wheel" \
  --config-settings=cmake.define.TRITRI_PYTHON_PREBUILT="${TRITRI_PREFIX:-}"
echo "pip install took $((SECONDS - start)) s"

# Run outside the checkout so that `import tritri` can only mean the installed package.
cd "$ROOT/build-python"
export PYTHONDONTWRITEBYTECODE=1
echo "=== pytest tests/python/test_bindings.py test_exact_io.py test_round_safe.py test_exact_classify.py test_boolean_bindings.py test_thread_failure.py"
"$VENV/bin/python" -m pytest -q -p no:cacheprovider "$ROOT/tests/python/test_bindings.py" \
  "$ROOT/tests/python/test_exact_io.py" "$ROOT/tests/python/test_round_safe.py" \
  "$ROOT/tests/python/test_exact_classify.py" "$ROOT/tests/python/test_boolean_bindings.py" \
  "$ROOT/tests/python/test_thread_failure.py"
echo "=== examples/python/arrange_example.py"
"$VENV/bin/python" "$ROOT/examples/python/arrange_example.py" "$ROOT/build-python/two_cubes.off"
echo "=== python tests passed"
