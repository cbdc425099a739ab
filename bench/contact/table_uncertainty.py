#!/usr/bin/python3
"""The stiffness table's sampling error in the band levels (kernels/spectral/README.md Eq. T-1 to T-4).

usage: table_uncertainty.py ROLLSPEC STUDY [--table-seeds 1,2,3,4,5] [--k 800] [--k-shift 100]
                            [--seeds 999,555] [--work DIR]

For every table seed t ([stiffness] table_seed): runs STUDY at study seed A (K realisations, the
table built or reused) and B (K realisations, the table must be reused: its stderr says "cached"),
and at study seed A with [stiffness] table_shift = +1 and -1 (K_s realisations, the same streams:
common random numbers), then
  - agreement of A and B within their stated intervals: |L_A - L_B| <= sqrt(h_A^2 + h_B^2) (h: half
    width of the 95 % interval in dB) in the bands 100 Hz - 5 kHz of every sensor;
  - the band sensitivity s = (L_+ - L_-) / 2 (Eq. T-2) and the widened half width
    h' = sqrt(h^2 + (z s)^2) (Eq. T-3);
  - coverage (Eq. T-4): how often run A's interval, without and with the table term, holds the
    reference level of the OTHER table seeds (the mean of their seed-B levels).
"""
import os
import argparse
import shutil
import sys
from pathlib import Path

import h5py
import numpy as np

Z = 1.959963984540054


def run(binary, study, out, sets):
    """The run's stderr (it says whether the table was cached)."""
    return run_or_exit([binary, "run", study, "--out", out, *(a for s in sets for a in ("--set", s))]).stderr


def bands(path):
    with h5py.File(path) as f:
        nominal = f["bands/nominal_frequency"][:]
        keep = (nominal >= 99.0) & (nominal <= 5001.0)
        level = f["bands/level_db"][:][:, keep]
        half = 0.5 * (f["bands/ci_upper_db"][:] - f["bands/ci_lower_db"][:])[:, keep]
    return level, half


def main():
    p = argparse.ArgumentParser()
    p.add_argument("binary")
    p.add_argument("study")
    p.add_argument("--table-seeds", default="1,2,3,4,5")
    p.add_argument("--seeds", default="999,555")
    p.add_argument("--k", type=int, default=800)
    p.add_argument("--k-shift", type=int, default=100)
    p.add_argument("--work", default="table-uncertainty")
    a = p.parse_args()
    work = Path(own_folder(a.work, "table_uncertainty")).resolve()
    work.mkdir(parents=True, exist_ok=True)
    studies = work / "studies"
    if not studies.exists():
        shutil.copytree(Path(a.study).resolve().parent, studies, ignore=shutil.ignore_patterns("tables"))
    study = studies / Path(a.study).name
    seed_a, seed_b = a.seeds.split(",")
    runs = {}
    for t in a.table_seeds.split(","):
        common = [f"stiffness.table_seed={t}"]
        out = lambda tag: work / f"t{t}-{tag}.h5"  # noqa: E731
        run(a.binary, study, out("a"), common + [f"study.seed={seed_a}", f"study.realisations={a.k}"])
        err_b = run(a.binary, study, out("b"), common + [f"study.seed={seed_b}", f"study.realisations={a.k}"])
        reused = "stiffness table: cached" in err_b
        for sign in ("+1", "-1"):
            run(a.binary, study, out(sign),
                common + [f"study.seed={seed_a}", f"study.realisations={a.k_shift}", f"stiffness.table_shift={sign}"])
        la, ha = bands(out("a"))
        lb, hb = bands(out("b"))
        lp, _ = bands(out("+1"))
        lm, _ = bands(out("-1"))
        s = 0.5 * (lp - lm)
        runs[t] = dict(la=la, ha=ha, lb=lb, hb=hb, s=s, reused=reused)
        agree = np.abs(la - lb) <= np.hypot(ha, hb)
        print(f"table_seed {t}: seed {seed_b} reused the table: {reused}; A and B agree within their intervals in "
              f"{agree.mean():.3f} of {agree.size} sensor-bands (largest |L_A - L_B| {np.abs(la - lb).max():.3f} dB); "
              f"table term z|s|: median {np.median(Z * np.abs(s)):.3f} dB, largest {Z * np.abs(s).max():.3f} dB; "
              f"realisation half width median {np.median(ha):.3f} dB")
    if len(runs) < 2:
        return
    plain, widened, n = 0, 0, 0
    for t, r in runs.items():
        ref = np.mean([o["lb"] for u, o in runs.items() if u != t], axis=0)
        h_wide = np.hypot(r["ha"], Z * r["s"])
        plain += int((np.abs(r["la"] - ref) <= r["ha"]).sum())
        widened += int((np.abs(r["la"] - ref) <= h_wide).sum())
        n += r["la"].size
    print(f"coverage of nominal 95 % intervals vs the other table seeds' mean ({n} sensor-bands): "
          f"realisations only {plain / n:.3f}; with the table term (Eq. T-3) {widened / n:.3f}")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import own_folder, run_or_exit, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
