#!/usr/bin/env bash
# Installs everything tritri needs on Debian (12 "bookworm" or later). Idempotent: runs
# apt-get only for packages that are missing, pip only if matplotlib cannot be imported.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

PACKAGES=(
  build-essential cmake ninja-build
  libcgal-dev libeigen3-dev libtbb-dev libgmp-dev libmpfr-dev libboost-dev
  googletest libgtest-dev libbenchmark-dev
  clang libclang-rt-dev  # libFuzzer and the sanitizers for scripts/fuzz.sh
  python3 python3-pip python3-venv python3-dev
)

SUDO=()
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null; then SUDO=(sudo --preserve-env=DEBIAN_FRONTEND); else
    echo "setup_debian.sh: not root and no sudo; cannot install packages" >&2; exit 1
  fi
fi

is_installed() {
  dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q '^install ok installed$'
}

missing=()
for p in "${PACKAGES[@]}"; do
  is_installed "$p" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup_debian.sh: installing ${missing[*]}"
  "${SUDO[@]}" apt-get update -q
  "${SUDO[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "setup_debian.sh: all Debian packages present"
fi

# matplotlib is only for the benchmark plots: a failure here is a warning, not an error.
if python3 -c 'import matplotlib' 2>/dev/null; then
  echo "setup_debian.sh: matplotlib present"
elif python3 -m pip install -q matplotlib 2>/dev/null ||
     python3 -m pip install -q --break-system-packages matplotlib; then
  echo "setup_debian.sh: matplotlib installed"
else
  echo "setup_debian.sh: WARNING: could not install matplotlib (no network?); plots will not work" >&2
fi
