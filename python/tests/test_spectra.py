"""rollspec.spectra against `rollspec psd` on the same samples, Parseval's identity, scipy's Welch,
and the chi-square intervals of its bands."""
import os
import subprocess

import numpy as np
import pytest
import scipy.signal
import scipy.stats

from rollspec import spectra

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")


def noise(n=6000, seed=52):
    rng = np.random.default_rng(seed)
    # Coloured, with an offset: the detrending and the window matter.
    return 0.3 + np.convolve(rng.standard_normal(n + 8), np.ones(9) / 3.0, mode="valid")


def test_welch_equals_the_psd_command_bit_for_bit(tmp_path):
    x, fs = noise(), 2500.0
    signal = tmp_path / "signal.csv"
    with open(signal, "w") as f:
        f.write("acc\n")
        f.writelines("%.17g\n" % v for v in x)  # printed exactly: the command reads the same doubles
    for segment, overlap, window in ((256, 0.5, "hann"), (500, 0.3, "rect")):
        out = subprocess.run(
            [ROLLSPEC, "psd", str(signal), "--fs", "2500", "--segment", str(segment), "--overlap", str(overlap),
             "--window", window, "--quiet"],
            capture_output=True, text=True, check=True,
        ).stdout
        table = np.genfromtxt(out.splitlines(), delimiter=",", names=True)
        r = spectra.welch(x, fs, segment=segment, overlap=overlap, window=window)
        assert np.array_equal(r["frequency"], table["frequency_hz"])
        assert np.array_equal(r["psd"], table[table.dtype.names[1]])
        assert r["overlap"] == int(np.floor(overlap * segment)) and r["segment"] == segment


def test_parseval_and_scipy():
    x, fs = noise(), 2500.0
    r = spectra.welch(x, fs, segment=256)
    # Parseval per segment: the one-sided density integrates to the windowed mean square of the
    # detrended segment, sum (w y)^2 / sum w^2; the estimate averages it over the segments.
    w = scipy.signal.get_window("hann", 256)
    step = 256 - r["overlap"]
    power = [np.sum((w * (s - s.mean())) ** 2) / np.sum(w**2)
             for s in (x[i:i + 256] for i in range(0, len(x) - 255, step))]
    assert len(power) == r["segments"]
    df = fs / 256
    assert r["psd"].sum() * df == pytest.approx(np.mean(power), rel=1e-12)
    f, p = scipy.signal.welch(x, fs, nperseg=256)
    assert np.array_equal(f, r["frequency"])
    assert np.allclose(r["psd"], p, rtol=1e-12, atol=0)


def test_channels_are_rows_and_choices_are_returned():
    x = np.vstack([noise(seed=1), noise(seed=2)])
    both = spectra.welch(x, 1000.0, segment=128, overlap=0.25, window="rectangular", detrend="none")
    one = spectra.welch(x[1], 1000.0, segment=128, overlap=0.25, window="rectangular", detrend="none")
    assert both["psd"].shape == (2, 65) and np.array_equal(both["psd"][1], one["psd"])
    assert (both["window"], both["detrend"], both["overlap"], both["samples"]) == ("rectangular", "none", 32, 6000)
    # D-16 for a rectangular window overlapping by a quarter: rho(1) = 32 / 128, rho(m > 1) = 0.
    n = both["segments"]
    assert both["equivalent_dof"] == pytest.approx(2 * n / (1 + 2 * (1 - 1 / n) * 0.25**2), rel=1e-12)


def test_bands_average_the_bins_and_carry_chi_square_intervals():
    x, fs = noise(20000), 4096.0
    r = spectra.bands(x, fs, segment=1024, band_min=20, band_max=1800, confidence=0.9)
    welch = spectra.welch(x, fs, segment=1024)
    df = fs / 1024
    index = np.round(10 * np.log10(r["centre"] / 1000))
    assert np.allclose(r["centre"], 1000 * 10 ** (index / 10), rtol=1e-15)
    assert r["lower"][0] >= 20 and r["upper"][-1] <= 1800
    for b in range(len(r["centre"])):
        # A band wholly made of whole bins (edges at bin boundaries) is their plain mean; any band lies
        # within the range of the bins it touches.
        touched = welch["psd"][int(np.floor(r["lower"][b] / df + 0.5)):int(np.floor(r["upper"][b] / df + 0.5)) + 1]
        assert touched.min() <= r["level"][b] <= touched.max()
        nu = r["dof"][b]
        assert nu > 2
        assert r["ci_lower"][b] / r["level"][b] == pytest.approx(nu / scipy.stats.chi2.ppf(0.95, nu), rel=1e-9)
        assert r["ci_upper"][b] / r["level"][b] == pytest.approx(nu / scipy.stats.chi2.ppf(0.05, nu), rel=1e-9)
    assert np.all(np.diff(r["dof"]) > 0)  # wider bands average more bins


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: spectra.welch(np.ones(100), 10.0, segment=2), "segment = 2: allowed: a whole number >= 4"),
        (lambda: spectra.welch(np.ones(100), 10.0, segment=200), "x = 100 samples per channel: fewer than one segment; allowed: at least segment = 200 samples"),
        (lambda: spectra.welch(np.ones(100), 0.0, segment=16), "fs = 0: allowed: a finite number > 0 (Hz)"),
        (lambda: spectra.welch(np.ones(100), 10.0, segment=16, overlap=0.99), "overlap = 0.99: allowed: a fraction in [0, 0.95]"),
        (lambda: spectra.welch(np.ones(100), 10.0, segment=16, window="hamming"), "window = 'hamming': allowed: hann, rectangular (or rect)"),
        (lambda: spectra.welch(np.ones(100), 10.0, segment=16, detrend="linear"), "detrend = 'linear': allowed: mean (also constant), none"),
        (lambda: spectra.welch(np.r_[np.ones(99), np.inf], 10.0, segment=16), "x: 1 value NaN or infinite; allowed"),
        (lambda: spectra.welch(np.ones((2, 2, 30)), 10.0, segment=16), "x: 3 dimension(s); allowed"),
        (lambda: spectra.welch(np.tile([1e200, -1e200], 50), 10.0, segment=16), "its PSD overflows a double"),
        (lambda: spectra.bands(np.ones(4096), 1000.0, confidence=0.2), "confidence ([spectrum] confidence) = 0.2: out of range; allowed: a finite number in [0.5, 0.999]"),
        (lambda: spectra.bands(np.ones(4096), 1000.0, band_min=30, band_max=31), "no third-octave band between them"),
    ],
)
def test_bad_input_is_a_value_error_naming_it(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert message in str(e.value)
    assert "\n" not in str(e.value)
