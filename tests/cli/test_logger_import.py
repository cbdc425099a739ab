"""rollspec psd on accelerometer logger exports as users have them: a preamble before the header,
';' with decimal commas, time stamps rounded to six printed digits, one column with a decimal comma,
a unit per column, integer WAV (which needs --scale). Each file is read with pandas as the reference
(read_csv with sep, decimal and skiprows spelled out) and the PSD checked against scipy.signal.welch;
every choice made from the file is said on stderr."""
import io

import numpy as np
import pandas as pd
import pytest
import scipy.io.wavfile
import scipy.signal

from conftest import EX_DATAERR, EX_USAGE, assert_refused, lorentzian_comparison, run

G = 9.80665
FS = 25600.0
PREAMBLE = ["Logger XY-200 serial 1234", "Date;2024-05-01;10:31:07", "Units;s;g"]


def logger_text(t, x, preamble=(), header="Time (s);Acc (g)", digits=6):
    """A logger export: stamps and values with `digits` significant digits, ';' and decimal commas."""
    rows = [*preamble, header] + [f"{a:.{digits}g};{b:.{digits}g}".replace(".", ",") for a, b in zip(t, x)]
    return "\n".join(rows) + "\n"


def signal(n=2**16, seed=1):
    rng = np.random.default_rng(seed)
    t = np.arange(n) / FS
    return t, 0.3 * np.sin(2 * np.pi * 1000.0 * t) + 0.1 * rng.standard_normal(n)


def psd(args, tmp_path, name="psd.csv"):
    out = tmp_path / name
    r = run(["psd", *args, "--out", out])
    assert r.returncode == 0, r.stderr
    data = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    return data, r.stderr


def welch(x, fs, segment):
    return scipy.signal.welch(x, fs=fs, window="hann", nperseg=segment, noverlap=segment // 2, axis=0)


def assert_psd(data, f, p, rtol=1e-10):
    np.testing.assert_allclose(data[:, 0], f, rtol=rtol, atol=0)
    np.testing.assert_allclose(data[:, 1], p, rtol=rtol, atol=rtol * p.max())


def test_rounded_stamps_are_accepted_and_fs_overrides_them(tmp_path):
    # Six significant digits at 25.6 kHz: from t = 1 s on the stamps are rounded to 1e-5 s, up to
    # 0.13 sample intervals off the grid; the rounding (half a unit of the last digit) is accepted.
    t, x = signal()
    sig = tmp_path / "logger.csv"
    sig.write_text(logger_text(t, x))
    ref = pd.read_csv(sig, sep=";", decimal=",")
    data, err = psd([sig, "--unit", "g", "--fs", 25600, "--segment", 4096], tmp_path)
    f, p = welch(ref["Acc (g)"].to_numpy() * G, FS, 4096)
    assert_psd(data, f, p)
    assert "--fs 25600 Hz overrides the time column 'Time (s)' (its stamps imply 25600" in err
    assert "semicolon-delimited (from the data rows), decimal comma" in err
    # without --fs the rate comes from the rounded stamps, a least-squares line through them all: the
    # end points alone would carry their rounding (up to 2 ppm here) into the rate
    data, err = psd([sig, "--unit", "g", "--segment", 4096], tmp_path, "own.csv")
    assert "Hz from the time column 'Time (s)' (seconds)" in err
    stamps = ref["Time (s)"].to_numpy()
    rate = 1 / np.polyfit(np.arange(stamps.size), stamps, 1)[0]
    assert rate == pytest.approx(FS, rel=1e-7)
    assert data[1, 0] == pytest.approx(FS / 4096, rel=1e-7)
    f, p = welch(ref["Acc (g)"].to_numpy() * G, rate, 4096)
    assert_psd(data, f, p, rtol=1e-9)


def test_real_gaps_and_jitter_in_rounded_stamps_are_refused(tmp_path):
    t, x = signal(n=8192)
    t = t + 1.0  # stamps 1.00000 ... : rounded to 1e-5 s, 0.256 sample intervals
    gap = tmp_path / "gap.csv"
    gap.write_text(logger_text(np.delete(t, 3000), np.delete(x, 3000)))
    # header = line 1, sample i = line i + 2: the stamp after the gap is sample 3000, line 3002
    assert_refused(run(["psd", gap, "--unit", "g", "--segment", 1024]), EX_DATAERR,
                   ["gap.csv:3002: time column 'Time (s)' steps by", "a missing, repeated or shifted sample",
                    "or within the rounding of its printed digits"])
    jitter = tmp_path / "jitter.csv"
    tj = t.copy()
    tj[5000] += 0.45 / FS  # more than rounding (0.128 + 0.128 intervals) explains, less than a step test catches
    jitter.write_text(logger_text(tj, x))
    assert_refused(run(["psd", jitter, "--unit", "g", "--segment", 1024]), EX_DATAERR,
                   ["jitter.csv:5002: time column 'Time (s)' ", "sample intervals", "within the rounding of its printed digits"])
    # --fs overrides even refused stamps, and says why they were refused
    r = run(["psd", jitter, "--unit", "g", "--segment", 1024, "--fs", 25600, "--out", tmp_path / "o.csv"])
    assert r.returncode == 0 and "overrides the time column" in r.stderr and "its stamps are refused" in r.stderr


def test_preamble_lines_are_found_or_skipped(tmp_path):
    t, x = signal(n=8192)
    sig = tmp_path / "logger.csv"
    sig.write_text(logger_text(t, x, preamble=PREAMBLE))
    ref = pd.read_csv(sig, sep=";", decimal=",", skiprows=3)
    assert list(ref.columns) == ["Time (s)", "Acc (g)"]
    data, err = psd([sig, "--unit", "g", "--fs", FS, "--segment", 1024], tmp_path)
    assert "skipped 3 preamble lines before the header 'Time (s);Acc (g)' (line 4" in err
    f, p = welch(ref["Acc (g)"].to_numpy() * G, FS, 1024)
    assert_psd(data, f, p)
    skipped, err = psd([sig, "--unit", "g", "--fs", FS, "--segment", 1024, "--skip-rows", 3], tmp_path, "skip.csv")
    np.testing.assert_array_equal(skipped, data)
    assert "preamble lines" not in err  # nothing found: --skip-rows said it
    assert_refused(run(["psd", sig, "--unit", "g", "--fs", FS, "--skip-rows", 2]), EX_DATAERR, ["logger.csv:4:"])
    assert_refused(run(["psd", sig, "--skip-rows", -1]), EX_USAGE, ["--skip-rows -1", "allowed: a whole number >= 0"])
    assert_refused(run(["psd", sig, "--skip-rows", 100000]), EX_DATAERR, ["--skip-rows 100000 skips the whole file"])
    # --quiet: the choices are not said
    r = run(["psd", sig, "--unit", "g", "--fs", FS, "--segment", 1024, "--quiet", "--out", tmp_path / "q.csv"])
    assert r.returncode == 0 and r.stderr == ""


def test_a_bad_row_is_still_named_not_taken_for_a_header(tmp_path):
    t, x = signal(n=512)
    text = logger_text(t, x, preamble=PREAMBLE).splitlines()
    text[40] = "0,0015;volts"
    sig = tmp_path / "bad.csv"
    sig.write_text("\n".join(text) + "\n")
    assert_refused(run(["psd", sig, "--fs", FS, "--segment", 64]), EX_DATAERR,
                   ["bad.csv:41: column 'Acc (g)' value 'volts' is not a number", "allowed: a decimal number"])


def test_one_column_with_a_decimal_comma(tmp_path):
    _, x = signal(n=8192)
    sig = tmp_path / "one.csv"
    sig.write_text("Acc (g)\n" + "".join(f"{v:.6f}\n".replace(".", ",") for v in x))
    ref = pd.read_csv(sig, decimal=",", sep=";")
    assert list(ref.columns) == ["Acc (g)"]
    data, err = psd([sig, "--unit", "g", "--fs", FS, "--segment", 1024], tmp_path)
    assert "one.csv: one column with a decimal comma" in err
    f, p = welch(ref["Acc (g)"].to_numpy() * G, FS, 1024)
    assert_psd(data, f, p)


def test_a_unit_per_column(tmp_path):
    _, x = signal(n=8192)
    y = 5.0 * np.random.default_rng(3).standard_normal(x.size)
    sig = tmp_path / "two.csv"
    sig.write_text("acc_g,acc_ms2\n" + "".join(f"{a:.17g},{b:.17g}\n" for a, b in zip(x, y)))
    ref = pd.read_csv(sig)
    data, _ = psd([sig, "--unit", "g,m/s^2", "--fs", FS, "--segment", 1024], tmp_path)
    f, p = welch(np.column_stack([ref["acc_g"] * G, ref["acc_ms2"]]), FS, 1024)
    np.testing.assert_allclose(data[:, 1:], p, rtol=1e-10, atol=1e-10 * p.max())
    # the units follow the picked channels' order
    data, _ = psd([sig, "--unit", "m/s2,g", "--column", "acc_ms2,acc_g", "--fs", FS, "--segment", 1024], tmp_path, "b.csv")
    np.testing.assert_allclose(data[:, 1:], p[:, ::-1], rtol=1e-10, atol=1e-10 * p.max())
    assert_refused(run(["psd", sig, "--unit", "g,g,g", "--fs", FS]), EX_USAGE,
                   ["--unit g,g,g: 3 units for 2 channels (acc_g, acc_ms2)", "one per channel"])
    assert_refused(run(["psd", sig, "--unit", "g,mm", "--fs", FS]), EX_USAGE, ["--unit g,mm: 'mm'", "allowed: g, m/s2"])


def test_time_column_option(tmp_path):
    _, x = signal(n=4096)
    sig = tmp_path / "stamped.csv"
    sig.write_text("stamp_us;t;acc\n" + "".join(f"{i * 1e6 / FS:.17g};{i % 7};{v:.17g}\n" for i, v in enumerate(x)))
    # 't' is named like a time but holds a counter: refused as stamps ...
    assert_refused(run(["psd", sig, "--segment", 512]), EX_DATAERR,
                   ["stamped.csv:9: time column 't' value 0 does not increase", "--time-column none (with --fs)"])
    # ... --time-column none makes every column a channel (the rate from --fs) ...
    data, _ = psd([sig, "--time-column", "none", "--fs", FS, "--segment", 512, "--column", "acc"], tmp_path)
    f, p = welch(x, FS, 512)
    assert_psd(data, f, p)
    # ... and --time-column NAME picks the stamps, in the unit its name gives (us: microseconds) ...
    r = run(["psd", sig, "--time-column", "stamp_us", "--segment", 512, "--column", "acc", "--out", tmp_path / "us.csv"])
    assert r.returncode == 0, r.stderr
    assert "sample rate 25600 Hz from the time column 'stamp_us' (microseconds by its name, --time-column)" in r.stderr
    # ... or in seconds when the name gives none
    sig.write_text(sig.read_text().replace("stamp_us;", "stamp;", 1))
    r = run(["psd", sig, "--time-column", "stamp", "--segment", 512, "--column", "acc", "--out", tmp_path / "s.csv"])
    assert r.returncode == 0, r.stderr
    assert "sample rate 0.0256 Hz from the time column 'stamp' (--time-column; its name gives no unit: seconds)" in r.stderr
    assert_refused(run(["psd", sig, "--time-column", "clock"]), EX_USAGE,
                   ["--time-column clock: no such column", "columns found: stamp, t, acc"])


def test_integer_wav_needs_scale(tmp_path):
    _, x = signal(n=8192)
    pcm = np.round(x * 20000).astype(np.int16)
    wav = tmp_path / "rec.wav"
    scipy.io.wavfile.write(wav, int(FS), pcm)
    assert_refused(run(["psd", wav, "--segment", 1024]), EX_USAGE,
                   ["rec.wav: integer PCM", "fractions of the recorder's full scale", "--scale 50 --unit g",
                    "float sound files are read as stored"])
    data, err = psd([wav, "--segment", 1024, "--scale", 50, "--unit", "g"], tmp_path)
    assert "sample rate 25600 Hz from the file header" in err
    f, p = welch(pcm / 32768.0 * 50 * G, FS, 1024)
    assert_psd(data, f, p)
    flt = tmp_path / "float.wav"
    scipy.io.wavfile.write(flt, int(FS), x.astype(np.float32))
    data, _ = psd([flt, "--segment", 1024], tmp_path, "float.csv")
    f, p = welch(x.astype(np.float32).astype(float), FS, 1024)
    assert_psd(data, f, p)
    assert_refused(run(["psd", wav, "--scale", 1, "--skip-rows", 2]), EX_USAGE, ["--skip-rows", "not CSV text"])


def test_compare_skips_the_preamble_of_a_measured_psd(tmp_path):
    res, f, p, want = lorentzian_comparison(tmp_path)
    export = tmp_path / "m-export.csv"
    export.write_text("Analyzer ZZ-9;serial 77\nAveraging;linear;32\n" + "frequency_hz;psd\n" +
                      "".join(f"{a:.17g};{b:.17g}\n".replace(".", ",") for a, b in zip(f, p)))
    got = run(["compare", res, export, "--format", "csv"])
    assert got.returncode == 0, got.stderr
    assert "skipped 2 preamble lines before the header 'frequency_hz;psd' (line 3" in got.stderr
    assert got.stdout == want.stdout.replace("m.csv", "m-export.csv")
    same = run(["compare", res, export, "--format", "csv", "--skip-rows", 2])
    assert same.returncode == 0 and same.stdout == got.stdout and "preamble lines" not in same.stderr


def test_time_column_option_with_mat_and_sound_files(tmp_path):
    fs = 4096.0
    _, x = signal(n=8192)
    mat = tmp_path / "rec.mat"
    scipy.io.savemat(mat, {"stamps": np.arange(x.size) / fs, "acc": x, "t": np.arange(x.size) % 7})
    # 't' (a counter) is taken by its name and refused; --time-column picks the stamps, 't' is a channel
    assert_refused(run(["psd", mat, "--segment", 1024]), EX_DATAERR, ["variable 't'", "does not increase"])
    data, err = psd([mat, "--time-column", "stamps", "--column", "acc", "--segment", 1024], tmp_path)
    assert "sample rate 4096 Hz from time variable 'stamps'" in err
    f, p = welch(x, fs, 1024)
    assert_psd(data, f, p)
    data, _ = psd([mat, "--time-column", "none", "--fs", fs, "--column", "t,acc", "--segment", 1024], tmp_path, "none.csv")
    assert data.shape[1] == 3
    assert_refused(run(["psd", mat, "--time-column", "clock"]), EX_USAGE,
                   ["--time-column clock: no such vector variable in", "variables: stamps, acc, t"])
    wav = tmp_path / "rec.wav"
    scipy.io.wavfile.write(wav, int(fs), x.astype(np.float32))
    assert_refused(run(["psd", wav, "--time-column", "stamps"]), EX_USAGE, ["--time-column stamps", "is a sound file"])


def test_a_units_row_under_the_header_is_read_as_units(tmp_path):
    # Time⇥Acceleration, then [s]⇥[m/s²]: the units row is no header, and no data row either
    _, x = signal(n=8192)
    clean = tmp_path / "clean.csv"
    clean.write_text("time_s,acc\n" + "".join(f"{i / FS:.17g},{v:.6f}\n" for i, v in enumerate(x)))
    want, _ = psd([clean, "--segment", 1024], tmp_path, "want.csv")
    export = tmp_path / "export.txt"
    export.write_text("Time\tAcceleration\n[s]\t[m/s²]\n" +
                      "".join(f"{i / FS:.17g}\t{v:.6f}\n" for i, v in enumerate(x)), encoding="utf-8")
    got, err = psd([export, "--segment", 1024], tmp_path, "got.csv")
    np.testing.assert_array_equal(got, want)
    assert "export.txt: line 2 is a units row" in err
    assert "sample rate 25600 Hz from the time column 'Time' (seconds, by the units row)" in err
    assert "'Acceleration': read in m/s^2 by the units row (line 2)" in err
    # in g by the units row: the PSD times g^2, as --unit g gives it
    export.write_text(export.read_text(encoding="utf-8").replace("[m/s²]", "[g]", 1), encoding="utf-8")
    got, _ = psd([export, "--segment", 1024], tmp_path, "g.csv")
    np.testing.assert_allclose(got[:, 1], G**2 * want[:, 1], rtol=1e-12)


def test_a_missing_sample_is_found_at_any_number_of_printed_digits(tmp_path):
    # 1 kHz, sample 500 deleted, stamps printed in whole ms (0..499, 501..): a 999 Hz logger prints the same
    # steps, so the stamps cannot tell; refused at the line of the gap, naming --fs
    fs, n = 1000.0, 4096
    x = np.random.default_rng(2).standard_normal(n)
    keep = np.arange(n) != 500
    for name, digits in (("ms", 0), ("s6", 6)):
        sig = tmp_path / f"gap-{name}.csv"
        stamps = np.arange(n)[keep] * (1.0 if name == "ms" else 1e-3)
        sig.write_text(("time_ms" if name == "ms" else "time_s") + ",acc\n" +
                       "".join(f"{t:.{digits}f},{v:.6f}\n" for t, v in zip(stamps, x[keep])))
        r = run(["psd", sig, "--segment", 256])
        assert_refused(r, EX_DATAERR, [f"gap-{name}.csv:502: time column", "steps by", "--fs HZ"])
    r = run(["psd", tmp_path / "gap-ms.csv", "--segment", 256])
    assert "steps by 2 (from 499 to 501) where most steps are 1: stamps printed to the nearest 1 cannot show" in r.stderr
    # the same stamps without the gap are an exact grid, read as such
    whole = tmp_path / "whole-ms.csv"
    whole.write_text("time_ms,acc\n" + "".join(f"{t},{v:.6f}\n" for t, v in zip(range(n), x)))
    _, err = psd([whole, "--segment", 256], tmp_path, "whole.csv")
    assert "sample rate 1000 Hz from the time column 'time_ms' (milliseconds)" in err
    # stamps too coarse for the rate (0.01 s at 1 kHz): refused naming --fs, which then reads the file
    coarse = tmp_path / "coarse.csv"
    coarse.write_text("time_s,acc\n" + "".join(f"{i / fs:.2f},{v:.6f}\n" for i, v in enumerate(x)))
    assert_refused(run(["psd", coarse, "--segment", 256]), EX_DATAERR,
                   ["stamps printed to the nearest 0.01 cannot show a missing or repeated sample", "--fs HZ"])
    got, err = psd([coarse, "--segment", 256, "--fs", 1000], tmp_path, "coarse-psd.csv")
    np.testing.assert_array_equal(got, psd([whole, "--segment", 256], tmp_path, "w2.csv")[0])


def test_zeit_ms_is_read_in_milliseconds(tmp_path):
    _, x = signal(n=4096)
    sig = tmp_path / "zeit.csv"
    sig.write_text("zeit_ms;acc\n" + "".join(f"{1000 * i / FS:.6f};{v:.6f}\n".replace(".", ",") for i, v in enumerate(x)))
    _, err = psd([sig, "--segment", 512], tmp_path)
    assert "sample rate 25600 Hz from the time column 'zeit_ms' (milliseconds)" in err
    sig.write_text("zeit_ms;count;acc\n" +
                   "".join(f"{1000 * i / FS:.6f};{i};{v:.6f}\n".replace(".", ",") for i, v in enumerate(x)))
    r = run(["psd", sig, "--time-column", "zeit_ms", "--column", "acc", "--segment", 512, "--out", tmp_path / "z.csv"])
    assert r.returncode == 0 and "sample rate 25600 Hz from the time column 'zeit_ms' (milliseconds by its name, " \
                                  "--time-column)" in r.stderr, r.stderr


def test_a_table_in_the_preamble_does_not_hide_the_data(tmp_path):
    # a 3000-row calibration table before a 4096-row recording: the header is the line followed by the
    # most rows of numbers in the whole file, not only in its first lines
    _, x = signal(n=4096)
    data = "time_s,acc\n" + "".join(f"{i / FS:.17g},{v:.6f}\n" for i, v in enumerate(x))
    alone = tmp_path / "alone.csv"
    alone.write_text(data)
    want, _ = psd([alone, "--segment", 512], tmp_path, "want.csv")
    for name, table in (("wide", "f_hz,sensitivity,phase\n" + "".join(f"{i},{1 + i / 1e4},{i / 100}\n" for i in range(3000))),
                        ("same-width", "f_hz,sensitivity\n" + "".join(f"{i},{1 + i / 1e4}\n" for i in range(3000)))):
        sig = tmp_path / f"{name}.csv"
        sig.write_text("Calibration of sensor 12\n" + table + data)
        got, err = psd([sig, "--segment", 512], tmp_path, f"{name}-psd.csv")
        np.testing.assert_array_equal(got, want)
        assert "skipped 3002 preamble lines (3000 rows of numbers among them: the data are the longer table after " \
               "them) before the header 'time_s,acc' (line 3003" in err
