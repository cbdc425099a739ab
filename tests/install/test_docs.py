"""The documentation site builds as a CMake target of the build tree (rollspec_docs, docs/build.sh against
its rollspec) and `cmake --install --component docs` puts it under share/doc/rollspec/html, where every
internal link still resolves."""
import sys

from conftest import BUILD, CMAKE, SOURCE, run


def test_the_site_installs_with_its_links_intact(tmp_path):
    run(CMAKE, "--build", BUILD, "--target", "rollspec_docs", timeout=900)
    run(CMAKE, "--install", BUILD, "--component", "docs", "--prefix", tmp_path)
    html = tmp_path / "share" / "doc" / "rollspec" / "html"
    assert (html / "index.html").is_file()
    assert len(list(html.rglob("*.html"))) == len(list((BUILD / "docs" / "html").rglob("*.html")))
    r = run(sys.executable, SOURCE / "docs" / "check_links.py", html)
    assert " 0 broken internal links" in r.stdout
