"""Ball-on-beam scene end to end: seed 002 rig modes and result layout, reproducibility, the default
integrator against the Dormand-Prince reference, and the linearised model against its
frequency-domain solution."""
import re

import h5py
import pytest
import numpy as np

from conftest import SOURCE, assert_bitwise_equal, run

RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"


def band_levels(path, sensor=-1, fmin=100.0, fmax=5000.0):
    with h5py.File(path) as f:
        lo, hi = f["/bands/lower_frequency"][:], f["/bands/upper_frequency"][:]
        sel = (lo >= fmin) & (hi <= fmax)
        return f["/bands/nominal_frequency"][sel], f["/bands/level_db"][sensor][sel]


def test_seed002_modes_within_two_percent():
    r = run(["modes", RIG])
    assert r.returncode == 0, r.stderr
    freq = {int(m.group(1)): float(m.group(2)) for m in re.finditer(r"^\s+(\d+)\s+([\d.]+)", r.stdout, re.M)}
    # The measured resonances are modes 2, 5 and 7 of the 420 mm effective beam (see the study file).
    for mode, measured in ((2, 504.0), (5, 2419.0), (7, 4465.0)):
        assert abs(freq[mode] / measured - 1) < 0.02, (mode, freq[mode])


def test_result_layout_and_threads(tmp_path):
    outs = []
    for threads in (1, 2):
        out = tmp_path / f"rig{threads}.h5"
        r = run(["run", RIG, "--out", out, "--quiet", "--set", "study.realisations=6", "--set", "output.time_histories=2"],
                env={"OMP_NUM_THREADS": str(threads)})
        assert r.returncode == 0, r.stderr
        outs.append(out)
    assert_bitwise_equal(*outs)
    with h5py.File(outs[0]) as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["/psd/sensor"][:]]
        assert names == ["sensor_1", "sensor_2", "sensor_3", "sensor_4", "sensor_5", "sensor_mean"]
        assert f["/psd/mean"].shape[0] == 6
        mean = f["/psd/mean"][:]
        assert np.allclose(mean[5], mean[:5].mean(axis=0), rtol=1e-12)
        for a in ("length", "effective_length", "width", "thickness", "youngs_modulus", "density"):
            assert a in f["/beam"].attrs
        assert f["/beam"].attrs["effective_length"] == 0.42
        assert f["/beam/modal_frequency"].attrs["units"] in (b"Hz", "Hz")
        assert 0.0 <= f["/contact/loss_of_contact_share"][0] < 0.5
        assert f["/time_history/sensor_acceleration"].shape[:2] == (2, 5)
        assert f["/time_history/contact_force"].shape[1] == f["/time_history/time"].shape[0]
        # The linearised law's mean force is the ball's weight (F0 fluctuates around m g).
        w = f["/ball"].attrs["mass"] * 9.81
        assert abs(f["/time_history/contact_force"][0].mean() / w - 1) < 0.05


def test_default_integrator_matches_dopri5_in_band_levels(tmp_path):
    # Near-linear regime (Hertz contact, small roughness: no loss of contact), 4 realisations.
    common = ["--quiet", "--set", "study.realisations=4", "--set", "contact.law=hertz", "--set", "texture.rms=0.05e-6",
              "--set", "ball.end=0.2", "--set", "spectrum.segment=1024"]
    fast, ref = tmp_path / "fast.h5", tmp_path / "ref.h5"
    assert run(["run", RIG, "--out", fast, *common]).returncode == 0
    r = run(["run", RIG, "--out", ref, *common, "--set", "signal.integrator=dopri5", "--set", "signal.rtol=1e-9"])
    assert r.returncode == 0, r.stderr
    with h5py.File(fast) as f:
        assert f["/contact/loss_of_contact_share"][0] < 0.05
    nominal, a = band_levels(fast)
    _, b = band_levels(ref)
    assert len(nominal) >= 15
    assert np.abs(a - b).max() < 0.1, dict(zip(nominal, np.round(a - b, 3)))


@pytest.mark.long  # minutes under the sanitizers: their pass skips it (tests/cli/CMakeLists.txt)
def test_default_settings_within_0_02_db_of_the_converged_run(tmp_path):
    """Issue 18 goal 2 (kernels/beam B40-B40a): the rig's own settings (4 substeps, the line at one
    sample per step, roughness band-limited to f_s/2 and drawn compensated for the patch filter's
    linear interpolant) against 64 substeps on a 4x finer line with the same harmonics (same seed,
    same line length): every band 100 Hz-5 kHz of the sensor mean within 0.02 dB (measured: 0.0018
    dB with 25 realisations). Without the band limit (step) the roughness above f_s/2 aliases into
    the bands and the same comparison is off by more than 0.1 dB (measured 0.39 dB at 25)."""
    dx = 1.0 / (25600 * 4)
    levels = {}
    for name, sets in {"default": [], "converged": ["signal.substeps=64", f"roughness.spacing={dx / 4!r}"],
                       "step": ["roughness.band_limit=step"],
                       "step_converged": ["roughness.band_limit=step", "signal.substeps=64", f"roughness.spacing={dx / 4!r}"]}.items():
        out = tmp_path / f"{name}.h5"
        args = ["run", RIG, "--out", out, "--quiet", "--set", "study.realisations=8", "--set", "output.reference=false"]
        r = run(args + [x for s in sets for x in ("--set", s)])
        assert r.returncode == 0, r.stderr
        nominal, levels[name] = band_levels(out, fmin=85.0)  # from the 100 Hz band (89-112 Hz), where aliases show first
    error = np.abs(levels["default"] - levels["converged"])
    assert error.max() < 0.02, dict(zip(nominal, np.round(error, 4)))
    assert np.abs(levels["step"] - levels["step_converged"]).max() > 0.1


@pytest.mark.long  # half a minute under the sanitizers: their pass skips it
def test_linearised_model_against_frequency_domain_solution(tmp_path):
    """Issue 5: the linearised model's Monte-Carlo mean lies inside its own chi-square 95 % interval
    around the frequency-domain solution in >= 90 % of the bins 100 Hz - 5 kHz.

    /reference/psd is the frequency-domain solution made exact for what the ensemble simulates
    (kernels/beam README B34a-c, B35a): the patch filter acting on the roughness samples (its linear
    interpolant adds sinc^2(k dx/2): -0.1 dB at 6 kHz, the main bias before), the Welch estimate's
    own time weights over ball positions, the Catmull-Rom reading of F0 at the steps, aliasing of the
    sampled outputs, the Welch window. /reference/degrees_of_freedom is the chi-square dof of the
    ensemble mean per bin for this non-stationary record (B34b): about 0.5-0.75 of the stationary
    Welch value (/psd@welch_degrees_of_freedom), which is why /psd/ci_* take theirs from the
    realisations' scatter instead (kernels/spectral D-21).

    What the reference leaves out is the moving load (quasi-stationary in the ball position); its
    bias grows with the ball's travel while the modes respond. Measured (worst sensor, 100 Hz - 5 kHz,
    rms bias beyond the sampling noise): 0.020 / 0.025 / 0.033 / 0.053 dB at 0.025 / 0.05 / 0.1 /
    0.2 m/s here; seed 002's own 1 m/s with loss factor 0.01 keeps only 82-87 % of the bins inside
    (K = 100-200), there v / (zeta_1 omega_1) = 0.18 m, half the traverse. So the check runs where the
    quasi-stationary approximation holds: 0.05 m/s, loss factor 0.05, Tf/tau = (1/f_1)/(traverse
    time) ~ 1e-3 and the ball's travel during the fundamental's decay time, v / (zeta_1 omega_1),
    ~ 1 % of the analysed length (asserted below). Light roughness: no loss of contact; start-up left
    out. Measured at this set-up (K = 100, seed 2002): 93 % of the bins inside for the sensor mean,
    89-94 % per sensor (92 % on average); median deviation within 0.01 dB. The former reference (continuous patch
    filter, uniform positions, no aliasing) holds 69-80 % of the bins here with the same dof, 57-72 % with
    the stationary /psd interval."""
    out = tmp_path / "lin.h5"
    speed, start, end, skip, loss_factor, realisations = 0.05, 0.1, 0.3, 0.15, 0.05, 100
    r = run(["run", RIG, "--out", out, "--quiet", "--set", f"study.realisations={realisations}", "--set", "texture.rms=0.01e-6",
             "--set", f"ball.speed={speed}", "--set", f"ball.start={start}", "--set", f"ball.end={end}",
             "--set", f"beam.loss_factor={loss_factor}", "--set", f"spectrum.skip_start={skip}",
             "--set", "spectrum.segment=1024"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        assert f["/contact/loss_of_contact_share"][0] == 0.0
        f1 = f["/beam/modal_frequency"][0]
        freq = f["/psd/frequency"][:]
        sel = (freq >= 100) & (freq <= 5000)
        mean, std, ref = f["/psd/mean"][:, sel], f["/psd/std"][:, sel], f["/reference/psd"][:, sel]
        lower, upper = f["/reference/mean_lower"][:, sel], f["/reference/mean_upper"][:, sel]
        dof, dof_stationary = f["/reference/degrees_of_freedom"][:, sel], f["/psd"].attrs["welch_degrees_of_freedom"]
        raw = f["/reference/psd_raw"][:, sel]
    # Quasi-stationary conditions (the reference's one approximation).
    analysed = end - (start + speed * skip)
    tf_over_tau = (1.0 / f1) / ((end - start) / speed)
    decay_travel = speed / (loss_factor / 2 * 2 * np.pi * f1)
    assert tf_over_tau < 0.01 and decay_travel / analysed < 0.02, (tf_over_tau, decay_travel / analysed)
    # The per-bin dof agrees with the realisations' own scatter (2 mean^2 / std^2 per realisation);
    # the stationary value overstates it.
    empirical = 2 * realisations * mean ** 2 / std ** 2
    assert np.all(np.abs(np.median(empirical / dof, axis=1) - 1) < 0.12), np.median(empirical / dof, axis=1)
    assert np.all(np.median(empirical / dof_stationary, axis=1) < 0.85)
    # The criterion: sensor mean, and the sensors on average.
    inside = ((mean >= lower) & (mean <= upper)).mean(axis=1)
    assert inside[-1] >= 0.90, inside
    assert inside[:-1].mean() >= 0.90, inside
    d = 10 * np.log10(mean[-1] / ref[-1])
    assert abs(np.median(d)) < 0.03, np.median(d)
    # The window smoothing matters: the unsmoothed solution misses resonances and dips by several dB.
    raw_d = 10 * np.log10(mean[-1] / raw[-1])
    assert np.percentile(np.abs(raw_d), 95) > 2 * np.percentile(np.abs(d), 95)


@pytest.mark.parametrize("spacing", ["0.05", "7e-4", "3.3e-5"])
@pytest.mark.parametrize("law", ["hertz", "linearised"])
def test_a_spacing_that_does_not_divide_the_span_still_covers_the_traverse(tmp_path, spacing, law):
    # 0.39 m / 0.05 m leaves the last sample at 0.35 m, short of the traverse's end at 0.37 m: the
    # line is extended to it (this once ended in an internal error).
    out = tmp_path / "r.h5"
    r = run(["run", SOURCE / "studies" / "seed002-rig-1ms.ini", "--out", out, "--quiet", "--set", "study.realisations=2",
             "--set", f"roughness.spacing={spacing}", "--set", f"contact.law={law}", "--set", "texture.source=iso8608"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        assert np.isfinite(f["/psd/mean"][:]).all() and (f["/psd/mean"][:, 1:] > 0).all()
