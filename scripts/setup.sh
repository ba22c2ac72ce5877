#!/usr/bin/env bash
# Installs what is missing (Debian packages, by name) and builds in Release.
# Usage: scripts/setup.sh [--target NAME]... [BUILD_DIR] [extra cmake arguments...]
# With --target, only those targets (and what they need) are built; the build
# directory is configured as always (tests on), so a later plain setup.sh in it
# builds the rest (scripts/main.sh builds its apps only, scripts/test.sh all).
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
while [ "${1:-}" = "--target" ]; do
  [ -n "${2:-}" ] || { echo "setup.sh: --target needs a name" >&2; exit 2; }
  targets+=(--target "$2")
  shift 2
done
build=${1:-build}
shift || true

packages=(g++ make cmake ninja-build pkg-config libeigen3-dev libnlopt-cxx-dev libsundials-dev libginac-dev
          libboost-program-options-dev libboost-dev libgtest-dev gnuplot-nox
          python3-dev pybind11-dev python3-pybind11 python3-numpy
          python3-pip python3-setuptools python3-wheel python3-venv
          python3-dask python3-distributed python3-h5py
          python3-pandas python3-matplotlib python3-nbclient python3-ipykernel
          python3-scipy)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

# Ninja for a new build directory: one job graph across the targets, where the
# Makefiles build a target's objects only after the targets it links (a fresh
# Release build: 392 s against 591 s of wall time on 2 cores, docs/benchmarks.md).
# An existing build directory keeps its generator.
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
