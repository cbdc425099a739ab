#!/usr/bin/python3
"""Coverage of `rollspec fit`'s 95 % profile-likelihood intervals (kernels/spectral D-27).

Each experiment makes a synthetic measurement with rollspec itself (the case's study at known key
values, another seed, M realisations, its sensor-mean PSD written as CSV) and fits the case's keys
from it. Prints the fraction of intervals that hold the truth, its binomial standard error, the mean
estimate, wall time and evaluations per fit. Cases:
  oscillator      the random oscillator's force.level (4 s records, bands 20 .. 200 Hz)
  oscillator-two  force.level and oscillator.damping_ratio together
  rig-rms         the seed 002 rig (studies/seed002-rig-1ms.ini, half its roll): the roughness level texture.rms
  rig-loss        the seed 002 rig: the beam's loss factor beam.loss_factor

  beam-s-loss     seed 001 beam S under the Hertz law (a third of the time out of contact): beam.loss_factor,
                  where common random numbers do not hold and the fit smooths its likelihood (D-27i)

    /usr/bin/python3 bench/engine/bench_fit_coverage.py [--case oscillator] [--experiments 100] [--jobs 2]
        [--first-seed S] [--log FILE]   (each fit's JSON appended as it ends; --summarise FILE prints the figures of a log)

The record (bench/records/fit-coverage.json) gathers logs, one row per case and build, and the section
between the markers in docs/howto/fit.md is rendered from it:

    /usr/bin/python3 bench/engine/bench_fit_coverage.py --record bench/records/fit-coverage.json \
        --from "CASE|BUILD|LOG|DESCRIPTION" [--from ...]     (BUILD: a short name; DESCRIPTION: what was measured)
    /usr/bin/python3 bench/engine/bench_fit_coverage.py --render   (the docs section alone, from the record)
"""
import argparse
import concurrent.futures
import json
import math
import os
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

RECORD = ROOT / "bench" / "records" / "fit-coverage.json"
DOC = ROOT / "docs" / "howto" / "fit.md"
BEGIN, END = "<!-- fit-coverage: begin (bench/engine/bench_fit_coverage.py) -->", "<!-- fit-coverage: end -->"
OSCILLATOR = ROOT / "studies" / "random-oscillator.ini"
RIG = ROOT / "studies" / "seed002-rig-1ms.ini"
BEAM_S = ROOT / "studies" / "seed001-beam-s-hertz.ini"
# The oscillator fast: 4 s records, the bands 20 .. 200 Hz around the 50 Hz resonance.
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
        "spectrum.band_max=200"]
# The rig with half its roll (0.18 m, to halve the cost of a run), its bands 89 .. 3548 Hz (16 bands,
# modes 2 and 5; K = 30 >= 16 + 4).
RIG_SETS = ["ball.end=0.2"]
RIG_BANDS = ["--fmin", "85", "--fmax", "3600"]
# Seed 001 beam S under the Hertz law, about a third of the time out of contact: the bands 160 .. 4000 Hz
# (15 bands; the 125 Hz band spans 2.3 bins and reads apart by the two band rules, D-27h).
BEAM_S_BANDS = ["--fmin", "140", "--fmax", "5600"]
CASES = {
    "oscillator": dict(study=OSCILLATOR, sets=FAST, bands=[], truth={"force.level": 2.0},
                       ranges={"force.level": "0.1:10:log"}, records=16, realisations=40),
    "oscillator-two": dict(study=OSCILLATOR, sets=FAST, bands=[],
                           truth={"force.level": 2.0, "oscillator.damping_ratio": 0.05},
                           ranges={"force.level": "0.1:10:log", "oscillator.damping_ratio": "0.01:0.2:log"},
                           records=16, realisations=40),
    "rig-rms": dict(study=RIG, sets=RIG_SETS, bands=RIG_BANDS, truth={"texture.rms": 0.123e-6},
                    ranges={"texture.rms": "0.03e-6:0.5e-6:log"}, records=25, realisations=30),
    "rig-loss": dict(study=RIG, sets=RIG_SETS, bands=RIG_BANDS, truth={"beam.loss_factor": 0.01},
                     ranges={"beam.loss_factor": "0.002:0.05:log"}, records=25, realisations=30),
    "beam-s-loss": dict(study=BEAM_S, sets=[], bands=BEAM_S_BANDS, truth={"beam.loss_factor": 0.01},
                        ranges={"beam.loss_factor": "0.002:0.05:log"}, records=25, realisations=30),
}


def sets(pairs):
    return [a for kv in pairs for a in ("--set", kv)]


def experiment(binary, seed, case, records, realisations, workdir, model_seed=None):
    d = Path(workdir) / f"e{seed}"
    d.mkdir()
    truth = [f"{k}={v}" for k, v in case["truth"].items()]
    subprocess.run([binary, "run", case["study"], "--out", d / "m.h5", "--quiet",
                    *sets(case["sets"] + truth + [f"study.realisations={records}", f"study.seed={seed}"])],
                   check=True, capture_output=True)
    with h5py.File(d / "m.h5") as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][-1, 1:]
    np.savetxt(d / "m.csv", np.c_[freq, psd], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
    start = time.time()
    out = subprocess.run([binary, "fit", case["study"], d / "m.csv", "--measured-averages", str(records),
                          "--format", "json", *case["bands"],
                          *[a for k, r in case["ranges"].items() for a in ("--vary", f"{k}={r}")],
                          *sets(case["sets"] + [f"study.realisations={realisations}"]
                                + ([f"study.seed={model_seed}"] if model_seed else []))],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"fit of seed {seed} failed ({out.returncode}): {out.stderr}")
    return json.loads(out.stdout), time.time() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.environ.get("ROLLSPEC_BIN", str(ROOT / "build/werror/rollspec")))
    ap.add_argument("--case", choices=sorted(CASES), default="oscillator")
    ap.add_argument("--experiments", type=int, default=100)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--records", type=int, help="M: realisations averaged into a measurement (default: the case's)")
    ap.add_argument("--realisations", type=int, help="K: realisations per fit evaluation (default: the case's)")
    ap.add_argument("--two", action="store_true", help="the same as --case oscillator-two")
    ap.add_argument("--model-seeds", action="store_true",
                    help="each fit's runs with a seed of their own (default: the study's, the same in every fit)")
    ap.add_argument("--first-seed", type=int, default=1000,
                    help="experiment i's measurement has seed FIRST + i (its model seed 50000 + that); another "
                         "FIRST gives experiments independent of an earlier run's")
    ap.add_argument("--log", help="append each experiment's fit (JSON, one line) here as it ends")
    ap.add_argument("--summarise", metavar="LOG", help="print the figures of a --log (an interrupted bench too)")
    ap.add_argument("--record", help="write this record from the --from logs, and the docs section from it")
    ap.add_argument("--from", dest="sources", action="append", default=[], metavar="CASE|BUILD|LOG|DESCRIPTION",
                    help="a log of --case CASE run with build BUILD (described by DESCRIPTION), for --record")
    ap.add_argument("--render", action="store_true", help="only rewrite the docs section from the record")
    a = ap.parse_args()
    if a.render:
        return render()
    if a.record:
        return write_record(a.record, a.sources)
    name = "oscillator-two" if a.two else a.case
    case = CASES[name]
    records, realisations = a.records or case["records"], a.realisations or case["realisations"]
    if a.summarise:  # a regular file of JSON lines: a FIFO would block the read
        check_input(a.summarise, "a --log of this bench", 256 * 2**20)
        runs = [(json.loads(line), None) for line in Path(a.summarise).read_text().splitlines() if line.strip()]
        return summarise(name, case, records, realisations, runs, a.jobs)

    if a.log:  # appended to as experiments end: a file of this bench's lines, checked before the first
        check_output_file(a.log, "--log", own=starts_with(b'{"'))

    def logged(seed, work):
        out = experiment(a.binary, seed, case, records, realisations, work, 50000 + seed if a.model_seeds else None)
        if a.log:
            with open(a.log, "a") as f:
                f.write(json.dumps(out[0] | {"seed": seed, "wall": out[1]}) + "\n")
        return out

    with tempfile.TemporaryDirectory() as work, concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        runs = list(pool.map(lambda s: logged(a.first_seed + s, work), range(a.experiments)))
    return summarise(name, case, records, realisations, runs, a.jobs)


def interval(r, k):
    """A fit's interval of key k, or None where the fit gave its estimate without one."""
    return r["parameters"][k].get("interval")


def figures(case, runs):
    """One row's figures per key of a log's fits (older logs lack the fields of the probe and the
    corrected test: those cells say so)."""
    rows = []
    for k, truth in case["truth"].items():
        given = [r for r in runs if interval(r, k) is not None]
        held = sum(interval(r, k)[0] <= truth <= interval(r, k)[1] for r in given)
        est = np.log([r["parameters"][k]["estimate"] for r in runs])
        sigma = np.median([math.log(interval(r, k)[1] / interval(r, k)[0]) / 3.92 for r in given]) if given else None
        new = all("p_value_uncorrected" in r for r in runs)
        corrected = [r["p_value"] for r in runs if new and r["p_value"] is not None]
        uncorrected = [r["p_value_uncorrected" if new else "p_value"] for r in runs]
        uncorrected = [p for p in uncorrected if p is not None]
        smoothed = sum(not r.get("objective", {}).get("common_random_numbers", True) for r in runs)
        rows.append({"key": k, "fits": len(runs), "given": len(given), "held": held,
                     "coverage": held / len(given) if given else None, "mean": float(np.exp(est.mean()) / truth),
                     "spread": float(est.std(ddof=1)), "sigma_ratio": sigma / est.std(ddof=1) if given else None,
                     "rejected": float(np.mean(np.array(corrected) < 0.05)) if corrected else None,
                     "median_p": float(np.median(corrected)) if corrected else None,
                     "median_p_uncorrected": float(np.median(uncorrected)),
                     "smoothed": smoothed, "runs": float(np.mean([r["evaluations"] for r in runs])),
                     "wall": float(np.mean([r.get("wall", float("nan")) for r in runs]))})
    return rows


COLUMNS = ["case", "build", "key", "fits", "fits smoothed (D-27i)", "intervals given", "holding the truth",
           "coverage", "geometric mean estimate / truth", "estimates' scatter (ln)", "interval sigma / scatter",
           "corrected test: rejected at 0.05", "median p, corrected", "median p, uncorrected", "runs per fit",
           "wall per fit (s)"]


def write_record(path, sources):
    if not sources:
        sys.exit("bench_fit_coverage: --record needs at least one --from CASE|BUILD|LOG|DESCRIPTION")
    bench_record.check_target(path, bench_record.is_record)
    rows, builds, data = [], {}, []
    for source in sources:
        parts = source.split("|")
        if len(parts) != 4 or parts[0] not in CASES:
            sys.exit(f"bench_fit_coverage: --from {source!r}: allowed: CASE|BUILD|LOG|DESCRIPTION, CASE one of "
                     f"{', '.join(sorted(CASES))}")
        name, build, log, description = parts
        runs = [json.loads(line) for line in Path(log).read_text().splitlines() if line.strip()]
        builds[build] = {"description": description}
        for f in figures(CASES[name], runs):
            def fmt(x, digits=3):
                return "n/a" if x is None else round(x, digits)
            rows.append([name, build, f["key"], f["fits"], f["smoothed"], f["given"], f["held"], fmt(f["coverage"]),
                         fmt(f["mean"], 4), fmt(f["spread"], 4), fmt(f["sigma_ratio"], 2), fmt(f["rejected"]),
                         fmt(f["median_p"], 2), fmt(f["median_p_uncorrected"], 2), fmt(f["runs"], 1),
                         fmt(f["wall"], 1)])
            data.append({"case": name, "build": build, **f})
    bench_record.write(path, title="rollspec fit: coverage of the 95 % intervals, by experiment", argv=sys.argv,
                       builds=builds, settings="Each fit: a synthetic measurement of M realisations of the case's "
                       "study at the truth (seed 1000 + i), fitted with model runs of a seed of their own "
                       "(--model-seeds); the fits ran one or two at a time at nice 10 on the shared machine, so "
                       "wall times are comparable only within a row.", columns=COLUMNS, rows=rows, data=data)
    if Path(path).resolve() == RECORD.resolve():
        render()
    return 0


def render():
    """The section of docs/howto/fit.md from the record."""
    rec = bench_record.load(RECORD)
    lines = [BEGIN, "", "## Coverage where the ball loses contact", "",
             "Measured by `" + rec["command"] + "` (" + rec["date"] + "), from the logs of "
             "`bench/engine/bench_fit_coverage.py --case CASE --model-seeds --log LOG` run with each build:", ""]
    lines += [f"- **{b}**: {v['description']}" for b, v in rec["builds"].items()]
    lines += ["", "| " + " | ".join(rec["columns"]) + " |", "|" + "---|" * len(rec["columns"])]
    lines += ["| " + " | ".join(bench_record.cell(c) for c in row) + " |" for row in rec["rows"]]
    lines += ["", "The coverage is the share of the intervals given that hold the truth (binomial standard error "
              "about 0.035 at 0.95 over 40 fits); the interval sigma is the median half-width in ln over 1.96, "
              "against the scatter of the ln estimates (1: the intervals are as wide as the estimates scatter). "
              "A fit smoothed its likelihood when its start's probe found common random numbers did not hold "
              "(kernels/spectral D-27i).", "", END]
    bench_record.splice_block(DOC, lines, BEGIN, END, "# Fitting")
    print(f"wrote {DOC}")
    return 0


def summarise(name, case, records, realisations, runs, jobs):
    n = len(runs)
    runs = [(r, t if t is not None else r.get("wall", float("nan"))) for r, t in runs]
    print(f"case {name}: M = {records}, K = {realisations}, {n} experiments")
    refused = [r for r, _ in runs if r.get("no_interval")]
    if refused:
        print(f"{len(refused)} of {n} fits gave no interval; first reason: {refused[0]['no_interval']}")
        runs = [(r, t) for r, t in runs if not r.get("no_interval")]
        n = len(runs)
    for k, truth in case["truth"].items():
        est = np.array([r["parameters"][k]["estimate"] for r, _ in runs])
        held = sum(r["parameters"][k]["interval"][0] <= truth <= r["parameters"][k]["interval"][1] for r, _ in runs)
        below = sum(r["parameters"][k]["interval"][1] < truth for r, _ in runs)
        frac = held / n
        print(f"{k}: truth {truth:.4g}: intervals holding it {held}/{n} = {frac:.3f} "
              f"(binomial s.e. at 0.95: {math.sqrt(0.95 * 0.05 / n):.3f}; {below} wholly below it); "
              f"estimate mean {est.mean():.4g}, spread {est.std(ddof=1):.3g}, "
              f"median log half-width {np.median([math.log(r['parameters'][k]['interval'][1] / r['parameters'][k]['interval'][0]) / 2 for r, _ in runs]):.3g}")
        # The intervals' own sigma (half-width / 1.96, in ln) against the estimates' scatter (ln): a ratio
        # above 1 means intervals wider than the scatter they should describe (over-coverage).
        sig = np.median([math.log(r["parameters"][k]["interval"][1] / r["parameters"][k]["interval"][0]) / 3.92
                         for r, _ in runs])
        print(f"  interval sigma / scatter of ln estimate: {sig / np.log(est).std(ddof=1):.2f}")
    pv = np.array([r["p_value"] for r, _ in runs if r["p_value"] is not None])
    print(f"goodness of fit: {np.mean(pv < 0.05):.3f} of {len(pv)} fits rejected at 0.05; median p {np.median(pv):.2f} "
          f"(0.5 if the law is calibrated)")
    print(f"per fit: wall {np.mean([t for _, t in runs]):.2f} s (jobs {jobs}), "
          f"evaluations {np.mean([r['evaluations'] for r, _ in runs]):.1f}")
    return 0


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.safe_output import check_input  # noqa: E402
from rollspec_post.script_main import check_output_file, starts_with, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
