#!/usr/bin/python3
"""Synthetic Monte Carlo of `rollspec fit`'s likelihood (kernels/spectral D-26, D-27): is the small-sample
factor c calibrated, and is the measurement's variance V_M right?

Band logs of one realisation are Gaussian, y ~ N(mu(theta), Sigma(theta)), with the seed 002 rig's mean and
between-band log covariance (16 bands 100 .. 3150 Hz, a K = 400 run saved by --save-rig) and its
sensitivities: a level key (every band log + theta, as texture.rms), or a loss-factor-like key that moves
the bands' shape and scatter (d ln m / d ln eta and d ln sigma / d ln eta of the rig, linear in theta).
A measurement is ln of the mean of M records' exp(y) at theta0; the model at theta is K realisations drawn
with the same normal deviates at every theta (common random numbers): its linear mean and log covariance
S. ln L is D-27a's (d, V as D-26b), maximised on a grid in theta; the 95 % interval is where
2 (ln L_max - ln L) <= 3.841. Prints coverage, the intervals' sigma against the estimates' scatter, and the
median p of D-26's test at the best fit, for several likelihood variants:
  c      -c/2 [T^2 + ln det V], c = (n-p)(n-p-1)/(n(n-1)), n = K - 1 (D-27b, the engine)
  none   c = 1
  t      -(n+1)/2 ln(1 + T^2/n) - ln det V / 2 (the covariance integrated out: multivariate t)

    /usr/bin/python3 bench/engine/fit_factor_check.py [--key level|loss] [--law gsg|fw] [--experiments 400]
        [--K 30] [--M 25] [--variants c,none,t]

The rig's figures (bench/engine/fit_factor_rig.npz) come from three K = 400 runs with one seed:
    for e in 0.008 0.01 0.0125; do rollspec run studies/seed002-rig-1ms.ini --out eta$e.h5 --quiet \
        --set ball.end=0.2 --set study.realisations=400 --set study.seed=777 --set beam.loss_factor=$e; done
    /usr/bin/python3 bench/engine/fit_factor_check.py --save-rig bench/engine/fit_factor_rig.npz \
        eta0.008.h5 eta0.01.h5 eta0.0125.h5
"""
import io
import os
import argparse
import sys
from pathlib import Path

import numpy as np
from scipy import stats

HERE = Path(__file__).resolve().parent


def fw(s, n):
    """Covariance of ln of an n-record mean (D-26a)."""
    return np.log1p(np.expm1(s) / n)


def covariance(S, K, M, law):
    """V of D-26a: "fw" elementwise ln(1 + (e^S - 1)/n) (before), "gsg" G S G with G^2 = diag(V_M + V_K) / diag S."""
    dS = np.diagonal(S, axis1=-2, axis2=-1)
    dM, dK = fw(dS, M), fw(dS, K)
    if law == "fw":
        return fw(S, M) + fw(S, K), dM, dK
    g = np.sqrt((dM + dK) / dS)
    return S * g[..., :, None] * g[..., None, :], dM, dK


def loglik(z, logm, S, K, M, variant, law):
    """ln L over a batch of model states: logm (..., p), S (..., p, p). Returns ln L, T^2."""
    p = z.shape[-1]
    V, dM, dK = covariance(S, K, M, law)
    d = z - (logm + 0.5 * (dK - dM))
    L = np.linalg.cholesky(V)
    w = np.linalg.solve(L, d[..., None])[..., 0]
    t2 = np.sum(w * w, axis=-1)
    logdet = 2.0 * np.sum(np.log(np.diagonal(L, axis1=-2, axis2=-1)), axis=-1)
    n = K - 1.0
    if variant == "c":
        c = (n - p) * (n - p - 1) / (n * (n - 1))
        return -0.5 * c * (t2 + logdet), t2
    if variant == "none":
        return -0.5 * (t2 + logdet), t2
    if variant == "t":
        return -0.5 * (n + 1) * np.log1p(t2 / n) - 0.5 * logdet, t2
    raise ValueError(variant)


def experiment(rng, rig, key, K, M, grid, variants, law):
    mu0, S0, A, B = rig["mu"], rig["S"], rig["A"], rig["B"]
    p = len(mu0)
    if key == "level":
        A, B = np.ones(p), np.zeros(p)
    L0 = np.linalg.cholesky(S0)
    # mu is the mean of ln x; the rig's mu is ln of the mean, shifted by S/2 (lognormal), alike at every theta.
    base = mu0 - 0.5 * np.diag(S0)

    def draw(eps, th):
        sd_scale = np.exp(B * th)  # the bands' log scatter moves with theta
        return base + A * th + (eps @ L0.T) * sd_scale

    meas = draw(rng.standard_normal((M, p)), 0.0)
    z = np.log(np.mean(np.exp(meas), axis=0))
    eps = rng.standard_normal((K, p))
    ys = np.stack([draw(eps, th) for th in grid])  # (G, K, p), common random numbers
    logm = np.log(np.mean(np.exp(ys), axis=1))
    S = np.stack([np.cov(y.T) for y in ys])
    out = {}
    for v in variants:
        ll, t2 = loglik(z, logm, S, K, M, v, law)
        i = int(np.argmax(ll))
        inside = grid[2.0 * (ll[i] - ll) <= 3.841]
        n = K - 1.0
        f = (n - p + 1) / (n * p) * t2[i]
        out[v] = (grid[i], inside.min(), inside.max(), stats.f.sf(f, p, n - p + 1))
    return out


def save_rig(path, lo, mid, hi):
    import h5py

    def load(fn):
        with h5py.File(fn) as f:
            lower, upper = f["bands/lower_frequency"][:], f["bands/upper_frequency"][:]
            sel = (lower >= 85) & (upper <= 3600)
            m = 10 ** (f["bands/level_db"][-1] / 10)[sel]
            return np.log(m), f["bands/log_level_covariance"][-1][np.ix_(sel, sel)]

    a, Sa = load(lo)
    c, Sc = load(mid)
    b, Sb = load(hi)
    h = np.log(0.0125 / 0.008)
    buf = io.BytesIO()
    np.savez(buf, mu=c, S=Sc, A=(b - a) / h, B=(np.log(np.diag(Sb)) - np.log(np.diag(Sa))) / (2 * h))
    write_output_file(os.path.realpath(path), buf.getvalue())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rig", default=str(HERE / "fit_factor_rig.npz"))
    ap.add_argument("--key", choices=["level", "loss"], default="level")
    ap.add_argument("--experiments", type=int, default=400)
    ap.add_argument("--K", type=int, default=30)
    ap.add_argument("--M", type=int, default=25)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--variants", default="c,none,t")
    ap.add_argument("--law", choices=["fw", "gsg"], default="gsg",
                    help="V: fw = elementwise Fenton-Wilkinson of S (the engine before), gsg = G S G (D-26a now)")
    ap.add_argument("--save-rig", nargs=4, metavar=("NPZ", "LOSS_0.008_H5", "LOSS_0.01_H5", "LOSS_0.0125_H5"))
    a = ap.parse_args()
    if a.save_rig:  # the .npz is replaced only if it is one (a zip archive); the three results are inputs
        check_output_file(a.save_rig[0], "--save-rig", own=starts_with(b"PK"))
        for h5 in a.save_rig[1:]:
            check_input(h5, "a rollspec result")
        return save_rig(*a.save_rig)
    check_input(a.rig, "a rig file (.npz)")
    rig = dict(np.load(a.rig))
    rng = np.random.default_rng(a.seed)
    grid = np.linspace(-1.5, 1.5, 601)
    variants = a.variants.split(",")
    res = [experiment(rng, rig, a.key, a.K, a.M, grid, variants, a.law) for _ in range(a.experiments)]
    p = len(rig["mu"])
    n = a.K - 1
    print(f"key {a.key}, V {a.law}: p = {p}, K = {a.K}, M = {a.M}, {a.experiments} experiments, "
          f"c = {(n - p) * (n - p - 1) / (n * (n - 1)):.3f}")
    for v in variants:
        est = np.array([r[v][0] for r in res])
        lo = np.array([r[v][1] for r in res])
        hi = np.array([r[v][2] for r in res])
        pv = np.array([r[v][3] for r in res])
        held = np.mean((lo <= 0) & (hi >= 0))
        cut = np.mean((lo <= grid[0]) | (hi >= grid[-1]))
        sig = np.median(hi - lo) / 3.92
        print(f"  {v:5s} coverage {held:.3f} (s.e. {np.sqrt(held * (1 - held) / len(res)):.3f}), mean estimate "
              f"{est.mean():+.4f}, scatter {est.std(ddof=1):.4f}, interval sigma / scatter {sig / est.std(ddof=1):.2f}, "
              f"median p {np.median(pv):.2f}, p < 0.05 {np.mean(pv < 0.05):.3f}, cut {cut:.3f}")
    return 0


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.safe_output import check_input  # noqa: E402
from rollspec_post.script_main import check_output_file, starts_with, write_output_file, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
