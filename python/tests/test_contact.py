"""rollspec.contact.solve against Hertz's closed forms (Johnson 1985, Eq. 4.22-4.24), its options'
errors, its array handling and the released interpreter lock."""
import math
import threading
import time

import numpy as np
import pytest

import rollspec
from rollspec import contact

# The kernel's own Hertz check (tests/kernels/contact/hertz_fixture.hpp): a 40 mm ball, steel on steel.
RADIUS, E_STAR, APPROACH = 0.02, 115.4e9, 0.241e-6


def hertz_force(approach):
    return 4.0 / 3.0 * E_STAR * math.sqrt(RADIUS) * approach**1.5


def hertz_grid(cells_per_radius, span=1.25):
    """Odd grid centred on the ball, `cells_per_radius` cells per contact radius at APPROACH."""
    a = math.sqrt(RADIUS * APPROACH)
    dx = a / cells_per_radius
    n = 2 * math.ceil(span * cells_per_radius) + 1
    return contact.ball_gap(RADIUS, dx, n, n, shape="paraboloid"), dx


def test_hertz_force_radius_and_stiffness_at_32_cells_per_radius():
    gap, dx = hertz_grid(32)
    r = contact.solve(gap, dx, e_star=E_STAR, approach=APPROACH, tolerance=1e-12)
    assert r["converged"] and r["stiffness_converged"]
    a = math.sqrt(RADIUS * APPROACH)
    # The kernel's doctest bounds at this grid: force 1e-4, radius 1e-2, stiffness 1e-3 (k = 2 E* a).
    assert abs(r["force"] / hertz_force(APPROACH) - 1) < 1e-4
    assert abs(math.sqrt(r["contact_area"] / math.pi) / a - 1) < 1e-2
    assert abs(r["stiffness"] / (2 * E_STAR * a) - 1) < 1e-3
    assert abs(r["max_pressure"] / (2 * E_STAR * a / (math.pi * RADIUS)) - 1) < 3e-4
    assert r["plastic_cells"] == 0 and r["residual"] < 1e-12
    # The outputs agree with one another: force = dx^2 sum p, the contact set is p > 0, the loaded gap
    # closes on it and stays open off it (D-7, to the tolerance of the stopping rule times the interference).
    p, g = r["pressure"], r["gap"]
    assert r["force"] == pytest.approx(dx * dx * p.sum(), rel=1e-12)
    assert np.array_equal(r["contact"], p > 0) and r["contact_cells"] == r["contact"].sum()
    interference = APPROACH - gap.min()
    assert np.abs(g[r["contact"]]).max() < 1e-10 * interference
    assert g[~r["contact"]].min() > -1e-10 * interference


def test_hertz_force_against_approach():
    """F(delta) = 4/3 E* sqrt(R) delta^1.5 over a factor 4 in approach on one grid."""
    gap, dx = hertz_grid(32, span=1.8)
    for scale in (0.5, 1.0, 2.0):
        r = contact.solve(gap, dx, e_star=E_STAR, approach=scale * APPROACH, tolerance=1e-12, stiffness=False)
        assert r["converged"]
        # 22.6 to 45 cells per contact radius: the kernel's convergence study (test_hertz.cpp) puts the
        # force error of 16 cells/radius under 1e-3.
        assert abs(r["force"] / hertz_force(scale * APPROACH) - 1) < 1e-3, scale


def test_load_control_finds_the_approach_of_the_force():
    gap, dx = hertz_grid(32)
    force = hertz_force(APPROACH)
    r = contact.solve(gap, dx, e_star=E_STAR, force=force, tolerance=1e-12)
    assert r["converged"]
    assert r["force"] == pytest.approx(force, rel=1e-12)
    # The approach for that force: Hertz's delta(P) to the grid's force error (1e-4 in force: 2/3 of it here).
    assert abs(r["approach"] / APPROACH - 1) < 1e-4
    assert math.isnan(r["stiffness"])
    # Displacement control at the approach found gives the same field.
    d = contact.solve(gap, dx, e_star=E_STAR, approach=r["approach"], tolerance=1e-12, stiffness=False)
    assert d["force"] == pytest.approx(force, rel=1e-9)
    assert np.array_equal(d["contact"], r["contact"])


def test_hardness_caps_the_pressure():
    gap, dx = hertz_grid(32)
    elastic = contact.solve(gap, dx, e_star=E_STAR, approach=APPROACH, tolerance=1e-12)
    p0 = elastic["max_pressure"]
    above = contact.solve(gap, dx, e_star=E_STAR, approach=APPROACH, tolerance=1e-12, hardness=1.5 * p0)
    assert np.array_equal(above["pressure"], elastic["pressure"])  # a cap never reached changes no bit
    capped = contact.solve(gap, dx, e_star=E_STAR, approach=APPROACH, tolerance=1e-12, hardness=0.8 * p0)
    assert capped["converged"] and capped["plastic_cells"] > 0
    assert capped["max_pressure"] == 0.8 * p0
    assert np.array_equal(capped["plastic"], capped["pressure"] == 0.8 * p0)
    assert capped["plastic_volume"] > 0
    assert capped["force"] < elastic["force"]
    # Saturated cells are pressed (g <= 0, D-7), to the stopping rule's tolerance.
    assert capped["gap"][capped["plastic"]].max() < 1e-10 * (APPROACH - gap.min())


def test_layouts_give_the_same_bits():
    gap, dx = hertz_grid(16)
    want = contact.solve(gap, dx, e_star=E_STAR, approach=APPROACH)
    wide = np.zeros((gap.shape[0], 2 * gap.shape[1]))
    wide[:, ::2] = gap
    strided = contact.solve(wide[:, ::2], dx, e_star=E_STAR, approach=APPROACH)
    fortran = contact.solve(np.asfortranarray(gap), dx, e_star=E_STAR, approach=APPROACH)
    single = contact.solve(gap.astype(np.float32).astype(np.float64), dx, e_star=E_STAR, approach=APPROACH)
    for other in (strided, fortran):
        assert np.array_equal(other["pressure"], want["pressure"])
        assert other["force"] == want["force"]
    assert single["converged"]


@pytest.mark.parametrize(
    "gap, kwargs, message",
    [
        ("nan", {}, "gap: 1 value NaN or infinite; allowed: a 2-D array (ny, nx) of the undeformed gap (m), finite"),
        ("1d", {}, "gap: 1 dimension(s); allowed: a 2-D array"),
        ("empty", {}, "gap: shape (0, 5), a side under 1; allowed"),
        ("text", {}, "gap: an array of dtype <U1; allowed"),
        ("complex", {}, "gap: an array of dtype complex128; allowed"),
        ("ok", {"tolerance": 1e-20}, "tolerance ([stiffness] tolerance) = 1e-20: out of range; allowed: a finite number in [1e-15, 0.01]"),
        ("ok", {"hardness": -1.0}, "hardness ([stiffness] hardness) = -1: out of range; allowed: a finite number >= 0 (Pa)"),
        ("ok", {"max_iterations": 5}, "max_iterations ([stiffness] max_iterations) = 5: out of range; allowed: a whole number in [10,"),
        ("ok", {"force": 1.0}, "approach, force = both given: one control; allowed: exactly one"),
        ("ok", {"approach": None}, "approach, force = neither given"),
        ("ok", {"e_star": 0.0}, "e_star = 0: not a size; allowed: a finite number > 0 (Pa, the effective modulus E*)"),
        ("ok", {"dy": float("nan")}, "dy = nan: not a size; allowed: a finite number > 0 (m)"),
        ("ok", {"approach": float("inf")}, "approach = inf: not finite"),
        ("ok", {"approach": None, "force": -1.0}, "force = -1: not a load; allowed: a finite force >= 0 (N)"),
        ("ok", {"approach": None, "hardness": 1e9, "force": 1e9}, "force = 1e+09 N: more than the grid can carry"),
    ],
)
def test_bad_input_is_a_value_error_naming_it(gap, kwargs, message):
    arrays = {
        "ok": np.ones((5, 5)),
        "nan": np.where(np.eye(5) * np.arange(5) == 3, np.nan, 1.0),
        "1d": np.ones(5),
        "empty": np.ones((0, 5)),
        "text": np.full((5, 5), "a"),
        "complex": np.ones((5, 5), complex),
    }
    args = {"e_star": 1e11, "approach": 1e-6}
    args.update(kwargs)
    args = {k: v for k, v in args.items() if v is not None}
    with pytest.raises(ValueError) as e:
        contact.solve(arrays[gap], 1e-6, **args)
    assert message in str(e.value)
    assert "\n" not in str(e.value)


def test_ball_gap_and_modulus():
    s = contact.ball_gap(0.01, 1e-5, 5, 3, shape="sphere")
    assert s.shape == (3, 5) and s[1, 2] == 0.0
    r = math.hypot(2e-5, 1e-5)
    assert s[0, 0] == pytest.approx(0.01 - math.sqrt(0.01**2 - r**2), rel=1e-12)
    assert contact.effective_modulus(210e9, 0.3, 210e9, 0.3) == pytest.approx(210e9 / (2 * (1 - 0.09)), rel=1e-15)
    with pytest.raises(ValueError, match="shape = 'cone': unknown ball shape; allowed: sphere, paraboloid"):
        contact.ball_gap(0.01, 1e-5, 5, 5, shape="cone")


def test_the_solve_releases_the_interpreter_lock():
    """The main thread keeps running Python while another thread is inside a solve."""
    dx = math.sqrt(RADIUS * APPROACH) / 38.4  # 256 x 256, 38.4 cells per contact radius
    gap = contact.ball_gap(RADIUS, dx, 256, 256, shape="paraboloid")
    state = {}

    def work():
        state["t0"] = time.perf_counter()
        state["result"] = contact.solve(gap, dx, e_star=E_STAR, approach=APPROACH, stiffness=False)
        state["t1"] = time.perf_counter()

    ticks = []
    worker = threading.Thread(target=work)
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)  # needs the lock to wake up; leaves the cores to the solver
    worker.join()
    assert state["result"]["converged"]
    seconds = state["t1"] - state["t0"]
    inside = [t for t in ticks if state["t0"] < t < state["t1"]]
    # Held, the lock would stop this loop from the call to its return (a tick or two at most, in the
    # interpreter's switch interval before the call); released, it ticks about every millisecond.
    assert seconds > 0.05
    assert len(inside) >= 10, (len(inside), seconds)


def test_help_reads_like_documentation():
    doc = contact.solve.__doc__
    assert "approach : float, optional" in doc and "Rigid approach w (m)" in doc
    assert "[stiffness] tolerance" in doc
    assert rollspec.__version__.count(".") == 2
