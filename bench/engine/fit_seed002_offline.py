#!/usr/bin/python3
"""The seed 002 stand-in fit of texture.rms (slope at the stand-ins' 0.35) replicated offline over many
model seeds (kernels/spectral D-27h). For a level key (a linearised contact: the band levels scale with
rms^2 and S does not change) the fit's likelihood (D-27a, D-26's V, the factor c of D-27b) has its
maximum and its profile interval in closed form: ln rms - ln rms_run = (sum_i c_i 1'V_i^-1 d_i) /
(2 sum_i c_i 1'V_i^-1 1), sigma = 1 / (2 sqrt(sum_i c_i 1'V_i^-1 1)). So one run per seed and point (at
the truth) replaces a 60-run fit. Prints the figures of D-27h.

    /usr/bin/python3 bench/engine/fit_seed002_offline.py [--seeds 200] [--binary build/werror/rollspec] [--keep DIR]
"""
import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fit_seed002_roughness as g  # noqa: E402  (the stand-ins, the rig, the points)

LN10 = np.log(10.0) / 10.0
M = g.RECORDS
TRUTH = [f"{k}={v:.6g}" for k, v in g.STANDIN.items()]


def run(binary, out, speed, k, seed):
    if not Path(out).exists():
        subprocess.run([binary, "run", g.RIG, "--out", out, "--quiet",
                        *g.sets(g.POINTS[speed] + TRUTH + [f"study.realisations={k}", f"study.seed={seed}"])],
                       check=True, capture_output=True)
    with h5py.File(out) as f:
        assert f["bands/sensor"][-1].decode() == "sensor_mean"
        return (f["bands/level_db"][-1] * LN10, f["bands/log_level_covariance"][-1], f["bands/lower_frequency"][:],
                f["bands/upper_frequency"][:])


def terms(y, cov, k, sel):
    """ln m + (V_K - V_M)/2, V^-1 and c of D-26b / D-27b for the bands `sel`."""
    s_all = cov[np.ix_(sel, sel)]
    s = np.diag(s_all)
    vm, vk = np.log1p(np.expm1(s) / M), np.log1p(np.expm1(s) / k)
    gg = np.sqrt((vm + vk) / s)
    n, p = k - 1, len(sel)
    return y[sel] + 0.5 * (vk - vm), np.linalg.inv(gg[:, None] * s_all * gg[None, :]), (n - p) * (n - p - 1) / (n * (n - 1))


def fit(zs, models):
    num = den = 0.0
    for z, (mu, vi, c) in zip(zs, models):
        one = np.ones(len(z))
        num += c * one @ vi @ (z - mu)
        den += c * one @ vi @ one
    return num / den / 2.0, 1.0 / np.sqrt(den) / 2.0


def linear_rule(csv, lo, hi):
    f = np.loadtxt(csv, delimiter=",", skiprows=1)
    out = []
    for a, b in zip(lo, hi):
        x = np.clip(f[:, 0], a, b)
        out.append(np.log(np.sum(np.diff(x) * (np.interp(x[1:], f[:, 0], f[:, 1]) + np.interp(x[:-1], f[:, 0], f[:, 1])) / 2) / (b - a)))
    return np.array(out)


def summary(name, r):
    r = np.array(r)
    sd, sigma = r[:, 0].std(ddof=1), r[:, 1].mean()
    held = np.sum(np.abs(r[:, 0]) <= 1.96 * r[:, 1])
    print(f"  {name}: ln-rms sd {sd:.4f}, sigma {sigma:.4f}, sd / sigma {sd / sigma:.2f}, held {held} of {len(r)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.environ.get("ROLLSPEC_BIN", str(g.ROOT / "build/werror/rollspec")))
    ap.add_argument("--seeds", type=int, default=200, help="model seeds 1..N (and the study's 2002)")
    ap.add_argument("--reference", type=int, default=2000, help="K of the reference run (seed 777777)")
    ap.add_argument("--keep", help="directory for the runs (reused when there)")
    a = ap.parse_args()
    work = own_folder(a.keep, "fit_seed002_offline") if a.keep else tempfile.mkdtemp()
    Path(work).mkdir(parents=True, exist_ok=True)
    seeds = [2002] + list(range(1, a.seeds + 1))
    runs = {sp: [run(a.binary, f"{work}/m{sp}-{s}.h5", sp, M, s) for s in seeds] for sp in g.POINTS}
    ref = {sp: run(a.binary, f"{work}/ref{sp}.h5", sp, a.reference, 777777) for sp in g.POINTS}
    csvs = {sp: g.stand_in(a.binary, work, sp) for sp in g.POINTS}
    lo, hi = ref[1][2], ref[1][3]
    for fmin in (85.0, 110.0):
        sel = np.where((lo >= fmin) & (hi <= 3600.0))[0]
        print(f"--fmin {fmin:g}: {len(sel)} bands per point ({lo[sel[0]]:.1f} .. {hi[sel[-1]]:.0f} Hz)")
        mod = {sp: [terms(y, c, M, sel) for y, c, _, _ in runs[sp]] for sp in g.POINTS}
        for rule in ("linear (as fit reads the CSV)", "bins (the stand-in's /bands/level_db)"):
            if rule.startswith("linear"):
                z = {sp: linear_rule(csvs[sp], lo[sel], hi[sel]) for sp in g.POINTS}
            else:
                with h5py.File(Path(work) / "standin-1ms.h5") as f1, h5py.File(Path(work) / "standin-3ms.h5") as f3:
                    z = {1: f1["bands/level_db"][-1][sel] * LN10, 3: f3["bands/level_db"][-1][sel] * LN10}
            n = len(seeds)
            summary(f"stand-ins by the {rule}, one seed for both points", [fit([z[1], z[3]], [mod[1][i], mod[3][i]]) for i in range(n)])
            summary(f"stand-ins by the {rule}, a seed per point", [fit([z[1], z[3]], [mod[1][i], mod[3][(i + 1) % n]]) for i in range(n)])
        # Whole experiments: the measurements other seeds' K = M means (bins' rule), every seed different.
        zz = {sp: [y[sel] for y, _, _, _ in runs[sp]] for sp in g.POINTS}
        n = len(seeds)
        # measurement seeds i and i + n/3, model seeds i + 2n/3 (and + 1 for the second point's own)
        for name, shift in (("one seed for both points", 0), ("a seed per point", 1)):
            summary(f"whole experiments, {name}",
                    [fit([zz[1][i], zz[3][(i + n // 3) % n]],
                         [mod[1][(i + 2 * n // 3) % n], mod[3][(i + 2 * n // 3 + shift) % n]]) for i in range(n)])
    # The model means against V_K, and the two points' shared-seed correlation (reference weights, 16 bands).
    sel = np.where((lo >= 85.0) & (hi <= 3600.0))[0]
    err = {}
    for sp in g.POINTS:
        sig = ref[sp][1][np.ix_(sel, sel)]
        w = np.linalg.solve(sig, np.ones(len(sel)))
        w /= w.sum()
        err[sp] = np.array([(y[sel] - ref[sp][0][sel]) @ w for y, _, _, _ in runs[sp]])
        print(f"{sp} m/s: GLS level error of the K = {M} means: sd {err[sp].std(ddof=1):.4f}, sqrt(w'Sigma w / K) {np.sqrt(w @ sig @ w / M):.4f}")
    print(f"correlation of the two points' level errors with one seed: {np.corrcoef(err[1], err[3])[0, 1]:.2f}")
    for sp in g.POINTS:
        y, cov, _, _ = ref[sp]
        with h5py.File(Path(work) / f"ref{sp}.h5") as f:
            fr, psd = f["psd/frequency"][:], f["psd/mean"][-1]
        lin = linear_rule_arrays(fr, psd, lo[sel], hi[sel])
        s = np.diag(cov)[sel]
        sdv = np.sqrt(2.0 * np.log1p(np.expm1(s) / M))  # V_M + V_K with K = M
        print(f"{sp} m/s: band rules' difference / sqrt(V_bb) per band:", " ".join(f"{v:+.2f}" for v in (lin - y[sel]) / sdv))
    return 0


def linear_rule_arrays(fr, psd, lo, hi):
    out = []
    for a, b in zip(lo, hi):
        x = np.clip(fr, a, b)
        out.append(np.log(np.sum(np.diff(x) * (np.interp(x[1:], fr, psd) + np.interp(x[:-1], fr, psd)) / 2) / (b - a)))
    return np.array(out)


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import own_folder, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
