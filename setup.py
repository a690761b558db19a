"""Builds the extension rigidfold._core with the project's CMake for pip and python3 -m build.

pyproject.toml holds the package's description; this file only adds the build step setuptools
cannot express: CMake configures the project (Release, no benchmarks) and builds the target
rigidfold_python, and the module it writes is copied into the wheel beside the pure-Python files
of python/rigidfold/.

RIGIDFOLD_CMAKE_BUILD_DIR=DIR reuses a build directory configured earlier (the README's `build/`, or
CI's instrumented one) instead of configuring a new one under setuptools' build_temp: nothing is
compiled twice. Nothing is downloaded: CMake finds what scripts/bootstrap.sh installed.
"""
import glob
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def project_version():
    """The version of CMakeLists.txt's project() call: the CLI and the module print the same."""
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        match = re.search(r"project\(rigidfold VERSION ([0-9.]+)", f.read())
    if not match:
        raise RuntimeError("CMakeLists.txt: no `project(rigidfold VERSION x.y.z` line")
    return match.group(1)


class CMakeBuild(build_ext):
    """Builds rigidfold._core with CMake instead of compiling sources itself."""

    def build_extension(self, ext):
        build_dir = os.environ.get("RIGIDFOLD_CMAKE_BUILD_DIR") or os.path.join(os.path.abspath(self.build_temp), "cmake")
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.run(["cmake", "-S", ROOT, "-B", build_dir, *generator, "-DCMAKE_BUILD_TYPE=Release",
                            "-DRIGIDFOLD_BENCHMARKS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", build_dir, "--target", "rigidfold_python", "-j", str(os.cpu_count() or 1)],
                       check=True)
        built = glob.glob(os.path.join(build_dir, "python", "rigidfold", "_core*.so"))
        if len(built) != 1:
            raise RuntimeError(f"{build_dir}/python/rigidfold: expected one _core*.so, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    version=project_version(),
    packages=["rigidfold"],
    package_dir={"rigidfold": "python/rigidfold"},
    ext_modules=[Extension("rigidfold._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
)
