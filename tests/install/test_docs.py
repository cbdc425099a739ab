"""The documentation site, built by the build tree's target rollspec_docs (docs/build.sh against its rollspec;
under CTest the test `docs` builds and checks it first, a fixture of this one), installs with
`cmake --install --component docs` under share/doc/rollspec/html, where every internal link still resolves."""
import sys

from conftest import BUILD, CMAKE, SOURCE, run


def test_the_site_installs_with_its_links_intact(tmp_path):
    if not (BUILD / "docs" / "html" / "index.html").is_file():  # run alone: build the target here
        run(CMAKE, "--build", BUILD, "--target", "rollspec_docs", timeout=900)
    run(CMAKE, "--install", BUILD, "--component", "docs", "--prefix", tmp_path)
    html = tmp_path / "share" / "doc" / "rollspec" / "html"
    assert (html / "index.html").is_file()
    assert len(list(html.rglob("*.html"))) == len(list((BUILD / "docs" / "html").rglob("*.html")))
    r = run(sys.executable, SOURCE / "docs" / "check_links.py", html)
    assert " 0 broken internal links" in r.stdout
