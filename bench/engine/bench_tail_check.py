#!/usr/bin/python3
"""The tail check of the band intervals (kernels/spectral D-29): its tables.

usage: bench_tail_check.py simulate
       bench_tail_check.py scene ROLLSPEC STUDY K[,K...] M K_REF [section.key=value ...]

simulate: D-21's interval and (c)'s warning on one band of synthetic realisations, 4000 ensembles
per law and K. scene: M ensembles of K realisations (study seeds 1000 + m) against one of K_REF
(seed 900001): coverage of the bands 100 Hz-5 kHz and the share of ensembles `run` warned about.
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np
from scipy import stats


def interval(x, level=0.95):
    """D-21: union of the gamma law (Satterthwaite dof, widened by t/z) and Cox's lognormal law."""
    K, m, s = len(x), x.mean(), x.std(ddof=1)
    nu, a = 2 * K * (m / s) ** 2, 1 - level
    z, t = stats.norm.ppf(1 - a / 2), stats.t.ppf(1 - a / 2, K - 1)
    lo, hi = (nu / stats.chi2.ppf(1 - a / 2, nu)) ** (t / z), (nu / stats.chi2.ppf(a / 2, nu)) ** (t / z)
    y = np.log(x)
    v = y.var(ddof=1)
    c, h = y.mean() + v / 2 - np.log(m), t * np.sqrt(v / K + v * v / (2 * (K - 1)))
    return m * min(lo, np.exp(c - h)), m * max(hi, np.exp(c + h))


def needed(y):
    """D-29 (a)-(c)."""
    K = len(y)
    d = y - y.mean()
    g1 = np.mean(d ** 3) / np.mean(d ** 2) ** 1.5 * np.sqrt(K * (K - 1)) / (K - 2)
    se = np.sqrt(6 * K * (K - 1) / ((K - 2) * (K + 1) * (K + 3)))
    return np.ceil(25 * max(g1 - 2 * se, 0) ** 2)


def simulate():
    rng = np.random.default_rng(1)
    laws = {
        "gamma, shape 1": (lambda n: rng.gamma(1, 1, n), 1.0),
        "lognormal, s_y = 1.5": (lambda n: rng.lognormal(0, 1.5, n), np.exp(1.125)),
        "gamma(20) x 10 with p = 0.1": (lambda n: rng.gamma(20, .05, n) * np.where(rng.random(n) < .1, 10, 1), 1.9),
        "gamma(20) x 30 with p = 0.05": (lambda n: rng.gamma(20, .05, n) * np.where(rng.random(n) < .05, 30, 1), 2.45),
        "Pareto, alpha = 2.5": (lambda n: rng.pareto(2.5, n) + 1, 2.5 / 1.5),
    }
    for name, (draw, mu) in laws.items():
        row = []
        for K in (8, 16, 25, 50):
            held = warned = 0
            for _ in range(4000):
                x = draw(K)
                lo, hi = interval(x)
                held += lo <= mu <= hi
                warned += K < needed(np.log(x))
            row.append(f"{held / 4000:.3f} / {warned / 4000:.3f}")
        print(f"| {name} | " + " | ".join(row) + " |")


def scene(binary, study, ks, M, k_ref, sets):
    work = Path(tempfile.mkdtemp())
    (work / "tables").mkdir()
    sets = [s.format(tmp=work) for s in sets]

    def run(seed, K, name):
        out = work / f"{name}.h5"
        args = [binary, "run", study, "--out", out, "--quiet", "--set", f"study.realisations={K}",
                "--set", f"study.seed={seed}"]
        for s in sets:
            args += ["--set", s]
        r = subprocess.run(args, capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        with h5py.File(out) as f:
            b = f["/bands"]
            return (b["centre_frequency"][()], b["level_db"][()], b["ci_lower_db"][()], b["ci_upper_db"][()],
                    int(np.ravel(b.attrs["tail_check_realisations_needed"])[0]))

    fc, ref, _, _, _ = run(900001, k_ref, "ref")
    sel = (fc >= 100) & (fc <= 5000)
    for K in ks:
        held, warned = [], 0
        for m in range(M):
            _, _, lo, hi, need = run(1000 + m, K, "e")
            held.append(((lo <= ref) & (ref <= hi))[:, sel])
            warned += need > K
        print(f"{Path(study).name} K = {K}: band coverage {np.mean(held):.3f}, warned {warned} of {M}")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


def main():
    if sys.argv[1:2] == ["simulate"]:
        simulate()
    elif sys.argv[1:2] == ["scene"] and len(sys.argv) >= 7:
        try:
            ks, reps, m = [int(k) for k in sys.argv[4].split(",")], int(sys.argv[5]), int(sys.argv[6])
        except ValueError:
            sys.exit("bench_tail_check: error: K,K,... R M must be whole numbers; usage: see the module text")
        scene(sys.argv[2], sys.argv[3], ks, reps, m, sys.argv[7:])
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    script_main(main)
