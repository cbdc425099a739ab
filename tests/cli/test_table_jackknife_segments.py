"""[stiffness] table_error = jackknife on the blocked-force table of [contact] blocked_force = solver
(kernels/spectral/README.md D-30d): its units are the half-overlapping Welch segments of F0 along the
one strip; sub-table i ([blocked_force] leave_out = i) is the cached table with segment i left out of
its PSD (no new solve), the mean of the other segments' periodograms as scipy forms them; the
intervals are widened by the leave-one-out runs' jackknife, scaled for the segments' overlap and
with the Welch mean's degrees of freedom; combinations without such a table are refused."""
import glob

import h5py
import numpy as np
from scipy import signal

from conftest import EX_CONFIG, assert_intervals_name_the_table, assert_refused, coarse_rig, run_copied_study
from test_table_jackknife import widened

K = 12
# A coarse rig (under a second per run): 12 um cells, a 6.6 mm strip, 518 positions, 64-position
# segments: 15 half-overlapping Welch segments of F0.
SOLVER = ["contact.blocked_force=solver", "surface.spacing=12e-6", "texture.short_wavelength=24e-6",
          "blocked_force.segment=64", "blocked_force.strip_length=6.6e-3", "ball.start=0.1", "ball.end=0.2",
          "spectrum.segment=128", "spectrum.band_min=400", "spectrum.band_max=5000", f"study.realisations={K}"]
SEGMENT = 64


def rig(tmp_path, name, *sets, command="run"):
    return coarse_rig(tmp_path, name, SOLVER, *sets, command=command)


def table_force(tmp_path):
    (table,) = glob.glob(str(tmp_path / "tables" / "blocked-force-*.h5"))
    with h5py.File(table) as f:
        return f["blocked_force/position"][:], f["blocked_force/force"][:], f["blocked_force/psd"][:]


def periodograms(position, force):
    """Each half-overlapping segment's one-sided PSD per rad/m (scipy: Hann, mean removed)."""
    fs = 1.0 / (position[1] - position[0])
    hop = SEGMENT // 2
    count = (len(force) - hop) // hop
    return np.array([signal.periodogram(force[j * hop:j * hop + SEGMENT], fs=fs, window="hann",
                                        detrend="constant")[1] for j in range(count)]) / (2 * np.pi)


def overlap(n):
    """D-30d: the variance factor 2 N / nu and the dof nu / 2 - 1 of N half-overlapping Hann segments,
    nu from Percival & Walden's equivalent dof of the Welch mean."""
    w = signal.get_window("hann", SEGMENT)
    rho = (w[:SEGMENT // 2] * w[SEGMENT // 2:]).sum() / (w * w).sum()
    nu = 2 * n / (1 + 2 * (1 - 1 / n) * rho ** 2)
    return 2 * n / nu, nu / 2 - 1


def test_a_left_out_segment_is_the_mean_of_the_other_periodograms(tmp_path):
    _, full = rig(tmp_path, "full.h5")
    r, left = rig(tmp_path, "left.h5", "blocked_force.leave_out=3")
    assert "Welch segment 3 left out" in r.stderr
    assert "built" not in r.stderr.split("blocked force table:")[1].splitlines()[0]  # the cached table: no new solve
    position, force, table_psd = table_force(tmp_path)
    p = periodograms(position, force)
    assert len(p) == 15
    (table,) = glob.glob(str(tmp_path / "tables" / "blocked-force-*.h5"))
    with h5py.File(full) as a, h5py.File(left) as b:
        # The result names the table it used (the cached file's input hash), the same for the sub-table's run.
        for f in (a, b):
            assert f["contact"].attrs["blocked_force_input_hash"].decode() == table.split("-")[-1][:-3]
        assert a["contact/blocked_force_psd"][()].tobytes() == table_psd.tobytes()
        np.testing.assert_allclose(table_psd, p.mean(axis=0), rtol=1e-10, atol=0)
        np.testing.assert_allclose(b["contact/blocked_force_psd"][:], np.delete(p, 3, axis=0).mean(axis=0),
                                   rtol=1e-10, atol=0)
        assert not np.allclose(b["bands/level_db"][:], a["bands/level_db"][:], rtol=0, atol=1e-3)


def test_jackknife_over_segments_widens_by_the_leave_one_out_runs(tmp_path):
    _, plain = rig(tmp_path, "plain.h5")
    r, jk = rig(tmp_path, "jk.h5", "stiffness.table_error=jackknife")
    assert "15 sub-tables of the blocked-force table" in r.stderr
    n = 15
    levels = []
    for i in range(n):
        _, loo = rig(tmp_path, f"loo{i}.h5", f"blocked_force.leave_out={i}")
        with h5py.File(loo) as f:
            levels.append(f["bands/level_db"][:])
    levels = np.array(levels)
    factor, dof = overlap(n)
    v = factor * (n - 1) / n * ((levels - levels.mean(axis=0)) ** 2).sum(axis=0)
    with h5py.File(plain) as p, h5py.File(jk) as j:
        assert_intervals_name_the_table(p, j, "blocked-force", f"{n} Welch segments of F0")
        assert abs(j["bands"].attrs["table_jackknife_variance_factor"] / factor - 1) < 1e-12
        assert abs(j["bands"].attrs["table_jackknife_dof"] / dof - 1) < 1e-12
        np.testing.assert_allclose(j["bands/table_std_db"][:], np.sqrt(v), rtol=1e-10, atol=0)
        # Common random numbers hold (a sub-table rescales F0's harmonics): (c) is not most of (a).
        assert "table_noise_warning" not in j["bands"].attrs
        assert np.median(np.sqrt(v)) > 0.1  # 15 segments: the F0 PSD's own error is large here
        level, lo, hi = p["bands/level_db"][:], p["bands/ci_lower_db"][:], p["bands/ci_upper_db"][:]
        want_lo, want_hi = widened(level, lo, hi, v, K=K, N=n, dof=dof)
        np.testing.assert_allclose(j["bands/ci_lower_db"][:], want_lo, rtol=0, atol=1e-7)
        np.testing.assert_allclose(j["bands/ci_upper_db"][:], want_hi, rtol=0, atol=1e-7)


def test_segment_leave_out_and_jackknife_refusals(tmp_path):
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, *SOLVER, "blocked_force.leave_out=15", command="plan")
    assert_refused(r, EX_CONFIG, ["[blocked_force] leave_out = 15", "allowed: -1 .. 14"])
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, "blocked_force.leave_out=0", command="plan")
    assert_refused(r, EX_CONFIG, ["[blocked_force] leave_out = 0", "blocked_force = solver", "allowed here: -1"])
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, "stiffness.table_error=jackknife", command="plan")
    assert_refused(r, EX_CONFIG, ["[stiffness] table_error = jackknife", "blocked-force table of at least 2 Welch",
                                  "allowed here: none"])


def test_run_says_below_which_frequency_f0_is_the_texture_shape(tmp_path):
    # F0's PSD is the solver's own from the table's third Welch bin: f = 3 v / (segment x step x cell).
    # The coarse rig: 64 positions of 12 um at 1 m/s -> 3 / 0.768 mm = 3906 Hz, above band_min = 400 Hz.
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, *SOLVER, command="plan")
    assert r.returncode == 0, r.stderr
    assert "[blocked_force] segment: F0's PSD is the contact solver's own from its Welch bin 3 up, wavelength " \
           "0.256 mm, i.e. 3906 Hz at [ball] speed = 1 m/s; the bands from [spectrum] band_min = 400 Hz" in r.stderr
    # A segment of 480 positions (5.76 mm) resolves from 521 Hz: still above 400 Hz; from 600 Hz up, none.
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, *SOLVER, "blocked_force.segment=480", command="plan")
    assert "i.e. 520.8 Hz" in r.stderr
    r, _ = run_copied_study("seed002-rig-1ms.ini", tmp_path, *SOLVER, "blocked_force.segment=480",
                            "spectrum.band_min=600", command="plan")
    assert r.returncode == 0 and "Welch bin 3" not in r.stderr, r.stderr
