"""`rollspec fit` of several measurements, each at its operating point (--measurement FILE --at KEYS),
with shared unknowns (kernels/spectral D-27f), and --journal: an interrupted fit resumed without
rerunning its finished evaluations."""
import os
import signal
import subprocess
import time

import pytest

from conftest import BIN, EX_CANTCREAT, EX_CONFIG, EX_DATAERR, EX_INTERRUPTED, EX_USAGE, assert_refused, run
from fit_experiment import FAST, RECORDS, REALISATIONS, STUDY, fit, measurement, sets

TRUTH = 2.0  # force.level, shared by both operating points
POINTS = (50, 80)  # oscillator.natural_frequency of the two measurements (Hz)


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    d = tmp_path_factory.mktemp("joint")
    return [measurement(d, 7100 + i, {"force.level": TRUTH, "oscillator.natural_frequency": fn})
            for i, fn in enumerate(POINTS)]


def joint(measured, *extra, fmt="json"):
    args = ["fit", STUDY, "--vary", "force.level=0.1:10:log", "--measured-averages", RECORDS, "--format", fmt,
            *sets(FAST + [f"study.realisations={REALISATIONS}"])]
    for csv, fn in zip(measured, POINTS):
        args += ["--measurement", csv, "--at", f"oscillator.natural_frequency={fn}"]
    return run(args + list(extra))


def test_joint_fit_recovers_the_shared_level_with_a_narrower_interval(measured):
    import json
    r = joint(measured)
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    p = out["parameters"]["force.level"]
    lo, hi = p["interval"]
    assert lo < p["estimate"] < hi
    assert abs(p["estimate"] - TRUTH) < 2.0 * (hi - lo) / 2.0  # fails about once in 10^4 (test_fit.py)
    assert [q["at"] for q in out["points"]] == [f"oscillator.natural_frequency={fn}" for fn in POINTS]
    assert all(0.0 < q["p_value"] <= 1.0 and q["bands"] == 9 for q in out["points"])
    assert out["bands"] == 18 and 0.0 < out["p_value"] <= 1.0
    # Each point alone, fitted at its own natural frequency: twice the data narrows the log interval by
    # about 1/sqrt(2); asserted: narrower than either alone (a level's width hardly varies between seeds).
    for csv, fn in zip(measured, POINTS):
        single, rs = fit(csv, {"force.level": "0.1:10:log"}, "--set", f"oscillator.natural_frequency={fn}")
        assert single is not None, rs.stderr
        slo, shi = single["parameters"]["force.level"]["interval"]
        assert hi / lo < shi / slo


def test_text_output_lists_each_point(measured):
    r = joint(measured, fmt="text")
    assert r.returncode == 0, r.stderr
    assert "joint fit over 2 points, 18 bands in all" in r.stdout
    assert "point 2: " in r.stdout and "at oscillator.natural_frequency=80" in r.stdout
    assert "Fisher's combination of the 2 points' tests" in r.stdout


@pytest.mark.parametrize("extra, code, words", [
    (["--measurement", "EXTRA"], EX_USAGE, ["3 measurements and 2 --at", "one --at per measurement"]),
    (["--at", "ball.speed=1"], EX_USAGE, ["2 measurements and 3 --at"]),
    (["--measured-averages", "16", "--measured-averages", "16"], EX_USAGE,
     ["--measured-averages given 3 times for 2 measurements"]),
])
def test_unpaired_points_are_refused(measured, extra, code, words):
    extra = [str(measured[0]) if e == "EXTRA" else e for e in extra]
    assert_refused(joint(measured, *extra), code, words)


def test_bad_at_is_refused(measured, tmp_path):
    base = ["fit", STUDY, "--vary", "force.level=0.1:10:log", "--measured-averages", RECORDS,
            "--set", f"study.realisations={REALISATIONS}"]
    r = run(base + ["--measurement", measured[0], "--at", "oscillator.natural_frequency"])
    assert_refused(r, EX_USAGE, ["--at oscillator.natural_frequency", "section.key=value"])
    r = run(base + ["--measurement", measured[0], "--at", "force.level=3"])
    assert_refused(r, EX_USAGE, ["force.level is varied by --vary"])
    r = run(base + ["--measurement", measured[0], "--at", "oscillator.natural_frequenc=60"])
    assert_refused(r, EX_CONFIG, ["natural_frequenc"])
    bad = tmp_path / "bad.csv"
    bad.write_text("frequency_hz,psd\n1,2\n2,x\n")
    r = run(base + ["--measurement", measured[0], "--at", "oscillator.mass=2", "--measurement", bad, "--at",
                    "oscillator.mass=3"])
    assert_refused(r, EX_DATAERR, [f"{bad}:3"])


def start_fit(measured, journal):
    cmd = [str(a) for a in ["fit", STUDY, measured[0], "--vary", "force.level=0.1:10:log", "--measured-averages", RECORDS,
                            "--format", "json", "--journal", journal,
                            *sets(FAST + [f"study.realisations={REALISATIONS}"])]]
    return [BIN] + cmd


def test_an_interrupted_fit_resumes_from_its_journal(measured, tmp_path):
    import json
    journal = tmp_path / "fit.journal"
    temp = tmp_path / "temp"  # the fit's run files go here (TMPDIR); an interrupt leaves none
    temp.mkdir()
    proc = subprocess.Popen(start_fit(measured, journal), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=dict(os.environ, TMPDIR=str(temp)))
    deadline = time.time() + 300
    while time.time() < deadline and proc.poll() is None:
        if journal.exists() and len(journal.read_text().splitlines()) >= 6:  # the key and 5 evaluations
            break
        time.sleep(0.02)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == EX_INTERRUPTED, err
    done = len(journal.read_text().splitlines()) - 1
    assert done >= 5
    assert not list(tmp_path.glob("fit.journal.tmp-*"))
    assert not list(temp.iterdir())
    r = subprocess.run(start_fit(measured, journal), capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    resumed = json.loads(r.stdout)
    assert resumed["reused_from_journal"] == done
    # The same fit uninterrupted: the same numbers bit for bit, and `done` more study runs.
    fresh = subprocess.run(start_fit(measured, tmp_path / "other.journal"), capture_output=True, text=True)
    assert fresh.returncode == 0, fresh.stderr
    whole = json.loads(fresh.stdout)
    assert whole["reused_from_journal"] == 0
    assert resumed["parameters"] == whole["parameters"]
    assert resumed["evaluations"] == whole["evaluations"] - done
    # Another fit (another measurement) refuses the journal instead of reusing its values.
    other = start_fit([measured[1]], journal)
    assert_refused(subprocess.run(other, capture_output=True, text=True), EX_CANTCREAT,
                   [str(journal), "the journal of another fit"])
