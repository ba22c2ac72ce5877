#!/usr/bin/env bash
# Every study's continuation against a baseline directory of outputs
# (BASE/<study>/branch.tsv, special_points.tsv), compared numerically by
# scripts/compare_branches.py. Usage: compare_baseline.sh BUILD BASE [TOL]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; base=${2:?baseline directory}; tol=${3:-1e-12}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0
for ini in studies/*.ini; do
  s=$(basename "$ini" .ini)
  if [ ! -f "$base/$s/branch.tsv" ]; then echo "$s: no baseline in $base, skipped"; continue; fi
  "$build/ss_continue" --study "$ini" --out "$out/$s" --no_plots > "$out/$s.log" || true
  scripts/compare_branches.py "$base/$s" "$out/$s" --tol "$tol" || status=1
done
exit $status
