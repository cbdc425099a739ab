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
    assert offered == long_options(command)
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
    (("compare", "result.h5", ""), ["folder", "measured.csv"]),
    (("compare", "--fmin", "100", "result.h5", ""), ["folder", "measured.csv"]),
    (("compare", "result.h5", "measured.csv", ""), []),
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
