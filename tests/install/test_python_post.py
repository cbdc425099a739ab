"""python-post installed with pip the documented way (README "Install"), in a temporary directory:

    /usr/bin/python3 -m venv --system-site-packages .venv
    .venv/bin/pip install --no-build-isolation --no-index --no-deps ./python-post

Debian 12's Python is externally managed (PEP 668), hence the venv over Debian's packages. pip
builds with Debian's setuptools and never touches the network. python-post is copied first:
setuptools writes build/ and *.egg-info beside pyproject.toml, which must not land in the sources.
"""
import os
import pathlib
import re
import shutil
import subprocess
import tomllib

import pytest

SOURCE = pathlib.Path(os.environ["ROLLSPEC_SOURCE"])
POST = SOURCE / "python-post"


def run(*args, **kw):
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, args))}: exit {r.returncode}\n{r.stdout}\n{r.stderr}"
    return r


def tree(path):
    return sorted(str(p.relative_to(path)) for p in path.rglob("*") if "__pycache__" not in p.parts)


@pytest.fixture(scope="module")
def venv(tmp_path_factory):
    before = tree(POST)
    work = tmp_path_factory.mktemp("pip")
    shutil.copytree(POST, work / "python-post", ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
    run("/usr/bin/python3", "-m", "venv", "--system-site-packages", work / ".venv")
    # No proxy, no index: any attempt to download fails instead of hanging or succeeding.
    env = {k: v for k, v in os.environ.items() if not k.lower().endswith("_proxy") and not k.startswith("PIP_")}
    env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", http_proxy="http://127.0.0.1:9", https_proxy="http://127.0.0.1:9")
    r = run(work / ".venv" / "bin" / "pip", "install", "--no-build-isolation", "--no-index", "--no-deps", "./python-post",
            cwd=work, env=env)
    assert "Successfully installed rollspec-post-" in r.stdout, r.stdout
    assert tree(POST) == before, "pip wrote into the source tree's python-post"
    return work / ".venv"


def test_console_command(venv):
    r = run(venv / "bin" / "rollspec-post", "--help", cwd=venv.parent)
    assert r.stdout.startswith("usage: rollspec-post ")
    for command in ("psd", "texture", "stiffness", "trajectory", "bench", "report"):
        assert command in r.stdout
    # The same parser as python3 -m rollspec_post (which names itself so).
    m = run(venv / "bin" / "python", "-m", "rollspec_post", "--help", cwd=venv.parent)
    assert m.stdout.startswith("usage: python3 -m rollspec_post ")
    assert m.stdout.split("\n\n", 1)[1] == r.stdout.split("\n\n", 1)[1]
    # A command runs through it: a usage error, exit 64 (sysexits, as the engine), names the command.
    bad = subprocess.run([str(venv / "bin" / "rollspec-post"), "psd"], capture_output=True, text=True)
    assert bad.returncode == 64 and "rollspec-post psd: error:" in bad.stderr, bad.stderr


def test_package_imports_from_the_venv(venv):
    code = "import rollspec_post, sys; print(rollspec_post.__file__); print(rollspec_post.__version__); print(rollspec_post.run)"
    r = run(venv / "bin" / "python", "-c", code, cwd=venv.parent)  # not from the source tree
    path, version = r.stdout.splitlines()[:2]
    assert path.startswith(str(venv / "lib")), path
    init = (POST / "rollspec_post" / "__init__.py").read_text()
    assert f'__version__ = "{version}"' in init


def test_declared_dependencies_come_from_debian(venv):
    """Every dependency in pyproject.toml imports in the venv (Debian's packages, .ci/setup) and,
    h5py aside (registered by Debian 12 under another name), pip sees it installed."""
    dependencies = tomllib.loads((POST / "pyproject.toml").read_text())["project"]["dependencies"]
    assert {"numpy", "scipy", "matplotlib", "h5py", "xarray", "h5netcdf"} <= set(dependencies)
    run(venv / "bin" / "python", "-c", "; ".join(f"import {d}" for d in dependencies))
    check = subprocess.run([str(venv / "bin" / "pip"), "check"], capture_output=True, text=True)
    ours = [line for line in check.stdout.splitlines() if line.startswith("rollspec-post")]
    assert all(re.fullmatch(r"rollspec-post \S+ requires h5py, which is not installed\.", line) for line in ours), check.stdout
