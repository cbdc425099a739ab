"""The bash completion (generated at build time from rollspec's help texts) against those texts.

The completion function is driven as bash drives it: COMP_WORDS / COMP_CWORD set, _rollspec called,
COMPREPLY printed. The help texts are parsed here independently (and more loosely) than by
cmake/cli_docs.cmake, so a command or an option the generator misses fails this test.
"""
import os
import pathlib
import re
import shlex
import subprocess

import pytest

BIN = os.environ["ROLLSPEC_BIN"]
COMPLETION = pathlib.Path(os.environ["ROLLSPEC_COMPLETION"])
BASH_COMPLETION = pathlib.Path("/usr/share/bash-completion/bash_completion")


def help_text(*args):
    r = subprocess.run([BIN, *args, "--help"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def commands():
    block = help_text().split("commands:\n")[1].split("\n\n")[0]
    found = re.findall(r"^\s+(\S+)\s", block, re.M)
    assert len(found) >= 9, block
    return found


def long_options(command):
    text = help_text(command)
    if "options:\n" not in text:  # `version --help` prints the version
        return []
    # An entry starts near the left margin ("  -o [ --out ] arg   text", "  --fs arg   text"); its
    # option is the first --name on the line. Continuation lines are indented further.
    entries = [line for line in text.split("options:\n")[1].splitlines() if re.match(r" {1,4}-", line)]
    return sorted(re.search(r"--[a-z][a-z0-9-]*", line).group(0) for line in entries)


def positional_options(command):
    """Options that only name a positional argument of the first usage line (STUDY.ini: --study,
    SIGNAL: --signal, [SCENE]: --scene): completed after they are typed, never offered."""
    text = help_text(command)
    if not text.startswith("usage:"):
        return set()
    first = text.split("\n\n")[0].split("\n       rollspec ")[0]
    return {"--" + m.lower() for m in re.findall(r"(?<![-\w])\[?([A-Z][A-Z_]+)(?:\.[a-z0-9]+)?\]?(?=[\s\]]|\.\.\.|$)",
                                                 first.split(command, 1)[1])
            if not re.search(r"--[a-z-]+ \[?" + m, first)}


def complete(*words, cwd=None):
    """COMPREPLY for the command line `words` with the cursor at the end of the last word."""
    script = (f"source {BASH_COMPLETION}\nsource {shlex.quote(str(COMPLETION))}\n"
              f"COMP_WORDS=({' '.join(shlex.quote(w) for w in words)})\n"
              f"COMP_CWORD={len(words) - 1}\nCOMP_LINE=\"${{COMP_WORDS[*]}}\"\nCOMP_POINT=${{#COMP_LINE}}\n"
              "_rollspec\nprintf '%s\\n' \"${COMPREPLY[@]}\"\n")
    r = subprocess.run(["bash", "-c", script], capture_output=True, text=True, cwd=cwd)
    assert r.returncode == 0, r.stderr
    return sorted(filter(None, r.stdout.split("\n")))


@pytest.fixture(scope="module", autouse=True)
def needs_bash_completion():
    if not BASH_COMPLETION.exists():
        pytest.skip("bash-completion is not installed (apt-get install bash-completion, or bash .ci/setup)")


def test_help_parsing_finds_real_options():
    """The test's own parsing: run has --out, --resume, --set; compare --measured-averages."""
    assert {"--out", "--resume", "--set", "--study", "--help"} <= set(long_options("run"))
    assert "--measured-averages" in long_options("compare")
    assert "--mea" not in long_options("compare")


def test_every_command_is_offered():
    assert complete("rollspec", "") == sorted(commands())
    assert complete("rollspec", "st") == ["stiffness"]
    assert complete("rollspec", "-") == ["--help", "--version", "-V", "-h"]


@pytest.mark.parametrize("command", commands())
def test_every_long_option_is_offered(command):
    offered = complete("rollspec", command, "--")
    assert offered == sorted(set(long_options(command)) - positional_options(command))
    if offered:
        assert complete("rollspec", command, "--he") == ["--help"]


@pytest.fixture()
def files(tmp_path):
    for name in ("study.ini", "result.h5", "measured.csv", "notes.txt"):
        (tmp_path / name).write_text("")
    (tmp_path / "folder").mkdir()
    return tmp_path


@pytest.mark.parametrize("words, expected", [
    (("run", ""), ["folder", "study.ini"]),                         # study file
    (("plan", "--set", "study.seed=1", ""), ["folder", "study.ini"]),  # after an option's value
    (("run", "study.ini", "--out", ""), ["folder", "result.h5"]),   # result file
    (("run", "-o", ""), ["folder", "result.h5"]),
    (("stiffness", "--out", ""), ["folder", "result.h5"]),
    (("texture", "--study", ""), ["folder", "study.ini"]),
    (("compare", ""), ["folder", "result.h5"]),                     # result, then measurement
    # recordings of any kind (CSV, WAV, FLAC, .mat) or a PSD table, one per roll: every file, again and again
    (("compare", "result.h5", ""), ["folder", "measured.csv", "notes.txt", "result.h5", "study.ini"]),
    (("compare", "--fmin", "100", "result.h5", ""), ["folder", "measured.csv", "notes.txt", "result.h5", "study.ini"]),
    (("compare", "result.h5", "measured.csv", ""), ["folder", "measured.csv", "notes.txt", "result.h5", "study.ini"]),
    (("compare", "result.h5", "measured.csv", "--noise", ""), ["folder", "measured.csv", "notes.txt", "result.h5",
                                                               "study.ini"]),
    (("compare", "--format", ""), ["csv", "json", "table"]),
    (("run", "--only", ""), []),                                    # a number: nothing offered
    (("version", ""), []),
])
def test_arguments_by_kind(files, words, expected):
    assert complete("rollspec", *words, cwd=files) == expected


def test_scene_names_after_keys():
    r = subprocess.run([BIN, "keys"], capture_output=True, text=True)
    scenes = sorted(re.findall(r"^([a-z][a-z0-9-]*):", r.stdout, re.M))
    assert "ball-on-beam" in scenes and len(scenes) >= 6
    assert complete("rollspec", "keys", "") == scenes
    assert complete("rollspec", "keys", "rolling-") == ["rolling-beam", "rolling-pipe"]
    assert complete("rollspec", "keys", "ball-on-beam", "") == []


def test_positional_options_are_hidden():
    assert positional_options("run") == {"--study"}
    assert positional_options("psd") == {"--signal"}
    assert positional_options("compare") == {"--result", "--measurement"}
    assert complete("rollspec", "run", "--st") == []
    assert complete("rollspec", "plan", "--s") == ["--set", "--sweep"]


def test_psd_completes_its_signal_and_options(files):
    assert complete("rollspec", "psd", "", cwd=files) == ["folder", "measured.csv", "notes.txt", "result.h5", "study.ini"]
    assert complete("rollspec", "psd", "--ti") == ["--time-column"]
    assert complete("rollspec", "psd", "--skip-rows", "3", "", cwd=files) == ["folder", "measured.csv", "notes.txt", "result.h5", "study.ini"]
    assert complete("rollspec", "psd", "--unit", "") == []  # UNIT: g, m/s2, mm/s2, in/s2, ... (free text)


def scene_keys():
    keys = set()
    scenes = re.findall(r"^([a-z][a-z0-9-]*):", subprocess.run([BIN, "keys"], capture_output=True, text=True).stdout, re.M)
    for scene in scenes:
        section = None
        for line in subprocess.run([BIN, "keys", scene], capture_output=True, text=True).stdout.splitlines():
            m = re.match(r"^\[(\w+)\]$", line)
            if m:
                section = m.group(1)
            m = re.match(r"^  (\w+) = ", line)
            if m and section:
                keys.add(f"{section}.{m.group(1)}=")
    return sorted(keys)


def test_set_completes_every_key_of_rollspec_keys():
    keys = scene_keys()
    assert "study.seed=" in keys and len(keys) > 30
    for command in ("run", "plan", "texture", "stiffness", "modes"):
        assert complete("rollspec", command, "--set", "") == keys
    assert complete("rollspec", "run", "--set", "study.se") == ["study.seed="]
    assert complete("rollspec", "plan", "s.ini", "--set", "spectrum.") == [k for k in keys if k.startswith("spectrum.")]


def test_set_completes_the_values_of_a_choice_key():
    # bash splits `--set spectrum.window=re` at '=': words --set, spectrum.window, =, re
    assert complete("rollspec", "run", "--set", "spectrum.window", "=", "") == ["hann", "rectangular"]
    assert complete("rollspec", "plan", "--set", "study.scene", "=", "rolling-") == ["rolling-beam", "rolling-pipe"]
    assert complete("rollspec", "run", "--set", "study.seed", "=", "") == []  # a number: nothing offered


def test_compare_and_fit_complete_measured_position():
    """The sensor nearest a place is one option of both commands that choose a result's row."""
    for command in ("compare", "fit"):
        assert complete("rollspec", command, "--measured-p") == ["--measured-position"]


def keys_of(scene):
    section, keys = None, set()
    for line in subprocess.run([BIN, "keys", scene], capture_output=True, text=True).stdout.splitlines():
        m = re.match(r"^\[(\w+)\]$", line)
        section = m.group(1) if m else section
        m = re.match(r"^  (\w+) = ", line)
        if m and section:
            keys.add(f"{section}.{m.group(1)}=")
    return sorted(keys)


def test_set_after_a_study_file_offers_its_scenes_keys_only(tmp_path):
    (tmp_path / "osc.ini").write_text("[study]\nscene = random-oscillator\nrealisations = 4\n")
    (tmp_path / "rig.ini").write_text("# my rig\n[study]\n  scene=ball-on-beam   # the beam\n")
    (tmp_path / "odd.ini").write_text("[study]\nscene = no-such-scene\n")
    oscillator = keys_of("random-oscillator")
    assert "oscillator.mass=" in oscillator and "beam.length=" not in oscillator
    for command in ("run", "plan", "texture", "stiffness", "modes"):
        assert complete("rollspec", command, "osc.ini", "--set", "", cwd=tmp_path) == oscillator
    assert complete("rollspec", "run", "--set", "study.seed=1", "osc.ini", "--set", "o", cwd=tmp_path) == \
        [k for k in oscillator if k.startswith("o")]
    assert complete("rollspec", "texture", "--study", "rig.ini", "--set", "beam.le", cwd=tmp_path) == ["beam.length="]
    assert complete("rollspec", "plan", "rig.ini", "--set", "", cwd=tmp_path) == keys_of("ball-on-beam")
    # No study file yet, an unreadable one or an unknown scene: every key, as before.
    assert complete("rollspec", "run", "--set", "", cwd=tmp_path) == scene_keys()
    assert complete("rollspec", "run", "absent.ini", "--set", "", cwd=tmp_path) == scene_keys()
    assert complete("rollspec", "run", "odd.ini", "--set", "", cwd=tmp_path) == scene_keys()
