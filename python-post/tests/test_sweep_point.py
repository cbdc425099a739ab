"""psd, report and panels read one point of a sweep result (--point K, or section.key=value): the point's
own spectra, checked against the same study run alone at that value; a sweep result without --point, a
point that is not there, and --point of a result that is no sweep are refused in one line (exit 64)."""
import os

import numpy as np
import pytest

from conftest import BIN, SOURCE, post

MASSES = [1.0, 2.5]
FAST = {"study.realisations": 4, "signal.duration": 4}


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    os.environ.setdefault("ROLLSPEC_BIN", BIN)
    import rollspec_post
    d = tmp_path_factory.mktemp("sweep")
    study = SOURCE / "studies" / "random-oscillator.ini"
    rollspec_post.run(study, d / "sweep.h5", set=FAST, sweep={"oscillator.mass": MASSES})
    rollspec_post.run(study, d / "alone.h5", set=dict(FAST, **{"oscillator.mass": MASSES[1]}))
    return d / "sweep.h5", d / "alone.h5"


@pytest.mark.parametrize("point", ["2", "oscillator.mass=2.5", "oscillator_mass=2.50"])
def test_psd_draws_the_point_the_study_gives_alone(results, point, monkeypatch):
    from rollspec_post import psd_plot
    from rollspec_post.result_file import select_point
    sweep, alone = results
    select_point(point)
    try:
        at_point = psd_plot.read_psd(str(sweep))
    finally:
        select_point(None)
    by_itself = psd_plot.read_psd(str(alone))
    for a, b in zip(at_point[1:4], by_itself[1:4]):  # mean, ci_lower, ci_upper: the same bits
        assert a.tobytes() == b.tobytes()
    assert at_point[5][0].endswith(" at oscillator.mass=2.5")


def test_psd_report_and_panels_read_a_point(results, tmp_path):
    sweep, alone = results
    r = post("psd", sweep, "--bands", "--point", "2", "--out", tmp_path / "p.png")
    assert r.returncode == 0, r.stderr
    r = post("report", sweep, "--point", "1", "--out", tmp_path / "r.html")
    assert r.returncode == 0, r.stderr
    assert "at the sweep point oscillator.mass=1" in (tmp_path / "r.html").read_text()
    r = post("panels", "--panel", "A", f"{sweep}=sweep", "--point", "oscillator.mass=1", "--out", tmp_path / "a.png")
    assert r.returncode == 0, r.stderr


@pytest.mark.parametrize("args,what", [
    ([], "is a sweep result of 2 points (crossed: oscillator.mass = 1, 2.5): choose one point"),
    (["--point", "3"], "--point 3: "),
    (["--point", "oscillator.mass=2"], "oscillator.mass = 2 is no point"),
    (["--point", "ball.speed=1"], "names no swept key"),
])
def test_a_sweep_result_needs_a_point_that_is_there(results, tmp_path, args, what):
    out = tmp_path / "o.png"
    r = post("psd", results[0], *args, "--out", out)
    assert r.returncode == 64 and what in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert not out.exists()


def test_a_point_of_a_result_that_is_no_sweep_is_refused(results, tmp_path):
    r = post("psd", results[1], "--point", "1", "--out", tmp_path / "o.png")
    assert r.returncode == 64 and "is not a sweep result" in r.stderr, r.stderr
