"""`python3 -m rollspec_post report`: one self-contained HTML page; it opens in headless Chromium
without console errors and its screenshot is not blank. Key figures are those `rollspec compare` prints."""
import base64
import html.parser
import os
import subprocess

import pytest

from conftest import BIN, hdf5_with_attributes, is_png_with_content, post, write_measurement

CHROMIUM = "/usr/bin/chromium"


class Resources(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.urls, self.tags = [], []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self.urls += [v for k, v in attrs if k in ("src", "href")]


@pytest.fixture
def report_with_measurement(oscillator_result, tmp_path):
    meas = write_measurement(oscillator_result, tmp_path / "meas.csv", 1.05)
    out = tmp_path / "report.html"
    r = post("report", oscillator_result, "--measurement", meas, "--out", out)
    assert r.returncode == 0, r.stderr
    return out, meas


def test_report_is_self_contained_and_matches_compare(report_with_measurement, oscillator_result):
    out, meas = report_with_measurement
    page = out.read_text()
    p = Resources()
    p.feed(page)
    assert "script" not in p.tags and "link" not in p.tags
    assert p.urls and all(u.startswith("data:image/png;base64,") for u in p.urls)
    assert base64.b64decode(p.urls[0].split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    for text in ("random-oscillator", "philox4x64-10", "[oscillator]", "loss-of-contact share", "run time"):
        assert text in page
    last = subprocess.run([BIN, "compare", oscillator_result, meas], capture_output=True, text=True).stdout
    rms, inside = last.strip().splitlines()[-1].replace("rms_db_error:", "").split("inside_ci:")
    n_in, n = map(int, inside.split("/"))
    assert f"rms ΔL over them {float(rms):.2f} dB" in page and f">{n_in} of {n}<" in page


@pytest.mark.skipif(not os.path.exists(CHROMIUM), reason="/usr/bin/chromium absent (Debian package chromium)")
def test_report_opens_in_headless_chromium(report_with_measurement, tmp_path):
    out, _ = report_with_measurement
    shot = tmp_path / "shot.png"
    r = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                        "--disable-background-networking", "--disable-component-update", "--disable-sync",
                        f"--user-data-dir={tmp_path / 'profile'}", "--enable-logging=stderr", "--v=0",
                        f"--screenshot={shot}", "--window-size=1200,2000", f"file://{out}"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr[-2000:]
    assert ":CONSOLE" not in r.stderr, r.stderr[-2000:]
    assert is_png_with_content(shot)


def test_report_clear_errors(oscillator_result, tmp_path):
    r = post("report", tmp_path / "missing.h5", "--out", tmp_path / "x.html")
    assert r.returncode == 66 and "no such file" in r.stderr
    other = hdf5_with_attributes(tmp_path / "other.h5", filetype="rollspec-stiffness-table", schema_version="1.0")
    r = post("report", other, "--out", tmp_path / "x.html")
    assert r.returncode == 65 and "not a rollspec file" in r.stderr
    r = post("report", oscillator_result, "--sensor", "3", "--out", tmp_path / "x.html")
    assert r.returncode == 64 and "--sensor 3" in r.stderr
    assert not (tmp_path / "x.html").exists()
