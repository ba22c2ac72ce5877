#!/usr/bin/env bash
# Seed figures 5-10 (section 4 of the seed paper) as PNGs in plots/.
# Usage: scripts/seed_figures.sh [BUILD_DIR]    (default: build)
# Simulates with BUILD_DIR/ss_simulate into BUILD_DIR/seed_figures/*.tsv (not
# committed), then runs plots/fig*.gp, which write plots/fig*.png.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
# A relative build dir is taken from the current directory, else from the root.
if [[ -d "$build" ]]; then
  build="$(cd "$build" && pwd)"
elif [[ -d "$root/$build" ]]; then
  build="$(cd "$root/$build" && pwd)"
else
  echo "seed_figures.sh: build directory '$build' not found" >&2
  exit 1
fi
sim="$build/ss_simulate"
if [[ ! -x "$sim" ]]; then
  echo "seed_figures.sh: $sim not found; build it first (cmake --build $build)" >&2
  exit 1
fi
if ! command -v gnuplot >/dev/null; then
  echo "seed_figures.sh: gnuplot not found on PATH" >&2
  exit 1
fi

data="$build/seed_figures"
mkdir -p "$data"
study="$root/studies/seed.ini"
# One trajectory into $data/NAME.tsv (ss_simulate writes --out DIR/trajectory.tsv).
simulate() {
  local name=$1
  shift
  "$sim" --study "$study" "$@" --no_plots --out "$data/$name"
  mv "$data/$name/trajectory.tsv" "$data/$name.tsv"
}

# Figs. 5, 6: v = 0.25 from (0, 0.25), on the stick set.
simulate fig05 --x0 0 --xdot0 0.25 --t_end 100 --dt 0.01
# Figs. 7, 8: v = 0.25 from (0, 0.125) and (0, 0.5), to the limit cycle.
simulate fig07 --x0 0 --xdot0 0.125 --t_end 60 --dt 0.01
simulate fig08 --x0 0 --xdot0 0.5 --t_end 60 --dt 0.01
# Figs. 9, 10: v = 0.45 (above the Hopf point) from (0, 0.45), to steady sliding.
simulate fig09 --v 0.45 --x0 0 --xdot0 0.45 --t_end 600 --dt 0.02

cd "$root"
for gp in plots/fig05_phase.gp plots/fig06_time.gp plots/fig07_phase.gp plots/fig08_phase.gp \
  plots/fig09_phase.gp plots/fig10_time.gp; do
  gnuplot -e "datadir='$data'; outdir='plots'" "$gp"
  echo "wrote ${gp%.gp}.png"
done
