"""Seed 002 §5, both speeds: the rig studies at 1 and 3 m/s, 100 realisations each (each study's own
seed), keep the seed's measured trends of the sensor-mean acceleration PSD. A calibration, not a
validation (CTest label `calibration`): the rig's roughness was chosen to give these facts
(docs/validation/seeds.md), so this test guards the calibration against later changes; it cannot show
that the model predicts them:

  - it falls off rapidly below 800 Hz: the 800 Hz third-octave band >= 15 dB above the 200 Hz band;
  - about +10 dB at 5 kHz from 1 to 3 m/s: the 5 kHz band rises by 7..13 dB;
  - little change below 1 kHz: the mean change of the bands 100..800 Hz within +-3 dB;
  - peaks at the measured resonances 504, 2419, 4465 Hz;

with the contact kept (the seed linearises about a maintained contact): loss of contact < 1 % of the
time. The roughness assumption that does it, and why, is in the study files' header. The earlier
assumption (self-affine H = 0.8, roll-off 50 um, rms 0.38 um) fails this test: 5 kHz +2.1 dB, loss
of contact 6.2 % at 1 m/s."""
import h5py
import numpy as np
import pytest

from conftest import SOURCE, run

MEASURED_RESONANCES = (504.0, 2419.0, 4465.0)  # seed 002 §4.1, Figs. 7-9 (EMA of the beam alone)
REALISATIONS = 100


def sensor_mean(f, group):
    names = [n.decode() if isinstance(n, bytes) else n for n in f[f"/{group}/sensor"][:]]
    return names.index("sensor_mean")


@pytest.fixture(scope="module")
def rig(tmp_path_factory):
    d = tmp_path_factory.mktemp("seed002")
    out = {}
    for speed in (1, 3):
        h5 = d / f"rig-{speed}ms.h5"
        r = run(["run", SOURCE / "studies" / f"seed002-rig-{speed}ms.ini", "--out", h5, "--quiet",
                 "--set", f"study.realisations={REALISATIONS}"])
        assert r.returncode == 0, r.stderr
        with h5py.File(h5) as f:
            assert f["/ball"].attrs["speed"][0] == speed
            i = sensor_mean(f, "bands")
            j = sensor_mean(f, "psd")
            out[speed] = {
                "bands": dict(zip(f["/bands/nominal_frequency"][:], f["/bands/level_db"][i])),
                "frequency": f["/psd/frequency"][:],
                "psd": f["/psd/mean"][j],
                "modes": f["/beam/modal_frequency"][:],
                "loss_of_contact": f["/contact/loss_of_contact_share"][0],
            }
    return out


def test_response_falls_off_below_800_hz(rig):
    for speed in (1, 3):
        b = rig[speed]["bands"]
        assert b[800.0] - b[200.0] >= 15.0, (speed, b[800.0] - b[200.0])


def test_five_khz_rises_about_10_db_from_1_to_3_m_per_s(rig):
    rise = rig[3]["bands"][5000.0] - rig[1]["bands"][5000.0]
    assert 7.0 <= rise <= 13.0, rise


def test_little_change_below_1_khz(rig):
    low = [f for f in rig[1]["bands"] if 100.0 <= f <= 800.0]
    assert len(low) == 10
    change = np.mean([rig[3]["bands"][f] - rig[1]["bands"][f] for f in low])
    assert abs(change) <= 3.0, change


def test_contact_is_kept(rig):
    # The seed linearises the contact about d0 (§4.2: "relative displacement of moderate order"), so
    # the ball must not leave the beam for more than a small share of the time.
    for speed in (1, 3):
        assert rig[speed]["loss_of_contact"] < 0.01, (speed, rig[speed]["loss_of_contact"])


def peak_centre(freq, psd, f0, half_width=0.1):
    """Power-weighted centre of the bins within 3 dB of the PSD's maximum in f0 +- 10 %, and that
    maximum's height above the lowest bin of the window (dB)."""
    w = (freq >= (1 - half_width) * f0) & (freq <= (1 + half_width) * f0)
    f, p = freq[w], psd[w]
    top = p >= p.max() / 2
    return (f[top] * p[top]).sum() / p[top].sum(), 10 * np.log10(p.max() / p.min())


def test_peaks_at_the_measured_resonances(rig):
    for speed in (1, 3):
        r = rig[speed]
        for measured in MEASURED_RESONANCES:
            # The model beam has a mode within 2 % of each resonance the seed measured on the beam alone.
            assert np.abs(r["modes"] / measured - 1).min() < 0.02, (measured, r["modes"])
            centre, height = peak_centre(r["frequency"], r["psd"], measured)
            assert height > 10.0, (speed, measured, height)  # a resonance peak, not a slope
            if measured == 504.0:
                # The 263 g ball on the 1 kg span lowers mode 2 by up to ~12 % when it is near an
                # antinode (below the ~800 Hz contact resonance it moves with the beam): the rolling
                # response's peak is smeared downwards over ~440..500 Hz.
                assert -0.08 < centre / measured - 1 < 0.02, (speed, measured, centre)
            else:
                assert abs(centre / measured - 1) < 0.02, (speed, measured, centre)
