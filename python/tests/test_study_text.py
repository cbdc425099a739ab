"""rollspec.studies.Study from text and from a dict against `rollspec run` on the same study: the result data are
the command's bit for bit, `set` as a list or a dict is the command's --set, and a bad line or key raises the
command's one-line message (the file's name replaced by "<string>" or "<dict>" when the text has no path). A text
study's checkpoint resumes from the same text and refuses another, as the command's does with its study file."""
import configparser
import os
import subprocess

import h5py
import pytest

from rollspec import studies
from sigint_when import SigintWhen, has_chunk

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
STUDY = os.path.join(SOURCE, "studies", "random-oscillator.ini")
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "ensemble.chunk_size=16",
        "study.realisations=40"]
DATA = ["/psd/mean", "/psd/frequency", "/bands/level_db", "/bands/ci_lower_db", "/bands/ci_upper_db", "/bands/std"]
PREFIX = "rollspec run: error: "


def command(study, out, sets):
    return subprocess.run([ROLLSPEC, "run", str(study), "--out", str(out), "--quiet",
                           *[a for s in sets for a in ("--set", s)]], capture_output=True, text=True)


def same_data(a, b):
    with h5py.File(a) as fa, h5py.File(b) as fb:
        for name in DATA:
            x, y = fa[name][...], fb[name][...]
            assert x.dtype == y.dtype and x.shape == y.shape and x.tobytes() == y.tobytes(), name


def study_text():
    with open(STUDY) as f:
        return f.read()


def study_dict():
    """The study file's sections and keys as a Python user writes them: numbers as numbers."""
    ini = configparser.ConfigParser(inline_comment_prefixes=("#",), interpolation=None)
    ini.read(STUDY)
    out = {}
    for section in ini.sections():
        out[section] = {}
        for key, text in ini[section].items():
            for kind in (int, float):
                try:
                    out[section][key] = kind(text)
                    break
                except ValueError:
                    pass
            else:
                out[section][key] = text
    return out


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    out = tmp_path_factory.mktemp("command") / "command.h5"
    r = command(STUDY, out, FAST)
    assert r.returncode == 0, r.stderr
    return out


def test_a_study_from_text_holds_the_commands_bits(reference, tmp_path):
    study = studies.Study.from_text(study_text())
    assert study.path is None and study.text == study_text()
    same_data(reference, studies.run(study, tmp_path / "text.h5", set=FAST, threads=2))
    # Without out, a study of no path has no name to give its result.
    with pytest.raises(ValueError, match="out = None: a study from text or a dict has no file name"):
        studies.run(study, set=FAST)


def test_a_study_from_a_dict_holds_the_commands_bits(reference, tmp_path):
    sections = study_dict()
    assert sections["oscillator"]["mass"] == 2.0 and sections["signal"]["sample_rate"] == 2048
    study = studies.Study.from_dict(sections)
    assert "[oscillator]\nmass = 2.0\n" in study.text
    # `set` as a dict is the command's --set of each item.
    sets = dict(s.split("=", 1) for s in FAST)
    sets["signal.duration"] = 4.0
    same_data(reference, studies.run(study, tmp_path / "dict.h5", set=sets, threads=1))


def test_a_study_with_a_path_is_read_as_that_file(reference, tmp_path, monkeypatch):
    path = tmp_path / "oscillator.ini"
    study = studies.Study.from_text(study_text(), path=path)
    assert study.path == str(path)
    monkeypatch.chdir(tmp_path)
    assert studies.run(study, set=FAST) == "oscillator.h5"  # the command's default name: the study's
    same_data(reference, tmp_path / "oscillator.h5")
    same_data(reference, studies.run(studies.Study.from_file(STUDY), tmp_path / "file.h5", set=FAST))


def test_errors_in_the_text_are_the_commands_line(tmp_path):
    text = study_text().replace("mass = 2.0", "mass = -2.0").replace("overlap = 0.5", "overlap = 0.5\nwindow_kind = x")
    for bad, key in ((text, "[oscillator] mass = -2.0: out of range"),
                     (text.replace("mass = -2.0", "mass = 2.0"), "unknown key [spectrum] window_kind = x")):
        path = tmp_path / "bad.ini"
        path.write_text(bad)
        r = command(path, tmp_path / "c.h5", FAST)
        assert r.returncode == 78 and r.stderr.startswith(PREFIX), r.stderr
        line = r.stderr.strip().splitlines()[-1][len(PREFIX):]
        entry = key.split("] ")[1].split(":")[0]  # "mass = -2.0"
        number = next(i for i, t in enumerate(bad.splitlines(), 1) if t.startswith(entry))
        assert line.startswith(f"{path}:{number}: {key}"), line
        with pytest.raises(ValueError) as e:
            studies.Study.from_text(bad, path=path)
        assert str(e.value) == line
        with pytest.raises(ValueError) as e:
            studies.Study.from_text(bad)
        assert str(e.value) == line.replace(str(path), "<string>")
    assert not (tmp_path / "c.h5").exists()


def test_errors_in_a_dict_name_the_key(tmp_path):
    sections = study_dict()
    sections["oscillator"]["mass"] = -1.0
    path = tmp_path / "bad.ini"
    path.write_text(studies.Study.from_text(study_text()).text.replace("mass = 2.0", "mass = -1.0"))
    r = command(path, tmp_path / "c.h5", FAST)
    assert r.returncode == 78, r.stderr
    with pytest.raises(ValueError) as e:
        studies.Study.from_dict(sections)
    assert "<dict>" in str(e.value) and "mass" in str(e.value) and "-1" in str(e.value)
    assert "oscillator" in str(e.value) and "allowed" in str(r.stderr) and "allowed" in str(e.value)
    for bad, what in (({"study": {"scene": ["a", {}]}}, "study.scene = {}: is a dict"),
                      ({"study": 3}, "study = 3: is not a dict"),
                      ({"study": {"description": "two\nlines"}}, "holds a line break")):
        with pytest.raises(ValueError, match=what):
            studies.Study.from_dict(bad)
    with pytest.raises(ValueError, match="text = '': is empty"):
        studies.Study.from_text(" \n")
    with pytest.raises(OSError, match="no-such.ini"):
        studies.Study.from_file(tmp_path / "no-such.ini")
    with pytest.raises(TypeError, match="allowed: a study file's path, or a rollspec.studies.Study"):
        studies.run({"study": {}}, tmp_path / "m.h5")


def test_a_text_study_resumes_its_own_checkpoint_and_refuses_another(tmp_path):
    sets = [s for s in FAST if not s.startswith("study.realisations")] + ["study.realisations=5000"]
    out, checkpoint = tmp_path / "m.h5", tmp_path / "m.h5.checkpoint"

    study = studies.Study.from_text(study_text())
    watcher = SigintWhen(lambda: has_chunk(checkpoint))
    with pytest.raises(KeyboardInterrupt, match="resume=True"):
        studies.run(study, out, set=sets, threads=2)
    watcher.join()
    assert checkpoint.is_dir() and not out.exists()
    # Another study's text is refused by the checkpoint, as the command refuses another study file.
    other = studies.Study.from_text(study_text().replace("mass = 2.0", "mass = 3.0"))
    with pytest.raises(ValueError, match=r"the checkpoint belongs to a different study \(the study file changed\)"
                                         r":\n  \[oscillator\] mass = 3"):
        studies.run(other, out, set=sets, resume=True)
    assert studies.run(study, out, set=sets, resume=True, threads=1) == str(out)
    assert not checkpoint.exists()
    assert command(STUDY, tmp_path / "whole.h5", sets).returncode == 0
    same_data(tmp_path / "whole.h5", out)


def test_a_sweep_from_text_holds_the_commands_bits_and_plan_refuses_it(tmp_path):
    text = study_text() + "\n[sweep]\noscillator.mass = 1, 2\n"
    path = tmp_path / "sweep.ini"
    path.write_text(text)
    sets = FAST[:-1] + ["study.realisations=8"]
    assert command(path, tmp_path / "command.h5", sets).returncode == 0
    study = studies.Study.from_text(text)
    same_data(tmp_path / "command.h5", studies.run(study, tmp_path / "module.h5", set=sets))
    with pytest.raises(ValueError, match="study = <string>: has a \\[sweep\\]"):
        studies.plan(study)
    n = text.splitlines().index("oscillator.mass = 1, 2") + 1
    refused = f"^<string>:{n}: \\[sweep\\] oscillator.mass = 1, -2: the value -2 is refused"
    with pytest.raises(ValueError, match=refused):
        studies.Study.from_text(text.replace("mass = 1, 2", "mass = 1, -2"))
