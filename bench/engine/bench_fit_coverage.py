#!/usr/bin/python3
"""Coverage of `rollspec fit`'s 95 % profile-likelihood intervals (kernels/spectral D-27).

Each experiment makes a synthetic measurement with rollspec itself (the random oscillator at a known
force.level, another seed, M realisations, its sensor-mean PSD written as CSV) and fits force.level
(and, with --two, oscillator.damping_ratio) from it. Prints the fraction of intervals that hold the
truth, its binomial standard error, the mean estimate, wall time and evaluations per fit.

    /usr/bin/python3 bench/engine/bench_fit_coverage.py [--experiments 100] [--jobs 2] [--two]
"""
import argparse
import concurrent.futures
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import h5py
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
STUDY = ROOT / "studies" / "random-oscillator.ini"
# A fast scene: 4 s records, the bands 20 .. 200 Hz around the 50 Hz resonance.
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
        "spectrum.band_max=200"]
TRUTH = {"force.level": 2.0, "oscillator.damping_ratio": 0.05}
RANGES = {"force.level": "0.1:10:log", "oscillator.damping_ratio": "0.01:0.2:log"}


def sets(pairs):
    return [a for kv in pairs for a in ("--set", kv)]


def experiment(binary, seed, keys, records, realisations, workdir):
    d = Path(workdir) / f"e{seed}"
    d.mkdir()
    truth = [f"{k}={TRUTH[k]}" for k in keys]
    subprocess.run([binary, "run", STUDY, "--out", d / "m.h5", "--quiet",
                    *sets(FAST + truth + [f"study.realisations={records}", f"study.seed={seed}"])],
                   check=True, capture_output=True)
    with h5py.File(d / "m.h5") as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][-1, 1:]
    np.savetxt(d / "m.csv", np.c_[freq, psd], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
    start = time.time()
    out = subprocess.run([binary, "fit", STUDY, d / "m.csv", "--measured-averages", str(records), "--format", "json",
                          *[a for k in keys for a in ("--vary", f"{k}={RANGES[k]}")],
                          *sets(FAST + [f"study.realisations={realisations}"])],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"fit of seed {seed} failed ({out.returncode}): {out.stderr}")
    return json.loads(out.stdout), time.time() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.environ.get("ROLLSPEC_BIN", str(ROOT / "build/werror/rollspec")))
    ap.add_argument("--experiments", type=int, default=100)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--records", type=int, default=16, help="M: realisations averaged into a measurement")
    ap.add_argument("--realisations", type=int, default=40, help="K: realisations per fit evaluation")
    ap.add_argument("--two", action="store_true", help="also fit oscillator.damping_ratio")
    a = ap.parse_args()
    keys = ["force.level"] + (["oscillator.damping_ratio"] if a.two else [])
    with tempfile.TemporaryDirectory() as work, concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        runs = list(pool.map(lambda s: experiment(a.binary, 1000 + s, keys, a.records, a.realisations, work),
                             range(a.experiments)))
    n = len(runs)
    for k in keys:
        est = np.array([r["parameters"][k]["estimate"] for r, _ in runs])
        held = sum(r["parameters"][k]["interval"][0] <= TRUTH[k] <= r["parameters"][k]["interval"][1] for r, _ in runs)
        frac = held / n
        print(f"{k}: truth {TRUTH[k]}: intervals holding it {held}/{n} = {frac:.3f} "
              f"(binomial s.e. at 0.95: {math.sqrt(0.95 * 0.05 / n):.3f}); "
              f"estimate mean {est.mean():.4g}, spread {est.std(ddof=1):.3g}")
    pv = np.array([r["p_value"] for r, _ in runs if r["p_value"] is not None])
    print(f"goodness of fit: {np.mean(pv < 0.05):.3f} of {len(pv)} fits rejected at 0.05")
    print(f"per fit: wall {np.mean([t for _, t in runs]):.2f} s (jobs {a.jobs}), "
          f"evaluations {np.mean([r['evaluations'] for r, _ in runs]):.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
