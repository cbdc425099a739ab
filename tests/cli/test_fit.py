"""`rollspec fit` (kernels/spectral D-27): a known force level recovered from a synthetic measurement,
an unidentifiable key refused by name, bad input refused like `run` refuses it."""
import pytest

from conftest import run
from fit_experiment import STUDY, fit, measurement

TRUTH = 2.0  # force.level, N^2/Hz


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    return measurement(tmp_path_factory.mktemp("fit"), 4242, {"force.level": TRUTH})


def test_recovers_the_force_level_inside_its_interval(measured):
    out, r = fit(measured, {"force.level": "0.1:10:log"})
    assert out is not None, r.stderr
    p = out["parameters"]["force.level"]
    lo, hi = p["interval"]
    assert lo < p["estimate"] < hi
    # One experiment: its 95 % interval misses the truth one time in twenty (test_fit_coverage.py counts
    # that over many); the truth within twice the half-width (about 3.9 sigma) fails once in 10^4.
    half = (hi - lo) / 2.0
    assert abs(p["estimate"] - TRUTH) < 2.0 * half
    # 16 records of nine bands pin the level to a few per cent: the interval is narrow, not the range.
    assert abs(p["estimate"] / TRUTH - 1.0) < 0.05
    assert hi / lo < 1.15
    assert out["correlation"] == [[1]]
    assert 0.0 < out["p_value"] <= 1.0
    assert 10 < out["evaluations"] < 100
    # A linear scene: the start's probe finds common random numbers hold (kernels/spectral D-27i a), so the
    # fit reads ln L of the study's seed; its test counts the fitted key (D-27j) beside compare's.
    assert out["objective"]["common_random_numbers"] is True and out["objective"]["incoherent_share"] < 1e-6
    assert out["no_interval"] is None and out["points"][0]["question"] is None
    assert "9 bands less 1 fitted key," in out["goodness_of_fit"] and "F = " in out["goodness_of_fit"]
    assert 0.0 < out["p_value_uncorrected"] <= 1.0


def test_text_output_names_the_key_and_the_test(measured):
    r = run(["fit", STUDY, measured, "--vary", "force.level=0.1:10:log", "--measured-averages", 16,
             "--set", "signal.duration=4", "--set", "signal.sample_rate=1024", "--set", "spectrum.segment=2048",
             "--set", "spectrum.band_min=20", "--set", "spectrum.band_max=200", "--set", "study.realisations=40"])
    assert r.returncode == 0, r.stderr
    assert "force.level" in r.stdout and "goodness_of_fit:" in r.stdout and "evaluations:" in r.stdout
    assert "objective: common random numbers hold" in r.stdout and "goodness_of_fit_uncorrected:" in r.stdout


def test_a_key_that_does_not_change_the_bands_is_refused_by_name(measured):
    # The force spectrum's upper end lies above the compared bands (20 .. 200 Hz): the bands cannot tell it.
    out, r = fit(measured, {"force.f_max": "300:500"})
    assert out is None
    assert r.returncode == 65, r.stderr
    assert "cannot identify force.f_max" in r.stderr


@pytest.mark.parametrize("vary, code, words", [
    ("force.nope=1:2", 78, "unknown key [force] nope"),
    ("force.level=2:1", 64, "lo 2 >= hi 1"),
    ("force.level=0:1:log", 64, "log range needs lo > 0"),
    ("force.level=1:x", 64, "not a finite number"),
    ("force.level=1:2:ln", 64, "the third field is `log`"),
    ("level=1:2", 64, "section.key=lo:hi"),
])
def test_bad_vary_is_refused(measured, vary, code, words):
    r = run(["fit", STUDY, measured, "--vary", vary, "--measured-averages", 16, "--set", "study.realisations=20"])
    assert r.returncode == code, r.stderr
    assert words in r.stderr
    assert r.stdout == ""


def test_missing_inputs_are_refused(tmp_path, measured):
    r = run(["fit", STUDY, tmp_path / "none.csv", "--vary", "force.level=1:2", "--measured-averages", 16])
    assert r.returncode == 66 and "none.csv" in r.stderr
    r = run(["fit", tmp_path / "none.ini", measured, "--vary", "force.level=1:2", "--measured-averages", 16])
    assert r.returncode == 66 and "none.ini" in r.stderr
    r = run(["fit", STUDY, measured, "--vary", "force.level=1:2"])
    assert r.returncode == 64 and "measured-averages" in r.stderr
    r = run(["fit", STUDY, measured, "--measured-averages", 16])
    assert r.returncode == 64 and "vary" in r.stderr
    r = run(["fit", STUDY, measured, "--vary", "force.level=1:2", "--set", "force.level=3", "--measured-averages", 16])
    assert r.returncode == 64 and "force.level is varied by --vary" in r.stderr


def test_a_band_of_a_bin_or_two_is_warned_about(tmp_path, measured):
    # On 16 Hz bins (spectrum.segment = 64 at 1024 Hz) the bands below ~110 Hz span about a bin or less: the
    # measurement's rule (its points joined linearly) and the model's (its bins) read them differently, by
    # several of the band's standard deviations beside the 50 Hz resonance (kernels/spectral D-27h).
    coarse = measurement(tmp_path, 4243, {"force.level": TRUTH, "spectrum.segment": 64})
    out, r = fit(coarse, {"force.level": "0.1:10:log"}, "--set", "spectrum.segment=64")
    assert out is not None, r.stderr
    lines = [x for x in r.stderr.splitlines() if x.startswith("rollspec fit: WARNING: band ")]
    assert lines and all("of the model's 16 Hz grid" in x and "D-27h" in x for x in lines), r.stderr
    assert any(x.startswith("rollspec fit: WARNING: band 70.79 .. 89.13 Hz spans 1.1 bins") for x in lines), r.stderr
    # The fast setting's 0.5 Hz bins resolve every band: no such warning.
    _, r = fit(measured, {"force.level": "0.1:10:log"})
    assert r.returncode == 0 and "WARNING: band" not in r.stderr, r.stderr
