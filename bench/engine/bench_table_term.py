#!/usr/bin/python3
"""The table term against the variance it stands for, measured directly (kernels/spectral D-30g): does the
jackknife over a table's units estimate how much the band levels move from one table to another?

usage: bench_table_term.py ROLLSPEC --scene beam-r|beam-s|route [--tables 16] [--first 101] [--k 2000]
                           [--own-seeds] [--set KEY=VALUE ...] [--work DIR] [--record FILE]

For each of --tables table seeds t (--first, --first + 1, ...) the study is run twice:
  model t    the study as shipped (its K, its study seed, [stiffness] table_error at its default): the
             jackknife's variance V_J of each band level and the sub-table runs' own noise n in it (D-30a, c);
  central t  --k realisations of table seed t at study seed 5000 + t, table_error = none: the table's band
             levels with little noise of their own, that noise known from the run's own realisations (the
             delta method on the band's mean PSD, (10/ln 10)^2 s^2 / (K m^2)).
Per band (sensor mean): the variance of the central levels over the tables less the mean of their own noise
is the variance between tables; divided by the mean V_J over the models it says whether the term is right
for a new surface (1), too small (over 1) or too large (under 1). Also over V_J - n, the jackknife's table
part without the runs' noise. The summary row divides the mean over the bands of the variance between tables
by that of V_J (or V_J - n), with a 95 % interval over the draw of the tables themselves (tables drawn again
with replacement; Philox stream).
The central runs also give the question a user's rig asks without a measurement's noise: the coverage of each
model's band intervals (every sensor row, every band) against the roughness's mean level, the mean of the other
tables' central levels, with the width ratio (the intervals' width over the width that would hold it 95 % of the
time) and its 95 % interval over the tables; with --own-seeds also for each model run at a study seed of its
own (7000 + t, as a user's run would be), not only at the shipped one that every model shares. Beside the
intervals as run (widened by V_J), the same runs' intervals recomputed as if widened by V_J - n, with the table
term's degrees of freedom nu_T = N - 1 as run, and with V_J's sampling error carried into Welch-Satterthwaite's
nu (V_J - n varies as V_J does), each with its widest interval (bench_table_verdict.noise_corrected). Those
leave out the bands where a run's interval cannot be inverted (some the term dominates), so the intervals as
run are also read on the same bands alone: the like-for-like comparison. The intervals as run are read on each
half of the table seeds alone too (the reference from that half's other tables): how far a coverage over half
as many tables, as bench_table_verdict.py's sixteen, moves with the tables drawn.
Unlike bench_table_verdict.py's ratio row, whose measurements are 25 rolls and whose noise is as large as
the variance sought, the central runs make the noise a few per cent of it.
Writes bench/records/validation/table-term-SCENE.json (or --record); --work keeps the runs (default: a
temporary directory) and a bench resumed with it reruns nothing it finds.
"""
import argparse
import shutil
import sys
import tempfile
import time
from pathlib import Path

import h5py
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True  # no __pycache__ in bench/ (the verdict bench is imported)
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "bench" / "engine"))
import bench_record  # noqa: E402
from bench_table_verdict import (REUSED, SCENES, BenchError, bands, coverage, mean_row_index,  # noqa: E402
                                 noise_corrected, over_tables_at_once, run_study)

DB = 10.0 / np.log(10.0)


def sensor_mean(path, with_term):
    """The sensor mean's band levels (dB), the noise variance of each (dB²), and with_term: V_J and n (dB²)."""
    with h5py.File(path, "r") as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["bands/sensor"][:]]
        row = mean_row_index(names)
        level = f["bands/level_db"][row]
        k = float(f["psd"].attrs["realisations"][0])
        noise = (DB * f["bands/std"][row] / 10.0 ** (level / 10.0)) ** 2 / k
        out = {"level": level, "noise": noise, "f": f["bands/nominal_frequency"][:]}
        if with_term:
            if "bands/table_std_db" not in f:
                raise BenchError(f"{path}: the model run has no table term (bands/table_std_db): is its table random?")
            out["vj"] = f["bands/table_std_db"][row] ** 2
            out["n"] = (f["bands/table_noise_std_db"][row] ** 2 if "bands/table_noise_std_db" in f
                        else np.zeros_like(level))
    return out


def stacked(central, models):
    """The tables' rows as arrays (tables x bands), stacked once: the bootstrap below picks rows thousands of
    times."""
    return {"level": np.array([c["level"] for c in central]), "noise": np.array([c["noise"] for c in central]),
            "vj": np.array([m["vj"] for m in models]),
            "table_part": np.array([m["vj"] - m["n"] for m in models])}


def ratios(rows, pick):
    """Per band: the variance between tables (less the central runs' own noise), the mean V_J and the mean
    V_J - n of the models, over the tables `pick` (rows from `stacked`); `pick` may hold one draw of tables per
    row, and then so does each figure."""
    pick = np.asarray(pick)
    noise = rows["noise"][pick].mean(axis=-2)
    between = np.var(rows["level"][pick], axis=-2, ddof=1) - noise
    return between, noise, rows["vj"][pick].mean(axis=-2), rows["table_part"][pick].mean(axis=-2)


def mean_ratio(rows, pick, part):
    """The mean over the bands of the variance between tables over that of V_J (part "vj") or of V_J - n
    ("table_part"), over the tables `pick` (or each row of it): the ratio of the band means, not the mean of
    the bands' ratios (a band whose V_J - n is near 0 would rule it). NaN where fewer than 3 distinct tables
    are picked."""
    pick = np.asarray(pick)
    ordered = np.sort(pick, axis=-1)
    distinct = 1 + np.count_nonzero(np.diff(ordered, axis=-1), axis=-1)
    b, _, v, tp = ratios(rows, pick)
    ratio = np.mean(b, axis=-1) / np.mean(v if part == "vj" else tp, axis=-1)
    return np.where(distinct < 3, np.nan, ratio)


def summarise(central, models):
    """Both mean ratios with their 95 % interval over the draw of the tables themselves."""
    rows = stacked(central, models)
    everything = np.arange(len(central))
    return {part: {"ratio": float(mean_ratio(rows, everything, part)),
                   "interval": over_tables_at_once(lambda picks: mean_ratio(rows, picks, part), len(central))}
            for part in ("vj", "table_part")}


def same_bands(intervals, where):
    """intervals left out (NaN) wherever `where`'s are: noise_corrected cannot invert a run's interval in
    some bands the table term dominates (its half width is not monotone in the realisations' part there),
    and leaves them out; its rows are read against the run's own intervals on the same bands."""
    out = {}
    for t, m in intervals.items():
        kept = np.isfinite(where[t]["lo"]) & np.isfinite(where[t]["hi"])
        out[t] = {key: np.where(kept, m[key], np.nan) for key in ("level", "lo", "hi")}
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("binary")
    p.add_argument("--scene", choices=sorted(SCENES), required=True)
    p.add_argument("--tables", type=int, default=16)
    p.add_argument("--first", type=int, default=101, help="the first table seed (default 101, the verdict bench's)")
    p.add_argument("--k", type=int, default=2000, help="realisations of each central run")
    p.add_argument("--own-seeds", action="store_true",
                   help="also run each model at a study seed of its own (7000 + t) for the coverage")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="for every run")
    p.add_argument("--work", help="a folder of its own for the runs (new, empty, or one it made); default: temporary")
    p.add_argument("--record", help="default: bench/records/validation/table-term-SCENE.json")
    a = p.parse_args()
    require_program(a.binary, "binary")
    if a.tables < 3 or a.k < 5:
        raise BenchError(f"--tables {a.tables} --k {a.k}: at least 3 tables and 5 realisations are needed")
    study, description = SCENES[a.scene]
    study = ROOT / study
    record = Path(a.record) if a.record else ROOT / "bench" / "records" / "validation" / f"table-term-{a.scene}.json"
    bench_record.check_target(record, own=bench_record.is_record)
    work = Path(own_folder(a.work, "bench_table_term")) if a.work else Path(tempfile.mkdtemp(prefix="table-term-"))
    (work / "tables").mkdir(exist_ok=True)
    sets = [f"stiffness.table_dir={work / 'tables'}", *a.set]
    start = time.monotonic()
    seeds = list(range(a.first, a.first + a.tables))
    models, central, levels = [], [], {}
    for t in seeds:
        model = run_study(a.binary, study, work / f"model-{t}.h5", sets + [f"stiffness.table_seed={t}"])
        middle = run_study(a.binary, study, work / f"central-{t}.h5",
                           sets + [f"stiffness.table_seed={t}", f"study.realisations={a.k}",
                                   f"study.seed={5000 + t}", "stiffness.table_error=none"])
        models.append(sensor_mean(model, True))
        central.append(sensor_mean(middle, False))
        levels[t] = bands(middle)
        if a.own_seeds:
            run_study(a.binary, study, work / f"own-{t}.h5", sets + [f"stiffness.table_seed={t}", f"study.seed={7000 + t}"])
        print(f"table {t}", file=sys.stderr)
    everything = np.arange(len(seeds))
    between, noise, vj, table_part = ratios(stacked(central, models), everything)
    rows = [[f"{f:.0f}", f"{b:.4f}", f"{n:.4f}", f"{v:.4f}", f"{v - tp:.4f}", f"{b / v:.2f}", f"{b / tp:.2f}"]
            for f, b, n, v, tp in zip(central[0]["f"], between, noise, vj, table_part)]

    summary = summarise(central, models)
    lo, hi = summary["vj"]["interval"]
    lo_t, hi_t = summary["table_part"]["interval"]
    rows.append(["mean over the bands (ratio of the means)", f"{np.mean(between):.4f}", f"{np.mean(noise):.4f}", f"{np.mean(vj):.4f}",
                 f"{np.mean(vj - table_part):.4f}", f"{summary['vj']['ratio']:.2f} ({lo:.2f}-{hi:.2f})",
                 f"{summary['table_part']['ratio']:.2f} ({lo_t:.2f}-{hi_t:.2f})"])
    found = {}
    for which, paths in (("shipped seed", {t: work / f"model-{t}.h5" for t in seeds}),
                         ("own seeds", {t: work / f"own-{t}.h5" for t in seeds} if a.own_seeds else None)):
        if paths is None:
            continue
        as_run = {t: bands(p) for t, p in paths.items()}
        found[f"{which}, as run (V_J)"] = as_run
        found[f"{which}, V_J - n with nu_T = N - 1"] = corrected = noise_corrected(paths)
        found[f"{which}, V_J - n with V_J's sampling error in nu"] = noise_corrected(paths, carry_vj_dof=True)
        if corrected is not None:  # the same sensor-bands as the V_J - n rows, for a like-for-like reading
            found[f"{which}, as run (V_J), on the bands of the V_J - n rows"] = same_bands(as_run, corrected)
    cover = {}
    for which, intervals in found.items():
        if intervals is None:  # a run without the sub-table runs' noise (n) recorded: no variant to form
            continue
        share, width, count, (low, high) = coverage(intervals, levels)
        widest = max(float(np.nanmax(m["hi"] - m["lo"])) for m in intervals.values())
        cover[which] = {"share": share, "width_ratio": width, "count": count, "interval": [low, high],
                        "widest_db": widest}
        rows.append([f"coverage of the roughness's mean level (the other tables' central runs), models at the {which}",
                     f"{share:.3f}", f"width ratio {width:.2f}", f"95 % over the tables {low:.3f}-{high:.3f}",
                     f"widest interval {widest:.1f} dB", f"{count} sensor-bands", ""])
    # How much a coverage over half as many tables moves with the tables drawn (the verdict bench runs 16):
    # the intervals as run, on each half of the seeds alone, the reference from that half's other tables.
    halves = {}
    if len(seeds) >= 8:
        for which in [w for w in found if w.endswith("as run (V_J)")]:
            for part in (seeds[:len(seeds) // 2], seeds[len(seeds) // 2:]):
                share, width, count, (low, high) = coverage({t: found[which][t] for t in part},
                                                            {t: levels[t] for t in part})
                name = f"{which}, tables {part[0]}-{part[-1]} alone"
                halves[name] = {"share": share, "width_ratio": width, "count": count, "interval": [low, high]}
                rows.append([f"coverage of the roughness's mean level, models at the {name}", f"{share:.3f}",
                             f"width ratio {width:.2f}", f"95 % over the tables {low:.3f}-{high:.3f}", "",
                             f"{count} sensor-bands", ""])
    minutes = (time.monotonic() - start) / 60.0
    bench_record.write(
        record, title=f"The table term against the variance between tables, measured directly: {description}"
        + (f", run with {', '.join(a.set)}" if a.set else ""),
        argv=sys.argv, builds={"current": {"description": "the build measured",
                                            "version": bench_record.build_version(a.binary)}},
        settings=f"{a.tables} table seeds from {a.first}; models as shipped"
                 + (" (and at study seeds 7000 + t)" if a.own_seeds else "")
                 + (f" with {', '.join(a.set)}" if a.set else "")
                 + f"; central runs of {a.k} realisations at study seed 5000 + t without the term; sensor mean; "
                   f"the mean over bands with its 95 % interval over the tables; {minutes:.0f} min"
                 + (f" (resumed from --work: {REUSED['runs']} runs reused)" if REUSED["runs"] else ""),
        columns=["band (Hz)", "variance between tables (dB²)", "central runs' own noise (dB²)", "V_J (dB²)",
                 "n (dB²)", "between / V_J", "between / (V_J - n)"],
        rows=rows, data={"tables": a.tables, "first_table_seed": a.first, "central_realisations": a.k,
                         "bands_hz": central[0]["f"].tolist(), "between_db2": between.tolist(),
                         "noise_db2": noise.tolist(), "vj_db2": vj.tolist(), "table_part_db2": table_part.tolist(),
                         "mean_ratio": summary,
                         "coverage": cover, "coverage_halves": halves})
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)


def guarded():
    try:
        return main()
    except (BenchError, bench_record.RecordError) as e:
        sys.exit(f"bench_table_term: {e}")


sys.path.insert(0, str(ROOT / "python-post"))
from rollspec_post.script_main import own_folder, require_program, script_main  # noqa: E402

if __name__ == "__main__":
    script_main(guarded)
