#!/usr/bin/env bash
# Installs the built tree into a temporary prefix, then builds and runs
# examples/ against the installed package (find_package(stickslip)), as a user
# outside this repository would. Usage: scripts/example.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
cmake -S examples -B "$tmp/example" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$tmp/example" >/dev/null
"$tmp/example/seed_branch"
"$tmp/example/own_system"
"$tmp/example/own_model"
"$tmp/prefix/bin/ss_continue" --version
# The installed apps' model compiler (a module in LIBDIR/stickslip, found from bin/).
"$tmp/prefix/bin/ss_simulate" --model "$tmp/prefix/share/stickslip/studies/models/belt.ini" \
  --t_end 20 --no_plots --out "$tmp/simulate" >/dev/null
test -s "$tmp/simulate/trajectory.tsv"
