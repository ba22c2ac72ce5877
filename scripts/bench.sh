#!/usr/bin/env bash
# Set up, build, and run the work-precision benchmark (bench/ss_bench.cpp): prints the
# table and writes plots/work_precision.tsv and plots/work_precision.png (a --quick run
# writes to build/bench/quick/ instead), then the peer comparison with AUTO-07p
# (bench/peers/auto_peer.sh; it installs auto-07p and gfortran when missing). Arguments
# other than --no_peers go to ss_bench:
#   scripts/bench.sh              full run, well under 3 minutes on 2 cores
#   scripts/bench.sh --quick      reduced set, < 20 s (the peer medians over 3 runs)
#   scripts/bench.sh --no_peers   ss_bench only
set -euo pipefail
cd "$(dirname "$0")/.."
args=() peers=1 reps=7
for a in "$@"; do
  case "$a" in
    --no_peers) peers=0 ;;
    --quick) reps=3; args+=("$a") ;;
    *) args+=("$a") ;;
  esac
done
scripts/setup.sh build
build/bench/ss_bench "${args[@]}"
if ((peers)); then
  bench/peers/auto_peer.sh --reps "$reps"
fi
