#!/usr/bin/env bash
# Build and run the work-precision benchmark (issue 6, bench/ss_bench.cpp): prints the
# table and writes plots/work_precision.tsv and plots/work_precision.png (a --quick run
# writes to build-bench/bench/quick/ instead). Arguments go to ss_bench:
#   scripts/bench.sh            full run, well under 3 minutes on 2 cores
#   scripts/bench.sh --quick    reduced set, < 20 s
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build-bench -j2 --target ss_bench > /dev/null
exec build-bench/bench/ss_bench "$@"
