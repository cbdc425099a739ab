"""bench/engine/bench_table_term.py's estimate of the table term's calibration, on simulated benches whose
truth is known: each table's band levels deviate from the roughness's mean by tau (variance T per band, between
tables), each central run adds its own noise of known variance, and each model's jackknife V_J is, as on a scene
whose sub-table runs lose their common random numbers, (T + n) chi²_9 / 9 (10 surfaces) with n the runs' own
noise. The bench's ratio "between / (V_J - n)" then has expectation about 1 and "between / V_J" T / (T + n); over
100 simulated benches of 32 tables the interval over the tables holds the true ratio about as often as its 95 %
says. About 10 s, no rollspec run."""
import sys

import numpy as np

from conftest import SOURCE

sys.path.insert(0, str(SOURCE / "bench" / "engine"))
sys.dont_write_bytecode = True
import bench_table_term  # noqa: E402

BANDS = 6
TABLE = np.linspace(0.05, 0.4, BANDS)   # T per band (dB²)
NOISE_N = np.linspace(0.15, 0.02, BANDS)  # the sub-table runs' own noise in V_J (dB²)
CENTRAL = 0.002                          # the central runs' own noise (dB²)


def simulated_bench(stream, tables=32, surfaces=10):
    central, models = [], []
    for _ in range(tables):
        level = stream.normal(0.0, np.sqrt(TABLE)) + stream.normal(0.0, np.sqrt(CENTRAL), BANDS)
        central.append({"level": level, "noise": np.full(BANDS, CENTRAL)})
        vj = (TABLE + NOISE_N) * stream.chisquare(surfaces - 1, BANDS) / (surfaces - 1)
        models.append({"vj": vj, "n": NOISE_N})
    return central, models


def test_the_ratios_recover_the_known_calibration_and_their_intervals_hold_it():
    stream = np.random.Generator(np.random.Philox(key=47))
    truth = {"vj": TABLE.mean() / (TABLE + NOISE_N).mean(), "table_part": 1.0}
    found = {part: [] for part in truth}
    held = {part: 0 for part in truth}
    benches = 100
    for _ in range(benches):
        central, models = simulated_bench(stream)
        summary = bench_table_term.summarise(central, models)
        for part, want in truth.items():
            ratio, (low, high) = summary[part]["ratio"], summary[part]["interval"]
            assert low <= ratio <= high
            found[part].append(ratio)
            held[part] += low <= want <= high
    for part, want in truth.items():
        # the estimate is a ratio of means, so only nearly unbiased: its mean over 100 benches within 5 %
        assert abs(np.mean(found[part]) / want - 1.0) < 0.05, (part, np.mean(found[part]), want)
        assert 0.88 <= held[part] / benches <= 1.0, (part, held[part])
