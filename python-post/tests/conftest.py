"""Result files made by the engine in the test run, for the plotting tests."""
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("ROLLSPEC_SOURCE", pathlib.Path(__file__).resolve().parents[2]))
BIN = os.environ.get("ROLLSPEC_BIN", str(SOURCE / "build" / "release" / "rollspec"))


def post(*args):
    env = dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"))
    return subprocess.run([sys.executable, "-m", "rollspec_post", *map(str, args)], capture_output=True, text=True,
                          env=env)


@pytest.fixture(scope="session")
def oscillator_result(tmp_path_factory):
    out = tmp_path_factory.mktemp("results") / "ro.h5"
    r = subprocess.run([BIN, "run", SOURCE / "studies" / "random-oscillator.ini", "--out", out, "--quiet",
                        "--set", "study.realisations=16"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return out
