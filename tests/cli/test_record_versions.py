"""Records cannot go stale unseen (bench/record_versions.py): every component's code still matches the hash
its figure version was declared with, every record is stamped with the current versions of the code that
computed it, and a change to that code (not to a comment) makes the component, and then its records, stale:
shown here on a copy of a kernel's sources changed on purpose. A few seconds."""
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import SOURCE

sys.dont_write_bytecode = True
sys.path.insert(0, str(SOURCE / "bench"))
import bench_record  # noqa: E402
import record_versions  # noqa: E402

RECORD_DIRS = [SOURCE / "bench" / "records", SOURCE / "bench" / "records" / "validation"]
# Records written before the figure versions were kept. They are rendered with a line saying that they are
# not checked against the current code. This set only shrinks: a record written now is stamped
# (bench_record.write), and once one of these scripts has run again its name can go (a stamped record is
# checked as stamped whether or not it is named here).
UNSTAMPED = {"common-random-numbers.json", "contact-kernel.json", "contact-tables-before-speed-work.json",
             "contact-tables.json", "ensemble-random-oscillator.json", "ensemble-rolling-pipe.json",
             "ensemble-seed002.json", "plan-estimates.json", "recording-verdict-no-noise.json",
             "recording-verdict-noise-63.json", "recording-verdict.json", "rolling-examples.json",
             "rolling-impacts.json", "scaling.json", "texture.json"}


def records():
    return [f for d in RECORD_DIRS for f in sorted(d.glob("*.json"))]


def test_every_component_matches_the_sources_its_version_was_declared_with():
    bad = record_versions.changed()
    assert not bad, "; ".join(
        f"{n}: its code changed since its figure version was declared: run `/usr/bin/python3 "
        f"bench/record_versions.py bump {n}` if the change can move a figure (its records then need their "
        f"scripts run again) or `accept {n}` if it cannot" for n, _, _ in bad)


def test_every_record_is_stamped_with_the_current_versions_of_its_code():
    stale = []
    for f in records():
        record = bench_record.load(f)
        if not record.get("versions"):
            if f.name not in UNSTAMPED:
                stale.append(f"{f.name}: no figure versions (a record written now is stamped by bench_record.write)")
            continue
        why = record_versions.stale(record)
        if why:
            stale.append(f"{f.name}: {'; '.join(why)}; remake it with: {record['command']}")
    assert not stale, "stale records: " + " | ".join(stale)


def test_the_unstamped_list_names_only_records_that_exist():
    names = {f.name for f in records()}
    assert UNSTAMPED <= names, sorted(UNSTAMPED - names)


@pytest.fixture
def kernel_copy(tmp_path):
    """A copy of the contact kernel's sources and a manifest declaring their version 1."""
    shutil.copytree(SOURCE / "kernels" / "contact", tmp_path / "kernels" / "contact")
    paths = ["kernels/contact"]
    manifest = {"components": {"contact": {"paths": paths, "version": 1,
                                           "sources": record_versions.sources_hash(paths, tmp_path)}}}
    return tmp_path, manifest, tmp_path / "kernels" / "contact" / "version.hpp"


def test_a_changed_line_of_code_makes_its_component_changed(kernel_copy):
    root, manifest, source = kernel_copy
    assert record_versions.changed(manifest, root) == []
    text = source.read_text()
    source.write_text(re.sub(r"kernel_version = (\d+);", lambda m: f"kernel_version = {int(m.group(1)) + 1};", text))
    assert [c[0] for c in record_versions.changed(manifest, root)] == ["contact"]


def test_a_new_source_file_makes_its_component_changed(kernel_copy):
    root, manifest, source = kernel_copy
    (source.parent / "extra.hpp").write_text("inline constexpr double tolerance = 1e-9;\n")
    assert [c[0] for c in record_versions.changed(manifest, root)] == ["contact"]


def test_a_file_another_component_owns_changes_that_component_only(kernel_copy):
    """'except': a file inside a component's folder that another component owns (the table test inside
    kernels/spectral) stales only the records stamped with its owner."""
    root, manifest, source = kernel_copy
    owned = ["kernels/contact/version.hpp"]
    folder = manifest["components"]["contact"]
    folder["except"] = owned
    folder["sources"] = record_versions.sources_hash(folder["paths"], root, owned)
    manifest["components"]["owner"] = {"paths": owned, "version": 1,
                                       "sources": record_versions.sources_hash(owned, root)}
    assert record_versions.changed(manifest, root) == []
    source.write_text(source.read_text() + "\ninline constexpr int another = 2;\n")
    assert [c[0] for c in record_versions.changed(manifest, root)] == ["owner"]


def test_comments_and_layout_do_not_change_a_component(kernel_copy):
    root, manifest, source = kernel_copy
    text = source.read_text()
    reworded = text.replace("// Version of", "//   The version of").replace("{", "{\n\n   ")
    reworded += "\n/* a block comment\n   over two lines */\n"
    assert reworded != text
    source.write_text(reworded)
    assert record_versions.changed(manifest, root) == []


def test_a_comment_marker_inside_a_string_is_code():
    a, b = Path("a.cpp"), Path("b.cpp")
    texts = {a: 'auto s = "x // y"; int n = 1;', b: 'auto s = "x // z"; int n = 1;'}
    original = Path.read_text
    try:
        Path.read_text = lambda self, **kw: texts[self]
        assert record_versions.code_of(a) != record_versions.code_of(b)
    finally:
        Path.read_text = original


def small_record(versions):
    return {"title": "A figure", "command": "/usr/bin/python3 bench/x.py --record r.json", "date": "2026-01-02",
            "machine": {"cores": 2}, "builds": {"current": {"description": "this build"}}, "settings": "once.",
            "columns": ["case", "share"], "rows": [["beam S", "5.1 %"]], "versions": versions}


def test_a_record_older_than_its_component_is_stale_and_shows_its_command_not_its_figures(kernel_copy):
    _, manifest, _ = kernel_copy
    current = small_record({"contact": 1})
    assert record_versions.stale(current, manifest) == []
    assert "| beam S | 5.1 % |" in bench_record.markdown(current, manifest=manifest)
    manifest["components"]["contact"]["version"] = 2  # what `bump contact` does
    why = record_versions.stale(current, manifest)
    assert why == ["contact version 1, now 2"]
    text = bench_record.markdown(current, manifest=manifest)
    assert "5.1 %" not in text and "bench/x.py --record r.json" in text and "contact version 1, now 2" in text


def test_a_record_is_stamped_with_the_versions_of_the_components_it_names(tmp_path):
    r = small_record({})
    path = tmp_path / "r.json"
    bench_record.write(path, title=r["title"], argv=["bench/x.py"], builds=r["builds"], settings=r["settings"],
                       columns=r["columns"], rows=r["rows"], components=["contact", "engine"])
    manifest = record_versions.load_manifest()
    assert json.loads(path.read_text())["versions"] == {c: manifest["components"][c]["version"]
                                                        for c in ("contact", "engine")}
    with pytest.raises(bench_record.RecordError, match="unknown component 'kernel'; allowed: "):
        bench_record.write(path, title=r["title"], argv=["bench/x.py"], builds=r["builds"], settings=r["settings"],
                           columns=r["columns"], rows=r["rows"], components=["kernel"])


def test_a_missing_record_renders_as_a_warning_that_says_so(tmp_path):
    text = bench_record.render_one(tmp_path / "nothing-yet.json")
    assert "`" + tmp_path.name + "/nothing-yet.json` is missing" in text and "{warning}" in text
    inside = bench_record.render_one(SOURCE / "bench" / "records" / "validation" / "nothing-yet.json")
    assert "`bench/records/validation/nothing-yet.json` is missing" in inside


def test_the_command_refuses_an_unknown_component_in_one_line():
    r = subprocess.run(["/usr/bin/python3", str(SOURCE / "bench" / "record_versions.py"), "bump", "kernel"],
                       capture_output=True, text=True)
    assert r.returncode == 65 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "unknown component 'kernel'" in r.stderr and not r.stdout


def test_check_bump_and_stale_on_a_copy_of_the_repository(tmp_path):
    """The whole rule through the command, on a copy: a changed kernel line fails `check`; `bump` raises the
    version and takes the new code; a record stamped before is then `stale`; `accept` after a comment-only
    change keeps the version."""
    for part in ("bench", "src", "kernels", "python-post/rollspec_post"):
        shutil.copytree(SOURCE / part, tmp_path / part, ignore=shutil.ignore_patterns("__pycache__"))
    script = [sys.executable, str(tmp_path / "bench" / "record_versions.py")]

    def cmd(*args):
        return subprocess.run(script + list(args), capture_output=True, text=True, cwd=tmp_path)

    records = tmp_path / "records"
    records.mkdir()
    version = json.loads((tmp_path / "bench" / "record_versions.json").read_text())["components"]["contact"]["version"]
    (records / "r.json").write_text(json.dumps(small_record({"contact": version})))
    assert cmd("check").returncode == 0
    assert cmd("stale", str(records)).returncode == 0
    source = tmp_path / "kernels" / "contact" / "version.hpp"
    source.write_text(source.read_text().replace("namespace rollspec::contact {",
                                                 "namespace rollspec::contact {\ninline constexpr int extra = 1;"))
    r = cmd("check")
    assert r.returncode == 1 and r.stdout.startswith("contact: sources changed since version"), r.stdout
    assert cmd("bump", "contact").returncode == 0
    assert cmd("check").returncode == 0
    r = cmd("stale", str(records))
    assert r.returncode == 1 and f"contact version {version}, now {version + 1}" in r.stdout, r.stdout
    source.write_text(source.read_text() + "\n// a comment only\n")
    assert cmd("check").returncode == 0  # comments do not count: nothing to accept
    source.write_text(source.read_text().replace("extra = 1;", "renamed = 1;"))
    assert cmd("check").returncode == 1
    assert cmd("accept", "contact").returncode == 0  # declared unable to move a figure: same version
    assert cmd("check").returncode == 0
    manifest = json.loads((tmp_path / "bench" / "record_versions.json").read_text())
    assert manifest["components"]["contact"]["version"] == version + 1
