"""`rollspec compare`'s combined test over bands (kernels/spectral D-26) on the seed 002 rig.

A 25-roll "measurement" of the same model (another study seed) is not rejected; one with twice the
beam's loss factor is, although most of its bands lie inside their prediction intervals. The result
holds the between-band covariance of the band logs it uses (its diagonal is /bands/log_std squared);
a result with too few realisations for the bands gets no test, and the K it would need is named."""
import json

import h5py
import numpy as np
import pytest

from conftest import SOURCE, measurement_from, run, study_result

STUDY = SOURCE / "studies" / "seed002-rig-1ms.ini"


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("combined")
    return {
        "model": study_result(STUDY, d, "model", "study.realisations=60"),
        "few": study_result(STUDY, d, "few", "study.realisations=12"),
        "same": measurement_from(study_result(STUDY, d, "same", "study.seed=3"), d / "same.csv"),
        "lossy": measurement_from(study_result(STUDY, d, "lossy", "study.seed=4", "beam.loss_factor=0.02"),
                                  d / "lossy.csv"),
    }


def compare(files, model, meas, *extra):
    r = run(["compare", files[model], files[meas], "--measured-averages", 25, "--fmin", 100, "--fmax", 5000,
             "--format", "json", *extra])
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_the_result_holds_the_band_log_covariance(files):
    with h5py.File(files["model"]) as f:
        c = f["/bands/log_level_covariance"]
        s = f["/bands/log_std"][:]
        assert c.shape == (s.shape[0], s.shape[1], s.shape[1])
        desc = c.attrs["description"]
        assert "covariance" in (desc.decode() if isinstance(desc, bytes) else desc)
        assert c.attrs["units"] in (b"1", "1")
        cov = c[:]
    assert np.array_equal(cov, np.swapaxes(cov, 1, 2))
    assert np.allclose(np.sqrt(np.diagonal(cov, axis1=1, axis2=2)), s, rtol=1e-12, atol=0)
    # Neighbouring bands of one roll are correlated: the test must not treat them as independent.
    corr = cov[-1] / np.outer(s[-1], s[-1])
    assert np.max(np.abs(corr[np.triu_indices_from(corr, 1)])) > 0.3


def test_the_same_model_is_accepted_and_loss_factor_x2_rejected(files):
    same = compare(files, "model", "same")
    assert same["combined_test"]["defined"] and same["p_value"] > 0.05 and not same["combined_test"]["rejected"]
    assert same["combined_test"]["dof"] == [16, 44]
    lossy = compare(files, "model", "lossy")
    assert lossy["p_value"] < 1e-3 and lossy["combined_test"]["rejected"]
    # The per-band count alone would not tell it apart: many bands are still inside.
    assert lossy["inside"] >= 0.3 * lossy["judged"]
    # The level is the user's: at a level below its p-value the same measurement is not rejected.
    assert not compare(files, "model", "lossy", "--test-level", lossy["p_value"] / 2)["combined_test"]["rejected"]


def test_the_table_prints_the_verdict_above_the_summary(files):
    r = run(["compare", files["model"], files["lossy"], "--measured-averages", 25, "--fmin", 100, "--fmax", 5000])
    lines = r.stdout.strip().splitlines()
    assert lines[-1].startswith("rms_db_error:")
    assert lines[-2].startswith("combined_test: REJECTED at level 0.05: p = ")


def test_too_few_realisations_get_no_test_and_the_k_needed(files):
    j = compare(files, "few", "same")
    assert j["p_value"] is None and not j["combined_test"]["defined"]
    assert "need K >= 20 realisations, the result has 12" in j["combined_test"]["verdict"]


def test_a_bad_test_level_is_refused(files):
    r = run(["compare", files["model"], files["same"], "--measured-averages", 25, "--test-level", 1.5])
    assert r.returncode == 64 and "--test-level" in r.stderr
