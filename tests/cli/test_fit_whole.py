"""Never lose a user's data III, fit: its keys are checked as a whole before the first run (each --vary
range against its key's type and range and at both ends, each --at point, --at naming a key twice), and
its journal is read only if it is a regular file (a FIFO or a device is refused at once), appended line
by line, and a torn last line is discarded, never reused. Each test fails on the build before this work."""
import json
import os
import signal
import subprocess
import time

import pytest

from conftest import BIN, EX_CANTCREAT, EX_CONFIG, EX_USAGE, assert_refused, run
from fit_experiment import FAST, RECORDS, REALISATIONS, STUDY, measurement, sets


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    return measurement(tmp_path_factory.mktemp("fit"), 4242, {"force.level": 2.0})


def fit_args(csv, *extra, vary="force.level=0.1:10:log"):
    return [str(a) for a in ["fit", STUDY, csv, "--vary", vary, "--measured-averages", RECORDS, "--format", "json",
                             *sets(FAST + [f"study.realisations={REALISATIONS}"]), *extra]]


@pytest.mark.parametrize("vary,code,fragments", [
    ("study.seed=1:100", EX_USAGE, ["takes a whole number", "varies real-valued keys only"]),
    ("force.level=-2:1", EX_USAGE, ["-2 lies outside the key's range", "allowed: a finite number > 0"]),
    ("force.lvel=1:2", EX_CONFIG, ["--vary force.lvel=1:2: ", "unknown key [force] lvel"]),
])
def test_vary_is_checked_against_its_key_before_any_run(measured, tmp_path, vary, code, fragments):
    r = run(fit_args(measured, vary=vary), env={"TMPDIR": str(tmp_path)}, timeout=60)
    assert_refused(r, code, fragments)
    assert "seed = 50.5" not in r.stderr and "level = -1.25" not in r.stderr
    assert not os.listdir(tmp_path), "a run was made before the refusal"


def test_a_vary_end_the_study_refuses_is_named_as_the_option(measured, tmp_path):
    # 0.01 s records hold no Welch segment (the study's 4096 samples at 2048 Hz): refused at that end
    r = run(["fit", STUDY, measured, "--vary", "signal.duration=0.01:8", "--measured-averages", RECORDS],
            env={"TMPDIR": str(tmp_path)}, timeout=60)
    assert_refused(r, EX_CONFIG, ["--vary signal.duration at 0.01: "])
    assert not os.listdir(tmp_path)


def test_at_names_a_key_once(measured):
    r = run(["fit", STUDY, "--measurement", measured, "--at", "oscillator.mass=2,oscillator.mass=3",
             "--vary", "force.level=0.1:10:log", "--measured-averages", RECORDS], timeout=60)
    assert_refused(r, EX_USAGE, ["oscillator.mass given twice", "each key once per --at"])


@pytest.mark.parametrize("kind", ["fifo", "/dev/zero", "directory"])
def test_a_journal_that_is_not_a_regular_file_is_refused_at_once(measured, tmp_path, kind):
    journal = {"fifo": tmp_path / "j", "/dev/zero": "/dev/zero", "directory": tmp_path}[kind]
    if kind == "fifo":
        os.mkfifo(journal)
    r = run(fit_args(measured, "--journal", journal), timeout=30)  # the build before hung on a FIFO
    assert_refused(r, EX_CANTCREAT, [f"--journal {journal} is "])


def interrupted_fit(csv, journal, lines):
    """A fit stopped (SIGINT) once its journal holds `lines` evaluations."""
    proc = subprocess.Popen([BIN, *fit_args(csv, "--journal", journal)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    deadline = time.time() + 300
    while time.time() < deadline and proc.poll() is None:
        if journal.exists() and len(journal.read_bytes().splitlines()) > lines:
            break
        time.sleep(0.02)
    proc.send_signal(signal.SIGINT)
    proc.communicate(timeout=120)
    assert proc.returncode == 130


def test_a_torn_last_line_is_discarded_not_reused(measured, tmp_path):
    journal = tmp_path / "fit.journal"
    interrupted_fit(measured, journal, 4)
    text = journal.read_bytes()
    assert text.endswith(b"\n")
    done = len(text.splitlines()) - 1
    journal.write_bytes(text[:-4])  # the last evaluation torn: its -ln L cut short, no newline
    r = run(fit_args(measured, "--journal", journal), timeout=600)
    assert r.returncode == 0, r.stderr
    resumed = json.loads(r.stdout)
    assert resumed["reused_from_journal"] == done - 1, "the torn line was reused as an evaluation"
    fresh = run(fit_args(measured, "--journal", tmp_path / "fresh.journal"), timeout=600)
    assert fresh.returncode == 0, fresh.stderr
    assert resumed["parameters"] == json.loads(fresh.stdout)["parameters"]
    # The journal was made whole again and then appended: every line ends, the same as the fresh one.
    assert journal.read_bytes() == (tmp_path / "fresh.journal").read_bytes()
