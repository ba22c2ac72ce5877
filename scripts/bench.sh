#!/usr/bin/env bash
# Set up, build, and run the work-precision benchmark (bench/ss_bench.cpp): prints the
# table and writes plots/work_precision.tsv and plots/work_precision.png (a --quick run
# writes to build/bench/quick/ instead). Arguments go to ss_bench:
#   scripts/bench.sh            full run, well under 3 minutes on 2 cores
#   scripts/bench.sh --quick    reduced set, < 20 s
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
exec build/bench/ss_bench "$@"
