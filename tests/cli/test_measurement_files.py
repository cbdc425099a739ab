"""rollspec psd on what data loggers and acoustics labs write (issue 17): CSV with ',', ';' (decimal
comma) or tab and a time column, --column, --unit g, --scale, WAV through libsndfile, MATLAB .mat
through matio (v5 from scipy, v7.3 written with h5py), and the refusals."""
import numpy as np
import pytest
import scipy.io
import scipy.io.wavfile
import scipy.signal

from conftest import EX_DATAERR, EX_NOINPUT, EX_USAGE, assert_refused, lorentzian_comparison, run

G = 9.80665


UNIT = " [(m/s^2)^2/Hz]"


def psd(args, tmp_path, name="psd.csv"):
    """Runs rollspec psd ARGS --out tmp_path/name; returns (header with each PSD title's unit checked and
    removed, data, raw bytes of the output)."""
    out = tmp_path / name
    r = run(["psd", *args, "--out", out])
    assert r.returncode == 0, r.stderr
    with open(out) as f:
        header = f.readline().strip().split(",")
    assert header[0] == "frequency_hz" and all(h.endswith(UNIT) for h in header[1:]), header
    header = [header[0]] + [h[:-len(UNIT)] for h in header[1:]]
    return header, np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2), out.read_bytes()


def sine_plus_noise(n, fs, f0, amplitude, sigma, seed, channels=1):
    rng = np.random.default_rng(seed)
    t = np.arange(n) / fs
    x = amplitude * np.sin(2 * np.pi * f0 * t + 0.3)[:, None] + sigma * rng.standard_normal((n, channels))
    return t, x


def write_plain(path, names, x):
    np.savetxt(path, x, delimiter=",", header=",".join(names), comments="", fmt="%.17g")


def plain_reference(tmp_path, names, x, fs):
    """x written as plain.csv (columns `names`) and the bytes of its PSD at --fs fs, 1024-sample segments."""
    plain = tmp_path / "plain.csv"
    write_plain(plain, names, x)
    return plain, psd([plain, "--fs", fs, "--segment", 1024], tmp_path, "plain-psd.csv")[2]


def three_channels(tmp_path, seed):
    """4096 Hz, 8192 samples of a 200 Hz sine plus noise on 3 channels, and plain_reference's PSD bytes of them
    as the channels acc, pair_1, pair_2: (fs, n, x, bytes)."""
    fs, n = 4096.0, 8192
    _, x = sine_plus_noise(n, fs, 200.0, 1.0, 0.3, seed=seed, channels=3)
    return fs, n, x, plain_reference(tmp_path, ["acc", "pair_1", "pair_2"], x, fs)[1]


def write_logger(path, t, names, x, delimiter=";", time_name="time_s"):
    """A logger export: a time column, then the channels; with ';' a decimal comma (same digits)."""
    rows = [delimiter.join([time_name, *names])]
    for ti, xi in zip(t, x):
        cells = [f"{ti:.17g}", *(f"{v:.17g}" for v in xi)]
        if delimiter == ";":
            cells = [c.replace(".", ",") for c in cells]
        rows.append(delimiter.join(cells))
    path.write_text("\n".join(rows) + "\n")


def welch(x, fs, segment):
    return scipy.signal.welch(x, fs=fs, window="hann", nperseg=segment, noverlap=segment // 2, axis=0)


def test_parseval_sine_plus_noise_rate_from_time_column(tmp_path):
    # A sine of amplitude A plus white noise of variance s^2: the PSD integrates to the mean square
    # A^2/2 + s^2. The integral of a Welch density estimate is the window-weighted mean square of the
    # segments, so it differs from A^2/2 + s^2 only by sampling scatter: the estimate of s^2 + 2 A s mean(sin*n)
    # over N = 2^16 samples has a standard deviation sqrt((2 s^4 + 2 A^2 s^2) / N_eff) with N_eff >= N/2 for
    # Hann segments overlapping by half: 0.0059 here, 0.26 % of 2.25. The tolerance, 1.5 %, is over 5 of those.
    fs, n, f0, amplitude, sigma = 25600.0, 2**16, 1234.5, 2.0, 0.5
    t, x = sine_plus_noise(n, fs, f0, amplitude, sigma, seed=5)
    sig = tmp_path / "sig.csv"
    write_logger(sig, t, ["acc"], x, delimiter=",")
    header, data, _ = psd([sig, "--segment", 4096], tmp_path)
    assert header == ["frequency_hz", "acc"]
    f, p = data[:, 0], data[:, 1]
    df = f[1] - f[0]
    assert df == pytest.approx(fs / 4096, rel=1e-12)  # the rate came from the time column
    integral = p.sum() * df
    assert integral == pytest.approx(amplitude**2 / 2 + sigma**2, rel=0.015)
    assert abs(f[np.argmax(p)] - f0) <= df
    # and the sine's power sits at f0 (Hann main lobe: +-2 bins), the noise's is flat elsewhere
    lobe = np.abs(f - f0) <= 2 * df
    assert p[lobe].sum() * df == pytest.approx(amplitude**2 / 2 + sigma**2 * lobe.sum() * df / (fs / 2), rel=0.03)


def test_semicolon_decimal_comma_and_tab_give_the_same_bits_as_plain_csv(tmp_path):
    # fs a power of two: the stamps i/fs are exact binary fractions, (t_last - t_0)/(n - 1) is exactly
    # 1/fs and the rate from the time column is exactly fs, so every bit of the output agrees.
    fs, n = 4096.0, 8192
    t, x = sine_plus_noise(n, fs, 300.0, 1.0, 0.2, seed=7, channels=2)
    plain, want = plain_reference(tmp_path, ["left", "right"], x, fs)
    semi = tmp_path / "logger.csv"
    write_logger(semi, t, ["left", "right"], x, delimiter=";")
    assert ";" in semi.read_text() and "0,0" in semi.read_text()
    assert psd([semi, "--segment", 1024], tmp_path, "semi-psd.csv")[2] == want
    # With a rate that is no binary fraction (25600 Hz) the rate from the stamps may differ from 25600 in
    # the last bits; given --fs (it agrees), --fs is used, and the bits agree again.
    t2 = np.arange(n) / 25600.0
    write_logger(semi, t2, ["left", "right"], x, delimiter=";")
    _, _, want2 = psd([plain, "--fs", 25600, "--segment", 1024], tmp_path, "plain2.csv")
    assert psd([semi, "--fs", 25600, "--segment", 1024], tmp_path, "semi2.csv")[2] == want2
    tab = tmp_path / "logger.txt"
    write_logger(tab, t, ["left", "right"], x, delimiter="\t", time_name="Time (s)")
    assert psd([tab, "--segment", 1024], tmp_path, "tab-psd.csv")[2] == want
    # quoted names and a time column in milliseconds
    ms = tmp_path / "ms.csv"
    ms.write_text('"t [ms]";"left";"right"\n' + "".join(
        f"{1000 * ti:.17g};{a:.17g};{b:.17g}\n".replace(".", ",") for ti, (a, b) in zip(t, x)))
    _, data, _ = psd([ms, "--segment", 1024], tmp_path, "ms-psd.csv")
    np.testing.assert_allclose(data, np.loadtxt(tmp_path / "plain-psd.csv", delimiter=",", skiprows=1), rtol=1e-12, atol=0)


def test_column_picks_channels_in_the_order_asked(tmp_path):
    fs, n = 1000.0, 4096
    _, x = sine_plus_noise(n, fs, 50.0, 1.0, 0.3, seed=11, channels=3)
    sig = tmp_path / "s.csv"
    write_plain(sig, ["a", "b", "c"], x)
    _, full, _ = psd([sig, "--fs", fs, "--segment", 512], tmp_path, "all.csv")
    for args in (["--column", "c", "--column", "a"], ["--column", "c,a"], ["--column", "c, a"]):
        header, data, _ = psd([sig, "--fs", fs, "--segment", 512, *args], tmp_path)
        assert header == ["frequency_hz", "c", "a"]
        np.testing.assert_array_equal(data, full[:, [0, 3, 1]])
    assert_refused(run(["psd", sig, "--fs", fs, "--column", "z"]), EX_USAGE,
                   ["--column z: no such channel in", "s.csv", "channels found: a, b, c"])
    assert_refused(run(["psd", sig, "--fs", fs, "--column", "a", "--column", "a"]), EX_USAGE, ["picked twice"])
    timed = tmp_path / "timed.csv"
    write_logger(timed, np.arange(n) / fs, ["a", "b", "c"], x)
    assert_refused(run(["psd", timed, "--column", "time_s"]), EX_USAGE, ["time_s: that is the time column", "channels: a, b, c"])


def test_unit_g_and_scale_multiply_the_psd_exactly(tmp_path):
    fs, n = 2000.0, 8192
    _, x = sine_plus_noise(n, fs, 120.0, 0.7, 0.1, seed=3)
    sig = tmp_path / "s.csv"
    write_plain(sig, ["acc"], x)
    _, base, _ = psd([sig, "--fs", fs, "--segment", 1024], tmp_path, "base.csv")
    _, in_g, _ = psd([sig, "--fs", fs, "--segment", 1024, "--unit", "g"], tmp_path, "g.csv")
    _, ms2, _ = psd([sig, "--fs", fs, "--segment", 1024, "--unit", "m/s2"], tmp_path, "ms2.csv")
    _, scaled, _ = psd([sig, "--fs", fs, "--segment", 1024, "--unit", "g", "--scale", 0.5], tmp_path, "scaled.csv")
    np.testing.assert_array_equal(ms2, base)
    np.testing.assert_array_equal(in_g[:, 0], base[:, 0])
    np.testing.assert_allclose(in_g[:, 1], G**2 * base[:, 1], rtol=1e-12, atol=0)
    np.testing.assert_allclose(scaled[:, 1], (0.5 * G) ** 2 * base[:, 1], rtol=1e-12, atol=0)
    _, mm, _ = psd([sig, "--fs", fs, "--segment", 1024, "--unit", "mm/s2"], tmp_path, "mm.csv")
    np.testing.assert_allclose(mm[:, 1], 1e-6 * base[:, 1], rtol=1e-12, atol=0)
    assert_refused(run(["psd", sig, "--fs", fs, "--unit", "mm/s"]), EX_USAGE, ["--unit mm/s", "allowed: g, m/s2", "mm/s2"])
    assert_refused(run(["psd", sig, "--fs", fs, "--scale", 0]), EX_USAGE, ["--scale 0", "allowed: a finite number > 0"])
    assert "(m/s^2)^2/Hz" in run(["psd", "--help"]).stdout


def test_wav_pcm16_and_float32(tmp_path):
    fs, n = 8000, 20000
    _, x = sine_plus_noise(n, fs, 440.0, 0.4, 0.05, seed=9, channels=2)
    pcm = np.round(x * 32767).astype(np.int16)
    wav = tmp_path / "rec.wav"
    scipy.io.wavfile.write(wav, fs, pcm)
    header, data, _ = psd([wav, "--segment", 1024, "--scale", 3.0, "--unit", "g"], tmp_path)
    assert header == ["frequency_hz", "channel_1", "channel_2"]
    f, p = welch(pcm / 32768.0 * 3.0 * G, fs, 1024)
    np.testing.assert_allclose(data[:, 0], f, rtol=1e-12, atol=0)
    for c in range(2):
        np.testing.assert_allclose(data[:, 1 + c], p[:, c], rtol=1e-10, atol=1e-10 * p[:, c].max())
    flt = tmp_path / "rec-float.wav"
    scipy.io.wavfile.write(flt, fs, x.astype(np.float32))
    header, data, _ = psd([flt, "--segment", 1024, "--column", "channel_2", "--fs", fs], tmp_path)
    assert header == ["frequency_hz", "channel_2"]
    f, p = welch(x.astype(np.float32).astype(np.float64)[:, 1], fs, 1024)
    np.testing.assert_allclose(data[:, 1], p, rtol=1e-10, atol=1e-10 * p.max())
    # a WAV under another name is still a WAV (by content); integer PCM needs --scale (full scale is no unit)
    other = tmp_path / "rec.dat"
    other.write_bytes(wav.read_bytes())
    a = psd([wav, "--segment", 1024, "--scale", 1], tmp_path, "a.csv")[2]
    assert psd([other, "--segment", 1024, "--scale", 1], tmp_path, "b.csv")[2] == a


def test_mat_v5_vector_matrix_and_fs_match_csv(tmp_path):
    fs, n, x, want = three_channels(tmp_path, seed=13)
    mat = tmp_path / "rec.mat"
    scipy.io.savemat(mat, {"acc": x[:, 0], "pair": x[:, 1:], "fs": fs, "note": "rig 2, roll 4",
                           "meta": {"sensor": "B&K 4508"}, "cells": np.array([1, "a"], dtype=object),
                           "spectrum": x[:16, 0] + 1j})
    assert psd([mat, "--segment", 1024], tmp_path, "mat-psd.csv")[2] == want
    header, data, _ = psd([mat, "--segment", 1024, "--column", "pair"], tmp_path, "pair.csv")
    assert header == ["frequency_hz", "pair_1", "pair_2"]
    assert_refused(run(["psd", mat, "--column", "meta"]), EX_DATAERR, ["--column meta", "variable 'meta' is a struct"])
    assert_refused(run(["psd", mat, "--column", "spectrum"]), EX_DATAERR, ["variable 'spectrum' is complex"])
    assert_refused(run(["psd", mat, "--fs", 4000]), EX_USAGE, ["--fs 4000 Hz disagrees with", "4096 Hz from variable 'fs'"])
    # what cannot be a rate or a channel is listed, not fatal: --fs reads the rest
    odd = tmp_path / "odd.mat"
    scipy.io.savemat(odd, {"acc": x[:, 0], "fs": np.array([[1.0, 2.0, 3.0]]), "wide": x[:, 1:].T})
    assert_refused(run(["psd", odd, "--segment", 1024]), EX_USAGE,
                   ["odd.mat: no sample rate", "or a scalar variable fs", "fs (named like a sample rate, but 1x3, not a scalar)",
                    "wide (a 2x8192 matrix, wider than tall", "probably transposed"])
    header, data, _ = psd([odd, "--segment", 1024, "--fs", fs], tmp_path, "odd.csv")
    assert header == ["frequency_hz", "acc"]
    # a time vector instead of fs; single and int16 classes; channels of another length are an error unless left out
    t = np.arange(n) / fs
    mat2 = tmp_path / "rec2.mat"
    scipy.io.savemat(mat2, {"t": t, "acc": x[:, 0], "single": x[:, 1].astype(np.float32),
                            "counts": np.round(x[:, 2] * 1000).astype(np.int16), "short": x[:100, 0]})
    assert_refused(run(["psd", mat2, "--segment", 1024]), EX_DATAERR, ["channel 'acc' has 8192 samples but 'short' 100"])
    header, data, _ = psd([mat2, "--segment", 1024, "--column", "acc,single,counts"], tmp_path, "mat2.csv")
    assert header == ["frequency_hz", "acc", "single", "counts"]
    f, p = welch(np.column_stack([x[:, 0], x[:, 1].astype(np.float32), np.round(x[:, 2] * 1000).astype(np.int16)]).astype(float), fs, 1024)
    np.testing.assert_allclose(data[:, 0], f, rtol=1e-12, atol=0)
    for c in range(3):
        np.testing.assert_allclose(data[:, 1 + c], p[:, c], rtol=1e-10, atol=1e-10 * p[:, c].max())


def write_mat73(path, variables):
    """A MATLAB v7.3 file as MATLAB writes it: HDF5 with a 512-byte user block holding the MAT header,
    each array stored transposed (HDF5 is row-major) with a MATLAB_class attribute."""
    import h5py
    with h5py.File(path, "w", userblock_size=512) as f:
        for name, value in variables.items():
            a = np.atleast_2d(np.asarray(value, dtype=np.float64))
            if a.shape[0] == 1 and np.ndim(value) == 1:
                a = a.T  # a column vector, N x 1
            d = f.create_dataset(name, data=a.T)
            # MATLAB's attribute: "double" in a 6-byte NULLTERM string (h5py's own would be NULLPAD,
            # which HDF5 converts to "doubl" for a NULLTERM reader such as matio)
            tid = h5py.h5t.C_S1.copy()
            tid.set_size(6)
            tid.set_strpad(h5py.h5t.STR_NULLTERM)
            attr = h5py.h5a.create(d.id, b"MATLAB_class", tid, h5py.h5s.create(h5py.h5s.SCALAR))
            attr.write(np.array(b"double", dtype="S6"), mtype=tid)
    header = b"MATLAB 7.3 MAT-file, Platform: GLNXA64, Created on: Mon Jan  1 00:00:00 2024 HDF5 schema 1.00 ."
    header = header.ljust(116, b" ") + b"\x00" * 8 + b"\x00\x02" + b"IM"
    with open(path, "r+b") as f:
        f.write(header)


def test_mat_v73(tmp_path):
    fs, _, x, want = three_channels(tmp_path, seed=17)
    mat = tmp_path / "rec73.mat"
    write_mat73(mat, {"acc": x[:, 0], "pair": x[:, 1:], "fs": fs})
    assert psd([mat, "--segment", 1024], tmp_path, "mat73-psd.csv")[2] == want


def test_compare_reads_a_semicolon_measured_psd_with_decimal_commas(tmp_path):
    # The measured-PSD reader is the same: a spreadsheet export gives the same comparison, digit for digit.
    res, f, p, want = lorentzian_comparison(tmp_path)
    semi = tmp_path / "m-semi.csv"
    semi.write_text('"frequency_hz";"psd"\r\n' + "".join(f"{a:.17g};{b:.17g}\r\n".replace(".", ",") for a, b in zip(f, p)))
    assert len(want.stdout.splitlines()) > 10
    got = run(["compare", res, semi, "--format", "csv"])
    assert got.returncode == 0, got.stderr
    assert got.stdout == want.stdout.replace("m.csv", "m-semi.csv")  # the summary names the file


def test_refusals(tmp_path):
    fs, n = 1000.0, 2048
    t, x = sine_plus_noise(n, fs, 50.0, 1.0, 0.3, seed=21)
    # a missing sample: the stamp after the gap is named by its line (header = line 1, sample i = line i + 2)
    gap = tmp_path / "gap.csv"
    write_logger(gap, np.delete(t, 700), ["acc"], np.delete(x, 700, axis=0))
    assert_refused(run(["psd", gap, "--segment", 256]), EX_DATAERR,
                   ["gap.csv:702: time column 'time_s' steps by 0.002", "a missing, repeated or shifted sample"])
    # a rate that changes half-way: the first stamp off the grid by more than 0.1 interval
    drift = tmp_path / "drift.csv"
    t2 = np.where(np.arange(n) < n // 2, t, t[n // 2] + (np.arange(n) - n // 2) * 1.05 / fs)
    write_logger(drift, t2, ["acc"], x)
    r = run(["psd", drift, "--segment", 256])
    assert_refused(r, EX_DATAERR, ["drift.csv:", "sample intervals off the uniform grid", "the sample rate is not constant"])
    back = tmp_path / "back.csv"
    t3 = t.copy()
    t3[10] = t3[9]
    write_logger(back, t3, ["acc"], x)
    assert_refused(run(["psd", back, "--segment", 256]), EX_DATAERR, ["back.csv:12: time column 'time_s' value 0.009 does not increase"])
    # --fs against the time column and against a WAV's rate: both values named
    good = tmp_path / "good.csv"
    write_logger(good, t, ["acc"], x)
    # (--fs overrides a time column, and says so: test_logger_import.py)
    wav = tmp_path / "r.wav"
    scipy.io.wavfile.write(wav, 8000, (x[:, 0] * 1000).astype(np.int16))
    assert_refused(run(["psd", wav, "--fs", 48000, "--segment", 256, "--scale", 1]), EX_USAGE,
                   ["--fs 48000 Hz disagrees with", "8000 Hz from the file header"])
    # no rate at all
    plain = tmp_path / "plain.csv"
    write_plain(plain, ["acc"], x)
    assert_refused(run(["psd", plain, "--segment", 256]), EX_USAGE, ["plain.csv: no sample rate", "give --fs HZ, or a time column"])
    # a damaged WAV: libsndfile's message and the file; a header cut short, a RIFF that is no WAVE
    bad = tmp_path / "broken.wav"
    bad.write_bytes(wav.read_bytes()[:30])
    r = run(["psd", bad, "--segment", 256])
    assert_refused(r, EX_DATAERR, ["broken.wav: cannot read it as a sound file:"])
    noise = tmp_path / "noise.wav"
    noise.write_bytes(b"RIFF" + bytes(range(256)) * 4)
    assert_refused(run(["psd", noise, "--segment", 256]), EX_DATAERR, ["noise.wav: cannot read it as a sound file:"])
    # a .mat without numeric variables: what it holds, and why none is a channel
    mat = tmp_path / "text.mat"
    scipy.io.savemat(mat, {"note": "no data", "meta": {"a": 1.0}, "z": np.arange(4) + 1j})
    assert_refused(run(["psd", mat, "--fs", 100]), EX_DATAERR,
                   ["text.mat: no channels", "note (text (char))", "meta (a struct)", "z (complex)"])
    notmat = tmp_path / "garbage.mat"
    notmat.write_bytes(b"\x01\x02" * 300)
    assert_refused(run(["psd", notmat, "--fs", 100]), EX_DATAERR, ["garbage.mat: cannot read it as a MATLAB .mat file"])
    # decimal marks: mixed in one file, or a thousands separator
    mixed = tmp_path / "mixed.csv"
    mixed.write_text("time_s;acc\n0;0,5\n0,001;0.25\n")
    assert_refused(run(["psd", mixed, "--segment", 4]), EX_DATAERR,
                   ["mixed.csv:3: column 'acc' value '0.25' has a decimal point, but this file writes a decimal comma (line 2, column 'acc')"])
    thousands = tmp_path / "thousands.csv"
    thousands.write_text("time_s;acc\n0;1.234,5\n")
    assert_refused(run(["psd", thousands, "--segment", 4]), EX_DATAERR, ["thousands.csv:2: column 'acc' value '1.234,5' holds both"])
    # a comma-delimited file with a row of the wrong width (a one-column decimal comma file: test_logger_import.py)
    comma_in_plain = tmp_path / "plaincomma.csv"
    comma_in_plain.write_text("a,b\n0,5\n1,2,3\n")
    assert_refused(run(["psd", comma_in_plain, "--fs", 10, "--segment", 4]), EX_DATAERR,
                   ["plaincomma.csv:3: 3 values, but the header names 2 columns (comma-delimited"])
    # missing files of every kind
    for name in ("absent.csv", "absent.wav", "absent.mat"):
        assert_refused(run(["psd", tmp_path / name, "--fs", 100]), EX_NOINPUT, [name])


def test_text_that_starts_like_a_sound_file_is_read_as_text(tmp_path):
    # Content decides only on a full magic number (RIFF....WAVE, FORM....AIFF, fLaC, ...), not 4 letters.
    sig = tmp_path / "riffle.csv"
    sig.write_text("RIFFLE_WAVE,FORM\n" + "".join(f"{np.sin(i)},{np.cos(i)}\n" for i in range(64)))
    header, data, _ = psd([sig, "--fs", 64, "--segment", 16], tmp_path)
    assert header == ["frequency_hz", "RIFFLE_WAVE", "FORM"] and data.shape == (9, 3)
