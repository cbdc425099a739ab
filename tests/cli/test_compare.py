"""`rollspec compare` asks the user's question (kernels/spectral D-21, D-22).

A "measurement" made from 25 realisations of the same ball-on-beam study with another seed must
agree with the model: with --measured-averages 25, >= 80 % of the bands from 100 Hz to 5 kHz lie
inside the prediction interval. A model with twice the roughness PSD must be told apart. The
output names the sensor and the question; csv reads in pandas with numeric columns; json holds
the same numbers; the output of `rollspec psd` chains into --column."""
import json

import h5py
import numpy as np
import pytest

from conftest import EX_USAGE, SOURCE, assert_refused, measurement_from, run, study_result

STUDY = SOURCE / "studies" / "seed001-beam-s-hertz.ini"


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("compare")
    model = study_result(STUDY, d, "model", "study.seed=1")
    rough = study_result(STUDY, d, "rough", "study.seed=1", "texture.rms=0.509e-6")  # rms x sqrt(2): twice the PSD
    few = study_result(STUDY, d, "few", "study.seed=1", "study.realisations=3")
    meas = measurement_from(study_result(STUDY, d, "measured", "study.seed=2"), d / "measured.csv")
    return {"model": model, "rough": rough, "few": few, "meas": meas, "dir": d}


def table_lines(r):
    """The output without the loss-of-contact WARNING or note line (this study's ball flies: it is flagged,
    test_loss_of_contact_flags.py)."""
    return [line for line in r.stdout.splitlines() if not line.startswith(("WARNING: ", "note: "))]


def last_line(r):
    assert r.returncode == 0, r.stderr
    line = r.stdout.strip().splitlines()[-1]
    assert line.startswith("rms_db_error:")
    inside, judged = map(int, line.split()[3].split("/"))
    return float(line.split()[1]), inside, judged


def test_a_measurement_of_the_same_model_lies_inside_its_prediction_interval(files):
    rms, inside, judged = last_line(run(["compare", files["model"], files["meas"], "--fmin", 100, "--fmax", 5000,
                                         "--measured-averages", 25]))
    assert judged == 16 and inside >= 0.8 * judged and rms < 1.0
    # The interval of the simulated mean alone ignores the measurement's own scatter: it holds fewer.
    _, inside_mean, _ = last_line(run(["compare", files["model"], files["meas"], "--fmin", 100, "--fmax", 5000]))
    assert inside_mean < inside


def test_a_model_with_twice_the_roughness_psd_is_told_apart(files):
    rms, inside, judged = last_line(run(["compare", files["rough"], files["meas"], "--fmin", 100, "--fmax", 5000,
                                         "--measured-averages", 25]))
    assert rms > 2.0 and inside <= 0.25 * judged


def test_the_output_names_the_sensor_and_the_question(files):
    r = run(["compare", files["model"], files["meas"]])
    head = table_lines(r)[:2]
    assert "sensor sensor_mean" in head[0] and "(25 realisations)" in head[0]
    assert "interval of the simulated mean" in head[1] and "--measured-averages" in head[1]
    r = run(["compare", files["model"], files["meas"], "--measured-averages", 25, "--sensor", "sensor_2"])
    assert "sensor sensor_2" in table_lines(r)[0]
    assert "prediction interval of a measurement averaged over M = 25" in table_lines(r)[1]
    # A number is the K of sensor_K, the name's own count (1-based), not a row index.
    assert "sensor sensor_2" in run(["compare", files["model"], files["meas"], "--sensor", 2]).stdout
    assert "sensor sensor_3" in run(["compare", files["model"], files["meas"], "--sensor", 3]).stdout
    for wrong in ("sensor_9", "0", "4"):
        r = run(["compare", files["model"], files["meas"], "--sensor", wrong])
        assert r.returncode == EX_USAGE and "has the sensors sensor_1, sensor_2, sensor_3, sensor_mean" in r.stderr
        assert "allowed: a name, or the number K of sensor_K" in r.stderr
    assert r.stdout == ""


def test_csv_reads_in_pandas_and_json_holds_the_same_numbers(files):
    import pandas as pd
    r = run(["compare", files["model"], files["meas"], "--measured-averages", 25, "--format", "csv"])
    assert r.returncode == 0, r.stderr
    csv = files["dir"] / "table.csv"
    csv.write_text(r.stdout)
    t = pd.read_csv(csv)  # the table alone: the summary goes to stderr
    assert all(t[c].dtype.kind in "fi" for c in t.columns if c != "use"), t.dtypes
    assert set(t["use"]) <= {"test", "noise floor", "flat floor"}
    assert "combined_test:" in r.stderr and "#" not in r.stdout
    j = json.loads(run(["compare", files["model"], files["meas"], "--measured-averages", 25, "--format", "json"]).stdout)
    assert j["sensor"] == "sensor_mean" and j["measured_averages"] == 25 and j["realisations"] == 25
    assert len(j["bands"]) == len(t)
    np.testing.assert_allclose([b["prediction_lower_db"] for b in j["bands"]], t["prediction_lower_db"], rtol=1e-9)
    assert j["inside"] == int(t["inside"].sum())


def test_psd_output_chains_into_compare_by_column(files, tmp_path):
    rng = np.random.default_rng(5)
    fs, n = 25600, 25600 * 4
    sig = tmp_path / "signal.csv"
    np.savetxt(sig, np.c_[rng.normal(size=n), 0.1 * rng.normal(size=n)], delimiter=",", header="ch1,ch3", comments="")
    out = tmp_path / "m.csv"
    r = run(["psd", sig, "--fs", fs, "--segment", 4096, "--out", out])
    assert r.returncode == 0, r.stderr
    r = run(["compare", files["model"], out, "--column", "ch3"])
    assert r.returncode == 0, r.stderr
    assert "column ch3" in r.stdout.splitlines()[0]
    white = 10 * np.log10(2 * 0.01 / fs)  # one-sided PSD of white noise of variance 0.01
    rows = [line.split() for line in table_lines(r)[3:-1]]
    assert len(rows) >= 10 and all(abs(float(x[2]) - white) < 1.0 for x in rows)
    r = run(["compare", files["model"], out])
    assert_refused(r, EX_USAGE, ["m.csv: 2 PSD columns (ch1, ch3", "no --column", "allowed: --column NAME"])


def test_too_few_realisations_give_no_interval_and_say_so(files):
    r = run(["compare", files["few"], files["meas"], "--measured-averages", 25])
    assert "question: none" in r.stdout and "fewer than the 5" in r.stdout
    assert r.stdout.strip().endswith("inside_ci: 0/0")


@pytest.mark.parametrize("args,fragment", [
    (["--fmin", "nan"], "--fmin nan: allowed: a finite frequency"),
    (["--fmin", "inf"], "--fmin inf: allowed: a finite frequency"),
    (["--fmin", 500, "--fmax", 100], "--fmax 100: allowed: a frequency above --fmin"),
    (["--measured-averages", 0.5], "--measured-averages 0.5: allowed: a finite count >= 1"),
    (["--format", "xml"], "--format xml: allowed: table, csv or json"),
])
def test_bad_options_are_refused(files, args, fragment):
    r = run(["compare", files["model"], files["meas"], *args])
    assert r.returncode == EX_USAGE and fragment in r.stderr and r.stdout == ""


def test_a_band_of_a_bin_or_two_is_warned_about(tmp_path):
    # As `fit` (kernels/spectral D-27h): on 16 Hz bins (spectrum.segment = 64 at 1024 Hz) the bands below ~110 Hz
    # span about a bin; the measurement's rule (points joined linearly) and the result's (its bins) read them
    # differently, by several of the band's standard deviations beside the 50 Hz resonance.
    from fit_experiment import FAST, STUDY, measurement, sets
    measured = measurement(tmp_path, 4243, {"force.level": 2.0})
    for segment, warned in ((64, True), (2048, False)):
        out = tmp_path / f"model-{segment}.h5"
        r = run(["run", STUDY, "--out", out, "--quiet",
                 *sets(FAST + ["study.realisations=40", f"spectrum.segment={segment}"])])
        assert r.returncode == 0, r.stderr
        r = run(["compare", out, measured, "--measured-averages", 16])
        assert r.returncode == 0, r.stderr
        lines = [x for x in r.stderr.splitlines() if "grid read differently" in x]
        if warned:  # one line naming the bands
            assert len(lines) == 1 and "of the result's 16 Hz grid" in lines[0] and "D-27h" in lines[0], r.stderr
            assert "70.79 .. 89.13 Hz (1.1 bins" in lines[0], lines[0]
        else:
            assert not lines, r.stderr
    # Without --measured-averages the question is the mean's own interval: no such warning.
    r = run(["compare", tmp_path / "model-64.h5", measured])
    assert r.returncode == 0 and "grid read differently" not in r.stderr, r.stderr
