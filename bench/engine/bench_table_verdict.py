#!/usr/bin/python3
"""The verdict against measurements from other tables (kernels/spectral D-30f, D-31): what a user's rig
with another surface of the model's roughness gives, at the shipped defaults.

usage: bench_table_verdict.py ROLLSPEC --scene beam-r|beam-s|route [--first 101] [--tables 20] [--models 5]
                              [--rolls 25]
                              [--pair K] [--set KEY=VALUE ...] [--work DIR] [--record FILE]

For each of --tables table seeds t (--first, --first + 1, ...; 101 unless given) the shipped study is run
twice:
  model t        the study as shipped (its K, its study seed, [stiffness] table_error at its default), table seed t;
  measurement t  --rolls realisations of table seed t at study seed 5000 + t, table_error = none: a rig with
                 that surface, measured over M = --rolls rolls (its sensor-mean PSD as a PSD table).
Figures (bands band_min..band_max of the study, every sensor row for the coverage, sensor_mean for compare):
  coverage   share of the model runs' band intervals that hold the other tables' mean level (the mean of the
             measurement runs of every other table), and the width ratio: the factor by which the intervals
             would have to be scaled to cover 0.95 (1: calibrated; over 1: too wide);
  size       `compare MODEL MEASUREMENT --measured-averages M` for every model table against the
             measurements of every other table: the share rejected at 0.05;
  power      the same with the model's beam.loss_factor x 2 and contact.damping x 2 (the first --models tables;
             default: all).
  own seeds  the coverage and the size again with each model at a study seed of its own (7000 + t): every model
             above shares the shipped study seed, so where common random numbers hold across tables its
             realisations' noise is one draw shared by all its comparisons, and those figures are conditional
             on that draw; with a seed per model they average over the model's noise as over its table.
  split      the sensor mean's band-level variance between tables against that of model minus measurement on the
             same table (the share the table term carries).
  noise      where the model runs record the sub-table runs' own noise n (D-30c): the coverage and width ratio
             the intervals would have widened by max(V_J - n, 0) instead of V_J (recomputed from the runs; not
             what run does).
  pair       with --pair K: the shipped study run with K realisations on table seeds 1 and 2, as a user would
             run it twice on two tables: the share of band levels (every sensor row) whose difference lies
             within the two intervals combined (sqrt(h1^2 + h2^2), h the half-widths), the median difference
             and the median half-width (an interval much wider than the differences is too wide).
  interval   beside each coverage and share rejected, its 95 % interval over the draw of the tables themselves
             (the comparisons share their tables, so a binomial interval over them would be too narrow): the
             tables drawn again with replacement, each as model and as measurement (a pigeonhole bootstrap).
compare's answers are kept in the work folder beside the runs, so a bench resumed with --work redoes neither.
Writes bench/records/validation/table-verdict-SCENE.json (or --record) through the bench record writer; --work keeps the
runs (default: a temporary directory).
"""
import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import h5py
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))
import bench_record  # noqa: E402

SCENES = {
    "beam-r": ("studies/seed001-beam-r.ini", "seed 001 beam R (stiffness table, 10 surfaces, ~50 % loss of contact)"),
    "beam-s": ("studies/seed001-beam-s.ini", "seed 001 beam S (stiffness table, 6 surfaces)"),
    "route": ("studies/seed002-rig-1ms-seed-route.ini",
              "seed 002 route at 1 m/s (blocked-force table from the contact solver on one strip)"),
}


class BenchError(Exception):
    pass


def run(binary, args, timeout=7200):
    try:
        r = subprocess.run([str(binary), *map(str, args)], capture_output=True, text=True, timeout=timeout)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise BenchError(f"{binary} {' '.join(map(str, args[:3]))}: {e}") from None
    if r.returncode:
        raise BenchError(f"{binary} {' '.join(map(str, args))}: exit {r.returncode}: {r.stderr.strip()[-400:]}")
    return r


REUSED = {"runs": 0, "answers": 0}  # what a resumed bench found in --work: the record says so beside its minutes


def run_study(binary, study, out, sets):
    REUSED["runs"] += out.exists()
    if not out.exists():
        # a run the bench was stopped in resumes from its checkpoints (the same bits as one run)
        resume = ["--resume"] if out.with_name(out.name + ".checkpoint").exists() else []
        run(binary, ["run", study, "--out", out, "--quiet", *resume] + sum([["--set", s] for s in sets], []))
    return out


def bands(path):
    with h5py.File(path, "r") as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["bands/sensor"][:]]
        return {"level": f["bands/level_db"][:], "lo": f["bands/ci_lower_db"][:], "hi": f["bands/ci_upper_db"][:],
                "names": names, "f": f["psd/frequency"][:], "psd": f["psd/mean"][:]}


def psd_table(result, out):
    b = bands(result)
    row = mean_row_index(b["names"])
    np.savetxt(out, np.c_[b["f"], b["psd"][row]], delimiter=",", header="frequency_hz,psd", comments="")
    return out


def coverage(models, measured):
    """Share of intervals holding the other tables' mean, and the scale that would make it 0.95."""
    hits, gaps = [], []
    for t, m in models.items():
        ref = np.mean([measured[u]["level"] for u in measured if u != t], axis=0)
        level, lo, hi = m["level"], m["lo"], m["hi"]
        ok = np.isfinite(level) & np.isfinite(ref) & np.isfinite(lo) & np.isfinite(hi)
        hits.append(((ref >= lo) & (ref <= hi))[ok])
        # the scale s at which [level - s (level - lo), level + s (hi - level)] just holds ref
        gap = np.where(ref >= level, (ref - level) / np.maximum(hi - level, 1e-12),
                       (level - ref) / np.maximum(level - lo, 1e-12))
        gaps.append(gap[ok])
    low, high = over_tables(lambda pick: np.concatenate([hits[i] for i in pick]).mean(), len(hits))
    hits, gaps = np.concatenate(hits), np.concatenate(gaps)
    return float(hits.mean()), float(1.0 / np.quantile(gaps, 0.95)), int(hits.size), (low, high)


def over_tables(share, n, draws=2000):
    """The 95 % interval of a figure over the draw of the n tables themselves: the comparisons share their
    tables (each model meets every measurement), so they are not independent and a binomial interval over
    them is too narrow. The tables are drawn again with replacement (a pigeonhole bootstrap, Owen 2007) and
    share(pick) recomputed; the stream is Philox (Random123's), keyed by the figure's draw count alone."""
    return over_tables_at_once(lambda picks: [share(pick) for pick in picks], n, draws)


def over_tables_at_once(shares, n, draws=2000):
    """over_tables for a share computed for all draws at once (shares(picks), picks a draws x n array, one
    figure per row): the same draws, so the same interval up to the rounding of the vectorised sums."""
    found = np.asarray(shares(table_draws(n, draws)), dtype=float)
    return tuple(float(x) for x in np.quantile(found[np.isfinite(found)], [0.025, 0.975]))


def table_draws(n, draws):
    """The pigeonhole bootstrap's draws of n tables with replacement, one row per draw."""
    stream = np.random.Generator(np.random.Philox(key=draws))
    return np.array([stream.integers(0, n, n) for _ in range(draws)])


def verdicts(binary, model, measurements, rolls):
    """compare's answer for each measurement; kept beside the model run, so a resumed bench reuses it."""
    out = []
    for path in measurements:
        answer = model.with_name(f"{model.stem}-vs-{path.stem}.json")
        REUSED["answers"] += answer.exists()
        if not answer.exists():
            r = run(binary, ["compare", model, path, "--measured-averages", rolls, "--format", "json"])
            partial = answer.with_suffix(".json.partial")
            partial.write_text(r.stdout)
            partial.replace(answer)
        j = json.loads(answer.read_text())
        out.append((j["p_value"], np.mean([b["inside"] for b in j["bands"] if b["inside"] is not None])))
    return out


def compared(binary, model, t, seeds, tables, rolls):
    """compare's answers for model t against every other table's measurement, keyed (t, u)."""
    others = [u for u in seeds if u != t]
    return dict(zip(((t, u) for u in others), verdicts(binary, model, [tables[u] for u in others], rolls)))


def rejections(found):
    """compare's answers {(model table, measurement table): (p, share inside)} summed up: the share rejected at
    0.05, the median p, and the share's 95 % interval over the tables (over_tables: a pair of draws of one
    table is no comparison)."""
    pv = np.array([x[0] if x[0] is not None else np.nan for x in found.values()], dtype=float)
    tables = sorted({t for key in found for t in key})
    index = {t: i for i, t in enumerate(tables)}
    rejected = np.full((len(tables), len(tables)), np.nan)
    for (t, u), x in found.items():
        rejected[index[t], index[u]] = float(x[0] is not None and x[0] < 0.05)

    def share(pick):
        chosen = rejected[np.ix_(pick, pick)][pick[:, None] != pick[None, :]]
        chosen = chosen[np.isfinite(chosen)]
        return chosen.mean() if chosen.size else np.nan

    return float(np.mean(pv < 0.05)), float(np.nanmedian(pv)), over_tables(share, len(tables))


def noise_corrected(paths, carry_vj_dof=False):
    """The model runs' band intervals as they would be if widened by the table term without the sub-table runs'
    own noise, max(V_J - n, 0) in place of V_J (kernels/spectral D-30b, c), nu_T as run: each side's
    realisations-only half width h recovered from the interval by inverting D-30b, then widened again. Not what
    `run` does (D-30 says why); a measurement of what the noise costs. None where a run records no noise.
    carry_vj_dof: the table term's degrees of freedom in Welch-Satterthwaite's nu from V_J's sampling error,
    V_J^2 / nu_T in place of (V_J - n)^2 / nu_T (V_J - n varies as V_J does; kernels/spectral D-30g)."""
    from scipy import optimize, stats

    def widen(h, k, v, nu_t, v_sampled=None):
        if not (h > 0 and v > 0):
            return h
        sw = h / stats.t.ppf(0.975, k - 1)
        s2 = sw * sw + v
        u = v if v_sampled is None else v_sampled
        return stats.t.ppf(0.975, s2 * s2 / (sw ** 4 / (k - 1) + u * u / nu_t)) * np.sqrt(s2)

    def unwiden(width, k, v, nu_t):
        if not (v > 0 and width > 0) or widen(1e-9, k, v, nu_t) > width:
            return np.nan
        return optimize.brentq(lambda h: widen(h, k, v, nu_t) - width, 1e-9, width)

    out = {}
    for t, path in paths.items():
        with h5py.File(path, "r") as f:
            if "bands/table_noise_std_db" not in f:
                return None
            v, n = f["bands/table_std_db"][:] ** 2, f["bands/table_noise_std_db"][:] ** 2
            k, nu_t = int(f["psd"].attrs["realisations"]), float(f["bands"].attrs["table_jackknife_dof"][0])
        b = bands(path)
        level, lo, hi = b["level"], b["lo"].copy(), b["hi"].copy()
        for i, j in np.ndindex(level.shape):
            vn, u = max(v[i, j] - n[i, j], 0.0), (v[i, j] if carry_vj_dof else None)
            lo[i, j] = level[i, j] - widen(unwiden(level[i, j] - lo[i, j], k, v[i, j], nu_t), k, vn, nu_t, u)
            hi[i, j] = level[i, j] + widen(unwiden(hi[i, j] - level[i, j], k, v[i, j], nu_t), k, vn, nu_t, u)
        out[t] = {"level": level, "lo": lo, "hi": hi}
    return out


def tables_text(interval):
    return f"95 % over the tables {interval[0]:.3f}-{interval[1]:.3f}"


def variance_split(models, measured):
    """Where the scatter of a measurement about the model comes from (sensor mean, dB², mean over bands):
    between tables (the measurements' variance over table seeds) and within one table (the variance of model
    minus measurement on the same table: the K and M realisations' own noise). The first is what the table
    term must carry; its share bounds the power any test can have against a change of that size."""
    def mean_row(b):
        return b["level"][mean_row_index(b["names"])]

    meas = np.array([mean_row(m) for m in measured.values()])
    diff = np.array([mean_row(models[t]) - mean_row(measured[t]) for t in measured])
    return float(np.nanmean(np.nanvar(meas, axis=0, ddof=1))), float(np.nanmean(np.nanvar(diff, axis=0, ddof=1)))


def table_variance_ratio(own, measured, rolls):
    """The table term against the variance it stands for (sensor mean; None where the runs have no table term):
    per band, the band-level variance between tables, measured (the variance of the measurements over table
    seeds, less their own realisations' noise), over the jackknife's estimate (the models' table variance,
    averaged over the models); the mean over bands, and its 95 % interval over the tables. The noise is the
    variance of model minus measurement on one table, each at a study seed of its own (the table cancels),
    split between the two in the ratio of their realisation counts (a band's noise goes as one over its count).
    Over 1: the term is too small for new surfaces; under 1: too large."""
    def model_row(path):
        with h5py.File(path, "r") as f:
            if "bands/table_std_db" not in f:
                return None
            row = mean_row_index([n.decode() if isinstance(n, bytes) else n for n in f["bands/sensor"][:]])
            return f["bands/level_db"][row], f["bands/table_std_db"][row] ** 2, float(f["psd"].attrs["realisations"][0])

    models = {t: model_row(path) for t, path in own.items()}
    tables = sorted(t for t in models if t in measured)
    if len(tables) < 3 or any(models[t] is None for t in tables):
        return None
    level, table_variance, k = (np.array([models[t][i] for t in tables]) for i in range(3))
    meas = np.array([measured[t]["level"][mean_row_index(measured[t]["names"])] for t in tables])

    def ratio(pick):
        if len(set(pick.tolist())) < 3:
            return np.nan
        noise = np.var(level[pick] - meas[pick], axis=0, ddof=1) * np.mean(k[pick]) / (np.mean(k[pick]) + rolls)
        between = np.var(meas[pick], axis=0, ddof=1) - noise
        return float(np.mean(between / np.mean(table_variance[pick], axis=0)))

    return ratio(np.arange(len(tables))), over_tables(ratio, len(tables))


def mean_row_index(names):
    return names.index("sensor_mean") if "sensor_mean" in names else 0


def pair(binary, study, work, sets, k):
    """Two runs of K realisations on table seeds 1 and 2: how often their band levels agree within their
    combined intervals, and how the differences compare with the intervals' half-widths (dB)."""
    a, b = (bands(run_study(binary, study, work / f"pair-{k}-table-{t}.h5",
                            sets + [f"stiffness.table_seed={t}", f"study.realisations={k}"])) for t in (1, 2))
    d = np.abs(a["level"] - b["level"])
    ha, hb = (a["hi"] - a["lo"]) / 2.0, (b["hi"] - b["lo"]) / 2.0
    ok = np.isfinite(d)
    agree = float(np.mean(d[ok] <= np.hypot(ha, hb)[ok]))
    return agree, float(np.median(d[ok])), float(np.median(np.r_[ha[ok], hb[ok]])), int(ok.sum())


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("binary")
    p.add_argument("--scene", choices=sorted(SCENES), required=True)
    p.add_argument("--tables", type=int, default=20)
    p.add_argument("--first", type=int, default=101, help="the first table seed (tables --first, --first + 1, ...)")
    p.add_argument("--models", type=int, default=0, help="tables whose models are compared (default: all)")
    p.add_argument("--rolls", type=int, default=25)
    p.add_argument("--pair", type=int, default=0, help="K of two more runs on table seeds 1 and 2 (0: none)")
    p.add_argument("--work", help="a folder of its own for the runs (new, empty, or one it made); default: temporary")
    p.add_argument("--record")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="a study key for every run, models and measurements (e.g. stiffness.realisations=12)")
    a = p.parse_args()
    if a.first < 3 or a.tables < 2 or a.rolls < 1 or a.models < 0 or a.pair < 0 or a.pair == 1:
        p.error(f"--first {a.first} --tables {a.tables} --rolls {a.rolls} --models {a.models} --pair {a.pair}: "
                "allowed: a first table seed of at least 3 (1 and 2 are --pair's), at least 2 tables, 1 roll, 0 or "
                "more models, a pair of 0 (none) or at least 2 realisations")
    require_program(a.binary, "binary")
    study, description = SCENES[a.scene]
    study = ROOT / study
    record = Path(a.record) if a.record else ROOT / "bench" / "records" / "validation" / f"table-verdict-{a.scene}.json"
    bench_record.check_target(record, own=bench_record.is_record)
    work = Path(own_folder(a.work, "bench_table_verdict")) if a.work else Path(tempfile.mkdtemp(prefix="table-verdict-"))
    (work / "tables").mkdir(exist_ok=True)
    # The study's own folder of tables stays untouched: the runs cache their tables under the work folder.
    sets = [f"stiffness.table_dir={work / 'tables'}", *a.set]
    start = time.monotonic()
    seeds = list(range(a.first, a.first + a.tables))
    a.models = a.models or a.tables
    measured, tables = {}, {}
    for t in seeds:
        r = run_study(a.binary, study, work / f"measurement-{t}.h5",
                      sets + [f"stiffness.table_seed={t}", f"study.realisations={a.rolls}", f"study.seed={5000 + t}",
                              "stiffness.table_error=none"])
        measured[t] = bands(r)
        tables[t] = psd_table(r, work / f"measurement-{t}.csv")
        print(f"measurement {t}", file=sys.stderr)
    models = {t: bands(run_study(a.binary, study, work / f"model-{t}.h5", sets + [f"stiffness.table_seed={t}"]))
              for t in seeds}
    cov, width, n_bands, cov_interval = coverage(models, measured)
    cases = [("correct model (size)", []), ("loss factor x 2", ["beam.loss_factor=0.02"]),
             ("contact damping x 2", ["contact.damping=200"])]
    between, within = variance_split(models, measured)
    rows = [["coverage of other tables' mean", f"{cov:.3f}", f"width ratio {width:.2f}; {tables_text(cov_interval)}",
             n_bands]]
    data = {"coverage": cov, "coverage_interval": cov_interval, "width_ratio": width,
            "variance_between_tables_db2": between,
            "variance_same_table_db2": within, "cases": {}}
    corrected = noise_corrected({t: work / f"model-{t}.h5" for t in seeds})
    if corrected:  # the count: the band intervals whose realisations-only width could be recovered
        cov_n, width_n, n_n, _ = coverage(corrected, measured)
        rows.append(["the same widened by max(V_J - n, 0): the table term without the sub-table runs' own noise "
                     "(not what run does)", f"{cov_n:.3f}", f"width ratio {width_n:.2f}", n_n])
        data["noise_corrected"] = {"coverage": cov_n, "width_ratio": width_n, "bands": n_n}
    rows.append(["band-level variance between tables (dB²)", f"{between:.3g}",
                 f"same table, model - measurement: {within:.3g} dB²", len(measured)])
    for name, extra in cases:
        found = {}
        for t in seeds[:a.models]:
            model = work / f"model-{t}.h5" if not extra else run_study(
                a.binary, study, work / f"model-{t}-{'-'.join(extra)}.h5", sets + [f"stiffness.table_seed={t}"] + extra)
            found.update(compared(a.binary, model, t, seeds, tables, a.rolls))
        rejected, median_p, interval = rejections(found)
        rows.append([name, f"{rejected:.3f}", f"median p {median_p:.3g}; {tables_text(interval)}", len(found)])
        data["cases"][name] = {"rejected": rejected, "median_p": median_p, "interval": interval,
                               "bands_inside": float(np.mean([x[1] for x in found.values()])),
                               "comparisons": len(found)}
        print(f"{name}: rejected {rejected:.3f}", file=sys.stderr)
    own = {t: work / f"model-{t}-own-seed.h5" for t in seeds}
    own_bands = {t: bands(run_study(a.binary, study, own[t], sets + [f"stiffness.table_seed={t}",
                                                                      f"study.seed={7000 + t}"])) for t in seeds}
    cov_o, width_o, n_o, cov_o_interval = coverage(own_bands, measured)
    rows.append(["coverage, each model at a study seed of its own", f"{cov_o:.3f}",
                 f"width ratio {width_o:.2f}; {tables_text(cov_o_interval)}", n_o])
    ratio = table_variance_ratio(own, measured, a.rolls)
    if ratio:
        rows.append(["table variance between tables over the jackknife's (sensor mean, mean over bands; each model at "
                     "its own seed)", f"{ratio[0]:.2f}", tables_text(ratio[1]), len(own)])
        data["own_seeds_table_variance_ratio"] = {"ratio": ratio[0], "interval": ratio[1]}
    found = {}
    for t in seeds[:a.models]:
        found.update(compared(a.binary, own[t], t, seeds, tables, a.rolls))
    rejected, median_p, interval = rejections(found)
    rows.append(["correct model (size), each at a study seed of its own", f"{rejected:.3f}",
                 f"median p {median_p:.3g}; {tables_text(interval)}", len(found)])
    data["own_seeds"] = {"coverage": cov_o, "coverage_interval": cov_o_interval, "width_ratio": width_o,
                         "rejected": rejected, "median_p": median_p, "interval": interval, "comparisons": len(found)}
    print(f"own seeds: coverage {cov_o:.3f}, rejected {rejected:.3f}", file=sys.stderr)
    if a.pair:
        agree, median_d, median_h, n = pair(a.binary, study, work, sets, a.pair)
        rows.append([f"two runs of K = {a.pair} on table seeds 1 and 2: bands agreeing within their intervals",
                     f"{agree:.3f}", f"median difference {median_d:.3g} dB, median half-width {median_h:.3g} dB", n])
        data["pair"] = {"realisations": a.pair, "agree": agree, "median_difference_db": median_d,
                        "median_half_width_db": median_h, "bands": n}
    minutes = (time.monotonic() - start) / 60.0
    bench_record.write(
        record, title=f"The verdict against measurements from other tables: {description}"
        + (f", table seeds {seeds[0]}-{seeds[-1]}" if a.first != 101 else "")
        + (f", run with {', '.join(a.set)}" if a.set else ""),
        argv=sys.argv, builds={"current": {"description": "the build measured",
                                            "version": bench_record.build_version(a.binary)}},
        settings=f"{a.tables} table seeds ({seeds[0]}-{seeds[-1]}); models as shipped"
                 + (f" with {', '.join(a.set)}" if a.set else "") +
                 " (and at study seeds 7000 + t); measurements of "
                 f"{a.rolls} rolls of each other table (study seed 5000 + t); compare --measured-averages {a.rolls} "
                 f"at level 0.05; {minutes:.0f} min"
                 + (f" (resumed from --work: {REUSED['runs']} runs and {REUSED['answers']} compare answers reused)"
                    if any(REUSED.values()) else ""),
        columns=["figure", "value", "detail", "count"], rows=rows, data=data)
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)


def guarded():
    try:
        return main()
    except (BenchError, bench_record.RecordError) as e:
        sys.exit(f"bench_table_verdict: {e}")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, str(ROOT / "python-post"))
from rollspec_post.script_main import own_folder, require_program, script_main  # noqa: E402

if __name__ == "__main__":
    script_main(guarded)
