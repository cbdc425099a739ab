"""[stiffness] table_error = jackknife: the part of the jackknife that is the sub-table runs' own noise
(kernels/spectral/README.md D-30c), against the formula computed here from each realisation of each
leave-one-out run made alone (`--only`). CTest label `long` (27 runs; not under the sanitizers, which run
the engine's combined ensemble in test_table_jackknife.py). On 64 x 64 cells the table's part is large
enough that the sub-table runs keep the study's K (D-30f raises K_J only where their own noise is more than
a quarter of it), so K single runs per sub-table check the formula."""
import h5py
import numpy as np

from conftest import run
from test_table_jackknife import K, N, SMALL, STUDY, go, jackknife, sets, text

COARSE = ["surface.nx=64", "surface.ny=64"]  # after SMALL's 128: the later --set holds


def paired_noise(x):
    """D-30c from the paired values x[i, r, ...] (sub-table i, realisation r; linear), as written down:
    (10/ln 10)^2 (N - 1)/N sum_i var_r(x_ir - mean_j x_jr) / (K mean^2)."""
    d = x - x.mean(axis=0)
    s2 = d.var(axis=1, ddof=1).sum(axis=0)
    return (10 / np.log(10)) ** 2 * (N - 1) / N * s2 / (K * x.mean(axis=(0, 1)) ** 2)


def each_realisation(tmp_path, tables):
    """x[i, r]: realisation r's PSD (linear) and band values under sub-table i, each run alone."""
    bins, bands = [], []
    for i in range(N):
        for r in range(K):
            out = tmp_path / f"only-{i}-{r}.h5"
            res = run(["run", STUDY, "--out", out, "--quiet", "--only", str(r),
                       *sets(*SMALL, *COARSE, f"stiffness.table_dir={tables}", f"stiffness.table_leave_out={i}")])
            assert res.returncode == 0, res.stderr
            with h5py.File(out) as f:
                bins.append(f["psd/mean"][:])
                bands.append(10 ** (f["bands/level_db"][:] / 10))
    shape = (N, K)
    return np.reshape(bins, shape + bins[0].shape), np.reshape(bands, shape + bands[0].shape)


def test_the_runs_own_noise_is_the_paired_realisations_variance(tmp_path):
    tables = tmp_path / "tables"
    tables.mkdir()
    jk = go(tmp_path, "jk", tables, *COARSE, "stiffness.table_error=jackknife")
    with h5py.File(jk) as j:
        assert int(j["bands"].attrs["table_jackknife_realisations"][0]) == K  # D-30f kept K
    levels = []
    for i in range(N):
        with h5py.File(go(tmp_path, f"loo{i}", tables, *COARSE, f"stiffness.table_leave_out={i}")) as f:
            levels.append(f["bands/level_db"][:])
    x_bins, x_bands = each_realisation(tmp_path, tables)
    # The runs' means are the means of their realisations run alone (the same streams).
    np.testing.assert_allclose(10 * np.log10(x_bands.mean(axis=1)), levels, rtol=0, atol=1e-9)
    v, noise = jackknife(levels), paired_noise(x_bands)
    with h5py.File(jk) as j:
        np.testing.assert_allclose(j["bands/table_noise_std_db"][:], np.sqrt(noise), rtol=1e-9, atol=0)
        power = j["psd/mean"][:] > 0
        np.testing.assert_allclose(j["psd/table_noise_std_db"][:][power],
                                   np.sqrt(paired_noise(np.where(power, x_bins, 1.0)))[power], rtol=1e-9, atol=0)
        share = np.median(np.minimum(noise, v) / v)
        warning = text(j["bands"].attrs, "table_noise_warning") if "table_noise_warning" in j["bands"].attrs else ""
    # part of the term is the runs' own noise here, and the warning says so exactly when it is most of it
    assert 0.05 < share < 1 and bool(warning) == (share > 0.5), (share, warning)
