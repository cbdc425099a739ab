#!/usr/bin/python3
"""Accuracy of a study's own settings against a converged run of the same study, and their cost per
realisation, as whole `rollspec run` commands (issue 18 goal 2). Prints a Markdown table for the README.

  /usr/bin/python3 bench/engine/bench_default_accuracy.py [--bin build/release/rollspec]
      [--study studies/seed002-rig-1ms.ini] [--realisations 25] [--cost-realisations 400]

Error: the largest |ΔL| of the sensor-mean third-octave bands 100 Hz-5 kHz against a converged run
of the same seed: 64 substeps with the line sampled at a quarter of the case's spacing (the same line
length, so the same roughness harmonics; checked for band_limit = output: the bands below 300 Hz agree
to 0.002 dB).
Cost: CPU seconds per realisation of a 1-thread run without the reference, from /usr/bin/time, minus
a 1-realisation run's (set-up). Cases: substeps 2/4/8 at their default line spacing v / (f_s substeps),
[roughness] band_limit = output (the default: roughness beyond f_s/2 dropped, the patch filter's
interpolation loss undone, kernels/beam B40-B40a) and = step (before issue 18).
"""
import os
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

from bench_whole_run import timed, whole_run_parser  # same folder: /usr/bin/time around a whole command, its options


def run(cmd):
    """CPU seconds of one whole command on 1 thread."""
    return timed(cmd, 1)[1]


def bands(path):
    """Sensor-mean band levels below 300 Hz (the harmonics check) and 100 Hz-5 kHz (the error)."""
    with h5py.File(path) as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["/bands/sensor"][:]]
        c = f["/bands/centre_frequency"][:]
        level = f["/bands/level_db"][names.index("sensor_mean")]
        return level[c < 300], level[(c >= 100) & (c <= 5000)]


def main():
    ap = whole_run_parser(25)
    ap.add_argument("--cost-realisations", type=int, default=400)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        speed, fs, setup = probe(a.bin, a.study, tmp)
        print(f"`{a.study}`: largest sensor-mean band error 100 Hz-5 kHz against 64 substeps on a 4x finer line "
              f"({a.realisations} realisations, same seed); CPU per realisation on 1 thread ({a.cost_realisations} "
              "realisations, set-up subtracted)\n")
        print("| band_limit | substeps | max band error | CPU per realisation |")
        print("|---|---|---|---|")
        for limit in ("output", "step"):
            for n in (2, 4, 8):
                error, cpu = case(a.bin, a.study, limit, n, a.realisations, a.cost_realisations, speed, fs, setup, tmp)
                print(f"| {limit} | {n} | {error:.4f} dB | {1e3 * cpu:.1f} ms |")


def probe(binary, study, tmp):
    """(ball speed, output sample rate, set-up CPU seconds) of the study."""
    base = [binary, "run", study, "--force", "--quiet", "--set", "output.reference=false"]
    with h5py.File(keep(base, tmp / "probe.h5", ["study.realisations=1"])) as f:
        speed = float(f["/ball"].attrs["speed"][0])
        fs = 2.0 * float(f["/psd/frequency"][-1])  # the one-sided PSD ends at f_s / 2
    return speed, fs, run(base + ["--out", tmp / "one.h5", "--set", "study.realisations=1"])


def case(binary, study, limit, n, realisations, cost_realisations, speed, fs, setup, tmp):
    """(max band error in dB, CPU seconds per realisation) of one band_limit / substeps case."""
    base = [binary, "run", study, "--force", "--quiet", "--set", "output.reference=false"]
    sets = [f"roughness.band_limit={limit}", f"signal.substeps={n}"]
    out = keep(base, tmp / "case.h5", [f"study.realisations={realisations}", *sets])
    conv = keep(base, tmp / "conv.h5", [f"study.realisations={realisations}", f"roughness.band_limit={limit}",
                                        "signal.substeps=64", f"roughness.spacing={speed / (fs * n) / 4!r}"])
    (lc, ec), (lr, er) = bands(out), bands(conv)
    # (band_limit = step: the finer line adds shorter waves, whose aliases reach the low bands.)
    if limit == "output" and np.abs(lc - lr).max() > 0.002:
        sys.exit(f"{limit}, {n} substeps: the converged run drew other harmonics (line length differs)")
    cpu = run(base + ["--out", tmp / "cost.h5", "--set", f"study.realisations={cost_realisations}",
                      *sum((["--set", s] for s in sets), [])])
    return float(np.abs(ec - er).max()), (cpu - setup) / (cost_realisations - 1)


def keep(base, out, sets):
    run(base + ["--out", out, *sum((["--set", s] for s in sets), [])])
    return out


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
