"""`python3 -m rollspec_post trajectory` on an analytic rolling disc (slides, then rolls)."""
import h5py
import numpy as np

from conftest import assert_plots, post, rollspec_ok


def test_plane_is_the_two_widest_coordinates(rolling_disc_result):
    from rollspec_post.trajectory_plot import plane_axes
    with h5py.File(rolling_disc_result) as f:
        assert plane_axes(f["/time_history/position"][()]) == (0, 2)  # x travels, z spans the beam
    assert plane_axes(np.random.default_rng(1).normal(size=(5, 2, 3)) * [1, 5, 9]) == (1, 2)


def test_trajectory_plot(rolling_disc_result, tmp_path):
    assert_plots("trajectory", rolling_disc_result, tmp_path / "traj.png")


def test_trajectory_refuses_a_psd_result(oscillator_result, tmp_path):
    r = post("trajectory", oscillator_result, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "/time_history/position" in r.stderr
    assert not (tmp_path / "x.png").exists()


def test_trajectory_of_an_engine_result(tmp_path):
    """Seed 000 example 4.1 run by the engine in the test run (1 s of the disc)."""
    from conftest import SOURCE
    res = tmp_path / "disc.h5"
    rollspec_ok("run", str(SOURCE / "studies" / "seed000-disc.ini"), "--out", str(res), "--quiet",
                "--set", "analysis.t_end=1")
    assert_plots("trajectory", res, tmp_path / "disc.png")


def test_flying_beam_legend_holds_only_energies_below_the_axes(tmp_path, monkeypatch):
    """studies/seed000-flying-beam.ini: each energy has a dimension scale `<name>_index` beside it; those
    are no energies, and the legend of the real ones sits below the axes, over no data."""
    import shutil
    import subprocess
    from conftest import BIN, SOURCE
    from figure_capture import capture_figures, overlap, renderer_of
    from rollspec_post import trajectory_plot
    studies = tmp_path / "studies"
    shutil.copytree(SOURCE / "studies", studies)
    res = tmp_path / "fb.h5"
    # 2 s of the 20 s flight: the energies and their scales are the same (a tenth of the run, under the sanitizers too)
    r = subprocess.run([BIN, "run", "studies/seed000-flying-beam.ini", "--out", res, "-q", "--set", "analysis.t_end=2"],
                       capture_output=True,
                       text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    with h5py.File(res) as f:
        group = f["/time_history/energy"]
        real = sorted(n.replace("_", " ") for n in group if n != "balance_error" and "CLASS" not in group[n].attrs)
        assert any("CLASS" in group[n].attrs for n in group), "the engine no longer writes dimension scales"
    figures = capture_figures(monkeypatch, trajectory_plot)
    trajectory_plot.plot_trajectory(res, tmp_path / "fb.png")
    fig = figures[0]
    ax_e = next(ax for ax in fig.axes if ax.get_title() == "energies")
    legend = ax_e.get_legend()
    assert sorted(t.get_text() for t in legend.get_texts()) == real
    assert not any("index" in line.get_label() for line in ax_e.get_lines())
    renderer = renderer_of(fig)
    box = legend.get_window_extent(renderer)
    for ax in fig.axes:  # over no axes, and not over the energies' time label
        assert overlap(box, ax.get_window_extent(renderer)) == 0, ax.get_title()
    assert overlap(box, ax_e.xaxis.label.get_window_extent(renderer)) == 0
    assert box.y1 < ax_e.get_window_extent(renderer).y0
