"""`python3 -m rollspec_post trajectory` on an analytic rolling disc (slides, then rolls)."""
import h5py
import numpy as np

from conftest import is_png_with_content, post


def test_plane_is_the_two_widest_coordinates(rolling_disc_result):
    from rollspec_post.trajectory_plot import plane_axes
    with h5py.File(rolling_disc_result) as f:
        assert plane_axes(f["/time_history/position"][()]) == (0, 2)  # x travels, z spans the beam
    assert plane_axes(np.random.default_rng(1).normal(size=(5, 2, 3)) * [1, 5, 9]) == (1, 2)


def test_trajectory_plot(rolling_disc_result, tmp_path):
    out = tmp_path / "traj.png"
    r = post("trajectory", rolling_disc_result, "--out", out)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)


def test_trajectory_refuses_a_psd_result(oscillator_result, tmp_path):
    r = post("trajectory", oscillator_result, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "/time_history/position" in r.stderr
    assert not (tmp_path / "x.png").exists()


def test_trajectory_of_an_engine_result(tmp_path):
    """Seed 000 example 4.1 run by the engine in the test run (1 s of the disc)."""
    import subprocess
    from conftest import BIN, SOURCE
    res = tmp_path / "disc.h5"
    r = subprocess.run([BIN, "run", str(SOURCE / "studies" / "seed000-disc.ini"), "--out", str(res), "--quiet",
                        "--set", "analysis.t_end=1"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = tmp_path / "disc.png"
    r = post("trajectory", res, "--out", out)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)
