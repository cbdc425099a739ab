"""`python3 -m rollspec_post texture` on a file made by `rollspec texture` in the test run."""
from conftest import SOURCE, assert_plots, post, rollspec_ok


def test_texture_plot(tmp_path):
    tex = tmp_path / "t.h5"
    rollspec_ok("texture", SOURCE / "studies" / "texture-demo.ini", "--out", tex, "--count", "4")
    assert_plots("texture", tex, tmp_path / "t.png")


def test_texture_plot_refuses_a_result_file(oscillator_result, tmp_path):
    r = post("texture", oscillator_result, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "rollspec-texture" in r.stderr


def test_colour_bar_label_clears_the_next_panel(tmp_path, monkeypatch):
    """The colour bar's label "height (µm)" must not touch the PSD panel's y label: at least 0.2 inch
    between them (it was 0.09 in, the two labels read as one)."""
    from figure_capture import capture_figures, overlap, renderer_of
    from rollspec_post import texture_plot
    tex = tmp_path / "t.h5"
    rollspec_ok("texture", SOURCE / "studies" / "texture-demo.ini", "--out", tex, "--count", "4")
    figures = capture_figures(monkeypatch, texture_plot)
    texture_plot.plot_texture(tex, tmp_path / "t.png")
    fig = figures[0]
    renderer = renderer_of(fig)
    colour_bar = next(ax for ax in fig.axes if ax.get_ylabel() == "height (µm)" and not ax.get_title())
    label = colour_bar.yaxis.label.get_window_extent(renderer)
    psd = next(ax for ax in fig.axes if ax.get_title().startswith("PSD"))
    assert (psd.get_tightbbox(renderer).x0 - label.x1) / fig.dpi >= 0.2
    for ax in fig.axes:
        if ax is not colour_bar:
            assert overlap(label, ax.get_tightbbox(renderer)) == 0, ax.get_title()
