#!/usr/bin/env bash
# The figures the documentation shows, each committed with the data and the
# gnuplot script that draw it: docs/figures/<study>/ holds one app run's whole
# output set (TSVs, .gp, PNGs). Redraw a figure there with `gnuplot <script>.gp`.
# plots/ is the main job's output directory and is not committed.
# Usage: scripts/docs_figures.sh [BUILD_DIR]   (default: build; about 4 min of CPU,
# most of it the forced charts, orbit diagrams and basins)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
for app in ss_continue ss_chart ss_basin ss_simulate ss_orbit_diagram; do
  [[ -x "$build/$app" ]] || { echo "docs_figures.sh: $build/$app not found; build it first" >&2; exit 1; }
done
command -v gnuplot >/dev/null || { echo "docs_figures.sh: gnuplot not found on PATH" >&2; exit 1; }

fig=docs/figures
mkdir -p "$fig"
# An app's run removes the other apps' outputs from its --out folder; several
# apps share a study's folder here, so run() puts back the files of the folder
# that the app did not write (they are other apps' figures and data).
run() {
  echo "+ $*"
  local out="" prev=""
  for a in "$@"; do
    [[ "$prev" == --out ]] && out="$a"
    prev="$a"
  done
  local keep
  keep="$(mktemp -d)"
  [[ -n "$out" && -d "$out" ]] && cp -a "$out"/. "$keep"/
  "$@" >/dev/null
  if [[ -n "$out" ]]; then
    for f in "$keep"/*; do
      [[ -e "$f" && ! -e "$out/$(basename "$f")" ]] && cp -a "$f" "$out"/
    done
  fi
  rm -rf "$keep"
}
run "$build/ss_continue" --study studies/seed.ini --out "$fig/seed"
run "$build/ss_continue" --study studies/stribeck.ini --out "$fig/stribeck"
run "$build/ss_continue" --study studies/den_hartog.ini --out "$fig/den_hartog"
# The forced oscillator's studies (issue 20): resonance curve and a section each.
for study in floor_static seed_forced stribeck_forced; do
  run "$build/ss_continue" --study "studies/$study.ini" --out "$fig/$study"
  run "$build/ss_simulate" --study "studies/$study.ini" --out "$fig/${study}_sim"
done
# Their chaos figures (issue 21): orbit diagram with exponents and basins in the
# study's folder, the (Omega, A) chart in its own.
for study in seed_forced stribeck_forced; do
  run "$build/ss_orbit_diagram" --study "studies/$study.ini" --out "$fig/$study"
  run "$build/ss_basin" --study "studies/${study}_basin.ini" --out "$fig/$study"
  run "$build/ss_chart" --study "studies/$study.ini" --out "$fig/${study}_chart"
done
# The seed belt below its Hopf point, forced: the NS curve of the 1:1 tongue.
run "$build/ss_chart" --study studies/forced_ns_seed.ini --out "$fig/forced_ns_seed_chart"
run "$build/ss_basin" --study studies/stribeck_basin.ini --out "$fig/stribeck_basin"
run "$build/ss_basin" --study studies/stribeck_basin_stability.ini --out "$fig/stribeck_basin_stability"
for chart in seed_chart stribeck_chart quintic_chart leine_chart; do
  run "$build/ss_chart" --study "studies/$chart.ini" --out "$fig/$chart"
done
# Systems with several masses or contacts (docs/systems.md). The chain's branch
# ends at SL with no orbit of its period beyond (sequence-ended, exit 0).
"$build/ss_continue" --study studies/mode_coupling.ini --out "$fig/mode_coupling" >/dev/null
"$build/ss_continue" --study studies/chain2.ini --out "$fig/chain2" >/dev/null 2>&1 || [[ $? -eq 1 ]]
run "$build/ss_basin" --study studies/chain2_basin.ini --out "$fig/chain2_basin"
run "$build/ss_orbit_diagram" --study studies/chain2.ini --set kc=0.5 --from 0.05 --to 0.45 --n 200 \
  --transient 300 --keep 100 --out "$fig/chain2_od"
run "$build/ss_chart" --study studies/brake_chart.ini --out "$fig/brake_chart"
# The other studies of several masses: two unequal blocks, the Coulomb chain
# (steady sliding, a center, and its trajectory into step) and ten blocks.
run "$build/ss_continue" --study studies/chain2_asym.ini --out "$fig/chain2_asym"
for study in chain2_coulomb chain10; do
  run "$build/ss_continue" --study "studies/$study.ini" --out "$fig/$study"
  run "$build/ss_simulate" --study "studies/$study.ini" --out "$fig/$study"
done
run "$build/ss_chart" --study studies/chain2_chart.ini --out "$fig/chain2_chart"
du -sh "$fig"
