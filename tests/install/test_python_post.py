"""python-post installed two ways, each into a temporary directory.

1. `cmake --install BUILD --component python_post --prefix P` (cmake/install.cmake): the package under
P/share/rollspec/python and the launcher P/bin/rollspec-post, which runs /usr/bin/python3 on it; with
P/bin on PATH, `rollspec-post` works from anywhere with no PYTHONPATH.

2. pip, the documented way (README "Install"):

    /usr/bin/python3 -m venv --system-site-packages .venv
    .venv/bin/pip install --no-build-isolation --no-index --no-deps ./python-post

Debian 12's Python is externally managed (PEP 668), hence the venv over Debian's packages. pip
builds with Debian's setuptools and never touches the network. python-post is copied first:
setuptools writes build/ and *.egg-info beside pyproject.toml, which must not land in the sources.
"""
import os
import re
import shutil
import subprocess
import tomllib

import pytest

from conftest import CMAKE, SOURCE, run

POST = SOURCE / "python-post"
BUILD = os.environ.get("ROLLSPEC_BUILD")


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
    # scipy is no longer one: the comparison is rollspec compare's (CHANGELOG, python-post's comparison)
    assert {"numpy", "matplotlib", "h5py", "xarray", "h5netcdf"} <= set(dependencies) and "scipy" not in dependencies
    run(venv / "bin" / "python", "-c", "; ".join(f"import {d}" for d in dependencies))
    check = subprocess.run([str(venv / "bin" / "pip"), "check"], capture_output=True, text=True)
    ours = [line for line in check.stdout.splitlines() if line.startswith("rollspec-post")]
    assert all(re.fullmatch(r"rollspec-post \S+ requires h5py, which is not installed\.", line) for line in ours), check.stdout


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    if not BUILD:
        pytest.skip("ROLLSPEC_BUILD not set (run through CTest)")
    p = tmp_path_factory.mktemp("prefix")
    run(CMAKE, "--install", BUILD, "--component", "python_post", "--prefix", p)
    return p


def user_env(prefix):
    """A user's shell: P/bin first on PATH, no PYTHONPATH pointing at the sources."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PATH"] = f"{prefix / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    return env


def test_cmake_install_puts_the_package_and_the_command(prefix):
    package = prefix / "share" / "rollspec" / "python" / "rollspec_post"
    sources = sorted(p.name for p in (POST / "rollspec_post").glob("*.py"))
    assert sorted(p.name for p in package.glob("*.py")) == sources
    for name in sources:
        assert (package / name).read_bytes() == (POST / "rollspec_post" / name).read_bytes(), name
    launcher = prefix / "bin" / "rollspec-post"
    assert os.access(launcher, os.X_OK)
    assert launcher.read_text().startswith("#!/usr/bin/python3\n")


def test_installed_command_on_path(prefix, tmp_path):
    env = user_env(prefix)
    assert shutil.which("rollspec-post", path=env["PATH"]) == str(prefix / "bin" / "rollspec-post")
    r = run("rollspec-post", "--help", cwd=tmp_path, env=env)
    assert r.stdout.startswith("usage: rollspec-post ")
    for command in ("psd", "texture", "trajectory", "panels", "report"):
        assert command in r.stdout
    bad = subprocess.run(["rollspec-post", "psd"], capture_output=True, text=True, cwd=tmp_path, env=env)
    assert bad.returncode == 64 and bad.stderr.startswith("rollspec-post psd: error:"), bad.stderr


def test_installed_command_draws_a_plot(prefix, tmp_path):
    """An engine result drawn by the installed copy (not the sources: they are off sys.path)."""
    result = tmp_path / "ro.h5"
    run(os.environ["ROLLSPEC_BIN"], "run", SOURCE / "studies" / "random-oscillator.ini", "--out", result, "--quiet",
        "--set", "study.realisations=6")
    env = user_env(prefix)
    r = run("rollspec-post", "psd", result, "--bands", "--out", tmp_path / "psd.png", cwd=tmp_path, env=env)
    assert r.stdout.strip() == f"wrote {tmp_path / 'psd.png'}"
    assert (tmp_path / "psd.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # through a symbolic link in another directory (~/bin/rollspec-post -> P/bin/rollspec-post)
    link = tmp_path / "home-bin" / "rollspec-post"
    link.parent.mkdir()
    link.symlink_to(prefix / "bin" / "rollspec-post")
    run(link, "--help", cwd=tmp_path, env=env)
