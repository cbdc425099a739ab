"""The documentation site builds as a CMake target of the build tree (rollspec_docs, docs/build.sh against
its rollspec) and `cmake --install --component docs` puts it under share/doc/rollspec/html, where every
internal link still resolves."""
import os
import pathlib
import subprocess
import sys

SOURCE = pathlib.Path(os.environ["ROLLSPEC_SOURCE"])
BUILD = pathlib.Path(os.environ["ROLLSPEC_BUILD"])
CMAKE = os.environ.get("CMAKE_COMMAND", "cmake")


def run(*args, **kw):
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, args))}: exit {r.returncode}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r


def test_the_site_installs_with_its_links_intact(tmp_path):
    run(CMAKE, "--build", BUILD, "--target", "rollspec_docs", timeout=900)
    run(CMAKE, "--install", BUILD, "--component", "docs", "--prefix", tmp_path)
    html = tmp_path / "share" / "doc" / "rollspec" / "html"
    assert (html / "index.html").is_file()
    assert len(list(html.rglob("*.html"))) == len(list((BUILD / "docs" / "html").rglob("*.html")))
    r = run(sys.executable, SOURCE / "docs" / "check_links.py", html)
    assert " 0 broken internal links" in r.stdout
