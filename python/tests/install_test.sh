#!/usr/bin/env bash
# ctest Python.Install: `cmake --install` into a temporary prefix puts the
# package in <prefix>/RELDIR; from outside the tree, with that directory on
# PYTHONPATH, `import stickslip` loads the installed copy and finds the seed's
# Hopf point (closed form 0.4409585518). Also checks that RELDIR under the
# prefix the interpreter searches by itself is on its sys.path (Debian's
# /usr/bin/python3: /usr/local; a venv or pyenv Python: its sys.prefix).
# Usage: install_test.sh BUILD_DIR PYTHON RELDIR
set -euo pipefail
build=$1 python=$2 reldir=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
cd "$tmp"
# The studies and the docs are installed; --study NAME finds an installed study
# from a directory without studies/.
test -f "$tmp/prefix/share/stickslip/studies/seed.ini"
test -f "$tmp/prefix/share/stickslip/studies/stribeck_forced.ini"
test -f "$tmp/prefix/share/doc/stickslip/library.md"
test -f "$tmp/prefix/share/doc/stickslip/README.md"
mkdir empty && cd empty
"$tmp/prefix/bin/ss_simulate" --study seed --t_end 1 --no_plots --out "$tmp/sim" >/dev/null
if "$tmp/prefix/bin/ss_simulate" --study no_such_study --no_plots --out "$tmp/x" 2>"$tmp/err"; then
  echo "--study no_such_study succeeded"; exit 1
fi
grep -q "no_such_study" "$tmp/err" || { cat "$tmp/err"; exit 1; }
cd "$tmp"
PYTHONPATH="$tmp/prefix/$reldir" "$python" - "$tmp/prefix/$reldir" "$reldir" <<'PY'
import os, sys, sysconfig
import stickslip
where, reldir = sys.argv[1], sys.argv[2]
assert stickslip.__file__.startswith(where), stickslip.__file__
assert os.path.exists(os.path.join(where, "stickslip", "__init__.pyi"))
b = stickslip.continue_branch(stickslip.Params(), "v", 0.3, 0.5)
hb = [s.p for s in b.special if s.label == "HB"]
assert len(hb) == 1 and abs(hb[0] - 0.4409585518) < 1e-9, hb
get = getattr(sysconfig, "get_default_scheme", None) or sysconfig._get_default_scheme
prefix = "/usr/local" if get() == "posix_local" else sys.prefix
own = os.path.join(prefix, reldir)
assert own in sys.path, (own, sys.path)
print("installed to <prefix>/%s; %s searches %s" % (reldir, sys.executable, own))
PY
