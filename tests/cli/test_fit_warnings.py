"""`rollspec fit` runs the study many times; the runs' own warnings (a suspect key, loss of contact, a
band's heavy tail) are said once: how many runs warned, then those of the run at the estimate, instead
of once per run."""
import re

from conftest import SOURCE, measurement_from, run

STUDY = SOURCE / "studies" / "seed002-rig-1ms.ini"
SHORT = ["ball.end=0.15", "study.realisations=20"]  # 0.1 m of roll, 20 realisations: a few seconds per run


def sets(pairs):
    return [a for kv in pairs for a in ("--set", kv)]


def test_run_warnings_are_gathered_and_those_at_the_estimate_said_once(tmp_path):
    m = tmp_path / "m.h5"
    r = run(["run", STUDY, "--out", m, "--quiet", *sets(SHORT + ["study.seed=91"])])
    assert r.returncode == 0, r.stderr
    csv = measurement_from(m, tmp_path / "m.csv")
    # The range's top is rough enough for the ball to lose contact: the runs there warn (a suspect key, and
    # the loss of contact itself), the run at the estimate (the study's own roughness) need not.
    r = run(["fit", STUDY, csv, "--measured-averages", 20, "--fmin", 400, "--fmax", 3200,
             "--vary", "texture.rms=2e-8:2e-6:log", *sets(SHORT)])
    assert r.returncode == 0, r.stderr
    summary = re.findall(r"rollspec fit: (\d+) of (\d+) runs of the study warned; (.*)", r.stderr)
    assert len(summary) == 1, r.stderr
    warned, runs, at_estimate = int(summary[0][0]), int(summary[0][1]), summary[0][2]
    assert 1 <= warned < runs, r.stderr
    assert at_estimate == "the run at the estimate did not", r.stderr
    # None of the warned runs' lines reach the terminal: before, each run printed its own.
    assert "rollspec: warning:" not in r.stderr and "rollspec: WARNING:" not in r.stderr, r.stderr
