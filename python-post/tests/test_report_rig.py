"""`report` on a ball-on-beam result (seed 001 beam R, 5 realisations): loss of contact above the
threshold is a warning at the top of the page, the rig's parameters come from the stored study (the
contact law's own keys only), and the comparison's headline is `rollspec compare --format json`'s level
offset with its interval, with the rms of ΔL about it."""
import html
import json
import re
import shutil
import subprocess

import h5py
import numpy as np
import pytest

from conftest import BIN, SOURCE, post


def beam(tmp_path, name, seed):
    """From a copy of studies/: the study caches its stiffness table in studies/tables, not in the sources."""
    studies = tmp_path / "studies"
    if not studies.exists():
        shutil.copytree(SOURCE / "studies", studies, ignore=shutil.ignore_patterns("tables"))
    out = tmp_path / f"{name}.h5"
    r = subprocess.run([BIN, "run", studies / "seed001-beam-r.ini", "--out", out, "--quiet",
                        "--set", "study.realisations=5", "--set", f"study.seed={seed}",
                        # the page's layout, not the table's error: without the jackknife's 11 sub-table runs
                        "--set", "stiffness.table_error=none"], capture_output=True,
                       text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    return out


@pytest.fixture(scope="module")
def beam_report(tmp_path_factory):
    d = tmp_path_factory.mktemp("beam")
    model, other = beam(d, "model", 1002), beam(d, "other", 7)
    with h5py.File(other) as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][-1, 1:]
    meas = d / "meas.csv"
    np.savetxt(meas, np.c_[freq, 2.0 * psd], delimiter=",", header="frequency_hz,psd", comments="")
    out = d / "report.html"
    r = post("report", model, "--measurement", meas, "--measured-averages", 5, "--out", out)
    assert r.returncode == 0, r.stderr
    return model, meas, out, html.unescape(out.read_text())


def text_of(page):
    return " ".join(re.sub(r"<[^>]+>", " ", page).split())


def test_loss_of_contact_above_the_threshold_is_a_warning_at_the_top(beam_report, tmp_path):
    model, meas, out, page = beam_report
    with h5py.File(model) as f:
        share = float(f["/contact/loss_of_contact_share"][0])
    assert share > 0.05  # the seed's beam R at 1 m/s flies: the case the warning is for
    banner = re.search(r'<div class="warning" role="alert">(.*?)</div>', page, re.S)
    assert banner, "no loss-of-contact warning"
    assert f"Loss of contact: {100 * share:.3g} % of the time" in text_of(banner.group(1))
    assert page.index('class="warning"') < page.index("<h2>Key figures</h2>")  # before everything else
    assert 'class="card alert"' in page
    quiet = tmp_path / "quiet.html"
    r = post("report", model, "--loss-threshold", "0.9", "--out", quiet)
    assert r.returncode == 0, r.stderr
    assert 'class="warning"' not in quiet.read_text()
    r = post("report", model, "--loss-threshold", "5", "--out", tmp_path / "x.html")
    assert r.returncode == 64 and "--loss-threshold" in r.stderr


def test_rig_parameters_from_the_stored_study(beam_report):
    _, _, _, page = beam_report
    rig = re.search(r"<h2>Rig</h2>(.*?)</table>", page, re.S)
    assert rig, "no rig table"
    text = text_of(rig.group(1))
    for expected in ("beam", "length 0.4 m", "thickness 0.0068 m", "ball", "radius 0.02 m", "speed 1 m/s",
                     "sensors", "positions 0.1, 0.2, 0.3 m", "texture", "source profiles", "15 measured profiles",
                     "contact law table", "damping 100 N s/m"):
        assert expected in text, (expected, text)
    assert "k0" not in text and "blocked_force" not in text  # the linearised law's keys, not this law's


def test_the_headline_is_compares_level_offset(beam_report):
    model, meas, _, page = beam_report
    engine = json.loads(subprocess.run([BIN, "compare", model, meas, "--measured-averages", "5", "--format", "json"],
                                       capture_output=True, text=True, check=True).stdout)
    o = engine["level_offset"]
    delta = np.array([b["delta_db"] for b in engine["bands"] if b["use"] == "test"])
    assert o["estimate_db"] < -1.5  # the measurement is 2 x another ensemble: about -3 dB of pure offset
    text = text_of(page)
    assert f"level offset, model − measurement {o['estimate_db']:+.2f} dB" in text, text[:2000]
    assert f"95 % interval {o['lower_db']:+.2f} … {o['upper_db']:+.2f} dB over {o['bands']} tested bands" in text
    assert f"rms of ΔL about it {np.sqrt(np.mean((delta - o['estimate_db']) ** 2)):.2f} dB" in text
    t = engine["combined_test"]
    assert not t["defined"]  # 5 realisations: too few for 18 bands; the card says why, as compare does
    assert "combined test over the tested bands — none (18 bands need K >= 22 realisations" in text, text[:3000]
