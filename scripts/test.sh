#!/usr/bin/env bash
# Set up, build, and run the whole test suite through ctest, except the tests
# labelled `slow` (minutes each: docs/studies.md's forced orbit diagrams, basins
# and charts rerun; `ctest --test-dir build -L slow` runs them).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
ctest --test-dir build --output-on-failure -j "$(nproc)" -LE slow
