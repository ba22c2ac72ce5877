#!/usr/bin/env bash
# The main job: set up, build, then the default study's continuation
# (v from 0.05 to 0.5), the seed's figures 5-10 and the stability charts, into plots/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
./build/ss_continue --study studies/seed.ini --out plots
scripts/seed_figures.sh build
# Stability charts in two parameters (ss_chart), each into plots/<study>/.
for chart in seed_chart stribeck_chart quintic_chart leine_chart seed_mu_chart; do
  ./build/ss_chart --study "studies/$chart.ini"
done
