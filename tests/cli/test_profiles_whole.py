"""Measured scans used whole and as exported (kernels/texture/README.md §4, Eq. 42-45).

Each scan of studies/data/measured-profiles goes to `[texture] source = profiles` as it is: one file
(or, for the AFM map, its 16 rows), positions as the instrument printed them. Two figures per scan:

- the octave levels of 100 generated lines, as long as the scan and analysed like it (linear trend
  removed, Hann window), against the scan's own periodogram, over the resolved band (octaves of bins
  from the first resolved bin the result records): within 1 dB;
- the variance of the lines against the scan's (after its linear trend): the synthesis' expected
  variance (its target PSD's sum) and the mean variance of lines with deterministic amplitudes, each
  within 5 %.

hfm-1, mitutoyo-2 and the AFM map's rows were never used to build the estimator; dektak-1, opdx-3 and
xy-4 were cut in halves before. Before the estimator kept the periodogram's level, every octave of a
whole scan moved by 10 log10(V / sum_{j>=1} G_j dk): +6.5 dB on hfm-1, +2.1 dB on dektak-1."""
import h5py
import numpy as np
import pytest
from scipy.signal import periodogram

from conftest import SOURCE, run, texture_study

DATA = SOURCE / "studies" / "data" / "measured-profiles"
SCANS = {name: [DATA / f"{name}.csv"] for name in ["hfm-1", "mitutoyo-2", "dektak-1", "opdx-3", "xy-4"]}
SCANS["top-1-rows"] = sorted((DATA / "top-1-rows").glob("row-*.csv"))


def heights(path):
    """Heights in m of one scan file (height_m or height_um)."""
    header = path.read_text().split("\n", 1)[0]
    z = np.loadtxt(path, delimiter=",", skiprows=1)[:, 1]
    return z * (1e-6 if header.endswith("height_um") else 1.0)


def texture(tmp_path, files, n, spacing, count, amplitudes="rayleigh"):
    study = tmp_path / "s.ini"
    study.write_text(texture_study(29, {"source": "profiles", "profiles": ", ".join(str(f) for f in files),
                                        "table_extension": "zero", "amplitudes": amplitudes},
                                   {"count": count, "length": repr((n + 0.5) * spacing), "spacing": repr(spacing)}))
    out = tmp_path / f"t-{amplitudes}-{count}.h5"
    r = run(["texture", study, "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    return h5py.File(out, "r")


def hann(z, spacing):
    """The scan's own estimator: Hann periodogram after the linear trend, per rad/m."""
    return periodogram(z, fs=1.0 / spacing, window="hann", detrend="linear", scaling="density")[1] / (2 * np.pi)


@pytest.mark.parametrize("scan", SCANS)
def test_lines_show_the_scans_octaves_and_variance(tmp_path, scan):
    files = SCANS[scan]
    zs = [heights(f) for f in files]
    n = zs[0].size
    x = np.loadtxt(files[0], delimiter=",", skiprows=1)[:, 0]
    # The spacing and the resolved band as rollspec reads the scan (rounded positions: the step they
    # were printed from), from a run whose lines are a little finer than the scan.
    with texture(tmp_path, files, n, 0.999 * (x[-1] - x[0]) / (n - 1), 1) as f:
        spacing = float(f["/profiles"].attrs["spacing"][0])
        first = int(round(float(f["/profiles"].attrs["resolved_wavenumber"][0]) * n * spacing / (2 * np.pi) + 0.5))
    t = np.arange(n)
    variance = np.mean([(z - np.polyval(np.polyfit(t, z, 1), t)).var() for z in zs])
    own = np.mean([hann(z, spacing) for z in zs], axis=0)
    with texture(tmp_path, files, n, spacing, 100) as f:
        lines = f["/texture/lines"][:]
    made = np.mean([hann(h, spacing) for h in lines], axis=0)
    octaves = []
    j = first
    while 2 * j <= own.size - 1:
        octaves.append(10 * np.log10(made[j:2 * j].sum() / own[j:2 * j].sum()))
        j *= 2
    with texture(tmp_path, files, n, spacing, 10, "deterministic") as f:
        k, g = f["/texture/psd_wavenumber"][:], f["/texture/psd_target"][:]
        expected = g.sum() * (k[1] - k[0]) / variance
        realised = f["/texture/lines"][:].var(axis=1).mean() / variance
    print(f"{scan}: first resolved bin {first}; octaves " + " ".join(f"{d:+.2f}" for d in octaves) +
          f" dB; variance expected {expected:.4f}, realised {realised:.4f} of the scan's")
    assert len(octaves) >= 5
    assert max(abs(d) for d in octaves) <= 1.0
    assert abs(expected - 1) <= 0.05
    assert abs(realised - 1) <= 0.05
