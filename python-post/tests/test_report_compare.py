"""The report and the ΔL panel show `rollspec compare`'s answer (its JSON), computed once by the engine: on
recordings of a rig whose model is 3 dB low, with logger noise and a recording of the rig at rest, the page's
headline is compare's level offset and verdict over the tested bands, the bands compare left out are marked
in the table and the plot with the reason, its warnings are on the page without the theory notes' equation
labels (those are footnotes), the options reach compare, and every failure is one line and an exit code."""
import html
import json
import os
import re
import subprocess

import h5py
import numpy as np
import pytest

from conftest import BIN, post

G = 9.80665
RIG = ("beam.length=1.0", "ball.radius=0.015", "ball.speed=2", "ball.end=0.95", "texture.rms=1e-8")
NOISE_DB = -63.0  # dB re 1 (m/s^2)^2/Hz, white: floors the bands up to 630 Hz


def engine(*args, cwd=None):
    r = subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    assert r.returncode == 0, r.stderr
    return r.stdout


def vendor_csv(path, fs, acc):
    rows = "\n".join(f"{i / fs:.6f};{a / G:.7f}".replace(".", ",") for i, a in enumerate(acc))
    path.write_text(f"Logger export\nTime (s);Acc (g)\n{rows}\n")
    return path


@pytest.fixture(scope="module")
def rig(tmp_path_factory):
    """A model of 40 realisations; three rolls of another seed x sqrt(2) with white noise; the rig at rest."""
    d = tmp_path_factory.mktemp("rig")
    engine("init", "ball-on-beam", "--out", d / "rig.ini")
    sets = [a for kv in RIG for a in ("--set", kv)]
    engine("run", d / "rig.ini", "--out", d / "model.h5", "--quiet", *sets, "--set", "study.realisations=40")
    engine("run", d / "rig.ini", "--out", d / "rolls.h5", "--quiet", *sets, "--set", "study.realisations=3",
           "--set", "study.seed=9", "--set", "output.time_histories=3")
    with h5py.File(d / "rolls.h5") as f:
        acc = np.sqrt(2.0) * f["/time_history/sensor_acceleration"][:, 0, :]
        fs = float(f["/psd"].attrs["sample_rate"][0])
    rng = np.random.default_rng(9)
    sigma = np.sqrt(10 ** (NOISE_DB / 10) * fs / 2)
    rolls = [vendor_csv(d / f"roll-{k}.csv", fs, a + sigma * rng.standard_normal(a.size)) for k, a in enumerate(acc, 1)]
    quiet = vendor_csv(d / "quiet.csv", fs, sigma * rng.standard_normal(4 * acc.shape[1]))
    return {"dir": d, "model": d / "model.h5", "rolls": rolls, "quiet": quiet}


def text_of(page):
    return " ".join(re.sub(r"<[^>]+>", " ", html.unescape(page)).split())


@pytest.fixture(scope="module")
def report(rig):
    out = rig["dir"] / "report.html"
    r = post("report", rig["model"], "--measurement", *rig["rolls"], "--noise", rig["quiet"], "--out", out)
    assert r.returncode == 0, r.stderr
    answer = json.loads(engine("compare", rig["model"], *rig["rolls"], "--noise", rig["quiet"], "--format", "json"))
    return out.read_text(), answer


def test_the_headline_is_compares_offset_and_verdict_over_the_tested_bands(report):
    page, answer = report
    o, text = answer["level_offset"], text_of(page)
    assert abs(o["estimate_db"] + 3.01) < 0.5 and answer["combined_test"]["defined"]
    figures = (f"{o['estimate_db']:+.2f} dB (95 % interval {o['lower_db']:+.2f} … {o['upper_db']:+.2f} dB) over "
               f"{o['bands']} tested bands")
    headline = re.search(r'<p class="headline">(.*?)</p>', page, re.S)
    assert headline and figures in text_of(headline.group(1)), text[:3000]
    verdict = "model rejected" if answer["combined_test"]["rejected"] else "not rejected"
    assert f"combined test at level 0.05: {verdict}, p = {answer['p_value']:.2g}" in text_of(headline.group(1))
    assert f"level offset, model − measurement {o['estimate_db']:+.2f} dB" in text
    assert f"{answer['inside']} of {answer['judged']}" in text


def test_left_out_bands_are_marked_with_the_reason(report):
    page, answer = report
    gone = [b for b in answer["bands"] if b["use"] != "test"]
    assert gone and all(b["use"] == "noise floor" for b in gone) and gone[0]["centre_hz"] == 12.5
    rows = re.findall(r'<tr class="left">(.*?)</tr>', page, re.S)
    assert len(rows) == len(gone)
    for row, band in zip(rows, gone):
        cells = re.findall(r"<td[^>]*>(.*?)</td>", row)
        assert float(cells[0]) == band["centre_hz"] and cells[-1] == "left out: noise floor"
    assert f"{len(gone)} of {answer['bands_compared']}" in text_of(page)
    assert "noise floor: within the margin of the noise recording's level" in text_of(page)


def test_compares_warnings_are_shown_without_equation_labels(report):
    page, answer = report
    notes = page.index("<h2>Notes</h2>")
    body = text_of(page[:notes])
    assert answer["warnings"] and "lie within 10 dB of the noise recording's level" in body
    assert not re.search(r"\bD-\d", body), re.findall(r".{60}\bD-\d+.{20}", body)
    assert "kernels/spectral" not in body
    footnotes = text_of(page[notes:page.index("<h2>Provenance</h2>")])
    assert "kernels/spectral/README.md" in footnotes and "D-33a" in footnotes
    assert "How the measurement was read" in page and "roll-1.csv … roll-3.csv (3 files): 'Acc (g)': read in g" in body


def test_the_plot_marks_the_left_out_bands(rig, report, tmp_path):
    from rollspec_post.psd_plot import plot_psd
    _, answer = report
    shown = plot_psd(rig["model"], tmp_path / "p.png", rig["rolls"], True, answer=answer)
    top, delta = shown["figure"].axes[:2]
    hatched = [p for p in delta.patches if p.get_hatch()]
    assert len(hatched) == sum(b["use"] != "test" for b in answer["bands"])
    assert "noise recording (rig at rest)" in shown["legend"]
    assert any("dotted: left out" in label for label in shown["legend"])
    measured = next(ln for ln in top.get_lines() if ln.get_label() == "measurement")
    f = np.asarray(answer["measured_psd"]["frequency_hz"])
    assert measured.get_xdata()[0] == f[f > 0][0]  # compare's spectrum, from the model's first bin on


def test_options_reach_compare(rig, tmp_path):
    out = tmp_path / "r.html"
    r = post("report", rig["model"], "--measurement", *rig["rolls"], "--noise", rig["quiet"], "--noise-margin", 30,
             "--fmin", 700, "--out", out)
    assert r.returncode == 0, r.stderr
    answer = json.loads(engine("compare", rig["model"], *rig["rolls"], "--noise", rig["quiet"], "--noise-margin", 30,
                               "--fmin", 700, "--format", "json"))
    assert answer["bands"][0]["centre_hz"] == 800 and f"{answer['level_offset']['estimate_db']:+.2f} dB" in out.read_text()
    assert "lie within 30 dB of the noise recording" in text_of(out.read_text())
    r = post("report", rig["model"], "--measurement", *rig["rolls"], "--noise", rig["quiet"], "--unit", "m/s2",
             "--out", out)
    assert r.returncode == 0, r.stderr
    wrong = json.loads(engine("compare", rig["model"], *rig["rolls"], "--noise", rig["quiet"], "--unit", "m/s2",
                              "--format", "json"))["level_offset"]["estimate_db"]
    assert wrong > 15 and f"level offset, model − measurement {wrong:+.2f} dB" in text_of(out.read_text())


def test_no_k0_for_a_hertz_law(report):
    page, _ = report
    rig = text_of(re.search(r"<h2>Rig</h2>(.*?)</table>", page, re.S).group(1))
    assert "contact law hertz" in rig and "k0" not in rig and "blocked_force" not in rig
    from rollspec_post.rig_summary import rig_parameters
    linearised = dict(rig_parameters("[contact]\nlaw = linearised\nk0 = 6800000\nblocked_force = spring\n"
                                     "damping = 100\nloss = damping_only\nfilter = patch\n"))["contact"]
    assert [k for k, _ in linearised] == ["law", "blocked_force", "k0", "damping", "filter"]


def one_line_refusal(r, code, *fragments):
    assert r.returncode == code, (r.returncode, r.stderr)
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
    for fragment in fragments:
        assert fragment in r.stderr, r.stderr


def test_failures_are_one_line_and_an_exit_code(rig, tmp_path):
    out = tmp_path / "r.html"
    env = dict(os.environ, ROLLSPEC_BIN=str(tmp_path / "no-such-rollspec"))
    r = subprocess.run(["/usr/bin/python3", "-m", "rollspec_post", "report", str(rig["model"]), "--measurement",
                        str(rig["rolls"][0]), "--out", str(out)], capture_output=True, text=True, env=env)
    one_line_refusal(r, 69, "no-such-rollspec", "set ROLLSPEC_BIN=/path/to/rollspec, or put rollspec on PATH")
    text = tmp_path / "words.csv"
    text.write_text("Time (s);Acc (g)\n0;a\n")
    one_line_refusal(post("report", rig["model"], "--measurement", text, "--out", out), 65, "rollspec compare: error:",
                     "words.csv")
    one_line_refusal(post("report", rig["model"], "--noise", rig["quiet"], "--out", out), 64, "--noise",
                     "--measurement FILE")
    one_line_refusal(post("report", rig["model"], "--measurement", *rig["rolls"], "--measured-averages", 0, "--out",
                          out), 64, "--measured-averages 0")
    one_line_refusal(post("psd", rig["model"], "--measurement", rig["rolls"][0], "--unit", "furlong", "--out",
                          tmp_path / "p.png"), 64, "furlong")
    assert not out.exists() and not (tmp_path / "p.png").exists()
