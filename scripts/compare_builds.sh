#!/usr/bin/env bash
# Every study through every app that takes it, in two builds, and every TSV
# written compared numerically (scripts/compare_branches.py; curves.tsv also
# by scripts/compare_curves.py). An app that refuses a study (exit 2) in the
# old build is skipped. Usage: compare_builds.sh OLD_BUILD NEW_BUILD [TOL] [STUDY...]
set -uo pipefail
cd "$(dirname "$0")/.."
old=${1:?old build directory}; new=${2:?new build directory}; tol=${3:-1e-12}
shift 3 2>/dev/null || shift $#
studies=("$@")
[ ${#studies[@]} -eq 0 ] && studies=(studies/*.ini)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0
for ini in "${studies[@]}"; do
  s=$(basename "$ini" .ini)
  for app in ss_continue ss_chart ss_basin ss_orbit_diagram ss_simulate; do
    mkdir -p "$out/old/$app" "$out/new/$app"
    "$old/$app" --study "$ini" --out "$out/old/$app/$s" --no_plots >"$out/old.log" 2>&1
    rc=$?
    [ $rc -eq 2 ] && continue
    "$new/$app" --study "$ini" --out "$out/new/$app/$s" --no_plots >"$out/new.log" 2>&1
    rn=$?
    if [ $rc -ne $rn ]; then echo "$app $s: exit $rc vs $rn"; status=1; continue; fi
    files=$(cd "$out/old/$app/$s" 2>/dev/null && ls *.tsv 2>/dev/null | paste -sd,)
    [ -z "$files" ] && continue
    if ! r=$(scripts/compare_branches.py "$out/old/$app/$s" "$out/new/$app/$s" --tol "$tol" \
                 --files "$files" 2>&1); then
      status=1
      if [ -f "$out/old/$app/$s/curves.tsv" ]; then
        r="$r
$(scripts/compare_curves.py "$out/old/$app/$s/curves.tsv" "$out/new/$app/$s/curves.tsv" --tol "$tol" 2>&1)"
      fi
    fi
    echo "$app $s: $(echo "$r" | head -c 3000)"
  done
done
exit $status
