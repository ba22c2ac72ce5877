#!/usr/bin/env bash
# Memory and undefined-behaviour checks, for CI and before a release:
#  1. builds in build-asan with -DSTICKSLIP_SANITIZE=ON (AddressSanitizer +
#     UndefinedBehaviorSanitizer, RelWithDebInfo) and runs the library's tests
#     there (ctest -L unit: the app tests, the docs and Python checks run once,
#     in the Release suite; three long reference runs too, see below) with ASAN_OPTIONS=detect_leaks=1 and
#     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1;
#  2. runs one continuation of the seed study under valgrind
#     (--leak-check=full --error-exitcode=3) on the plain Release build in build.
# Fails (non-zero exit) on any sanitizer report, failing test or valgrind error.
#
# LeakSanitizer needs ptrace-like access to the process; some containers and
# sandboxes refuse it ("LeakSanitizer has encountered a fatal error" or "does
# not work under ptrace"). That is detected up front: the suite then runs with
# detect_leaks=0, and leaks are left to the valgrind step, which says so.
#
# Usage: scripts/sanitize.sh
# Environment: ASAN_BUILD (default build-asan), RELEASE_BUILD (default build),
#              JOBS (default nproc), CTEST_ARGS (extra ctest arguments).
set -euo pipefail
cd "$(dirname "$0")/.."

asan_build=${ASAN_BUILD:-build-asan}
release_build=${RELEASE_BUILD:-build}
jobs=${JOBS:-$(nproc)}
script_start=$SECONDS

say() { echo "sanitize: $*" >&2; }
elapsed() { echo "$((SECONDS - $1)) s"; }

# valgrind is not among setup.sh's packages: install it if it is missing.
if ! command -v valgrind >/dev/null; then
  say "installing valgrind"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    valgrind >/dev/null
fi

# --- 1. ASan + UBSan over the whole suite ----------------------------------
t=$SECONDS
say "building $asan_build (ASan + UBSan, RelWithDebInfo at -O1)"
# -O1, as the sanitizers' own docs advise: the build took 361 s instead of
# 445 s at -O2 on the 2-core CI machine; the suite still runs in about a minute.
# -g1 (line tables only): reports still name file and line, and a test's
# compile takes 27% less CPU than with -g (docs/benchmarks.md, "CI build time").
# The benchmarks are left out (-DSTICKSLIP_BENCH=OFF): no test runs them.
# The baseline kernel only (-DSTICKSLIP_KERNEL_CLONES=OFF): the Release suite
# ran the x86-64-v3 clone on a CPU with AVX2 and FMA, so this one covers the other.
# The app tests are neither built nor run here (-DSTICKSLIP_APP_TESTS=OFF, ctest -L unit):
# they run once, in the Release suite; valgrind runs one app below. No Python module either.
generator=()  # Ninja for a new build directory, as in setup.sh
if [ ! -f "$asan_build/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S . -B "$asan_build" "${generator[@]}" -DSTICKSLIP_SANITIZE=ON -DSTICKSLIP_BENCH=OFF -DSTICKSLIP_APP_TESTS=OFF \
  -DSTICKSLIP_PYTHON=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSTICKSLIP_KERNEL_CLONES=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" >/dev/null
# CLN (under GiNaC, for model files) leaks 26 bytes at load in every program:
# suppressed (scripts/lsan.supp), already for the build, whose test discovery
# runs each test program.
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp"
# Only what runs here: the unit test programs, and ss_continue for the probe below.
cmake --build "$asan_build" -j "$jobs" --target stickslip_unit_tests ss_continue \
  >"$asan_build/sanitize-build.log" 2>&1 || {
  tail -40 "$asan_build/sanitize-build.log" >&2
  say "FAILED: sanitizer build (log: $asan_build/sanitize-build.log)"
  exit 1
}
asan_build_time=$(elapsed "$t")
say "sanitizer build: $asan_build_time"

export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
asan_common=abort_on_error=0:halt_on_error=1:strict_string_checks=1
# Can LeakSanitizer run here? A run of the smallest app tells.
leaks=1
probe_err=$(mktemp)
if ! ASAN_OPTIONS="$asan_common:detect_leaks=1" "$asan_build/ss_continue" --help >/dev/null \
    2>"$probe_err"; then
  if grep -q "LeakSanitizer" "$probe_err"; then
    leaks=0
    say "LeakSanitizer cannot run here ($(grep -m1 LeakSanitizer "$probe_err" | cut -c1-120));"
    say "running the suite with detect_leaks=0; the valgrind step below checks for leaks"
  else
    cat "$probe_err" >&2
    rm -f "$probe_err"
    say "FAILED: $asan_build/ss_continue --help under ASan"
    exit 1
  fi
fi
rm -f "$probe_err"
export ASAN_OPTIONS="$asan_common:detect_leaks=$leaks"

t=$SECONDS
say "ctest under ASan + UBSan (ASAN_OPTIONS=$ASAN_OPTIONS)"
ctest_log="$asan_build/ctest-sanitize.log"
ctest_ok=1
# Three long reference runs are left to the Release suite: each repeats, for
# a minute or more under the sanitizers, code that shorter tests here run too
# (the doubled chart curves are the one chart's curves at m = 2 and 4:
# SystemChartForced*, ForcedCurvePoints.*; the sliding bifurcations: the other
# ForcedSwitchingSliding tests). Under ASan they took 185 s, 78 s and 33 s of
# the suite's 609 s (docs/benchmarks.md, "CI build time").
heavy='^(SystemChartDoubled\.(Second|Third)DoublingCurveMatchesOneParameterRuns|'
heavy+='ForcedSwitchingSliding\.DenHartogFloorReferenceHasCrossingThenGrazingSlidingNoSwitching)$'
# shellcheck disable=SC2086
ctest --test-dir "$asan_build" --output-on-failure -j "$jobs" -L unit -E "$heavy" ${CTEST_ARGS:-} \
  >"$ctest_log" 2>&1 ||
  ctest_ok=0
asan_test_time=$(elapsed "$t")
reports=$(grep -cE "ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:" "$ctest_log" || true)
grep -E "tests passed|tests failed|Total Test time" "$ctest_log" >&2 || true
failed=()
if [ "$ctest_ok" -ne 1 ] || [ "$reports" -ne 0 ]; then
  grep -E -A25 "ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:" "$ctest_log" | head -120 >&2 ||
    true
  grep -E "^\s+[0-9]+ - .*\((Failed|Timeout|Subprocess|SEGFAULT|Exception)" "$ctest_log" >&2 || true
  say "FAILED: ctest under ASan + UBSan, $asan_test_time: $reports sanitizer report(s)," \
    "$(grep -cE "^\s+[0-9]+ - " "$ctest_log" || true) failing test(s) (log: $ctest_log)"
  failed+=("sanitized tests")
else
  say "ctest under ASan + UBSan: clean, $asan_test_time (detect_leaks=$leaks)"
fi

# --- 2. valgrind on the Release build --------------------------------------
t=$SECONDS
say "building $release_build/ss_continue (Release, no sanitizers, libstdc++ shared)"
# Linked against the shared libstdc++ (STICKSLIP_STATIC_APPS=OFF): valgrind
# intercepts operator new/delete only there, so mismatched new/delete show.
# The apps' static default is restored after the run.
cmake -S . -B "$release_build" -DCMAKE_BUILD_TYPE=Release -DSTICKSLIP_SANITIZE=OFF \
  -DSTICKSLIP_STATIC_APPS=OFF >/dev/null
cmake --build "$release_build" -j "$jobs" --target ss_continue >/dev/null
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
vg_log="$release_build/valgrind-ss_continue.log"
say "valgrind --leak-check=full: ss_continue --study studies/seed.ini --no_plots --out $out"
vg_status=0
valgrind --leak-check=full --errors-for-leak-kinds=definite,indirect,possible \
  --error-exitcode=3 --log-file="$vg_log" --suppressions=scripts/valgrind.supp \
  "$release_build/ss_continue" --study studies/seed.ini --no_plots --out "$out" >/dev/null ||
  vg_status=$?
valgrind_time=$(elapsed "$t")
cmake -S . -B "$release_build" -DSTICKSLIP_STATIC_APPS=ON >/dev/null
cmake --build "$release_build" -j "$jobs" --target ss_continue >/dev/null
grep -E "ERROR SUMMARY|definitely lost|indirectly lost|possibly lost|All heap blocks" "$vg_log" |
  sed 's/^==[0-9]*== */  /' >&2 || true
if [ "$vg_status" -ne 0 ]; then
  say "FAILED: valgrind (exit $vg_status; 3 = memory errors or leaks; log: $vg_log)"
  failed+=("valgrind")
elif [ ! -s "$out/branch.tsv" ]; then
  say "FAILED: no branch.tsv from the valgrind run"
  failed+=("valgrind")
else
  say "valgrind: clean, $valgrind_time"
fi
timings="sanitizer build $asan_build_time, sanitized tests $asan_test_time, valgrind step"
timings+=" $valgrind_time; leaks checked by"
timings+=" $([ "$leaks" -eq 1 ] && echo "LeakSanitizer and valgrind" || echo "valgrind only")"
if ((${#failed[@]})); then
  say "FAILED (${failed[*]}) after $(elapsed "$script_start") ($timings)"
  exit 1
fi
say "all clean in $(elapsed "$script_start") ($timings)"
