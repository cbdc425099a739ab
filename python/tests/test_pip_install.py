"""`pip install --no-build-isolation --no-index --no-deps --prefix P .` from a checkout (pyproject.toml,
setup.py) installs the module with Debian's setuptools and no network, where that Python imports it.

The checkout's packaging files are copied to a scratch directory (pip builds in the tree it is given and
would leave its build/ and egg-info in the source tree), and setup.py reuses this build's CMake tree
(ROLLSPEC_PIP_BUILD_DIR), so the test builds nothing: a fresh checkout configures build/pip and compiles
the engine there (the how-to page's command)."""
import glob
import os
import re
import shutil
import subprocess
import sys

import pytest

BUILD = os.environ.get("ROLLSPEC_BUILD")
SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def has_pip():
    return subprocess.run([sys.executable, "-m", "pip", "--version"], capture_output=True).returncode == 0


@pytest.mark.skipif(not BUILD, reason="needs ROLLSPEC_BUILD, the build directory (set by CTest)")
@pytest.mark.skipif(not has_pip(), reason="needs pip for this Python (Debian: apt-get install python3-pip)")
def test_pip_installs_the_module_under_a_prefix(tmp_path):
    checkout = tmp_path / "checkout"
    (checkout / "python").mkdir(parents=True)
    for f in ("pyproject.toml", "setup.py", "CMakeLists.txt"):
        shutil.copy(os.path.join(SOURCE, f), checkout / f)
    shutil.copytree(os.path.join(SOURCE, "python", "rollspec"), checkout / "python" / "rollspec")
    prefix = tmp_path / "prefix"
    env = dict(os.environ, ROLLSPEC_PIP_BUILD_DIR=BUILD, PIP_NO_CACHE_DIR="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    r = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-deps",
                        "--prefix", str(prefix), str(checkout)], capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    # Debian's pip puts P/local/lib/python3.X/dist-packages (its posix_local scheme); others P/lib/...
    installed = glob.glob(str(prefix / "**" / "rollspec" / "__init__.py"), recursive=True)
    assert len(installed) == 1, installed
    package = os.path.dirname(installed[0])
    for f in ("__init__.pyi", "contact.pyi", "spectra.pyi", "studies.pyi", "surfaces.pyi", "py.typed"):
        assert os.path.isfile(os.path.join(package, f)), f
    core = glob.glob(os.path.join(package, "_core*.so"))
    assert len(core) == 1
    with open(core[0], "rb") as a, open(glob.glob(os.path.join(BUILD, "python", "rollspec", "_core*.so"))[0], "rb") as b:
        assert a.read() == b.read()  # the module this build made, not another
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        version = re.search(r"project\(rollspec\s+VERSION\s+([0-9.]+)", f.read()).group(1)
    out = subprocess.run(
        [sys.executable, "-c", "import rollspec, numpy; print(rollspec.__version__, rollspec.__file__, "
                               "rollspec.spectra.welch(numpy.ones(64), 8.0, segment=16)['segment'])"],
        capture_output=True, text=True, check=True, cwd="/", env=dict(os.environ, PYTHONPATH=os.path.dirname(package)))
    assert out.stdout.split() == [version, installed[0], "16"]
    dist = glob.glob(os.path.join(os.path.dirname(package), "rollspec-%s.dist-info" % version))
    assert len(dist) == 1  # pip knows it: `pip uninstall` and `pip show` work on it
