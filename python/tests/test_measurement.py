"""rollspec.spectra.read_measurement against `rollspec psd` on the same files (CSV, WAV, FLAC, MAT): the
same samples give the command's PSD bit for bit; a unit in a column's name converts to m/s^2; a bad file
raises the command's own one-line message."""
import os
import subprocess
import sys

import numpy as np
import pytest
import scipy.io

from rollspec import spectra

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
EXAMPLE = os.path.join(SOURCE, "studies", "data", "example-signal.csv")  # ';', decimal comma, Time (s)

sys.path.append(os.path.join(SOURCE, "tests", "cli"))  # the command-line tests' sound file writer
from sound_files import write_pcm16  # noqa: E402


def psd_command(path, *options):
    """The command's PSD table: frequency and one row per channel, read from its %.17g text."""
    out = subprocess.run([ROLLSPEC, "psd", str(path), "--quiet", *map(str, options)],
                         capture_output=True, text=True, check=True).stdout
    table = np.genfromtxt(out.splitlines(), delimiter=",", names=True)
    return table["frequency_hz"], np.array([table[n] for n in table.dtype.names[1:]])


def command_error(path, *options):
    """The command's one-line refusal (stderr without its 'rollspec psd: error: ' prefix) and exit code."""
    r = subprocess.run([ROLLSPEC, "psd", str(path), "--quiet", *map(str, options)], capture_output=True, text=True)
    prefix = "rollspec psd: error: "
    assert r.returncode != 0 and r.stderr.startswith(prefix) and r.stderr.count("\n") == 1, r.stderr
    return r.stderr[len(prefix):].rstrip("\n"), r.returncode


def write_flac(path, rate=8000, frames=6000):
    """16-bit stereo FLAC through libsndfile."""
    rng = np.random.default_rng(3)
    write_pcm16(path, rng.normal(0, 3000, (frames, 2)).astype("<i2"), rate, 0x170000)


def test_each_format_gives_the_psd_command_bits(tmp_path):
    flac = tmp_path / "roll.flac"
    write_flac(flac)
    mat = tmp_path / "roll.mat"
    rng = np.random.default_rng(7)
    scipy.io.savemat(mat, {"fs": 2048.0, "acc": rng.standard_normal((3000, 2)), "temperature": 21.5})
    cases = [
        (EXAMPLE, {}, ["--segment", 512]),
        (os.path.join(SOURCE, "studies", "data", "example-signal.wav"), {"scale": 2.0, "unit": "g"},
         ["--scale", 2, "--unit", "g", "--segment", 512]),
        (flac, {"scale": 50.0, "unit": "g"}, ["--scale", 50, "--unit", "g", "--segment", 256]),
        (mat, {"column": "acc"}, ["--column", "acc", "--segment", 256]),
    ]
    for path, kwargs, options in cases:
        r = spectra.read_measurement(path, **kwargs)
        segment = options[options.index("--segment") + 1]
        w = spectra.welch(r["samples"], r["sample_rate"], segment=segment)
        f, p = psd_command(path, *options)
        assert np.array_equal(w["frequency"], f), path
        assert w["psd"].tobytes() == p.tobytes(), path
        assert r["samples"].shape == (len(r["channels"]), w["samples"])
    r = spectra.read_measurement(mat, column="acc")
    assert r["channels"] == ["acc_1", "acc_2"] and r["sample_rate"] == 2048.0 and r["rate_source"]


def test_a_unit_in_the_column_name_converts_to_metres_per_second_squared(tmp_path):
    rng = np.random.default_rng(11)
    values = rng.standard_normal(400) * 0.2  # g
    path = tmp_path / "logger.csv"
    with open(path, "w") as f:
        f.write("time_s,Acc (g),Acc (mm/s^2)\n")
        f.writelines("%.17g,%.17g,%.17g\n" % (i / 1000, v, 1e3 * v) for i, v in enumerate(values))
    r = spectra.read_measurement(path)
    assert r["channels"] == ["Acc (g)", "Acc (mm/s^2)"] and r["time_column"] == "time_s"
    assert r["samples"][0].tobytes() == (values * 9.80665).tobytes()  # the standard gravity, exact
    assert np.allclose(r["samples"][1], values, rtol=1e-15, atol=0)  # (1e3 v) * 1e-3
    g, mm = r["units"]
    assert (g["unit"], g["factor"], g["origin"]) == ("g", 9.80665, "name")
    assert (mm["unit"], mm["factor"], mm["origin"]) == ("mm/s^2", 1e-3, "name")
    assert r["sample_rate"] == pytest.approx(1000.0, rel=1e-12) and "time_s" in r["rate_source"]
    # unit= overrides the names, as --unit does; a column picks one channel.
    r = spectra.read_measurement(path, column="Acc (g)", unit="m/s2")
    assert r["samples"].shape == (1, 400) and r["samples"][0].tobytes() == values.tobytes()
    assert r["units"][0]["origin"] == "unit"
    assert any("Acc (g)" in note for note in r["notes"])


def test_a_bad_file_raises_the_command_message(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b\n1,2\n3,x\n")
    missing = tmp_path / "missing.csv"
    volts = tmp_path / "volts.csv"
    volts.write_text("t,v (V)\n" + "".join("%d,%d\n" % (i, i % 3) for i in range(20)))
    cases = [
        (bad, {"fs": 100.0}, ["--fs", 100, "--segment", 4], ValueError, 65),
        (missing, {"fs": 100.0}, ["--fs", 100], OSError, 66),
        (volts, {}, ["--segment", 4], ValueError, 65),
        (os.path.join(SOURCE, "studies", "data", "example-signal.wav"), {}, [], ValueError, 64),  # needs scale
        (EXAMPLE, {"column": "nope"}, ["--column", "nope"], ValueError, 64),
        (tmp_path, {"fs": 100.0}, ["--fs", 100], OSError, 66),  # a directory
    ]
    for path, kwargs, options, error, code in cases:
        message, exit_code = command_error(path, *options)
        with pytest.raises(error) as e:
            spectra.read_measurement(path, **kwargs)
        assert (str(e.value), exit_code) == (message, code)


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        ({"fs": -1.0}, ValueError, "fs = -1: allowed: a finite number > 0 (Hz)"),
        ({"skip_rows": -2}, ValueError, "skip_rows = -2: allowed: a whole number >= 0 (lines before the header)"),
        ({"time_column": ""}, ValueError, "time_column = '': allowed: a column name, or none"),
        ({"column": [1]}, TypeError, "column: a list; allowed: a channel name or a sequence of names, or None"),
        ({"fs": "fast"}, TypeError, "fs: a str; allowed: a sample rate (Hz), or None"),
        ({"path": EXAMPLE + "\0.wav"}, ValueError, "path: a name with an embedded null byte; allowed: a file name"),
    ],
)
def test_bad_arguments_are_refused_before_the_file_is_read(kwargs, error, message):
    kwargs = dict(kwargs)
    with pytest.raises(error) as e:
        spectra.read_measurement(kwargs.pop("path", "/nonexistent/never-read.csv"), **kwargs)
    assert str(e.value) == message
