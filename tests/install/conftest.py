"""Shared by the installation tests: where the sources and the build tree are (from CTest's
environment), `run`, which asserts a command succeeds and shows its output when it does not, and the
fixture `prefix`, the build tree installed into a temporary prefix."""
import os
import pathlib
import subprocess
import sys

import pytest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree

SOURCE = pathlib.Path(os.environ["ROLLSPEC_SOURCE"])
BUILD = pathlib.Path(os.environ["ROLLSPEC_BUILD"])
CMAKE = os.environ.get("CMAKE_COMMAND", "cmake")


def run(*args, **kw):
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, args))}: exit {r.returncode}\n{r.stdout[-4000:]}\n{r.stderr[-4000:]}"
    return r


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    """`cmake --install` of the build tree into a temporary prefix, once per test file."""
    p = tmp_path_factory.mktemp("prefix")
    run(CMAKE, "--install", BUILD, "--prefix", p)
    return p
