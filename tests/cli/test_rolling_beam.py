"""Rolling-beam scene through the study format: seed 000 example 4.1 (disc) against its analytic
values, and example 4.2 (cantilever on a plane) with and without the rolling correction."""
import h5py
import numpy as np
import pytest

from conftest import SOURCE, run

R, W0, V0, MU, G, M, EPS_N = 0.2, 127.03, 2.355, 0.25, 9.81, 1000.0, 1e8


def test_disc_slides_then_rolls(tmp_path):
    out = tmp_path / "disc.h5"
    r = run(["run", SOURCE / "studies" / "seed000-disc.ini", "--out", out, "--quiet", "--set", "analysis.record_every=1"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        t = f["/time_history/time"][:]
        slip = f["/time_history/contact/slip"][:, 0]
        v = np.linalg.norm(f["/time_history/velocity"][:, 0, :], axis=1)
        gap = f["/time_history/contact/normal_gap"][:, 0]
        friction_work = f["/time_history/energy/friction_work"][-1]
        q = f["/time_history/rotation"][:, 0]
        w_z = f["/time_history/angular_velocity"][:, 0, 2]
    # Rotations: orthonormal, about the disc axis z, and each step turns by the incremental Rodrigues
    # rotation of the trapezoidal angular velocity, theta = 2 atan(alpha / 2), alpha = h (w_n + w_n+1) / 2
    # (D-12; kernels/rolling README R-30..R-33).
    assert np.allclose(np.einsum("tij,tkj->tik", q, q), np.eye(3), atol=1e-12)
    angle = np.unwrap(np.arctan2(q[:, 1, 0], q[:, 0, 0]))
    alpha = 0.5 * (w_z[1:] + w_z[:-1]) * np.diff(t)
    assert np.abs(np.diff(angle) - 2 * np.arctan(alpha / 2)).max() < 1e-9
    with h5py.File(out) as f:
        for name in ("kinetic", "penalty", "friction_work", "balance_error"):
            assert f["/time_history/energy/" + name].attrs["units"] in (b"J", "J")
    sliding = np.flatnonzero(slip == 1)
    assert sliding.size and sliding[0] <= 2
    t_roll = t[np.flatnonzero((slip == 0) & (t > t[sliding[0]]))[0]]
    t_exact = (R * W0 - V0) / (3 * MU * G)
    assert abs(t_roll / t_exact - 1) < 0.005, t_roll
    v_exact = (V0 + R * W0 / 2) / 1.5
    # After rolling starts the tangential penalty spring rings undamped (seed 000 remarks it): average it.
    assert abs(v[t > 5].mean() / v_exact - 1) < 0.003
    # Energy lost to friction: the kinetic energy difference of the analytic motion.
    e0 = 0.5 * M * V0**2 + 0.5 * (0.5 * M * R**2) * W0**2
    e1 = 0.5 * M * v_exact**2 + 0.5 * (0.5 * M * R**2) * (v_exact / R) ** 2
    assert abs(friction_work / (e0 - e1) - 1) < 0.005
    # Static penetration m g / eps_n (while rolling).
    assert abs(-gap[t > 5].mean() / (M * G / EPS_N) - 1) < 0.02


def test_disc_without_rolling_correction_keeps_slipping_longer(tmp_path):
    out = tmp_path / "nr.h5"
    r = run(["run", SOURCE / "studies" / "seed000-disc-no-rolling.ini", "--out", out, "--quiet", "--set", "analysis.t_end=2"])
    assert r.returncode == 0, r.stderr


def cantilever(tmp_path, name):
    out = tmp_path / (name + ".h5")
    r = run(["run", SOURCE / "studies" / (name + ".ini"), "--out", out, "--quiet", "--set", "beam.elements=20",
             "--set", "analysis.t_end=2", "--set", "analysis.record_every=1"])
    assert r.returncode == 0, r.stderr
    return h5py.File(out)


def test_cantilever_friction_moment_twists_only_with_rolling(tmp_path):
    with cantilever(tmp_path, "seed000-cantilever") as a, cantilever(tmp_path, "seed000-cantilever-no-rolling") as b:
        ma, mb = a["/time_history/contact/moment"][-1], b["/time_history/contact/moment"][-1]
        # Friction moments about the beam axis (x) load torsion only with the rolling correction.
        assert np.abs(ma[:, 0]).sum() > 1e3
        assert np.abs(mb).max() == 0.0
        # The tip reaction in y at t = 2 (tip pushed 5 m sideways): rolling lowers it (seed 000 Fig. 12).
        ra, rb = a["/time_history/reaction"][-1, -1], b["/time_history/reaction"][-1, -1]
        assert abs(ra) < abs(rb)
        tip = a["/time_history/position"][-1, -1]
        assert abs(tip[1] - 5.0) < 1e-9


def test_frictionless_impact_on_a_wall(tmp_path):
    """A floor and a wall (two planes): a frictionless disc sliding at 2 m/s hits the wall and comes
    back; trapezoidal Newmark with the penalty force changes the energy by at most 0.2 % per impact
    at dt = 1e-3 (measured +0.16 %)."""
    out = tmp_path / "wall.h5"
    r = run(["run", SOURCE / "studies" / "seed000-disc.ini", "--out", out, "--quiet",
             "--set", "plane.point=0,0,0; 1,0,0", "--set", "plane.normal=0,1,0; -1,0,0", "--set", "contact.friction=0",
             "--set", "disc.velocity=2,0,0", "--set", "disc.angular_velocity=0,0,0", "--set", "analysis.t_end=1",
             "--set", "analysis.record_every=1"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        v = f["/time_history/velocity"][:, 0, 0]
        k = f["/time_history/energy/kinetic"][:]
        assert list(f["/time_history/contact/plane"][:]) == [0.0, 1.0]
        wall_force = f["/time_history/contact/force"][:, 1, 0]
    assert v[0] == 2.0 and v[-1] < -1.99
    assert (wall_force <= 0).all() and wall_force.min() < 0  # the wall pushes back (-x), never pulls
    assert abs(k[-1] / k[0] - 1) <= 0.002


def puck(tmp_path, name, *sets):
    out = tmp_path / (name + ".h5")
    args = [a for kv in sets for a in ("--set", kv)]
    r = run(["run", SOURCE / "studies" / "seed000-puck.ini", "--out", out, "--quiet", "--set", "analysis.t_end=10.6",
             "--set", "analysis.record_every=1", *args])
    assert r.returncode == 0, r.stderr
    return h5py.File(out)


def impacts(f):
    active = f["/time_history/contact/active"][:].max(axis=1)
    return int(((active[1:] == 1) & (active[:-1] == 0)).sum())


@pytest.mark.long  # minutes under the sanitizers: their pass skips it (tests/cli/CMakeLists.txt)
def test_puck_between_walls_energy(tmp_path):
    """Seed 000 example 4.3 (dt = 1e-4): frictionless, the energy-consistent option keeps the energy to
    1e-8 over at least 10 impacts (measured 1.5e-14); Newmark loses at most 0.2 % per impact; with
    mu = 0.4 the energy never increases (energy-consistent option) and friction converts spin into
    translation."""
    with puck(tmp_path, "ec", "analysis.integrator=energy-consistent") as f:
        t = f["/time_history/time"][:]
        e = f["/time_history/energy/kinetic"][:] + f["/time_history/energy/penalty"][:]
        after = t >= 0.1  # the load pulse is over
        n = impacts(f)
        assert n >= 10
        assert np.abs(e[after] / e[after][0] - 1).max() < 1e-8
    with puck(tmp_path, "nm") as f:
        e = f["/time_history/energy/kinetic"][:] + f["/time_history/energy/penalty"][:]
        assert abs(e[-1] / e[after][0] - 1) <= 0.002 * impacts(f)
    with puck(tmp_path, "mu", "analysis.integrator=energy-consistent", "contact.friction=0.4") as f:
        e = (f["/time_history/energy/kinetic"][:] + f["/time_history/energy/penalty"][:]
             + f["/time_history/energy/tangential_elastic"][:])
        assert (np.diff(e[after]) <= 1e-9 * e[after][0]).all()
        w = np.abs(f["/time_history/angular_velocity"][:, 0, 1])
        assert w[-1] < 0.5 * w[after][0]


@pytest.mark.long  # minutes under the sanitizers: their pass skips it (tests/cli/CMakeLists.txt)
def test_flying_beam_runs_and_balances_energy(tmp_path):
    """Seed 000 example 4.4 without friction for the first 2.5 s (the wall impact at ~1.9 s): energy
    balance within 1e-3 of the largest kinetic energy (kernel test: 1.3e-5 of it with its own tolerances)."""
    out = tmp_path / "fb.h5"
    r = run(["run", SOURCE / "studies" / "seed000-flying-beam.ini", "--out", out, "--quiet", "--set", "analysis.t_end=2.5",
             "--set", "contact.friction=0"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        k = f["/time_history/energy/kinetic"][:]
        assert np.abs(f["/time_history/energy/balance_error"][:]).max() < 1e-3 * k.max()
        assert f["/time_history/contact/active"][:].reshape(len(k), -1, 2)[:, :, 1].max() == 1  # the wall was hit
