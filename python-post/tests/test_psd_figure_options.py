"""`psd` for a paper: --title, --label, --measurement-label, --ylim, --style seed; the measured band
levels drawn beside the simulated ones; minor tick labels on a log axis under two decades. Checked on
the figure itself (line styles, legend texts, limits, tick labels), not only on the file's bytes."""
import numpy as np
import pytest

from conftest import post, write_measurement
from figure_capture import overlap, renderer_of


@pytest.fixture
def measurement(oscillator_result, tmp_path):
    return write_measurement(oscillator_result, tmp_path / "meas.csv", 1.2)


def line(ax, label):
    return next(ln for ln in ax.get_lines() if ln.get_label() == label)


def test_seed_style_title_labels_and_limits(oscillator_result, measurement, tmp_path):
    from rollspec_post.psd_plot import plot_psd
    shown = plot_psd(oscillator_result, tmp_path / "p.png", measurement, title="Oscillator, 16 runs",
                     label="model", measurement_label="rig, 3 Mar", ylim=(-80.0, -10.0), style="seed")
    fig = shown["figure"]
    ax = fig.axes[0]
    assert fig._suptitle is not None and fig._suptitle.get_text() == "Oscillator, 16 runs"
    assert ax.get_ylim() == (-80.0, -10.0)
    computed, measured = line(ax, "model"), line(ax, "rig, 3 Mar")
    assert computed.get_linestyle() == ":" and measured.get_linestyle() == "-"
    assert measured.get_color() in ("k", "black", (0.0, 0.0, 0.0, 1.0))
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "model" in texts and "rig, 3 Mar" in texts
    # defaults of the seed style name both curves too
    seed = plot_psd(oscillator_result, tmp_path / "q.png", measurement, style="seed")
    assert {"computed, mean of 16", "measured"} <= set(seed["legend"])
    assert line(seed["figure"].axes[0], "computed, mean of 16").get_linestyle() == ":"


def test_compare_draws_the_measured_band_levels(oscillator_result, measurement, tmp_path):
    from rollspec_post.psd_plot import plot_psd
    shown = plot_psd(oscillator_result, tmp_path / "p.png", measurement, True, measurement_label="rig")
    fig, cmp = shown["figure"], shown["comparison"]
    top, delta = fig.axes[0], fig.axes[1]
    from matplotlib.collections import LineCollection
    black = [c for c in top.collections if isinstance(c, LineCollection) and np.allclose(c.get_color()[0], (0, 0, 0, 1))]
    assert len(black) == 1
    levels = np.array([seg[0][1] for seg in black[0].get_segments()])
    np.testing.assert_allclose(levels, [b["measured_db"] for b in cmp["bands"] if b["use"] == "test"])
    assert "third-octave bands: simulated, rig" in shown["legend"] and "rig" in shown["legend"]
    assert "rig" in delta.get_ylabel()
    renderer = renderer_of(fig)  # the legend's entries do not run into each other
    boxes = [t.get_window_extent(renderer) for t in top.get_legend().get_texts()]
    assert all(overlap(a, b) == 0 for i, a in enumerate(boxes) for b in boxes[i + 1:])


def test_log_axis_under_two_decades_labels_its_minor_ticks(oscillator_result, tmp_path):
    from rollspec_post.psd_plot import plot_psd
    fig = plot_psd(oscillator_result, tmp_path / "p.png", xscale="log", fmin=2.0, fmax=40.0)["figure"]
    renderer_of(fig)
    minor = [t.get_text() for t in fig.axes[0].xaxis.get_minorticklabels() if t.get_text()]
    assert {"2", "3", "20"} <= set(minor), minor


def test_command_line_options(oscillator_result, measurement, tmp_path):
    out = tmp_path / "p.pdf"
    r = post("psd", oscillator_result, "--bands", "--measurement", measurement, "--style", "seed", "--title", "T",
             "--label", "sim", "--measurement-label", "meas", "--ylim", "-90", "0", "--out", out)
    assert r.returncode == 0, r.stderr
    assert out.read_bytes()[:5] == b"%PDF-"
    r = post("psd", oscillator_result, "--ylim", "0", "-90", "--out", tmp_path / "x.png")
    assert r.returncode == 64 and "--ylim" in r.stderr and not (tmp_path / "x.png").exists()
    r = post("psd", oscillator_result, "--style", "fancy", "--out", tmp_path / "x.png")
    assert r.returncode == 64 and "Traceback" not in r.stderr
