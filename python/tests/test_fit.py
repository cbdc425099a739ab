"""rollspec.studies.fit against `rollspec fit --format json` on the same input: the same object after json.loads
(a force level fitted to a synthetic measurement of the random oscillator, on 1 and 2 threads); a bad
request raises the command's one-line message before any run."""
import json
import os
import shutil
import subprocess
import time

import h5py
import numpy as np
import pytest

from rollspec import studies
from sigint_when import SigintWhen

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
# The random oscillator, short records, nine bands around its resonance (tests/cli/fit_experiment.py).
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
        "spectrum.band_max=200"]
RECORDS, REALISATIONS, TRUTH = 16, 20, 2.0


def command(*args):
    return subprocess.run([ROLLSPEC, *[str(a) for a in args]], capture_output=True, text=True)


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    """The study and a measured PSD of M records at force.level = TRUTH and another seed."""
    d = tmp_path_factory.mktemp("fit")
    study = d / "oscillator.ini"
    shutil.copy(os.path.join(SOURCE, "studies", "random-oscillator.ini"), study)
    sets = FAST + [f"force.level={TRUTH}", f"study.realisations={RECORDS}", "study.seed=4242"]
    r = command("run", study, "--out", d / "m.h5", "--quiet", *[a for s in sets for a in ("--set", s)])
    assert r.returncode == 0, r.stderr
    with h5py.File(d / "m.h5") as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][-1, 1:]
    np.savetxt(d / "m.csv", np.c_[freq, psd], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
    return study, d / "m.csv"


SETS = FAST + [f"study.realisations={REALISATIONS}"]


@pytest.fixture(scope="module")
def command_json(measured):
    study, csv = measured
    r = command("fit", study, csv, "--vary", "force.level=0.1:10:log", "--measured-averages", RECORDS,
                "--format", "json", *[a for s in SETS for a in ("--set", s)])
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


@pytest.mark.parametrize("threads", [1, 2])
def test_fit_returns_the_commands_json(measured, command_json, threads):
    study, csv = measured
    out = studies.fit(study, csv, vary="force.level=0.1:10:log", measured_averages=RECORDS, set=SETS,
                      threads=threads)
    assert out == command_json
    # A fit, not an empty answer: an estimate inside its interval (whether that holds the truth 95 % of the
    # time is tests/cli/test_fit_coverage.py's question, not one draw's).
    lo, hi = out["parameters"]["force.level"]["interval"]
    assert lo < out["parameters"]["force.level"]["estimate"] < hi


def test_a_bad_request_is_the_commands_line(measured, tmp_path):
    study, csv = measured
    with pytest.raises(ValueError, match=r"--vary force\.level given twice"):
        studies.fit(study, csv, vary=["force.level=1:2", "force.level=1:3"], measured_averages=RECORDS)
    with pytest.raises(ValueError, match=r"--set force\.level=3: force\.level is varied by --vary"):
        studies.fit(study, csv, vary="force.level=1:2", measured_averages=RECORDS, set=["force.level=3"])
    with pytest.raises(OSError, match="no such study file"):
        studies.fit(tmp_path / "none.ini", csv, vary="force.level=1:2", measured_averages=RECORDS)
    with pytest.raises(ValueError, match="threads"):
        studies.fit(study, csv, vary="force.level=1:2", measured_averages=RECORDS, threads=0)


def test_ctrl_c_stops_a_fit_and_its_journal_resumes_it(measured, command_json, tmp_path):
    # Ctrl-C in the Python session (SIGINT to this process) once the journal holds two evaluations:
    # KeyboardInterrupt naming the journal; called again with it, the fit reruns none it finished and
    # gives the uninterrupted fit's answer.
    study, csv = measured
    journal = tmp_path / "fit.journal"
    # the key and 2 evaluations
    watcher = SigintWhen(lambda: journal.exists() and len(journal.read_text().splitlines()) >= 3, timeout=120.0)
    with pytest.raises(KeyboardInterrupt, match="journal"):
        studies.fit(study, csv, vary="force.level=0.1:10:log", measured_averages=RECORDS, set=SETS,
                    journal=journal, threads=2)
    stopped = time.monotonic()
    assert watcher.join().sent, "the fit ended before its journal held two evaluations"
    print("Ctrl-C to KeyboardInterrupt: %.3f s" % (stopped - watcher.sent))
    done = len(journal.read_text().splitlines()) - 1
    assert done >= 2
    resumed = studies.fit(study, csv, vary="force.level=0.1:10:log", measured_averages=RECORDS, set=SETS,
                          journal=journal, threads=1)
    assert resumed["reused_from_journal"] == done
    assert resumed["evaluations"] == command_json["evaluations"] - done
    assert resumed["parameters"] == command_json["parameters"]
