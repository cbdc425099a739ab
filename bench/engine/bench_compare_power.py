#!/usr/bin/python3
"""Size and power of `rollspec compare`'s combined test over bands (kernels/spectral D-26).

usage: bench_compare_power.py [--binary B] [--study S] [--trials N] [--reference K] [--rolls M] [--cases I,J]

A reference result (K realisations, the study's own seed) is the model. Each trial's "measurement"
is the sensor-mean PSD averaged over M rolls of an independent run (its own study seed), of the
same model (size: how often a correct model is rejected) or of a changed one (power): loss factor
x 2, contact damping x 2, roughness PSD x 2 (texture rms x sqrt 2). Each measurement is compared
with `compare --measured-averages M --format json`; the rejection rate at 0.05 and the mean
fraction of bands inside the per-band prediction intervals (D-22) are printed per case.
"""
import os
import argparse
import json
import math
import subprocess
import sys
import tempfile
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
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="rollspec-power-") as tmp:
        tmp = Path(tmp)
        ref = tmp / "reference.h5"
        run(a.binary, a.study, ref, a.reference, None, [])
        print(f"study {Path(a.study).name}: reference K = {a.reference}, measurements of M = {a.rolls} rolls, "
              f"{a.trials} trials per case, level {a.level}")
        print(f"{'case':24s} {'rejected':>10s} {'bands inside (mean)':>20s}")
        for c in (int(i) for i in a.cases.split(",")):
            name, overrides = CASES[c]
            rejected, inside = 0, []
            for t in range(a.trials):
                out, csv = tmp / "m.h5", tmp / "m.csv"
                run(a.binary, a.study, out, a.rolls, 900000 + 1000 * c + t, overrides)
                measurement_csv(out, csv)
                r = subprocess.run([a.binary, "compare", str(ref), str(csv), "--measured-averages", str(a.rolls),
                                    "--test-level", str(a.level), "--format", "json"],
                                   check=True, capture_output=True, text=True)
                j = json.loads(r.stdout)
                if j["p_value"] is None:
                    sys.exit("no combined test: " + j["combined_test"]["verdict"])
                rejected += j["p_value"] < a.level
                inside.append(j["inside"] / j["judged"])
            print(f"{name:24s} {rejected:4d}/{a.trials:<4d}  {100.0 * sum(inside) / len(inside):17.1f} %", flush=True)


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
