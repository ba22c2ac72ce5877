"""Builds the extension stickslip._core with CMake (pyproject.toml has the rest).

The interpreter running this (pip's) is the one CMake builds for; first it is
checked for what the build needs (NumPy, pybind11, wheel, the Python headers),
and what is missing is named. Environment: STICKSLIP_CMAKE_BUILD_DIR reuses a
configured build tree (only its target stickslip_python is built); without it,
./build is reused when it was configured for this interpreter in Release, else
a tree under build/setuptools is made (kept: a second install is incremental).
CMAKE_BUILD_PARALLEL_LEVEL as for cmake --build (default: every core).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent


def missing_requirements():
    """What this interpreter lacks to build and import stickslip: (what, Debian package)."""
    import importlib.util
    import sysconfig
    missing = []
    if importlib.util.find_spec("setuptools") is None:
        missing.append(("setuptools", "python3-setuptools"))
    if importlib.util.find_spec("numpy") is None:
        missing.append(("NumPy", "python3-numpy"))
    if importlib.util.find_spec("wheel") is None:
        missing.append(("wheel (pip's bdist_wheel)", "python3-wheel"))
    cmake_dirs = ["/usr/lib/cmake/pybind11", "/usr/share/cmake/pybind11",
                  "/usr/local/share/cmake/pybind11"]
    if importlib.util.find_spec("pybind11") is None and not any(map(os.path.isdir, cmake_dirs)):
        missing.append(("pybind11", "pybind11-dev"))
    include = sysconfig.get_paths().get("include") or ""
    if not os.path.exists(os.path.join(include, "Python.h")):
        missing.append(("the Python headers (Python.h in %s)" % include, "python3-dev"))
    if shutil.which("cmake") is None:
        missing.append(("cmake", "cmake"))
    if shutil.which("pkg-config") is None:
        missing.append(("pkg-config", "pkg-config"))
    if not os.path.exists("/usr/include/ginac/ginac.h"):  # model files
        missing.append(("GiNaC (ginac/ginac.h)", "libginac-dev"))
    return missing


def check_interpreter():
    missing = missing_requirements()
    if not missing:
        return
    what = ", ".join(m[0] for m in missing)
    debian = " ".join(m[1] for m in missing)
    sys.exit("stickslip: cannot build for %s (Python %s): it has no %s.\n"
             "  Debian's /usr/bin/python3: sudo apt-get install %s (scripts/setup.sh does),\n"
             "  then /usr/bin/python3 -m pip install --no-build-isolation .\n"
             "  Another interpreter (pyenv, venv): install the same there, e.g.\n"
             "  %s -m pip install numpy pybind11 wheel, or make a venv with\n"
             "  /usr/bin/python3 -m venv --system-site-packages VENV."
             % (sys.executable, sys.version.split()[0], what, debian, sys.executable))


def reusable_build():
    """./build if it was configured for this interpreter in Release, else None."""
    cache = ROOT / "build" / "CMakeCache.txt"
    if not cache.exists():
        return None
    text = cache.read_text(errors="replace")
    py = re.search(r"^_?Python3_EXECUTABLE:\w+=(.*)$", text, re.M)  # find_package: _Python3_...
    kind = re.search(r"^CMAKE_BUILD_TYPE:\w+=(.*)$", text, re.M)
    sanitize = re.search(r"^STICKSLIP_SANITIZE:\w+=(ON|TRUE|1)$", text, re.M | re.I)
    if not py or not kind or kind.group(1) != "Release" or sanitize:
        return None
    same = os.path.realpath(py.group(1)) == os.path.realpath(sys.executable)
    return str(ROOT / "build") if same else None


check_interpreter()  # before setuptools: its absence is named too
from setuptools import Extension, setup  # noqa: E402
from setuptools.command.build_ext import build_ext  # noqa: E402


def version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(stickslip VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.environ.get("STICKSLIP_CMAKE_BUILD_DIR") or reusable_build()
        if build:
            print("stickslip: reusing the build tree %s" % build, flush=True)
        else:
            build = os.path.join(os.path.abspath(self.build_temp), "cmake")
            args = ["-DCMAKE_BUILD_TYPE=Release", "-DPython3_EXECUTABLE=" + sys.executable,
                    "-DBUILD_TESTING=OFF", "-DSTICKSLIP_INSTALL=OFF"]
            if shutil.which("ccache"):
                args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            subprocess.run(["cmake", "-S", str(ROOT), "-B", build] + args, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", build, "--target", "stickslip_python", "--parallel",
                        jobs], check=True)
        built = list(pathlib.Path(build, "python", "stickslip").glob("_core*"))
        if len(built) != 1:
            sys.exit("setup.py: expected one stickslip/_core* in %s/python, found %s" % (build, built))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        if built[0].name != target.name:  # built for another interpreter
            sys.exit("setup.py: %s was built, %s needs %s" % (built[0], sys.executable, target.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(version=version(), ext_modules=[Extension("stickslip._core", sources=[])],
      cmdclass={"build_ext": CMakeBuild}, options={"build": {"build_base": "build/setuptools"}})
