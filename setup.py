"""pip's way to the Python module rollspec (pyproject.toml): CMake builds the extension rollspec._core,
the one target of the project it needs, and setuptools packages it with python/rollspec (the package's
Python files, type stubs and py.typed).

The CMake build tree is build/pip in this checkout (configured on first use: Release, no tests or
benchmarks, the Python that runs pip, and ROLLSPEC_CMAKE_ARGS: more -D options or a -G generator), or
ROLLSPEC_PIP_BUILD_DIR, an existing configured tree to reuse (its module built for the same Python).
CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs; CMAKE_CXX_COMPILER_LAUNCHER=ccache is CMake's own."""
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

try:
    from setuptools.errors import ExecError
except ImportError:  # setuptools < 59
    from distutils.errors import DistutilsExecError as ExecError

SOURCE = os.path.dirname(os.path.abspath(__file__))


def cmake_version():
    """project(rollspec VERSION X.Y.Z) of the top CMakeLists.txt: the module's own __version__."""
    with open(os.path.join(SOURCE, "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(rollspec\s+VERSION\s+([0-9.]+)", f.read())
    if not m:
        raise ExecError("rollspec: no project(rollspec VERSION ...) in CMakeLists.txt")
    return m.group(1)


def run(command, what):
    print("rollspec: " + " ".join(command), flush=True)
    r = subprocess.run(command)
    if r.returncode != 0:
        raise ExecError(f"rollspec: {what} failed (exit {r.returncode}); the C++ build needs the packages the "
                        "README names, plus pybind11-dev and python3-dev for the module")


class CMakeBuild(build_ext):
    """build_ext for rollspec._core: configure (once) and build the CMake target rollspec_python, then
    copy the module where setuptools packages it."""

    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if not cmake:
            raise ExecError("rollspec: cmake not found; allowed: Debian's cmake (apt-get install cmake)")
        build = os.environ.get("ROLLSPEC_PIP_BUILD_DIR") or os.path.join(SOURCE, "build", "pip")
        build = os.path.abspath(build)
        if not os.path.isfile(os.path.join(build, "CMakeCache.txt")):
            run([cmake, "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DROLLSPEC_TESTS=OFF",
                 "-DROLLSPEC_BENCH=OFF", "-DROLLSPEC_PYTHON_MODULE=ON", "-DPython_EXECUTABLE=" + sys.executable,
                 *shlex.split(os.environ.get("ROLLSPEC_CMAKE_ARGS", ""))],
                "configuring " + build)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        run([cmake, "--build", build, "--target", "rollspec_python", "--parallel", jobs], "building the module")
        # The module's file name carries the ABI it was built for: it must be this Python's.
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = os.path.join(build, "python", "rollspec", "_core" + suffix)
        if not os.path.isfile(built):
            found = [os.path.basename(f) for f in glob.glob(os.path.join(build, "python", "rollspec", "_core*"))]
            raise ExecError(f"rollspec: {build} holds no module for {sys.executable} (_core{suffix}; found: "
                            f"{', '.join(found) or 'none'}); allowed: a tree configured with "
                            f"-DPython_EXECUTABLE={sys.executable}, or no ROLLSPEC_PIP_BUILD_DIR")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=cmake_version(),
    packages=["rollspec"],
    package_dir={"rollspec": "python/rollspec"},
    package_data={"rollspec": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("rollspec._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
