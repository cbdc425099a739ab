"""cmake --install puts the example studies, the data files they read and a template of every scene under
share/rollspec/studies, and they plan (and run) from there, whatever the current directory; the man page
has a STUDY FILE section."""
import os
import re
import shutil

import pytest

from conftest import SOURCE, run


def tree(root):
    return sorted(str(f.relative_to(root)) for f in root.rglob("*") if f.is_file() and "__pycache__" not in f.parts)


def test_studies_and_their_data_installed(prefix):
    studies = prefix / "share" / "rollspec" / "studies"
    source = SOURCE / "studies"
    for ini in source.glob("*.ini"):
        assert (studies / ini.name).read_bytes() == ini.read_bytes(), ini.name
    assert tree(studies / "data") == tree(source / "data")
    scenes = [line.split(":")[0] for line in run(prefix / "bin" / "rollspec", "keys").stdout.splitlines()]
    assert sorted(p.stem for p in (studies / "templates").glob("*.ini")) == sorted(scenes)
    assert "rollspec init" in (studies / "templates" / "README.md").read_text()


def test_installed_study_plans_and_runs_from_elsewhere(prefix, tmp_path):
    rollspec = prefix / "bin" / "rollspec"
    studies = prefix / "share" / "rollspec" / "studies"
    before = tree(studies)
    # Reads 15 measured profiles through relative paths: they resolve against the study's directory.
    r = run(rollspec, "plan", studies / "seed001-beam-r.ini", cwd=tmp_path)
    assert "texture" in r.stdout
    for template in sorted((studies / "templates").glob("*.ini")):
        run(rollspec, "plan", template, cwd=tmp_path)
    run(rollspec, "run", studies / "random-oscillator.ini", "--set", "study.realisations=2", "--out", "r.h5", "--quiet",
        cwd=tmp_path)
    assert (tmp_path / "r.h5").is_file()
    assert tree(studies) == before  # planning and running wrote nothing into the installation


def test_man_page_study_file_section(prefix):
    man = prefix / "share" / "man" / "man1" / "rollspec.1"
    if os.environ.get("ROLLSPEC_MAN_PAGE") != "ON":
        pytest.skip("help2man was not found at configure time: no man page")
    text = man.read_text()
    section = text.split('.SH "STUDY FILE"')[1].split(".SH ")[0] if '.SH "STUDY FILE"' in text else ""
    assert section, "no STUDY FILE section"
    for words in ("INI", "[section]", "SI units", "rollspec keys", "rollspec init", "section.key", "share/rollspec/studies"):
        assert words in section.replace("\\-", "-").replace("\\fB", "").replace("\\fI", "").replace("\\fR", ""), words
    if shutil.which("man"):
        rendered = run("man", "-l", man, env=dict(os.environ, MANWIDTH="100", MANPAGER="cat", PAGER="cat")).stdout
        assert re.search(r"^STUDY FILE$", rendered, re.M)
