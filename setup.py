"""Builds the extension stickslip._core with CMake (pyproject.toml has the rest).

The interpreter running this (pip's) is the one CMake builds for. Environment:
STICKSLIP_CMAKE_BUILD_DIR reuses a configured build tree (only its target
stickslip_python is built); CMAKE_BUILD_PARALLEL_LEVEL as for cmake --build.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(stickslip VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.environ.get("STICKSLIP_CMAKE_BUILD_DIR")
        if not build:
            build = os.path.join(os.path.abspath(self.build_temp), "cmake")
            subprocess.run(["cmake", "-S", str(ROOT), "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                            "-DPython3_EXECUTABLE=" + sys.executable, "-DBUILD_TESTING=OFF",
                            "-DSTICKSLIP_INSTALL=OFF"], check=True)
        subprocess.run(["cmake", "--build", build, "--target", "stickslip_python"], check=True)
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
