#!/usr/bin/python3
"""The stiffness table's own error in the band intervals by a leave-one-surface-out jackknife
(kernels/spectral/README.md D-30): the coverage of its intervals, as `run` writes them (--engine) or combined here.

usage: table_jackknife.py ROLLSPEC STUDY [--n 4] [--size-key KEY] [--set KEY=VALUE ...] [--k 25] [--table-seeds 11,12,13,14,15]
                          [--ref-seeds 21,22,23,24] [--k-ref 400] [--seed 999] [--ref-seed 555] [--work DIR]
                          [--engine] [--reuse-reference]

--engine: the widened intervals as `run` writes them with [stiffness] table_error = jackknife (one run
per table seed; its sub-tables made from one solve per surface), instead of the N sub-table runs made
and combined here; both give the same intervals (the engine's t quantiles to about 1e-8 dB).

Reference: the mean band level (dB) over the tables of --ref-seeds, each at K_ref realisations.
For every test table seed t: the full N-surface table and its N leave-one-out sub-tables
([stiffness] table_leave_out = i; the stiffness table only: use --engine for others), each run at the same study seed and K (common random numbers:
the differences are the table's alone). theta_i: band levels (dB) with sub-table i, theta: with
the full table; jackknife variance V_J = (N - 1)/N sum_i (theta_i - mean theta_i)^2 (D-30a).
Within-ensemble standard error s_w = h / t_{K-1} (h: half width of the engine's 95 % interval in
dB); combined s^2 = s_w^2 + V_J, Welch-Satterthwaite dof nu = s^4 / (s_w^4/(K-1) + V_J^2/(N-1)),
half width t_nu s (D-30b). Coverage of the reference by [L - h, L + h] and by the widened
interval, bands 100 Hz - 5 kHz of every sensor.
"""
import os
import argparse
import sys
from pathlib import Path

import h5py
import numpy as np
from scipy import stats


def run(binary, study, out, sets):
    run_or_exit([binary, "run", study, "--out", out, "--quiet", *(a for s in sets for a in ("--set", s))])


def bands(path):
    with h5py.File(path) as f:
        nominal = f["bands/nominal_frequency"][:]
        keep = (nominal >= 99.0) & (nominal <= 5001.0)
        return (f["bands/level_db"][:][:, keep], f["bands/ci_lower_db"][:][:, keep],
                f["bands/ci_upper_db"][:][:, keep])


def widened(level, lo, hi, var_j, k, n, t_k):
    """D-30b on each side of the engine's (asymmetric) interval, as `[stiffness] table_error = jackknife`."""
    out = []
    for h in (level - lo, hi - level):
        s_w = h / t_k
        s2 = s_w ** 2 + var_j
        nu = s2 ** 2 / (s_w ** 4 / (k - 1) + var_j ** 2 / (n - 1))
        out.append(stats.t.ppf(0.975, nu) * np.sqrt(s2))
    return level - out[0], level + out[1], nu


def engine_term(a, work, t, sets, level):
    """(widened lower, upper, V_J, how, more) of table seed t as `run` writes them (table_error = jackknife);
    `how` and `more` complete the seed's line (the runs' own noise in V_J, D-30c)."""
    jk = work / f"engine-{t}.h5"
    run(a.binary, a.study, jk, sets + ["stiffness.table_error=jackknife"])
    level_j, lo_j, hi_j = bands(jk)
    with h5py.File(jk) as f:
        nominal = f["bands/nominal_frequency"][:]
        keep = (nominal >= 99.0) & (nominal <= 5001.0)
        var_j = f["bands/table_std_db"][:][:, keep] ** 2
        noise = f["bands/table_noise_std_db"][:][:, keep] ** 2
    assert np.array_equal(level_j, level), "the jackknife run's central values differ from the plain run's"
    return (lo_j, hi_j, var_j, " (engine)",
            f"; the runs' own noise is {np.median(np.minimum(noise, var_j) / var_j):.2f} of V_J (median, D-30c)")


def sub_table_term(a, work, t, sets, level, lo, hi, t_k):
    """(widened lower, upper, V_J, how, more) of table seed t from its N leave-one-out sub-table runs combined
    here (D-30a, D-30b); `more` completes the seed's line (the median dof)."""
    theta = []
    for i in range(a.n):
        sub = work / f"loo-{t}-{i}.h5"
        run(a.binary, a.study, sub, sets + [f"stiffness.table_leave_out={i}"])
        theta.append(bands(sub)[0])
    theta = np.array(theta)
    var_j = (a.n - 1) / a.n * ((theta - theta.mean(axis=0)) ** 2).sum(axis=0)
    lo_j, hi_j, nu = widened(level, lo, hi, var_j, a.k, a.n, t_k)
    return lo_j, hi_j, var_j, "", f", median dof {np.median(nu):.1f}"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("binary")
    p.add_argument("study")
    p.add_argument("--n", type=int, default=4)
    p.add_argument("--k", type=int, default=25)
    p.add_argument("--table-seeds", default="11,12,13,14,15")
    p.add_argument("--ref-seeds", default="21,22,23,24")
    p.add_argument("--k-ref", type=int, default=400)
    p.add_argument("--seed", type=int, default=999)
    p.add_argument("--ref-seed", type=int, default=555)
    p.add_argument("--work", default="table-jackknife")
    p.add_argument("--engine", action="store_true", help="the intervals of run's table_error = jackknife")
    p.add_argument("--reuse-reference", action="store_true", help="keep reference files of an earlier call in --work")
    p.add_argument("--size-key", default="stiffness.realisations",
                   help="the key --n sets: the table's surfaces, or equivalent_roughness.strips; none: the study's "
                        "own (the blocked-force table's Welch segments follow from its strip)")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="more settings for every run")
    a = p.parse_args()
    shared = set(a.table_seeds.split(",")) & set(a.ref_seeds.split(","))
    if shared:
        sys.exit(f"table_jackknife.py: --table-seeds and --ref-seeds share {','.join(sorted(shared))}: a test table "
                 "must not be part of the reference")
    work = Path(own_folder(a.work, "table_jackknife")).resolve()
    (work / "tables").mkdir(parents=True, exist_ok=True)
    size = [] if a.size_key == "none" else [f"{a.size_key}={a.n}"]
    # The plain runs without the term, whatever the study says (the engine's runs add it).
    common = [*size, f"stiffness.table_dir={work / 'tables'}", "stiffness.table_error=none", *a.set]

    refs = []
    for t in map(int, a.ref_seeds.split(",")):
        out = work / f"ref-{t}.h5"
        if not (a.reuse_reference and out.exists()):
            run(a.binary, a.study, out, common + [f"stiffness.table_seed={t}", f"study.seed={a.ref_seed}",
                                                  f"study.realisations={a.k_ref}"])
        refs.append(bands(out)[0])
    ref = np.mean(refs, axis=0)

    held, held_j, ratio, full_levels, var_j_all = [], [], [], [], []
    t_k = stats.t.ppf(0.975, a.k - 1)
    for t in map(int, a.table_seeds.split(",")):
        sets = common + [f"stiffness.table_seed={t}", f"study.seed={a.seed}", f"study.realisations={a.k}"]
        out = work / f"full-{t}.h5"
        run(a.binary, a.study, out, sets)
        level, lo, hi = bands(out)
        if a.engine:
            lo_j, hi_j, var_j, how, more = engine_term(a, work, t, sets, level)
        else:
            lo_j, hi_j, var_j, how, more = sub_table_term(a, work, t, sets, level, lo, hi, t_k)
        held.append((lo <= ref) & (ref <= hi))
        held_j.append((lo_j <= ref) & (ref <= hi_j))
        full_levels.append(level)
        var_j_all.append(var_j)
        print(f"table seed {t}: coverage {np.mean(held[-1]):.3f} without, {np.mean(held_j[-1]):.3f} with the "
              f"jackknife term{how}; median sqrt(V_J) {np.median(np.sqrt(var_j)):.3f} dB, median h "
              f"{np.median(0.5 * (hi - lo)):.3f} dB{more}", flush=True)
    between = np.var(np.array(full_levels), axis=0, ddof=1)
    print(f"coverage of the other table seeds' mean ({len(held)} tables x {held[0].size} sensor-bands): "
          f"{np.mean(held):.3f} without, {np.mean(held_j):.3f} with the jackknife term")
    print(f"between-table variance of the band levels over the mean jackknife variance (median over "
          f"sensor-bands): {np.median(between / np.mean(var_j_all, axis=0)):.2f}")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import own_folder, run_or_exit, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
