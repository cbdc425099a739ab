"""[stiffness] table_error = jackknife on the equivalent-roughness table of [contact] filter = solver
(kernels/spectral/README.md D-30): a leave-one-strip-out sub-table is the cached table without that strip
(no new solve), the same bits as a table made of the other strips; the jackknife's intervals are those
computed here from the leave-one-out runs; combinations that have no such table are refused."""
import h5py
import numpy as np

from conftest import EX_CONFIG, assert_intervals_name_the_table, assert_refused, coarse_rig, run_copied_study
from test_table_jackknife import widened

# The coarse rig of test_solver_filter.py (seconds): 12 um cells, a 6.6 mm strip, 128-position segments.
N, K = 4, 12
SOLVER = ["contact.law=hertz", "contact.filter=solver", "surface.spacing=12e-6", "texture.short_wavelength=24e-6",
          "blocked_force.segment=128", "blocked_force.strip_length=6.6e-3", "ball.start=0.1", "ball.end=0.106",
          "spectrum.segment=128", "spectrum.band_min=400", "spectrum.band_max=5000", f"study.realisations={K}"]


def rig(tmp_path, name, *sets, command="run"):
    return coarse_rig(tmp_path, name, SOLVER, *sets, command=command)


def test_leaving_out_the_last_strip_is_the_table_of_the_others(tmp_path):
    # Strip s is the surface realisation s: the 3-strip table without strip 2 is the 2-strip table.
    _, two = rig(tmp_path, "two.h5", "equivalent_roughness.strips=2")
    r, left = rig(tmp_path, "left.h5", "equivalent_roughness.strips=3", "equivalent_roughness.leave_out=2")
    assert "strip 2 left out" in r.stderr
    with h5py.File(two) as a, h5py.File(left) as b:
        for d in ("psd/mean", "bands/level_db", "bands/ci_lower_db", "contact/force_psd"):
            assert a[d][()].tobytes() == b[d][()].tobytes(), d


def test_jackknife_over_strips_widens_by_the_leave_one_out_runs(tmp_path):
    strips = f"equivalent_roughness.strips={N}"
    _, plain = rig(tmp_path, "plain.h5", strips)
    r, jk = rig(tmp_path, "jk.h5", strips, "stiffness.table_error=jackknife")
    assert "sub-tables of the equivalent-roughness table" in r.stderr
    levels = []
    for i in range(N):
        _, loo = rig(tmp_path, f"loo{i}.h5", strips, f"equivalent_roughness.leave_out={i}")
        with h5py.File(loo) as f:
            levels.append(f["bands/level_db"][:])
    levels = np.array(levels)
    v = (N - 1) / N * ((levels - levels.mean(axis=0)) ** 2).sum(axis=0)
    with h5py.File(plain) as p, h5py.File(jk) as j:
        assert_intervals_name_the_table(p, j, "equivalent-roughness", f"{N} strips")
        np.testing.assert_allclose(j["bands/table_std_db"][:], np.sqrt(v), rtol=1e-12, atol=0)
        assert np.median(np.sqrt(v)) > 0.05  # the strips' own error is seen here
        level, lo, hi = p["bands/level_db"][:], p["bands/ci_lower_db"][:], p["bands/ci_upper_db"][:]
        want_lo, want_hi = widened(level, lo, hi, v, K=K, N=N)
        np.testing.assert_allclose(j["bands/ci_lower_db"][:], want_lo, rtol=0, atol=1e-7)
        np.testing.assert_allclose(j["bands/ci_upper_db"][:], want_hi, rtol=0, atol=1e-7)


def test_strip_leave_out_and_jackknife_refusals(tmp_path):
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, *SOLVER, "equivalent_roughness.strips=2",
                            "equivalent_roughness.leave_out=2", command="plan")
    assert_refused(r, EX_CONFIG, ["[equivalent_roughness] leave_out = 2", "allowed: -1 .. 1"])
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, *SOLVER, "equivalent_roughness.line=strip",
                            "equivalent_roughness.leave_out=0", command="plan")
    assert_refused(r, EX_CONFIG, ["[equivalent_roughness] leave_out = 0", "line = strip: -1"])
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, *SOLVER, "equivalent_roughness.strips=1",
                            "stiffness.table_error=jackknife", command="plan")
    assert_refused(r, EX_CONFIG, ["[stiffness] table_error = jackknife", "at least 2 strips", "allowed here: none"])
