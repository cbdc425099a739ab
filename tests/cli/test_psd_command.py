"""rollspec psd against scipy.signal.welch on the same data (issue 2: <= 1e-10 relative)."""
import numpy as np
import scipy.signal

from conftest import EX_DATAERR, EX_NOINPUT, EX_USAGE, run


def write_signal(path, x):
    np.savetxt(path, x, delimiter=",", header="left,right", comments="", fmt="%.17g")


def read_psd(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1)


def test_matches_scipy_welch_hann_and_rect(tmp_path):
    rng = np.random.default_rng(1)
    x = rng.standard_normal((20000, 2)) + [[3.0, -1.0]]
    x[:, 1] += np.sin(2 * np.pi * 37.0 * np.arange(20000) / 1000.0)
    sig = tmp_path / "signal.csv"
    write_signal(sig, x)
    # rectangular: the study key spectrum.window's spelling; rect: its short form
    for window, scipy_window, overlap in (("hann", "hann", 0.5), ("rectangular", "boxcar", 0.25), ("rect", "boxcar", 0.25)):
        out = tmp_path / f"psd_{window}.csv"
        r = run(["psd", sig, "--fs", 1000, "--segment", 512, "--overlap", overlap, "--window", window, "--out", out])
        assert r.returncode == 0, r.stderr
        header, data = read_psd(out)
        assert header == ["frequency_hz", "left [(m/s^2)^2/Hz]", "right [(m/s^2)^2/Hz]"]
        f, p = scipy.signal.welch(x.T, fs=1000.0, window=scipy_window, nperseg=512, noverlap=int(overlap * 512))
        np.testing.assert_allclose(data[:, 0], f, rtol=1e-12, atol=0)
        for c in range(2):
            np.testing.assert_allclose(data[:, 1 + c], p[c], rtol=1e-10, atol=1e-10 * p[c].max())


def test_bad_inputs(tmp_path):
    r = run(["psd", tmp_path / "missing.csv", "--fs", 100])
    assert r.returncode == EX_NOINPUT and "missing.csv" in r.stderr
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b\n1,2\n3,x\n")
    r = run(["psd", bad, "--fs", 100, "--segment", 4])
    assert r.returncode == EX_DATAERR and "bad.csv:3" in r.stderr and "'x'" in r.stderr
    r = run(["psd", bad, "--fs", -1])
    assert r.returncode == EX_USAGE and "--fs" in r.stderr
    r = run(["psd", bad, "--fs", 100, "--window", "hamming"])
    assert r.returncode == EX_USAGE and "--window hamming: allowed: hann, rectangular (or rect)" in r.stderr
    short = tmp_path / "short.csv"
    short.write_text("a\n1\n2\n3\n4\n5\n")
    r = run(["psd", short, "--fs", 10, "--segment", 8])
    assert r.returncode == EX_DATAERR and "fewer than one segment" in r.stderr
