"""Real measured line scans keep their roughness through profile -> PSD -> line texture.

Three scans that nobody tuned on (studies/data/measured-profiles: Dektak and OPDx stylus scans and
a fine stylus scan, from SurfaceTopography's test data), steep and flat spectra. For grids as long
as the profiles and longer (the synthesis' fundamental at or below the table's first wavenumber),
the expected variance of the lines (the synthesised PSD's integral, Eq. 14b) and the mean variance
of 600 realised lines hold the profiles' variance (after the linear trend, Eq. 15) within 5 %."""
import h5py
import numpy as np
import pytest

from conftest import SOURCE, run

DATA = SOURCE / "studies" / "data" / "measured-profiles"
SCANS = ["dektak-1", "opdx-3", "xy-4"]


def profiles(scan):
    out = []
    for part in "ab":
        d = np.loadtxt(DATA / f"{scan}-{part}.csv", delimiter=",", skiprows=1)
        t = np.arange(len(d))
        z = d[:, 1] - np.polyval(np.polyfit(t, d[:, 1], 1), t)
        out.append((d[1, 0] - d[0, 0], z))
    return out


def study(tmp_path, scan, length, spacing, count):
    p = tmp_path / f"{scan}.ini"
    p.write_text(f"""[study]
scene = texture
realisations = 1
seed = 29

[texture]
source = profiles
profiles = {DATA / (scan + '-a.csv')}, {DATA / (scan + '-b.csv')}
table_extension = zero

[lines]
count = {count}
length = {length!r}
spacing = {spacing!r}
""")
    return p


@pytest.mark.parametrize("longer", [1.0, 1.5, 2.3])
@pytest.mark.parametrize("scan", SCANS)
def test_lines_keep_the_measured_variance(tmp_path, scan, longer):
    ps = profiles(scan)
    dx, n = ps[0][0], len(ps[0][1])
    variance = np.mean([z.var() for _, z in ps])
    out = tmp_path / "t.h5"
    count = 600
    r = run(["texture", study(tmp_path, scan, (np.floor(longer * n) + 0.5) * dx, dx, count), "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        k, g = f["/texture/psd_wavenumber"][:], f["/texture/psd_target"][:]
        lines = f["/texture/lines"][:]
    expected = g.sum() * (k[1] - k[0]) / variance
    realised = lines.var(axis=1)
    mean, se = realised.mean() / variance, realised.std() / np.sqrt(count) / variance
    print(f"{scan} x{longer}: expected {expected:.4f}, realised {mean:.4f} +- {se:.4f} of the profiles' variance")
    assert abs(expected - 1) < 0.05
    assert abs(mean - 1) < 0.05 + 2 * se


def test_a_grid_beyond_the_table_names_the_key_that_allows_it(tmp_path):
    dx, n = profiles("opdx-3")[0][0], 1500
    p = study(tmp_path, "opdx-3", 2.5 * n * dx, dx, 2)
    p.write_text(p.read_text().replace("table_extension = zero\n", ""))
    r = run(["texture", p, "--out", tmp_path / "t.h5"])
    assert r.returncode == 78 and "[texture] table_extension" in r.stderr and "allowed" in r.stderr, r.stderr
