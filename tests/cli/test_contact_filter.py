"""[contact] filter = none | patch | iso2d of the ball-on-beam scene (issue 19; kernels/texture README
Eq. 36-40, kernels/beam B35): the key and its errors, the path PSDs in /roughness against an
independent scipy evaluation of Eq. 38, the synthesised texture against G_eq (through the linearised
model's frequency-domain reference), and seed 001 beam S above 2 kHz."""
import h5py
import numpy as np
import pytest
from scipy import integrate

from conftest import EX_CONFIG, SOURCE, assert_refused, hertz_radius, run

BEAM_S = SOURCE / "studies" / "seed001-beam-s-hertz.ini"
RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"
SHORT = ["--set", "ball.end=0.12", "--set", "spectrum.segment=1024"]  # 0.1 s records: fast


def test_bad_filter_value_names_the_allowed_ones(tmp_path):
    r = run(["plan", BEAM_S, "--set", "contact.filter=sinc"])
    assert_refused(r, EX_CONFIG, ["[contact] filter = sinc", "none", "patch", "iso2d", "solver"])


def test_the_retired_key_names_its_successor(tmp_path):
    study = tmp_path / "s.ini"
    study.write_text(BEAM_S.read_text().replace("filter = patch", "patch_filter = true"))
    r = run(["plan", study])
    assert_refused(r, EX_CONFIG, ["patch_filter = true", "[contact] filter = none | patch | iso2d | solver", "filter = patch"])


def test_iso2d_with_the_solver_blocked_force_is_refused():
    r = run(["plan", RIG, "--set", "contact.blocked_force=solver", "--set", "contact.filter=iso2d"])
    assert_refused(r, EX_CONFIG, ["[contact] filter = iso2d", "blocked_force = solver"])


@pytest.mark.parametrize("filt,words", [("none", "point contact"), ("patch", "1D average"), ("iso2d", "G_eq")])
def test_plan_shows_the_filter_and_the_contact_radius(filt, words):
    r = run(["plan", BEAM_S, "--set", f"contact.filter={filt}"])
    assert r.returncode == 0, r.stderr
    assert f"contact filter: {filt}" in r.stdout and words in r.stdout, r.stdout
    if filt != "none":
        assert f"a = {hertz_radius() * 1e6:.4g} um" in r.stdout, r.stdout


def self_affine(k, hurst, k_r, k_s, rms):
    """The [texture] self-affine line PSD (kernels/texture Eq. 6-7) with plateau to k = 0."""
    a = 1 + 2 * hurst
    c = rms ** 2 / (k_r + k_r * (1 - (k_s / k_r) ** (1 - a)) / (a - 1))
    return np.where(k < k_r, c, c * (np.asarray(k) / k_r) ** -a) * (np.asarray(k) <= k_s), c


def iso2d_scipy(k, a, hurst, k_r, k_s, rms):
    """Eq. 38 from the line PSD by adaptive quadrature: C_iso by the inverse Abel transform (Eq. 19, the
    power-law part plus the cut-off's jump, Eq. 20), then the filtered projection."""
    s = 1 + 2 * hurst
    _, c = self_affine(k_r, hurst, k_r, k_s, rms)
    jump = c * (k_s / k_r) ** -s

    def c_iso(r):  # smooth part S(r) = -2 pi int_r^inf G'(q) / sqrt(q^2 - r^2) dq, G' = -s G / q above k_r
        f = lambda q: s * c * (q / k_r) ** -s / q / np.sqrt(q + r)
        if r >= k_r:  # 1/sqrt(q - r) at the lower end: QUADPACK's algebraic weight
            return 2 * np.pi * integrate.quad(f, r, k_s, weight="alg", wvar=(-0.5, 0.0), limit=200, epsabs=0, epsrel=1e-10)[0]
        return 2 * np.pi * integrate.quad(lambda q: f(q) / np.sqrt(q - r), k_r, k_s, limit=200, epsabs=0, epsrel=1e-10)[0]

    y_end = np.sqrt(k_s ** 2 - k ** 2)
    w = lambda q: (np.sin(q * a) / (q * a)) ** 2
    smooth = lambda y: c_iso(np.hypot(k, y)) * w(np.hypot(k, y))
    kinks = [np.sqrt(k_r ** 2 - k ** 2)] if k < k_r else []
    edges = sorted(set([0.0, *kinks, *np.linspace(0, y_end, 40)[1:-1], y_end]))
    total = sum(integrate.quad(smooth, lo, hi, limit=200, epsabs=0, epsrel=1e-9)[0] for lo, hi in zip(edges[:-1], edges[1:]))
    th = integrate.quad(lambda t: w(np.hypot(k, y_end * np.sin(t))), 0, np.pi / 2, limit=400, epsabs=0, epsrel=1e-10)[0]
    return total / np.pi ** 2 + 2 * jump / np.pi * th


def test_roughness_group_against_an_independent_evaluation(tmp_path):
    out = tmp_path / "s.h5"
    r = run(["run", BEAM_S, "--out", out, "--quiet", "--set", "study.realisations=1", "--set", "contact.filter=iso2d", *SHORT])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        g = f["/roughness"]
        k, raw, patch, iso = g["wavenumber"][:], g["psd_raw"][:], g["psd_patch"][:], g["psd_iso2d"][:]
        a, dx = g.attrs["contact_half_width"], g.attrs["spacing"]
        assert g.attrs["filter"] in ("iso2d", b"iso2d")
        assert f["/contact"].attrs["patch_half_width"] == 0.0  # iso2d does not average the line again
    assert a == pytest.approx(hertz_radius(), rel=1e-9, abs=0)
    # The study's [texture]: H 0.8, roll-off 50 um, cut-off 4 um, rms 0.36 um.
    k_r, k_s = 2 * np.pi / 50e-6, 2 * np.pi / 4e-6
    expected_raw, _ = self_affine(k, 0.8, k_r, k_s, 0.36e-6)
    assert np.allclose(raw, expected_raw, rtol=1e-9)
    # patch: the band-limited line drawn compensated for the linear interpolant (B40a), then B35a on
    # the samples: the continuous sin(ka)/(ka) up to O(dx/a) aliases (dx/a = 0.14 here)
    t = np.sinc(k * a / np.pi)
    low = k * a < 1
    assert np.allclose(patch[low], raw[low] * t[low] ** 2, rtol=0.02)
    # the band limit (B40, [roughness] band_limit = output): nothing beyond k_B = pi f_s / v
    k_b = np.pi * 25600 / 1.0
    assert np.all(iso[k > k_b] == 0) and np.all(patch[k > k_b] == 0) and np.all(iso[k <= k_b] > 0)
    assert np.all(iso <= raw * (1 + 1e-3)) and np.all(patch <= raw * (1 + 1e-9))
    for kk in (60.0, 4e3, 3e4, 7e4):  # below the band limit k_B = 8.0e4 rad/m
        i = np.argmin(abs(np.log(k / kk)))
        ref = iso2d_scipy(k[i], a, 0.8, k_r, k_s, 0.36e-6)
        assert iso[i] == pytest.approx(ref, rel=1e-3, abs=0), (k[i], iso[i], ref)


def band_sum_above(path, f_low=2000.0):
    with h5py.File(path) as f:
        lo, level = f["/bands/lower_frequency"][:], f["/bands/level_db"][-1]
        sel = lo >= f_low * 2 ** (-1 / 6) * 0.999
        return 10 * np.log10(np.sum(10 ** (level[sel] / 10)))


def test_seed001_beam_s_iso2d_below_patch_below_none_above_2khz(tmp_path):
    levels = {}
    for filt in ("none", "patch", "iso2d"):
        out = tmp_path / f"{filt}.h5"
        r = run(["run", BEAM_S, "--out", out, "--quiet", "--set", "study.realisations=3", "--set", f"contact.filter={filt}",
                 "--set", "ball.end=0.2"])
        assert r.returncode == 0, r.stderr
        levels[filt] = band_sum_above(out)
    # The same Philox streams for all three: only the PSD differs. patch removes (sin ka/ka)^2 of the
    # short waves; iso2d also the across-path roughness shorter than the contact (most of ground steel's).
    assert levels["patch"] < levels["none"] - 1.0, levels
    assert levels["iso2d"] < levels["patch"] - 3.0, levels


def test_iso2d_texture_has_the_g_eq_spectrum(tmp_path):
    """The linearised rig's /reference is computed from G_eq (not from the realisations): the
    ensemble mean agrees with it under iso2d, and the iso2d reference differs from the point contact's
    where ka > 1. Quasi-stationary set-up of test_ball_on_beam's reference test, fewer realisations."""
    common = ["--quiet", "--set", "texture.rms=0.01e-6", "--set", "ball.speed=0.05", "--set", "ball.start=0.1",
              "--set", "ball.end=0.2", "--set", "beam.loss_factor=0.05", "--set", "spectrum.skip_start=0.15",
              "--set", "spectrum.segment=1024", "--set", "study.realisations=12"]
    refs = {}
    for filt in ("none", "iso2d"):
        out = tmp_path / f"{filt}.h5"
        r = run(["run", RIG, "--out", out, "--set", f"contact.filter={filt}", *common])
        assert r.returncode == 0, r.stderr
        with h5py.File(out) as f:
            freq = f["/psd/frequency"][:]
            sel = (freq >= 100) & (freq <= 5000)
            mean, ref = f["/psd/mean"][-1, sel], f["/reference/psd"][-1, sel]
            refs[filt] = ref
            if filt == "iso2d":
                d = 10 * np.log10(mean / ref)
                assert abs(np.median(d)) < 0.2, np.median(d)
    a = hertz_radius()
    ka = 2 * np.pi * freq[sel] / 0.05 * a
    drop = 10 * np.log10(refs["iso2d"] / refs["none"])
    assert np.all(drop <= 0.01), drop.max()
    assert np.median(drop[ka > 10]) < -10, np.median(drop[ka > 10])
