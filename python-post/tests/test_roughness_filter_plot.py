"""`python3 -m rollspec_post roughness`: the path PSD raw and under each contact filter, from /roughness."""
import shutil

import numpy as np
import pytest

from conftest import SOURCE, assert_plots, post, rollspec_ok


@pytest.fixture(scope="module")
def beam_result(tmp_path_factory):
    out = tmp_path_factory.mktemp("results") / "beam.h5"
    rollspec_ok("run", SOURCE / "studies" / "seed001-beam-s-hertz.ini", "--out", out, "--quiet",
                "--set", "study.realisations=1", "--set", "ball.end=0.12", "--set", "spectrum.segment=1024",
                "--set", "contact.filter=iso2d")
    return out


def test_roughness_plot(beam_result, tmp_path):
    assert_plots("roughness", beam_result, tmp_path / "r.png")


def test_plotted_curves_obey_the_filters(beam_result):
    from rollspec_post.roughness_filter_plot import read_roughness
    k, curves, used, a, speed = read_roughness(beam_result)
    assert used == "iso2d" and set(curves) == {"none", "patch", "iso2d"} and speed == 1.0
    raw, patch, iso = curves["none"], curves["patch"], curves["iso2d"]
    # Both filters only remove power (|w^| <= 1, kernels/texture Eq. 37; B35a <= 1).
    assert np.all(iso <= raw * (1 + 1e-3)) and np.all(patch <= raw * (1 + 1e-9))
    # patch at ka << 1 passes the line PSD; its first zero sits at ka = pi (B35).
    low = k * a < 0.05
    assert np.allclose(patch[low], raw[low], rtol=2e-3)
    i = np.argmin(abs(k * a - np.pi))
    assert patch[i] < 1e-3 * raw[i]
    # iso2d at ka << 1 is flat like the line PSD's plateau (the contact passes the along-path waves)
    # but far below it: ground steel's power sits at wavelengths < 2a across the path too.
    assert np.ptp(np.log(iso[low])) < 0.01
    assert np.all(iso[low] < 0.2 * raw[low])
    # iso2d has no zeros: it sums over all directions, sin(qa)/(qa) vanishes only on rings. Up to the
    # band limit (B40): beyond it the line carries nothing.
    assert np.all(iso[k <= np.pi * 25600 / speed] > 0)


@pytest.fixture(scope="module")
def solver_result(tmp_path_factory):
    """The seed 002 rig with filter = solver on a coarse strip (12 um cells, the texture cut at 24 um; as
    tests/cli/test_solver_filter.py): seconds."""
    out = tmp_path_factory.mktemp("solver") / "rig.h5"
    sets = ["contact.law=hertz", "contact.filter=solver", "surface.spacing=12e-6", "texture.short_wavelength=24e-6",
            "blocked_force.segment=128", "blocked_force.strip_length=6.6e-3", "ball.start=0.1", "ball.end=0.106",
            "spectrum.segment=128", "study.realisations=1"]
    study = out.parent / "rig.ini"  # its tables are written beside it, not in the source tree
    shutil.copy(SOURCE / "studies" / "seed002-rig-1ms.ini", study)
    rollspec_ok("run", study, "--out", out, "--quiet", *[a for kv in sets for a in ("--set", kv)])
    return out


def test_solver_curve_is_drawn_and_follows_the_patch(solver_result, tmp_path):
    from rollspec_post.roughness_filter_plot import read_roughness
    k, curves, used, a, speed = read_roughness(solver_result)
    assert used == "solver" and set(curves) == {"none", "patch", "iso2d", "solver"}
    raw, iso, solver = curves["none"], curves["iso2d"], curves["solver"]
    # ER-3: h_eq is the roughness averaged by the flat-punch weight, whose first-order transfer is
    # G_eq (iso2d) on an isotropic surface: near the patch scale the solver curve is far below the raw
    # line and within a few dB of G_eq (the strips are few and short: a Welch estimate, not G_eq itself).
    band = (k * a > 1.0) & (k * a < 2.5) & (raw > 0)
    assert np.all(solver[band] < 0.5 * raw[band])
    assert abs(10 * np.log10(np.mean(solver[band]) / np.mean(iso[band]))) < 3.0
    assert_plots("roughness", solver_result, tmp_path / "s.png")


def test_refuses_a_result_without_roughness(oscillator_result, tmp_path):
    r = post("roughness", oscillator_result, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "/roughness" in r.stderr
