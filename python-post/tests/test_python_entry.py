"""`python3 -m rollspec_post` under a Python without its modules (pyenv, conda, python3 -S): one line
naming what is needed, what is missing and the command that fixes it, exit 69; never a traceback."""
import os
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE

NEEDED = "needs numpy, h5py, matplotlib"


def other_python():
    """The first python3 on PATH that is not this one and cannot import h5py (pyenv's here), else None."""
    for d in os.environ.get("PATH", "").split(os.pathsep):
        exe = shutil.which("python3", path=d)
        if not exe or os.path.realpath(exe) == os.path.realpath(sys.executable):
            continue
        r = subprocess.run([exe, "-c", "import h5py"], capture_output=True, timeout=60)
        if r.returncode != 0:
            return exe
    return None


def run(python, *args, env=None):
    env = dict(env or os.environ, PYTHONPATH=str(SOURCE / "python-post"))
    return subprocess.run([*python, "-m", "rollspec_post", *map(str, args)], capture_output=True, text=True,
                          env=env, timeout=120, cwd="/")


def check_one_line(r, missing):
    assert r.returncode == 69, (r.returncode, r.stderr)
    assert "Traceback" not in r.stderr and r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith("rollspec-post " + NEEDED), lines[0]
    assert f": {', '.join(missing)}):" in lines[0] and "/usr/bin/python3" in lines[0]
    assert "apt-get install " + " ".join(f"python3-{m}" for m in missing) in lines[0], lines[0]


@pytest.mark.parametrize("command", [["psd", "r.h5", "--out", "/tmp/never.png"],
                                     ["panels", "--panel", "A", "r.h5=x", "--out", "/tmp/never.png"],
                                     ["report", "r.h5", "--out", "/tmp/never.html"]])
def test_python_without_site_packages(command):
    """python3 -S has none of the modules (the state of a fresh pyenv or conda Python)."""
    check_one_line(run([sys.executable, "-S"], *command), ["numpy", "h5py", "matplotlib"])


def test_python_first_on_path():
    exe = other_python()
    if exe is None:
        pytest.skip("no python3 on PATH without h5py")
    r = run([exe], "psd", "r.h5", "--out", "/tmp/never.png")
    assert r.returncode == 69 and "Traceback" not in r.stderr and len(r.stderr.splitlines()) == 1, r.stderr
    assert r.stderr.startswith("rollspec-post " + NEEDED) and "h5py" in r.stderr.split("missing from")[1]
    # argparse alone answers --help: the user learns the commands before installing anything
    h = run([exe], "--help")
    assert h.returncode == 0 and "psd" in h.stdout


def test_only_h5py_missing(oscillator_result, tmp_path):
    """h5py that fails to import (a conda h5py built for another libhdf5): named alone, its package alone."""
    (tmp_path / "h5py.py").write_text("raise ModuleNotFoundError('No module named h5py', name='h5py')\n")
    env = dict(os.environ)
    r = subprocess.run([sys.executable, "-m", "rollspec_post", "psd", oscillator_result, "--out", tmp_path / "x.png"],
                       capture_output=True, text=True, timeout=120,
                       env=dict(env, PYTHONPATH=f"{tmp_path}{os.pathsep}{SOURCE / 'python-post'}"))
    check_one_line(r, ["h5py"])
