"""`cmake --install` puts the package rollspec where Debian's Python finds it: PREFIX/lib/python3.X/
dist-packages for /usr/local and /usr, PREFIX/lib/python3.X/site-packages for other prefixes."""
import os
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

BUILD = os.environ.get("ROLLSPEC_BUILD")
VERSION = "python%d.%d" % sys.version_info[:2]


def install(prefix, env=None):
    subprocess.run(["cmake", "--install", BUILD, "--prefix", str(prefix), "--component", "python"],
                   check=True, capture_output=True, env=env)


def imports_from(directory):
    env = dict(os.environ, PYTHONPATH=str(directory))
    out = subprocess.run([sys.executable, "-c", "import rollspec, rollspec.contact; print(rollspec.__file__)"],
                         check=True, capture_output=True, text=True, env=env, cwd="/")
    return out.stdout.strip()


@pytest.mark.skipif(not BUILD, reason="needs ROLLSPEC_BUILD, the build directory (set by CTest)")
def test_install_under_a_prefix_and_under_usr_local(tmp_path):
    install(tmp_path / "user")
    site = tmp_path / "user" / "lib" / VERSION / "site-packages"
    assert imports_from(site) == str(site / "rollspec" / "__init__.py")
    for stub in ("__init__.pyi", "contact.pyi", "spectra.pyi", "studies.pyi", "surfaces.pyi", "py.typed"):
        assert (site / "rollspec" / stub).is_file()
    # DESTDIR stages the default prefix: /usr/local/lib/python3.X/dist-packages, on Debian's sys.path.
    install("/usr/local", env=dict(os.environ, DESTDIR=str(tmp_path / "stage")))
    staged = tmp_path / "stage" / "usr" / "local" / "lib" / VERSION / "dist-packages"
    assert imports_from(staged) == str(staged / "rollspec" / "__init__.py")
    assert "/usr/local/lib/%s/dist-packages" % VERSION in subprocess.run(
        ["/usr/bin/python3", "-c", "import sys; print(sys.path)"], capture_output=True, text=True).stdout


def readme_first_command():
    """The README's first command (the set-up and default study), one line of shell."""
    text = (Path(__file__).resolve().parents[2] / "README.md").read_text().splitlines()
    fence = next(i for i, line in enumerate(text) if line.startswith("```sh"))
    return text[fence + 1]


@pytest.mark.skipif(not BUILD, reason="needs ROLLSPEC_BUILD, the build directory (set by CTest)")
def test_readme_first_command_makes_import_rollspec_work(tmp_path):
    # Its install step, run as written (the build folder being this build's), in a home of its own: then
    # Debian's python3, with no PYTHONPATH, imports the module from the user's site directory.
    step = next(s.strip() for s in readme_first_command().split("&&") if s.strip().startswith("cmake --install"))
    assert "--component python" in step, step
    home = tmp_path / "home"
    home.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "PYTHONNOUSERSITE")}
    env["HOME"] = str(home)
    subprocess.run(["bash", "-c", step.replace("build/release", shlex.quote(BUILD))], check=True,
                   capture_output=True, env=env, cwd=tmp_path)
    out = subprocess.run(["/usr/bin/python3", "-c", "import rollspec; print(rollspec.__version__, rollspec.__file__)"],
                         capture_output=True, text=True, env=env, cwd="/")
    assert out.returncode == 0, out.stderr
    version, where = out.stdout.split()
    cache = (Path(BUILD) / "CMakeCache.txt").read_text()
    assert "CMAKE_PROJECT_VERSION:STATIC=%s\n" % version in cache, out.stdout
    assert where.startswith(str(home / ".local" / "lib")), where
