"""rollspec.studies.compare against `rollspec compare --format json` on the same input: the same object after
json.loads, for a PSD table (the model's own mean, and the same in g read as m/s^2, whose unit slip is also a
Python warning) and for recordings with a noise recording; a bad option or a missing file raises the command's
one-line message."""
import json
import os
import shutil
import subprocess

import h5py
import numpy as np
import pytest

from rollspec import studies

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
# The random oscillator, short records, nine bands around its 40 Hz resonance.
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
        "spectrum.band_max=200", "study.realisations=16"]
G = 9.80665


def command(*args):
    return subprocess.run([ROLLSPEC, *[str(a) for a in args]], capture_output=True, text=True)


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    d = tmp_path_factory.mktemp("compare")
    shutil.copy(os.path.join(SOURCE, "studies", "random-oscillator.ini"), d / "oscillator.ini")
    r = command("run", d / "oscillator.ini", "--out", d / "model.h5", "--quiet",
                *[a for s in FAST for a in ("--set", s)])
    assert r.returncode == 0, r.stderr
    return d, str(d / "model.h5")


def own_mean(result, path, factor):
    """The result's last PSD row (the sensor mean, or its one sensor) times factor, as a PSD table."""
    with h5py.File(result) as f:
        freq, psd = f["/psd/frequency"][...], f["/psd/mean"][...][-1]
    path.write_text("frequency_hz,psd\n" + "".join(f"{a!r},{b * factor!r}\n" for a, b in zip(freq, psd)))
    return path


def recording(path, channels, seed, level=1.0, fs=1024.0, seconds=8.0):
    """A CSV recording of white noise (m/s^2) on every channel the compared row averages."""
    x = level * np.random.default_rng(seed).standard_normal((int(fs * seconds), channels))
    rows = "".join(f"{i / fs!r}," + ",".join(repr(v) for v in row) + "\n" for i, row in enumerate(x))
    path.write_text("Time (s)," + ",".join(f"acc{k}" for k in range(channels)) + "\n" + rows)
    return path


def by_command(result, files, *args):
    r = command("compare", result, *files, "--format", "json", *args)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_a_psd_table_gives_the_commands_json(model):
    d, result = model
    table = own_mean(result, d / "own.csv", 1.0)
    got = studies.compare(result, table, measured_averages=16)
    assert got == by_command(result, [table], "--measured-averages", "16")
    assert got["combined_test"]["rejected"] is False and all(b["inside"] for b in got["bands"])
    slipped = own_mean(result, d / "in_g.csv", 1 / G**2)
    with pytest.warns(UserWarning, match=r"--unit g"):
        got = studies.compare(result, [slipped], measured_averages=16, fmin=25, test_level=0.01)
    assert got == by_command(result, [slipped], "--measured-averages", "16", "--fmin", "25", "--test-level", "0.01")
    assert got["combined_test"]["rejected"] is True


def test_recordings_with_noise_give_the_commands_json(model):
    d, result = model
    with h5py.File(result) as f:
        sensors = [s.decode() if isinstance(s, bytes) else s for s in f["/bands/sensor"][...]]
    channels = max(1, sum(s != "sensor_mean" for s in sensors))
    rolls = [recording(d / f"roll{k}.csv", channels, seed=k) for k in range(3)]
    quiet = recording(d / "quiet.csv", channels, seed=99, level=1e-4)
    got = studies.compare(result, rolls, noise=quiet, unit="m/s2", fmax=150, noise_margin=6)
    assert got == by_command(result, rolls, "--noise", quiet, "--unit", "m/s2", "--fmax", "150", "--noise-margin", "6")
    assert got["measured_averages"] == 3 and got["noise_psd"] is not None


def test_errors_are_the_commands_line(model, tmp_path):
    d, result = model
    table = own_mean(result, tmp_path / "own.csv", 1.0)
    prefix = "rollspec compare: error: "
    r = command("compare", result, table, "--fmin", "100", "--fmax", "50")
    assert r.returncode == 64 and r.stderr.startswith(prefix), r.stderr
    with pytest.raises(ValueError) as e:
        studies.compare(result, table, fmin=100, fmax=50)
    assert str(e.value) == r.stderr.strip().splitlines()[-1][len(prefix):]
    with pytest.raises(OSError, match="no-such.csv"):
        studies.compare(result, tmp_path / "no-such.csv")
    with pytest.raises(OSError, match="no-such.h5"):
        studies.compare(tmp_path / "no-such.h5", table)
    with pytest.raises(TypeError, match="recordings"):
        studies.compare(result, 3)
