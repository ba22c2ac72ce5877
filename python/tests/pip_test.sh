#!/usr/bin/env bash
# ctest Python.Pip: `pip install --no-build-isolation --no-index` of this tree
# into a venv made with --system-site-packages (Debian's NumPy, setuptools and
# wheel; nothing downloaded), then `import stickslip` from outside the tree.
# STICKSLIP_CMAKE_BUILD_DIR makes setup.py reuse the test's build tree rather
# than configure and compile a fresh one (that path is the same but minutes long).
# Usage: pip_test.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
src=$1 build=$2 python=$3
if ! "$python" -c "import setuptools, wheel, venv" 2>/dev/null || ! "$python" -m pip --version >/dev/null 2>&1; then
  echo "pip_test: needs python3-pip, python3-setuptools, python3-wheel, python3-venv" >&2
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$python" -m venv --system-site-packages "$tmp/venv"
cd "$tmp"
STICKSLIP_CMAKE_BUILD_DIR="$build" "$tmp/venv/bin/python" -m pip install --no-build-isolation \
  --no-index --quiet "$src"
"$tmp/venv/bin/python" - "$tmp/venv" <<'PY'
import sys
import stickslip
assert stickslip.__file__.startswith(sys.argv[1]), stickslip.__file__
b = stickslip.continue_branch(stickslip.Params(), "v", 0.3, 0.5)
hb = [s.p for s in b.special if s.label == "HB"]
assert len(hb) == 1 and abs(hb[0] - 0.4409585518) < 1e-9, hb
print("pip installed", stickslip.__version__, "to", stickslip.__file__)
PY
