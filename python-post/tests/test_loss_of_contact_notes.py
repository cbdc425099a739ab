"""A ball-on-beam result whose run warned of loss of contact (law = linearised: what the loss moved exceeds
the bands' intervals, kernels/spectral D-35) carries the warning onto the PSD figure (red, the run's own
words) and into the report's flag box. One whose law models the loss (hertz) and noted a loss above 5 %
carries the note (grey on the figure, quoted in the box). A smooth beam's result gets neither."""
import html
import re
import subprocess

import h5py
import pytest

from conftest import BIN, post


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    d = tmp_path_factory.mktemp("loss")
    r = subprocess.run([BIN, "init", "ball-on-beam", "--out", d / "rig.ini"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = {}
    for name, sets in {"hertz": ["study.realisations=2", "texture.rms=1e-6"],
                       "linearised": ["study.realisations=10", "texture.rms=2.5e-7", "contact.law=linearised"],
                       "smooth": ["study.realisations=2", "texture.rms=1e-9"]}.items():
        out[name] = d / f"{name}.h5"
        args = [a for kv in sets for a in ("--set", kv)]
        r = subprocess.run([BIN, "run", d / "rig.ini", "--out", out[name], "--quiet", *args], capture_output=True,
                           text=True)
        assert r.returncode == 0, r.stderr
    return out


def stored(path, kind="warning"):
    with h5py.File(path) as f:
        a = f["/contact"].attrs
        said = a[f"loss_of_contact_{kind}"].decode() if f"loss_of_contact_{kind}" in a else None
        return float(f["/contact/loss_of_contact_share"][0]), said


KIND = {"hertz": ("note", "Loss of contact: "), "linearised": ("warning", "LOSS OF CONTACT: ")}


@pytest.mark.parametrize("name", ["hertz", "linearised"])
def test_the_psd_figure_carries_the_warning(results, name, tmp_path):
    from rollspec_post.psd_plot import plot_psd
    kind, prefix = KIND[name]
    share, said = stored(results[name], kind)
    assert said and share > 0.05 and stored(results[name], "note" if kind == "warning" else "warning")[1] is None
    shown = plot_psd(results[name], tmp_path / "p.png")
    assert shown["loss_note"] == prefix + said
    texts = [t.get_text() for t in shown["figure"].axes[0].texts]
    assert shown["loss_note"] in texts  # drawn on the axes, not only returned
    r = post("psd", results[name], "--out", tmp_path / "cli.png")
    assert r.returncode == 0, r.stderr


@pytest.mark.parametrize("name", ["hertz", "linearised"])
def test_the_report_opens_with_the_flag_box(results, name, tmp_path):
    kind = KIND[name][0]
    share, said = stored(results[name], kind)
    out = tmp_path / "report.html"
    r = post("report", results[name], "--out", out)
    assert r.returncode == 0, r.stderr
    page = html.unescape(out.read_text())
    box = re.search(r'<div class="warning" role="alert">(.*?)</div>', page, re.S)
    assert box, "no loss-of-contact flag box"
    text = " ".join(re.sub(r"<[^>]+>", " ", box.group(1)).split())
    assert f"Loss of contact: {100 * share:.3g} % of the time" in text and said in text, text
    assert ("The run warned: " if kind == "warning" else "The run noted: ") in text, text
    assert page.index('class="warning"') < page.index("<h2>Key figures</h2>")


def test_a_smooth_result_has_no_note_and_no_box(results, tmp_path):
    from rollspec_post.psd_plot import plot_psd
    assert stored(results["smooth"]) == (0.0, None) and stored(results["smooth"], "note") == (0.0, None)
    assert plot_psd(results["smooth"], tmp_path / "p.png")["loss_note"] is None
    out = tmp_path / "report.html"
    assert post("report", results["smooth"], "--out", out).returncode == 0
    assert 'class="warning"' not in out.read_text()
