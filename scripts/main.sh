#!/usr/bin/env bash
# The main job: set up, build the five apps (the README's tour runs them all)
# and the Python module, not the tests (scripts/test.sh builds those in the same
# build/), then the default study's continuation (v from 0.05 to 0.5), the
# seed's figures 5-10, the stability charts, into plots/, and a short sweep.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --target ss_apps --target stickslip_python build
./build/ss_continue --study studies/seed.ini --out plots
scripts/seed_figures.sh build
# The mode-coupling brake model (docs/systems.md): steady sliding, HB, the stick-slip branch.
./build/ss_continue --study studies/mode_coupling.ini --out plots/mode_coupling
# Stability charts in two parameters (ss_chart), each into plots/<study>/.
for chart in seed_chart stribeck_chart quintic_chart leine_chart seed_mu_chart; do
  ./build/ss_chart --study "studies/$chart.ini"
done
# 10^5 belt orbits on a LocalCluster of 2 workers (examples/python/sweep.py:
# P(stick-slip) and the median amplitude per v), with the Python the module was
# built for; prints its rate, the cluster's start included; writes plots/sweep.tsv.
python=$(sed -n 's/^_Python3_EXECUTABLE:INTERNAL=//p' build/CMakeCache.txt)
(cd plots && PYTHONPATH="$PWD/../build/python" "${python:-python3}" ../examples/python/sweep.py 5000 20)
