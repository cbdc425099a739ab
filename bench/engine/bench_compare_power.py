#!/usr/bin/python3
"""Size and power of `rollspec compare`'s combined test over bands (kernels/spectral D-26).

usage: bench_compare_power.py [--binary B] [--study S] [--trials N] [--reference K] [--rolls M] [--cases I,J]
           [--size-at K1,K2] [--record bench/records/validation/compare-power.json]

A reference result (K realisations, the study's own seed) is the model. Each trial's "measurement"
is the sensor-mean PSD averaged over M rolls of an independent run (its own study seed), of the
same model (size: how often a correct model is rejected) or of a changed one (power): loss factor
x 2, contact damping x 2, roughness PSD x 2 (texture rms x sqrt 2). Each measurement is compared
with `compare --measured-averages M --format json`; the rejection rate at 0.05 and the mean
fraction of bands inside the per-band prediction intervals (D-22) are printed per case.
--size-at compares the correct model's measurements with the model at fewer realisations too (the first
K1, K2 of the study's own seed). --record writes the table as a record that the documentation's accuracy
page renders (bench/bench_record.py). With the defaults and --size-at 50,25: 23 minutes wall on 2 cores that
other work kept busy (2026-11-29).
"""
import os
import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import h5py

SOURCE = Path(__file__).resolve().parents[2]
CASES = [
    ("correct model (size)", []),
    ("loss factor x 2", ["beam.loss_factor=0.02"]),
    ("contact damping x 2", ["contact.damping=200"]),
    ("roughness PSD x 2", [f"texture.rms={0.123e-6 * math.sqrt(2.0)!r}"]),
]


def run(binary, study, out, realisations, seed, overrides):
    cmd = [binary, "run", str(study), "--out", str(out), "--quiet", "--set", f"study.realisations={realisations}"]
    if seed is not None:
        cmd += ["--set", f"study.seed={seed}"]
    for o in overrides:
        cmd += ["--set", o]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def measurement_csv(result, csv):
    with h5py.File(result) as f:
        names = [s.decode() if isinstance(s, bytes) else s for s in f["/psd/sensor"][:]]
        row = names.index("sensor_mean") if "sensor_mean" in names else 0
        freq, psd = f["/psd/frequency"][:], f["/psd/mean"][row]
    csv.write_text("frequency_hz,psd\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(freq, psd)))


def compare(binary, ref, csv, rolls, level):
    r = subprocess.run([binary, "compare", str(ref), str(csv), "--measured-averages", str(rolls),
                        "--test-level", str(level), "--format", "json"], check=True, capture_output=True, text=True)
    j = json.loads(r.stdout)
    if j["p_value"] is None:
        fail("no combined test: " + j["combined_test"]["verdict"], 70)
    return j["p_value"] < level, j["inside"] / j["judged"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=str(SOURCE / "build/werror/rollspec"))
    ap.add_argument("--study", default=str(SOURCE / "studies/seed002-rig-1ms.ini"))
    ap.add_argument("--trials", type=int, default=40)
    ap.add_argument("--reference", type=int, default=200, help="realisations of the model's result")
    ap.add_argument("--rolls", type=int, default=25, help="rolls averaged into each measurement")
    ap.add_argument("--level", type=float, default=0.05)
    ap.add_argument("--cases", default=",".join(str(i) for i in range(len(CASES))),
                    help="indices of the cases to run: " + ", ".join(f"{i} {c[0]}" for i, c in enumerate(CASES)))
    ap.add_argument("--size-at", default="", help="K1,K2: the correct model's measurements against the model at "
                                                  "these realisations too")
    ap.add_argument("--record", help="write the table as a record (bench/records/validation/*.json)")
    a = ap.parse_args()
    bench_record.check_record_target(a.record)
    try:
        cases = [int(i) for i in a.cases.split(",")]
        smaller = [int(k) for k in a.size_at.split(",") if k.strip()]
    except ValueError:
        fail(f"--cases {a.cases!r} / --size-at {a.size_at!r}: allowed: comma-separated integers", 64)
    if any(not 0 <= c < len(CASES) for c in cases) or any(k < 2 for k in smaller) or a.trials < 1:
        fail(f"--cases: indices 0..{len(CASES) - 1}; --size-at: realisations >= 2; --trials >= 1", 64)
    start, busy = time.monotonic(), bench_record.busy_seconds()
    rows = []
    with tempfile.TemporaryDirectory(prefix="rollspec-power-") as tmp:
        tmp = Path(tmp)
        refs = {a.reference: tmp / "reference.h5"}
        run(a.binary, a.study, refs[a.reference], a.reference, None, [])
        for k in smaller:
            refs[k] = tmp / f"reference-{k}.h5"
            run(a.binary, a.study, refs[k], k, None, [])
        print(f"study {Path(a.study).name}: reference K = {a.reference}, measurements of M = {a.rolls} rolls, "
              f"{a.trials} trials per case, level {a.level}")
        print(f"{'case':24s} {'model K':>8s} {'rejected':>10s} {'bands inside (mean)':>20s}")
        for c in cases:
            name, overrides = CASES[c]
            ks = [a.reference] + (smaller if c == 0 else [])
            rejected, inside = {k: 0 for k in ks}, {k: [] for k in ks}
            for t in range(a.trials):
                out, csv = tmp / "m.h5", tmp / "m.csv"
                run(a.binary, a.study, out, a.rolls, 900000 + 1000 * c + t, overrides)
                measurement_csv(out, csv)
                for k in ks:
                    r, share = compare(a.binary, refs[k], csv, a.rolls, a.level)
                    rejected[k] += r
                    inside[k].append(share)
            for k in ks:
                mean_inside = 100.0 * sum(inside[k]) / len(inside[k])
                print(f"{name:24s} {k:8d} {rejected[k]:4d}/{a.trials:<4d}  {mean_inside:17.1f} %", flush=True)
                rows.append([name, k, f"{rejected[k]} / {a.trials}", f"{mean_inside:.1f} %"])
    wall = time.monotonic() - start
    if a.record:
        bench_record.write_measured(
            a.record, a.binary, title="compare's combined test: size and power (kernels/spectral D-26)", argv=sys.argv,
            settings=f"study {Path(a.study).name}, sensor mean; each measurement the mean of {a.rolls} rolls of "
                     f"an independent run, {a.trials} per case, test level {a.level}; the model the study's "
                     f"own seed; {wall / 60:.0f} min wall",
            columns=["measurements from", "model K", "rejected", "bands inside the prediction intervals (mean)"],
            rows=rows, other_cores=bench_record.other_work(busy, bench_record.own_cpu(), wall),
            components=["engine", "beam", "contact", "integrators", "spectral", "texture"])


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import bench_record  # noqa: E402  (the records the documentation renders; it puts python-post on the path)
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
