"""The documentation site builds with warnings as errors (`bash docs/build.sh`) against the build tree's
rollspec, its generated reference holds every command of `rollspec --help` (with that command's
options) and every key of every scene of `rollspec keys`, and the README stays short and free of
lab-notebook material (commit hashes, issue numbers, load averages)."""
import html
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("ROLLSPEC_SOURCE", Path(__file__).resolve().parents[2]))
BIN = os.environ.get("ROLLSPEC_BIN", str(SOURCE / "build" / "werror" / "rollspec"))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(SOURCE / "docs"))
import generate_reference as gen  # noqa: E402  (the same parsers the site is generated with)
sys.path.insert(0, str(SOURCE / "bench"))
import bench_record  # noqa: E402  (the bench scripts' record format the benchmarks page renders)


SMART_QUOTES = str.maketrans({"\u2018": "'", "\u2019": "'", "\u201c": '"', "\u201d": '"'})


def text_of(page):
    """An HTML page's text, tags dropped and entities decoded, whitespace collapsed, Sphinx's smart quotes
    back to the straight ones the sources hold (README's is printed README’s)."""
    raw = re.sub(r"<[^>]+>", " ", page.read_text())
    return re.sub(r"\s+", " ", html.unescape(raw)).translate(SMART_QUOTES)


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """Under CTest (ROLLSPEC_BUILD set) the site is the build tree's target rollspec_docs, built once here and
    then installed by the test install_docs; run alone, it is built into a temporary directory."""
    build = os.environ.get("ROLLSPEC_BUILD")
    if build:
        cmd = [os.environ.get("CMAKE_COMMAND", "cmake"), "--build", build, "--target", "rollspec_docs"]
        out = Path(build) / "docs"
    else:
        out = tmp_path_factory.mktemp("docs")
        cmd = ["bash", str(SOURCE / "docs" / "build.sh"), str(out)]
    r = subprocess.run(cmd, env=dict(os.environ, ROLLSPEC_BIN=BIN), capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, f"{' '.join(cmd)} failed (exit {r.returncode}):\n{r.stdout[-3000:]}\n{r.stderr[-6000:]}"
    return out / "html"


def test_every_command_and_option_is_in_the_reference(site):
    page = text_of(site / "reference" / "generated" / "commands.html")
    commands = gen.commands(BIN)
    assert len(commands) >= 5
    for name, _ in commands:
        assert f"rollspec {name}" in page, name
        options = re.findall(r"(?<![\w-])(--[a-z][a-z-]*)", gen.run([BIN, name, "--help"]))
        missing = sorted({o for o in options if o not in page})
        assert not missing, f"rollspec {name}: options missing from the reference: {missing}"


def test_every_key_of_every_scene_is_in_the_reference(site):
    page = text_of(site / "reference" / "generated" / "keys.html")
    scenes = gen.scenes(BIN)
    assert len(scenes) >= 5
    for scene, _ in scenes:
        sections = gen.parse_keys(gen.run([BIN, "keys", scene]))
        assert sections, scene
        for section, keys in sections:
            heading = f"{scene} [{section}]"
            assert heading in page, heading
            body = page.split(heading, 1)[1]
            for key, default, *_ in keys:
                assert re.search(rf"\b{re.escape(key)} {re.escape(default)}" if default else rf"\b{re.escape(key)}\b",
                                 body), f"{scene} [{section}] {key} = {default}"


def test_schema_exit_codes_and_api_are_generated(site):
    schema = text_of(site / "reference" / "generated" / "schema.html")
    for name in ("/psd/frequency", "/psd/mean", "/psd/ci_lower", "/bands/level_db", "filetype", "(m/s^2)^2/Hz"):
        assert name in schema, name
    codes = text_of(site / "reference" / "generated" / "exit-codes.html")
    for code in ("64", "65", "66", "73", "78", "130"):
        assert f" {code} " in codes, code
    api = text_of(site / "reference" / "python.html")
    assert "open_result" in api and "run(" in api.replace("run (", "run(")
    assert (site / "validation" / "benchmarks.html").exists()
    assert list((site / "_images").glob("goals*.png")), "the benchmark figure from bench/goals.json"


def test_every_benchmark_record_is_on_the_benchmarks_page(site):
    page = text_of(site / "validation" / "benchmarks.html")
    records = sorted((SOURCE / "bench" / "records").glob("*.json"))
    assert records, "no benchmark record in bench/records"
    for path in records:
        record = bench_record.load(path)
        last_row = map(bench_record.cell, record["rows"][-1])
        for text in (record["title"], record["command"], *record["columns"], *last_row):
            assert re.sub(r"\s+", " ", html.unescape(text)) in page, f"{path.name}: {text!r} not on the page"


def small_record():
    return {"title": "Hertz solve", "command": "/usr/bin/python3 bench/x.py --record r.json", "date": "2026-01-02",
            "machine": {"cores": 2, "cpu": "test CPU"}, "settings": "2 threads, median of 3.",
            "builds": {"reference": {"description": "the build before", "version": "rollspec 0.1.0 (git 0123abc)"},
                       "current": {"description": "this build"}},
            "columns": ["case", "seconds"], "rows": [["512²", 0.2261], ["1024²", "1.04"]]}


def test_a_benchmark_record_renders_as_a_table_under_its_command(tmp_path):
    (tmp_path / "a.json").write_text(__import__("json").dumps(small_record()))
    gen.write_bench_records(tmp_path, tmp_path)
    text = (tmp_path / "bench-records.md").read_text()
    assert "### Hertz solve" in text
    assert "```text\n/usr/bin/python3 bench/x.py --record r.json\n```" in text
    assert "2 cores (test CPU)" in text and "**reference**: the build before" in text
    assert "| case | seconds |\n|---|---|\n| 512² | 0.2261 |\n| 1024² | 1.04 |" in text
    assert "0123abc" not in text, "the build's version line (its commit) is kept, not printed"


@pytest.mark.parametrize("change, fault", [
    (lambda r: r.pop("command"), "no 'command'"),
    (lambda r: r["rows"].append(["2048²"]), "row 3 has 1 cells, the columns 2"),
    (lambda r: r["machine"].pop("cores"), "'machine' has no 'cores'"),
    (lambda r: r["builds"]["current"].update(description="main at ba5a7c3"), "printed text names a commit (ba5a7c3"),
    (lambda r: r.update(notes="load average 3.1"), "printed text names a load average"),
])
def test_a_malformed_benchmark_record_is_refused_in_one_line(tmp_path, change, fault):
    record = small_record()
    change(record)
    (tmp_path / "bad.json").write_text(__import__("json").dumps(record))
    with pytest.raises(bench_record.RecordError, match=re.escape(f"benchmark record bad.json: {fault}")):
        bench_record.load(tmp_path / "bad.json")


def write_small(path):
    r = small_record()
    bench_record.write(path, title=r["title"], argv=["bench/x.py", "--record", "r.json"], builds=r["builds"],
                       settings=r["settings"], columns=r["columns"], rows=r["rows"])


def test_a_record_replaces_only_a_record_and_never_a_foreign_or_special_file(tmp_path):
    record = tmp_path / "r.json"
    write_small(record)
    write_small(record)  # its own record: replaced
    assert bench_record.load(record)["title"] == small_record()["title"]
    link = tmp_path / "link.json"
    link.symlink_to(record)
    write_small(link)  # a link to a record: the record is replaced, the link stays
    assert link.is_symlink() and bench_record.load(record)
    foreign = tmp_path / "notes.json"
    foreign.write_text('{"mine": 1}\n')
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    for path, fault in ((foreign, "exists and is not a benchmark record"), (fifo, "is not a regular file"),
                        (tmp_path, "is not a regular file"), (tmp_path / "no" / "r.json", "no directory")):
        with pytest.raises(bench_record.RecordError, match=re.escape(f"{path}: {fault}")):
            write_small(path)
    assert foreign.read_text() == '{"mine": 1}\n'
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fifo.json", "link.json", "notes.json", "r.json"]


def test_a_malformed_benchmark_record_fails_the_docs_build_in_one_line(tmp_path):
    records = tmp_path / "records"
    records.mkdir()
    (records / "broken.json").write_text('{"title": "x",')
    env = dict(os.environ, ROLLSPEC_BIN=BIN, ROLLSPEC_BENCH_RECORDS=str(records))
    r = subprocess.run(["bash", str(SOURCE / "docs" / "build.sh"), str(tmp_path / "out")], capture_output=True,
                       text=True, timeout=600, env=env)
    assert r.returncode != 0
    assert r.stderr.startswith("generate_reference: benchmark record broken.json: not JSON"), r.stderr
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert not (tmp_path / "out" / "html").exists()


def lab_notebook_findings(text):
    """Commit hashes, issue numbers and load averages in a user-facing text (empty: none)."""
    # 1.509577e-03 is a number, not a commit.
    numbers = re.sub(r"(?<![0-9a-f.])\d*\.?\d+e[-+]?\d+(?![0-9a-f])", " ", text)
    hashes = [w for w in re.findall(r"\b[0-9a-f]{7,40}\b", numbers)
              if re.search(r"[a-f]", w) and re.search(r"\d", w) and not re.fullmatch(r"\d+e\d+", w)]
    found = [f"commit hash {h}" for h in hashes]
    found += [f"issue number '{m}'" for m in re.findall(r"\bissues? #?\d+", text, re.I)]
    found += ["load average" for _ in re.findall(r"load average", text, re.I)]
    return found


def test_readme_is_short_and_has_no_lab_notebook():
    text = (SOURCE / "README.md").read_text()
    assert len(text.splitlines()) <= 160
    assert not lab_notebook_findings(text), lab_notebook_findings(text)


def test_no_site_page_names_an_issue_a_commit_or_a_load_average(site):
    found = {}
    for page in sorted(site.rglob("*.html")):
        if page.name in ("genindex.html", "search.html", "py-modindex.html") or "_modules" in page.parts:
            continue
        hits = lab_notebook_findings(text_of(page))
        if hits:
            found[str(page.relative_to(site))] = hits[:5]
    assert not found, f"lab-notebook material on the site: {found}"


def test_citation_and_changelog_are_readable():
    import yaml
    cff = yaml.safe_load((SOURCE / "CITATION.cff").read_text())
    assert cff["cff-version"] == "1.2.0" and cff["title"] and cff["authors"]
    version = subprocess.run([BIN, "version"], capture_output=True, text=True, check=True).stdout.split()[1]
    assert cff["version"] == version, f"CITATION.cff says {cff['version']}, the binary {version}"
    changelog = (SOURCE / "CHANGELOG.md").read_text()
    assert "## [Unreleased]" in changelog and f"## [{version}]" in changelog


def test_gallery_examples_ran(site):
    examples = sorted((SOURCE / "docs" / "examples").glob("plot_*.py"))
    assert examples
    for example in examples:
        page = site / "gallery" / (example.stem + ".html")
        assert page.exists(), f"{example.name} has no gallery page"
        assert f"sphx_glr_{example.stem}_001.png" in page.read_text(), f"{example.name} drew no figure"


def test_every_link_inside_the_site_resolves(site):
    r = subprocess.run([sys.executable, str(SOURCE / "docs" / "check_links.py"), str(site)], capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert re.search(r"links: \d+ pages, 0 broken internal links", r.stdout), r.stdout


def test_the_link_check_finds_a_missing_page_and_a_missing_anchor(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "index.html").write_text(
        '<html><body><h1 id="top">x</h1><a href="sub/page.html#here">ok</a><a href="#top">ok</a>'
        '<a href="gone.html">missing</a><a href="sub/page.html#nowhere">bad anchor</a>'
        '<a href="https://example.org/x">external</a></body></html>')
    (tmp_path / "sub" / "page.html").write_text('<html><body><p id="here">y</p><a href="../index.html">up</a>'
                                                '</body></html>')
    r = subprocess.run([sys.executable, str(SOURCE / "docs" / "check_links.py"), str(tmp_path)], capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 1
    assert "index.html: gone.html: no such file" in r.stderr
    assert "index.html: sub/page.html#nowhere: no anchor #nowhere in page.html" in r.stderr
    assert r.stderr.count("check_links:") == 2 and "1 external links" in r.stdout


CHROMIUM = "/usr/bin/chromium"
# In each page, every code block and table whose content is wider than its box (a line or a column cut off)
LAYOUT_PROBE = """<script>
window.addEventListener('load', function () {
  var cut = [];
  document.querySelectorAll('article pre, article .table-wrapper, article table').forEach(function (el) {
    if (el.scrollWidth > el.clientWidth + 1) cut.push(el.tagName + ' ' + (el.textContent || '').trim().slice(0, 60));
  });
  document.body.setAttribute('data-cut', JSON.stringify(cut));
});
</script>"""
# Pages with the longest usage lines, the widest tables and the longest commands.
WIDE_PAGES = ("reference/generated/commands.html", "reference/generated/keys.html", "validation/benchmarks.html",
              "tutorials/compare.html", "tutorials/tour.html", "tutorials/your-rig.html")


@pytest.mark.skipif(not os.path.exists(CHROMIUM), reason="/usr/bin/chromium absent (Debian package chromium)")
@pytest.mark.parametrize("page", WIDE_PAGES)
def test_nothing_is_cut_off_at_1280_px(site, page, tmp_path):
    """Headless Chromium lays the page out in a 1280 px window; no code line or table column runs out of its
    box (docs/_static/rollspec.css wraps them)."""
    import json
    path = site / page
    probe = path.with_name(path.stem + ".layout-probe.html")  # beside it: the page's CSS and images resolve
    probe.write_text(path.read_text().replace("</body>", LAYOUT_PROBE + "</body>"))
    try:
        r = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                            "--disable-background-networking", "--disable-component-update", "--disable-sync",
                            f"--user-data-dir={tmp_path / 'profile'}", "--window-size=1280,900",
                            "--virtual-time-budget=3000", "--dump-dom", f"file://{probe}"],
                           capture_output=True, text=True, timeout=120)
    finally:
        probe.unlink()
    found = re.search(r'data-cut="([^"]*)"', r.stdout)
    assert found, f"the probe did not run: {r.stderr[-1000:]}"
    cut = json.loads(html.unescape(found.group(1)))
    assert not cut, f"{page}: cut off at 1280 px: {cut[:5]}"

