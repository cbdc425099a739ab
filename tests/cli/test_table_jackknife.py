"""[stiffness] table_error = jackknife (kernels/spectral/README.md D-30): run's intervals include the
stiffness table's own sampling error by a leave-one-surface-out jackknife.

On seed 001 beam R with a small 3-surface table: the central values are those of the run without the
jackknife bit for bit; the sub-tables the jackknife caches are those `table_leave_out = i` builds on its
own, bit for bit; and every band's and bin's interval is widened by exactly the term computed here from
the three leave-one-out runs made separately with `table_leave_out` (D-30a, b).
"""
import h5py
import numpy as np
from scipy import stats

from conftest import EX_CONFIG, SOURCE, assert_refused, run

STUDY = SOURCE / "studies" / "seed001-beam-r.ini"
N, K = 3, 8
SMALL = ["stiffness.realisations=3", "surface.nx=128", "surface.ny=128", f"study.realisations={K}",
         "stiffness.table_seed=5"]


def sets(*kv):
    return [a for s in kv for a in ("--set", s)]


def go(tmp_path, name, tables, *extra):
    out = tmp_path / f"{name}.h5"
    r = run(["run", STUDY, "--out", out, "--quiet", *sets(*SMALL, f"stiffness.table_dir={tables}", *extra)])
    assert r.returncode == 0, r.stderr
    return out


def widened(level, lo, hi, v, K=K, N=N, dof=None):
    """D-30b on each side, as a plain reference (scipy's t quantiles); the table term of `dof`
    degrees of freedom (N - 1 unless given)."""
    t_k = stats.t.ppf(0.975, K - 1)
    nu_t = N - 1 if dof is None else dof
    out = []
    for h in (level - lo, hi - level):
        s_w = h / t_k
        s2 = s_w ** 2 + v
        nu = s2 ** 2 / (s_w ** 4 / (K - 1) + v ** 2 / nu_t)
        out.append(np.where(v > 0, stats.t.ppf(0.975, nu) * np.sqrt(s2), h))
    return level - out[0], level + out[1]


def text(attrs, name):
    v = attrs[name]
    return v.decode() if isinstance(v, bytes) else v


def jackknife(theta):
    theta = np.asarray(theta)
    return (N - 1) / N * ((theta - theta.mean(axis=0)) ** 2).sum(axis=0)


def test_jackknife_widens_by_the_leave_one_out_runs_and_keeps_the_central_values(tmp_path):
    shared, alone = tmp_path / "tables", tmp_path / "alone"
    shared.mkdir()
    alone.mkdir()
    plain = go(tmp_path, "plain", shared, "stiffness.table_error=none")
    jk = go(tmp_path, "jk", shared, "stiffness.table_error=jackknife")
    # The sub-table runs take as many realisations as bring their own noise to a quarter of the term
    # (D-30f): the leave-one-out runs below take as many. The sub-tables each built on its own (their
    # own table directory), and their runs.
    with h5py.File(jk) as j:
        k_j = int(j["bands"].attrs.get("table_jackknife_realisations", K))
    assert k_j >= K
    loo = [go(tmp_path, f"loo{i}", alone, f"stiffness.table_leave_out={i}", f"study.realisations={k_j}")
           for i in range(N)]
    cached = sorted(shared.glob("stiffness-*.h5"))
    assert len(cached) == N + 1 and len(sorted(alone.glob("stiffness-*.h5"))) == N
    for built in alone.glob("stiffness-*.h5"):  # the jackknife's sub-table of the same inputs: the same bits
        with h5py.File(built) as a, h5py.File(shared / built.name) as b:
            for d in ("force_mean", "stiffness_mean", "force_std"):
                assert a[f"stiffness/{d}"][:].tobytes() == b[f"stiffness/{d}"][:].tobytes(), d

    with h5py.File(plain) as p, h5py.File(jk) as j:
        for d in ("psd/mean", "psd/std", "bands/level_db", "bands/std", "bands/log_std", "contact/force_psd",
                  "contact/loss_of_contact_share"):
            assert p[d][()].tobytes() == j[d][()].tobytes(), d
        assert text(p["bands"].attrs, "interval_includes") == "realisations only (conditional on the stiffness table)"
        assert text(j["bands"].attrs, "interval_includes") == f"realisations, stiffness table (jackknife over {N} surfaces)"
        assert text(j["psd"].attrs, "interval_includes") == text(j["bands"].attrs, "interval_includes")
        assert int(j["bands"].attrs["table_jackknife_surfaces"]) == N
        assert "table_std_db" not in p["bands"]
        level, lo, hi = p["bands/level_db"][:], p["bands/ci_lower_db"][:], p["bands/ci_upper_db"][:]
        jlo, jhi, jsd = j["bands/ci_lower_db"][:], j["bands/ci_upper_db"][:], j["bands/table_std_db"][:]
        mean, blo, bhi = p["psd/mean"][:], p["psd/ci_lower"][:], p["psd/ci_upper"][:]
        jblo, jbhi, jbsd = j["psd/ci_lower"][:], j["psd/ci_upper"][:], j["psd/table_std_db"][:]
        jnoise, jbnoise = j["bands/table_noise_std_db"][:], j["psd/table_noise_std_db"][:]
        warning = text(j["bands"].attrs, "table_noise_warning") if "table_noise_warning" in j["bands"].attrs else ""
        assert text(j["bands/table_std_db"].attrs, "units") == "dB"

    levels, bins = [], []
    for path in loo:
        with h5py.File(path) as f:
            levels.append(f["bands/level_db"][:])
            bins.append(10 * np.log10(f["psd/mean"][:]))
    v = jackknife(levels)
    assert np.median(np.sqrt(v)) > 0.05  # the table term is not negligible here: the test can see it
    np.testing.assert_array_equal(jsd, np.sqrt(v))
    # The runs' own noise in it (D-30c; its values: test_table_jackknife_noise.py), and the warning says so
    # exactly when it is most of it (median share over the bands above a half).
    share = np.median(np.minimum(jnoise ** 2, v) / v)
    assert 0 < share < 1 and bool(warning) == (share > 0.5), (share, warning)  # small once K_J is raised (D-30f)
    want_lo, want_hi = widened(level, lo, hi, v)
    np.testing.assert_allclose(jlo, want_lo, rtol=0, atol=1e-7)  # dB; the two t quantiles' own accuracy
    np.testing.assert_allclose(jhi, want_hi, rtol=0, atol=1e-7)
    assert np.all(jhi - jlo > hi - lo)

    has_power = mean > 0
    vb = jackknife(np.where(has_power, bins, 0.0))
    assert np.all(jbnoise[has_power] >= 0) and np.all(np.isnan(jbnoise[~has_power]) | (jbnoise[~has_power] >= 0))
    # numpy's log10 and the C library's differ in the last bits
    np.testing.assert_allclose(jbsd[has_power], np.sqrt(vb)[has_power], rtol=1e-12, atol=0)
    assert np.all(np.isnan(jbsd[~has_power]))
    db = 10 * np.log10(np.where(has_power, mean, 1.0))
    want_blo, want_bhi = widened(db, 10 * np.log10(np.where(has_power, blo, 1.0)),
                                 10 * np.log10(np.where(has_power, bhi, 1.0)), vb)
    ok = has_power & (blo > 0)
    np.testing.assert_allclose(10 * np.log10(jblo[ok]), want_blo[ok], rtol=0, atol=1e-7)
    np.testing.assert_allclose(10 * np.log10(jbhi[ok]), want_bhi[ok], rtol=0, atol=1e-7)


def test_jackknife_is_refused_without_a_rough_stiffness_table(tmp_path):
    for study, extra in (("seed001-beam-r-hertz.ini", []), ("seed001-beam-r.ini", ["stiffness.surface=smooth"])):
        r = run(["plan", SOURCE / "studies" / study, *sets("stiffness.table_error=jackknife", *extra)])
        assert_refused(r, EX_CONFIG, ["[stiffness] table_error = jackknife", "needs a rough stiffness table",
                                      "allowed here: none"])
    r = run(["plan", STUDY, *sets("stiffness.table_error=jackknife", "stiffness.table_leave_out=1")])
    assert_refused(r, EX_CONFIG, ["table_error = jackknife", "table_leave_out = -1"])
