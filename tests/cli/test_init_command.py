"""rollspec init SCENE: a commented study template that loads, plans and runs as it stands, whose first keys
carry their unit and meaning from the key table, and which never replaces a file it did not write."""
import re
import subprocess

import h5py
import pytest

from conftest import BIN, EX_CANTCREAT, EX_USAGE, assert_refused, run

SCENES = ["random-oscillator", "ball-on-beam", "rolling-beam", "rolling-pipe", "stiffness", "texture"]
OWN_COMMAND = {"stiffness": "stiffness", "texture": "texture"}  # scenes without an ensemble
FIRST_PART = "# ==== The keys to set first ===="
REST_PART = "# ==== Every other key"


def keys_table(scene):
    """{section.key: (default or None, unit or None)} from `rollspec keys SCENE`."""
    r = run(["keys", scene])
    assert r.returncode == 0, r.stderr
    table, section, key = {}, None, None
    for line in r.stdout.splitlines():
        if m := re.match(r"^\[(.+)\]$", line):
            section = m.group(1)
        elif m := re.match(r"^  (\w+) = (.*)$", line):
            key = f"{section}.{m.group(1)}"
            table[key] = [None if m.group(2) == "(required)" else m.group(2), None]
        elif m := re.match(r"^      allowed: a (?:finite|whole) number(?: in [\[(][^\])]*[\])]| [<>]=? \S+)?"
                           r"(?:, a power of two)? \((.+)\)$", line):
            table[key][1] = m.group(1)
    return {k: tuple(v) for k, v in table.items()}


def template(scene, tmp_path, name=None):
    path = tmp_path / (name or f"{scene}.ini")
    r = run(["init", scene, "--out", path])
    assert r.returncode == 0, r.stderr
    return path


def first_keys(text):
    """[(section.key, value, comment lines above it)] of the uncommented part."""
    part = text.split(FIRST_PART)[1].split(REST_PART)[0]
    out, section, comment = [], None, []
    for line in part.splitlines():
        if m := re.match(r"^\[(.+)\]$", line):
            section, comment = m.group(1), []
        elif line.startswith("#"):
            comment.append(line.lstrip("#").strip())
        elif m := re.match(r"^(\w+) = (.*)$", line):
            out.append((f"{section}.{m.group(1)}", m.group(2), " ".join(comment)))
            comment = []
    return out


def run_study(scene, study, tmp_path, *edits):
    command = OWN_COMMAND.get(scene, "run")
    out = tmp_path / f"{study.stem}.h5"
    # One realisation: the template's scene, tables and writer all run; more would only repeat them
    # (the rolling pipe's template takes minutes per realisation under the sanitizers).
    sets = [] if command != "run" else ["--set", "study.realisations=1"]
    r = run([command, study, "--out", out, "--quiet", *sets] if command == "run" else [command, study, "--out", out])
    assert r.returncode == 0, f"{command} {study}: exit {r.returncode}\n{r.stderr[-3000:]}"
    return out


# The rolling pipe's template runs for minutes under the sanitizers: long, which their pass skips.
@pytest.mark.parametrize("scene", [pytest.param(s, marks=pytest.mark.long) if s == "rolling-pipe" else s for s in SCENES])
def test_template_loads_plans_and_runs(scene, tmp_path):
    study = template(scene, tmp_path)
    assert study.read_text().startswith("# rollspec-study-template")
    r = run(["plan", study])
    assert r.returncode == 0, r.stderr
    out = run_study(scene, study, tmp_path)
    with h5py.File(out) as f:
        assert f.attrs["filetype"]


def test_scene_list_is_the_registry():
    assert SCENES == [line.split(":")[0] for line in run(["keys"]).stdout.splitlines()]
    assert run(["init"]).stdout == run(["keys"]).stdout


@pytest.mark.parametrize("scene", SCENES)
def test_first_keys_carry_unit_meaning_and_default(scene, tmp_path):
    table = keys_table(scene)
    text = template(scene, tmp_path).read_text()
    first = first_keys(text)
    assert len(first) >= 8, first
    assert first[0][:2] == ("study.scene", scene)
    assert {"study.realisations", "study.seed"} <= {k for k, _, _ in first}
    for key, value, comment in first:
        default, unit = table[key]
        assert comment, f"{key} has no comment"
        if unit:
            assert f"[unit: {unit}]" in comment, (key, comment)
        assert ("required" if default is None else f"default: {default or 'empty'}") in comment, (key, comment)
    # Every other key once, commented out at its table default.
    rest = text.split(REST_PART)[1]
    commented = dict(re.findall(r"^# (\w+) = (.*)$", rest, re.M))
    sections = re.findall(r"^\[(.+)\]$", rest, re.M)
    assert len(sections) == len(set(sections))
    listed = {k for k, _, _ in first}
    for key, (default, _) in table.items():
        if key in listed:
            continue
        assert commented.get(key.split(".")[1]) is not None, f"{key} missing from the template"
        assert f"[{key.split('.')[0]}]" in rest
    assert len(re.findall(r"^# \w+ = ", rest, re.M)) == len(table) - len(listed)


def test_stdout_is_the_file(tmp_path):
    assert run(["init", "ball-on-beam"]).stdout == template("ball-on-beam", tmp_path).read_text()


def test_user_edits_five_keys_and_runs(tmp_path):
    """A 1 m steel beam, a 30 mm ball at 2 m/s, the record over most of the span, two accelerometers."""
    study = template("ball-on-beam", tmp_path, "rig.ini")
    text = study.read_text()
    edits = {"length": ("0.4", "1"), "radius": ("0.02", "0.015"), "speed": ("1", "2"), "end": ("0.35", "0.9"),
             "positions": ("0.2", "0.3, 0.5")}
    for key, (old, new) in edits.items():
        line = f"\n{key} = {old}\n"
        assert text.count(line) == 1, key
        text = text.replace(line, f"\n{key} = {new}\n")
    study.write_text(text)
    assert run(["plan", study]).returncode == 0
    with h5py.File(run_study("ball-on-beam", study, tmp_path)) as f:
        stored = f.attrs["study"]
        stored = stored.decode() if isinstance(stored, bytes) else stored
    for key, (_, new) in edits.items():
        assert re.search(rf"^{key} = {re.escape(new.replace(' ', ''))}$", stored.replace(", ", ","), re.M), key


def test_refuses_a_file_it_did_not_write(tmp_path):
    notes = tmp_path / "rig.ini"
    notes.write_text("[study]\nscene = ball-on-beam\n# my own study, hours of work\n")
    r = run(["init", "ball-on-beam", "--out", notes])
    assert_refused(r, EX_CANTCREAT, [str(notes), "not a study written by rollspec init", "--force"])
    assert notes.read_text().startswith("[study]\nscene = ball-on-beam\n# my own")
    assert not list(tmp_path.glob("rig.ini.tmp-*"))
    # An edited template is the user's work too; the unedited one is written again as it is.
    study = template("ball-on-beam", tmp_path)
    assert run(["init", "ball-on-beam", "--out", study]).returncode == 0
    study.write_text(study.read_text().replace("\nspeed = 1\n", "\nspeed = 2\n"))
    assert_refused(run(["init", "ball-on-beam", "--out", study]), EX_CANTCREAT, ["edited since", "--force"])
    assert "\nspeed = 2\n" in study.read_text()
    r = run(["init", "texture", "--out", notes, "--force"])
    assert r.returncode == 0, r.stderr
    assert notes.read_text() == run(["init", "texture"]).stdout
    assert_refused(run(["init", "texture", "--out", tmp_path]), EX_CANTCREAT, ["directory"])


@pytest.mark.parametrize("scene", ["ball_on_beam", "", "beam"])
def test_unknown_scene_names_the_scenes(scene, tmp_path):
    r = run(["init", scene, "--out", tmp_path / "s.ini"]) if scene else run(["init", "--scene", "nope"])
    assert_refused(r, EX_USAGE, ["unknown scene", *SCENES])
    assert not (tmp_path / "s.ini").exists()


def test_usage_and_output_errors(tmp_path):
    r = run(["init", "--help"])
    assert r.returncode == 0 and r.stdout.startswith("usage: rollspec init")
    assert_refused(run(["init", "ball-on-beam", "--frobnicate"]), EX_USAGE, ["frobnicate", "usage: rollspec init"])
    assert_refused(run(["init", "ball-on-beam", "--out", tmp_path / "missing" / "s.ini"]), EX_CANTCREAT,
                   ["cannot create output file", "missing/s.ini"])
    with open("/dev/full", "w") as full:
        r = subprocess.run([BIN, "init", "ball-on-beam"], stdout=full, stderr=subprocess.PIPE, text=True)
    assert r.returncode == 74 and "cannot write standard output" in r.stderr, r.stderr
