"""Real measured line scans keep their variance through profile -> PSD -> line texture, whole.

Three scans (studies/data/measured-profiles: Dektak and OPDx stylus scans and a fine stylus scan,
from SurfaceTopography's test data), steep and flat spectra, each one file used whole and as
exported (the Dektak positions are printed to 0.1 um for 0.156 um steps). For grids as long as the
scan and longer (the synthesis' fundamental at or below the scan's), the expected variance of the
lines (the synthesised PSD's integral, Eq. 14b) and the mean variance of 200 realised lines hold the
scan's variance (after the linear trend, Eq. 15) within 5 %: the resolved band at its measured level
and the unresolved rest in the scan's longest cell (Eq. 43-45)."""
import h5py
import numpy as np
import pytest

from conftest import SOURCE, run, texture_study

DATA = SOURCE / "studies" / "data" / "measured-profiles"
SCANS = ["dektak-1", "opdx-3", "xy-4"]


def profile(scan):
    """The scan's step and heights after the linear trend, in m."""
    path = DATA / f"{scan}.csv"
    d = np.loadtxt(path, delimiter=",", skiprows=1)
    z = d[:, 1] * (1e-6 if path.read_text().split("\n", 1)[0].endswith("height_um") else 1.0)
    t = np.arange(len(d))
    return (d[-1, 0] - d[0, 0]) / (len(d) - 1), z - np.polyval(np.polyfit(t, z, 1), t)


def study(tmp_path, scan, length, spacing, count):
    p = tmp_path / f"{scan}.ini"
    p.write_text(texture_study(29, {"source": "profiles", "profiles": DATA / (scan + ".csv"), "table_extension": "zero"},
                               {"count": count, "length": repr(length), "spacing": repr(spacing)}))
    return p


@pytest.mark.parametrize("longer", [1.0, 1.5, 2.3])
@pytest.mark.parametrize("scan", SCANS)
def test_lines_keep_the_measured_variance(tmp_path, scan, longer):
    dx, z = profile(scan)
    dx, n = 0.999 * dx, len(z)  # lines a little finer than the scan: its Nyquist wavenumber resolved
    variance = z.var()
    out = tmp_path / "t.h5"
    count = 200
    r = run(["texture", study(tmp_path, scan, (np.floor(longer * n) + 0.5) * dx, dx, count), "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        k, g = f["/texture/psd_wavenumber"][:], f["/texture/psd_target"][:]
        lines = f["/texture/lines"][:]
    expected = g.sum() * (k[1] - k[0]) / variance
    realised = lines.var(axis=1)
    mean, se = realised.mean() / variance, realised.std() / np.sqrt(count) / variance
    print(f"{scan} x{longer}: expected {expected:.4f}, realised {mean:.4f} +- {se:.4f} of the scan's variance")
    assert abs(expected - 1) < 0.05
    assert abs(mean - 1) < 0.05 + 2 * se


def test_a_grid_beyond_the_table_names_the_key_that_allows_it(tmp_path):
    dx, n = profile("opdx-3")[0], 3001
    p = study(tmp_path, "opdx-3", 2.5 * n * dx, dx, 2)
    p.write_text(p.read_text().replace("table_extension = zero\n", ""))
    r = run(["texture", p, "--out", tmp_path / "t.h5"])
    assert r.returncode == 78 and "[texture] table_extension" in r.stderr and "allowed" in r.stderr, r.stderr
