"""`python3 -m rollspec_post sweep`: band levels against the swept value and PSDs of points overlaid, from a
sweep the engine runs here through rollspec_post.run(..., sweep=...); a plain result is refused in one line."""
import os

import numpy as np
import pytest

from conftest import BIN, SOURCE, is_png_with_content, post
from figure_capture import capture_figures

SPEEDS = [1.0, 1.5, 2.0]  # oscillator masses in kg, as a stand-in for any swept key


@pytest.fixture(scope="module")
def sweep_result(tmp_path_factory):
    os.environ.setdefault("ROLLSPEC_BIN", BIN)
    import rollspec_post
    out = tmp_path_factory.mktemp("sweep") / "sweep.h5"
    groups = rollspec_post.run(SOURCE / "studies" / "random-oscillator.ini", out,
                               set={"study.realisations": 8, "signal.duration": 8},
                               sweep={"oscillator.mass": SPEEDS})
    assert list(groups["psd"]["oscillator_mass"].values) == SPEEDS
    assert groups["psd"]["mean"].dims[0] == "oscillator_mass"
    return out


def test_sweep_plot_draws_levels_against_the_swept_values(sweep_result, tmp_path, monkeypatch):
    from rollspec_post import sweep_plot
    figures = capture_figures(monkeypatch, sweep_plot)
    out = tmp_path / "sweep.png"
    sweep_plot.plot_sweep(str(sweep_result), str(out))
    assert is_png_with_content(out)
    left, right = figures[0].axes[:2]
    assert list(left.get_xticks()) == SPEEDS
    assert left.get_xlabel() == "oscillator_mass (kg)"
    import h5py
    with h5py.File(sweep_result) as f:
        levels = f["/bands/level_db"][()][:, 0, :]
    drawn = [line for line in left.get_lines()]
    assert len(drawn) == np.sum(np.any(np.isfinite(levels), axis=0))
    assert np.array_equal(drawn[0].get_xdata(), SPEEDS)
    first = int(np.argmax(np.any(np.isfinite(levels), axis=0)))
    assert np.array_equal(drawn[0].get_ydata(), levels[:, first])
    assert len(right.get_lines()) == len(SPEEDS)


def test_sweep_command_and_its_refusals(sweep_result, oscillator_result, tmp_path):
    out = tmp_path / "s.png"
    r = post("sweep", sweep_result, "--out", out, "--points", "0", "2")
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)
    r = post("sweep", oscillator_result, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "not a sweep result" in r.stderr and "Traceback" not in r.stderr
    r = post("sweep", sweep_result, "--out", tmp_path / "x.png", "--points", "7")
    assert r.returncode == 64 and "points 0 to 2" in r.stderr
    assert not (tmp_path / "x.png").exists()


def test_no_legend_covers_the_data(tmp_path, monkeypatch):
    """Thirty bands and twelve points: the bands get a colour bar, the points a colour bar of the swept value; a
    few points get their legend above the axes. Nothing drawn inside the axes but the data."""
    import h5py
    from figure_capture import overlap, renderer_of
    from rollspec_post import sweep_plot
    path = tmp_path / "wide.h5"
    masses = np.linspace(1.0, 2.1, 12)
    nominal = 1000.0 * 10 ** (np.arange(-19, 11) / 10)
    freq = np.linspace(0.0, 12800.0, 513)
    with h5py.File(path, "w") as f:
        f.attrs["filetype"], f.attrs["schema_version"] = "rollspec-result", "2.0"
        f.create_group("/sweep")
        f["/bands/oscillator_mass"] = masses
        f["/bands/oscillator_mass"].make_scale("oscillator_mass")
        f["/bands/level_db"] = -60.0 + masses[:, None, None] + np.log10(nominal)[None, None, :]
        f["/bands/level_db"].dims[0].attach_scale(f["/bands/oscillator_mass"])
        f["/bands/sensor"] = np.array(["sensor_1"], dtype=h5py.string_dtype())
        f["/bands/nominal_frequency"], f["/psd/frequency"] = nominal, freq
        f["/psd/mean"] = np.ones((masses.size, 1, freq.size)) * masses[:, None, None] * 1e-6
    figures = capture_figures(monkeypatch, sweep_plot)
    for points, bars in ((None, 2), ([0, 5, 11], 1)):
        sweep_plot.plot_sweep(str(path), str(tmp_path / "w.png"), points=points)
        fig = figures[-1]
        renderer = renderer_of(fig)
        left, right = fig.axes[:2]
        assert len(left.get_lines()) == 30 and left.get_legend() is None
        assert len(fig.axes) == 2 + bars  # the colour bars
        legend = right.get_legend()
        assert (legend is None) == (points is None)
        if legend is not None:
            assert len(legend.get_texts()) == 3
            assert overlap(legend.get_window_extent(renderer), right.get_window_extent(renderer)) == 0
            boxes = [t.get_window_extent(renderer) for t in legend.get_texts()]
            assert all(overlap(a, b) == 0 for i, a in enumerate(boxes) for b in boxes[i + 1:])
