"""Calibration of `rollspec fit`'s intervals on a ball-on-beam scene (kernels/spectral D-27g), label
`statistics`: the seed 002 rig with half its roll, synthetic measurements at the study's beam loss
factor made with other seeds, each fitted for it; the nominal 95 % profile intervals must hold the truth
about 95 % of the time. The loss factor is the harder key: it changes the bands' shape and their
scatter (a level key is calibrated by test_fit_coverage.py on the oscillator; the rig's roughness level,
texture.rms, by bench/engine/bench_fit_coverage.py --case rig-rms: 55 of 60).
Budget: 20 experiments, 20 fits of ~32 runs, about 8 s each (a fit's runs write only the spectra it
reads): 83 s on 2 idle cores (fewer experiments would assert nothing useful). Asserted: at least 16 of 20 hold the truth,
which a calibrated 95 % fit meets with probability 0.9974 (P[X <= 15] = 0.0026); a fit covering 80 %
meets it with probability 0.63, one covering 70 % with 0.24, so this catches gross under-coverage only.
The fuller experiment is bench/engine/bench_fit_coverage.py (--case rig-loss: 55 of 60)."""
import concurrent.futures

import pytest

from conftest import SOURCE, measure_and_fit

RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"
# As bench_fit_coverage.py --case rig-rms / rig-loss --model-seeds (other seeds): each fit's runs with a
# seed of their own, so the model's own noise varies between experiments as the measurement's does (with
# the study's seed in every fit, all fits share one model error and coverage is conditional on it);
# a 0.18 m roll, the 16 bands 89 .. 3548 Hz (modes 2 and 5), M = 25 as the rig, K = 30.
SHORT = ["ball.end=0.2"]
BANDS = ["--fmin", "85", "--fmax", "3600"]
RECORDS, REALISATIONS, EXPERIMENTS = 25, 30, 20
CASES = {"beam.loss_factor": (0.01, "0.002:0.05:log")}


def one(directory, key, seed):
    truth, rng = CASES[key]
    out = measure_and_fit(RIG, directory, seed, key, truth, rng, short=SHORT, bands=BANDS, records=RECORDS,
                          realisations=REALISATIONS)
    # The rig's linearised contact keeps common random numbers (kernels/spectral D-27i a): the fit reads ln L
    # of the study's seed and gives its profile intervals; it does not smooth or refuse where it need not.
    assert out["objective"]["common_random_numbers"] is True and out["objective"]["incoherent_share"] < 0.01
    assert out["no_interval"] is None
    return out["parameters"][key]


@pytest.mark.parametrize("key", sorted(CASES))
def test_rig_intervals_hold_the_truth_at_their_nominal_rate(tmp_path, key):
    truth = CASES[key][0]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        fits = list(pool.map(lambda s: one(tmp_path, key, 6100 + s), range(EXPERIMENTS)))
    held = sum(p["interval"][0] <= truth <= p["interval"][1] for p in fits)
    below = sum(p["interval"][1] < truth for p in fits)
    print(f"{key}: coverage {held}/{EXPERIMENTS} ({below} wholly below the truth)")
    assert held >= 16, f"{key}: {held}/{EXPERIMENTS} intervals hold the truth, {below} wholly below it"
