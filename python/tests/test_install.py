"""`cmake --install` puts the package rollspec where Debian's Python finds it: PREFIX/lib/python3.X/
dist-packages for /usr/local and /usr, PREFIX/lib/python3.X/site-packages for other prefixes."""
import os
import subprocess
import sys

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
