#!/usr/bin/env bash
# Peer comparison on the smooth part of the seed branch (steady sliding, HB, pure-slip
# orbits down past GR): AUTO-07p's compiled executable against build/ss_continue.
# Installs auto-07p and gfortran when missing, compiles stickslip.f90 once into
# build/peers/auto/, then times and checks both tools against the closed-form HB and the
# long-double reference integrator's GR and periods (auto_peer.py prints the table).
#   bench/peers/auto_peer.sh [--reps N]      (default 7 runs per median)
# Exit 1 when AUTO's Hopf point is off the closed form or its branch is empty.
set -euo pipefail
cd "$(dirname "$0")/../.."
here=bench/peers
work=build/peers/auto
auto_lib=/usr/lib/auto-07p/lib

if ! command -v gfortran >/dev/null || ! [ -d "$auto_lib" ]; then
  echo "auto_peer: installing auto-07p gfortran" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq \
    --no-install-recommends auto-07p gfortran >/dev/null
fi
# The tool under test and the references' tool (ss_accuracy --seed_references); a no-op after
# scripts/setup.sh build.
if [ ! -f build/CMakeCache.txt ]; then
  echo "auto_peer: build/ is not configured (run scripts/setup.sh build)" >&2
  exit 1
fi
cmake --build build -j "$(nproc)" --target ss_continue ss_accuracy >/dev/null

mkdir -p "$work"
cp "$here"/stickslip.f90 "$here"/c.hb "$here"/c.po "$here"/c.hb.tight "$here"/c.po.tight "$work"/
# The flags of AUTO's own cmds.make (-O2, OpenMP); the library objects as its @r links them.
if [ ! -x "$work/stickslip.exe" ] || [ "$here/stickslip.f90" -nt "$work/stickslip.exe" ]; then
  gfortran -O2 -fPIC -std=legacy -fopenmp -c "$work/stickslip.f90" -o "$work/stickslip.o"
  gfortran -O2 -fPIC -std=legacy -fopenmp "$work/stickslip.o" "$auto_lib"/*.o -o "$work/stickslip.exe"
fi
exec python3 "$here/auto_peer.py" --work "$work" --tool build/ss_continue \
  --reference build/bench/ss_accuracy "$@"
