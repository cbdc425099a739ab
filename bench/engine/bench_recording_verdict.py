#!/usr/bin/python3
"""The verdict of `rollspec compare RESULT roll-*.csv` on recordings (kernels/spectral D-26, D-22, D-34): size,
power and prediction-interval coverage on the README's ten-minute rig.

usage: bench_recording_verdict.py [--bin B] [--recordings N] [--rolls M] [--noise-db DB|none]
                                  [--realisations K] [--model-seeds S] [--work DIR] [--record FILE]

The model: `rollspec init ball-on-beam`, the README's edits ("Your rig in ten minutes"), `rollspec run` at the
template's K, once per model seed: model-seed<s>.h5 at study seed s = the template's seed + j, j = 0 .. S - 1.
A user's model run is itself a random draw, and its sampling error is common to every recording compared with
it: so each case's N recordings are split into S equal blocks, block j compared with the model of seed j, and
the size answers the question the test's level promises (a new model run and a new recording); the spread of
the S blocks' sizes (each conditional on one model run) is a row of its own. S = 1 is one model for all.
Its contact is the Hertz law (no random table), so a rig's surface is another draw of the same realisation
streams: a recording's rolls come from other study seeds (7000 and up, below; the model seeds stay under 7000).
Each of N recordings is M rolls, one CSV per roll (`Time (s),Acc (m/s^2)`), the sensor's acceleration from
`output.time_histories` of a run of the case below at its own study seed, plus white logger noise at --noise-db
(dB re 1 (m/s^2)^2/Hz; one quiet.csv per case, ten rolls long, passed as --noise as the README does). The runs
hold at most 1000 time histories, so a case is run in batches of floor(1000 / M) recordings, batch b of case c
at study seed 7000 + 1000 c + b.
Cases: the right model (size); recordings x sqrt(2) (the model 3 dB low); beam.loss_factor x 2; the first mode
10 % up (beam.youngs_modulus x 1.21: every bending mode x 1.1, and the Hertz contact modulus x 1.095).
Each recording: `rollspec compare model-seed<s>.h5 roll-*.csv [--noise quiet.csv] --format json` (M from the
file count). Figures: the share with p < 0.05 (with its Wilson 95 % interval), the share of tested bands inside the
per-band 95 % prediction intervals for M rolls (right model: the mean over recordings and the pooled share), and
the level offset. Writes bench/records/recording-verdict.json (or --record) through the bench record writer;
--work keeps the model, quiet recordings and every recording's verdict (default: a temporary folder, removed).
"""
import argparse
import json
import math
import os
import re
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
sys.dont_write_bytecode = True  # nothing written into the sources
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, own_folder, require_program, script_main  # noqa: E402

EX_USAGE, EX_DATAERR, EX_SOFTWARE, EX_CANTCREAT = 64, 65, 70, 73
LEVEL = 0.05
MAX_HISTORIES = 1000  # [output] time_histories' largest value
RECORDING_SEEDS = 7000  # the recordings' study seeds start here; the model seeds stay below
# (name, (section, key, factor) of the run's one changed key, factor on the recorded acceleration, label)
CASES = [
    ("right", None, 1.0, "right model"),
    ("level", None, math.sqrt(2.0), "model 3 dB low (recordings x sqrt 2)"),
    ("loss", ("beam", "loss_factor", 2.0), 1.0, "loss factor x 2"),
    ("mode", ("beam", "youngs_modulus", 1.21), 1.0, "first mode +10 % (beam.youngs_modulus x 1.21)"),
]
TARGETS = {"size": (0.03, 0.08), "power": (0.90, 1.0), "coverage": (0.90, 0.98)}


class BenchError(Exception):
    def __init__(self, message, exit_code=EX_SOFTWARE):
        super().__init__(message)
        self.exit_code = exit_code


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line and exit 64, not argparse's usage block
        fail(message, EX_USAGE)


def run(binary, args, cwd):
    try:
        r = subprocess.run([str(binary), *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=3600)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise BenchError(f"{binary} {' '.join(map(str, args[:2]))}: {e}") from None
    if r.returncode:
        last = (r.stderr.strip().splitlines() or [""])[-1]
        raise BenchError(f"rollspec {' '.join(map(str, args[:2]))} ... exited {r.returncode}: {last}")
    return r


def readme_edits():
    """[(section, key, value)] of the README's '#   edit rig.ini: [beam] length = 1.0   speed = 2 ...' line."""
    readme = ROOT / "README.md"
    text = readme.read_text(encoding="utf-8")
    m = re.search(r"^## Your rig in ten minutes$.*?^#\s+edit rig\.ini:([^\n]*)$", text, re.M | re.S)
    if not m:
        raise BenchError(f"{readme}: no '#   edit rig.ini:' line under '## Your rig in ten minutes'", EX_DATAERR)
    section, edits = None, []
    for token in re.split(r"\s{3,}", m.group(1).strip()):
        t = re.fullmatch(r"(?:\[(\w+)\]\s*)?(\w+) = (\S+)", token)
        if not t or not (t.group(1) or section):
            raise BenchError(f"{readme}: cannot read the edit '{token}' of the ten-minute rig", EX_DATAERR)
        section = t.group(1) or section
        edits.append((section, t.group(2), t.group(3)))
    return edits


def sets(pairs):
    return sum([["--set", p] for p in pairs], [])


def time_histories(path):
    with h5py.File(path, "r") as f:
        acc = f["/time_history/sensor_acceleration"][:, 0, :]
        t = f["/time_history/time"][()]
        fs = float(f["/psd"].attrs["sample_rate"][0])
        f1 = float(f["/beam/modal_frequency"][0])
    return t, acc, fs, f1


def write_csv(path, t, a):
    path.write_text("Time (s),Acc (m/s^2)\n" + "".join(f"{x:.9g},{y:.9g}\n" for x, y in zip(t, a)))


def half_width(band):
    lo, hi = band["prediction_lower_db"], band["prediction_upper_db"]
    return None if lo is None or hi is None else (hi - lo) / 2


def verdict(binary, folder, files, noise, model):
    """compare's answer on one recording against one model run, reduced to what the figures need."""
    args = ["compare", "../" + model, *files] + (["--noise", "../" + noise] if noise else []) + ["--format", "json"]
    j = json.loads(run(binary, args, folder).stdout)
    tested = [b for b in j["bands"] if b["use"] == "test"]
    o = j["level_offset"] or {}
    return {"p": j["p_value"], "verdict": j["combined_test"]["verdict"], "tested": len(tested),
            "inside": sum(bool(b["inside"]) for b in tested),
            "offset": o.get("estimate_db"), "offset_lo": o.get("lower_db"), "offset_hi": o.get("upper_db"),
            "bands": [[b["centre_hz"], b["use"], b["inside"], half_width(b)] for b in j["bands"]],
            "averages": j["measured_averages"]}


def run_case(a, case, work, noise_sigma):
    """Every recording of one case: batches of runs at their own seeds, each recording compared."""
    index = [c[0] for c in CASES].index(case[0])
    name, changed, factor = case[0], case[1], case[2]
    overrides = [] if not changed else [
        f"{changed[0]}.{changed[1]}={changed[2] * float(study_value(work, changed[0], changed[1]))!r}"]
    per_batch = MAX_HISTORIES // a.rolls
    found, f1 = [], None
    noise = None
    for b in range((a.recordings + per_batch - 1) // per_batch):
        n = min(per_batch, a.recordings - b * per_batch)
        seed = RECORDING_SEEDS + 1000 * index + b
        rolls = work / f"rolls-{name}.h5"
        run(a.bin, ["run", "rig.ini", "--out", rolls.name, "--quiet"]
            + sets(a.edits + overrides + [f"study.seed={seed}", f"study.realisations={n * a.rolls}",
                                          f"output.time_histories={n * a.rolls}"]), work)
        t, acc, fs, f1 = time_histories(rolls)
        rolls.unlink()
        sigma = noise_sigma(fs)
        if sigma and noise is None:  # the rig at rest, as long as ten rolls, once per case
            noise = f"quiet-{name}.csv"
            quiet_t = np.arange(10 * t.size) / fs
            write_csv(work / noise, quiet_t, sigma * np.random.default_rng([seed, 0]).standard_normal(quiet_t.size))
        for r in range(n):
            i = b * per_batch + r  # the recording's index; its block picks the model run
            block = i // (a.recordings // len(a.models))
            folder = work / f"{name}-{i + 1:04d}"
            folder.mkdir()
            rng = np.random.default_rng([seed, r + 1])
            files = []
            for k in range(a.rolls):
                files.append(f"roll-{k + 1}.csv")
                x = factor * acc[r * a.rolls + k]
                write_csv(folder / files[-1], t, x + sigma * rng.standard_normal(x.size) if sigma else x)
            v = verdict(a.bin, folder, files, noise, a.models[block][1])
            if v["averages"] != a.rolls:
                raise BenchError(f"compare took {v['averages']} rolls from {a.rolls} recordings in {folder}")
            found.append(v | {"seed": seed, "recording": r, "model_seed": a.models[block][0]})
            shutil.rmtree(folder)
        print(f"{name}: {len(found)}/{a.recordings} recordings", file=sys.stderr, flush=True)
    (work / f"verdicts-{name}.json").write_text(json.dumps(found) + "\n")
    return found, f1, overrides


def wilson(k, n, z=1.959964):
    if n == 0:
        return float("nan"), float("nan")
    p = k / n
    centre, half = p + z * z / (2 * n), z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return max(0.0, (centre - half) / (1 + z * z / n)), min(1.0, (centre + half) / (1 + z * z / n))


def rejection(found):
    tested = [v for v in found if v["p"] is not None]
    k = sum(v["p"] < LEVEL for v in tested)
    lo, hi = wilson(k, len(tested))
    return k, len(tested), lo, hi


def per_model_seed(found):
    """[[model seed, rejected, tested]] in the order of the model seeds."""
    seeds = sorted({v["model_seed"] for v in found})
    return [[s, *rejection([v for v in found if v["model_seed"] == s])[:2]] for s in seeds]


def meets(value, target):
    return "yes" if target[0] <= value <= target[1] else "no"


def band_coverage(found):
    """Per band centre: [recordings where it was tested, of those inside, mean half-width of the interval (dB)]."""
    per = {}
    for v in found:
        for centre, use, inside, half in v["bands"]:
            if use == "test":
                c = per.setdefault(centre, [0, 0, 0.0])
                c[0] += 1
                c[1] += bool(inside)
                c[2] += (half or 0.0)
    return {centre: [n, k, w / n] for centre, (n, k, w) in per.items()}


def figures(results, f1):
    """The record's rows, the raw figures, and a note on the bands the prediction intervals miss."""
    rows, data = [], {"cases": {}, "first_mode_hz": f1}
    for name, _, factor, label in CASES:
        found = results[name]
        k, n, lo, hi = rejection(found)
        blocks = per_model_seed(found)
        offsets = [v["offset"] for v in found if v["offset"] is not None]
        truth = 10 * math.log10(1.0 / factor**2)  # model - measurement
        held = sum(v["offset_lo"] <= truth <= v["offset_hi"] for v in found if v["offset"] is not None)
        share = k / n if n else float("nan")
        kind = "size" if name == "right" else "power"
        rows.append([f"{kind}: {label}", round(share, 3), f"{lo:.3f} .. {hi:.3f}",
                     "0.03 .. 0.08" if kind == "size" else ">= 0.90", meets(share, TARGETS[kind]), n])
        data["cases"][name] = {
            "label": label, "rejected": k, "tested": n, "no_test": len(found) - n, "share": share,
            "wilson_95": [lo, hi], "median_p": float(np.median([v["p"] for v in found if v["p"] is not None]))
            if n else None, "offset_mean_db": float(np.mean(offsets)) if offsets else None,
            "offset_truth_db": truth, "offset_interval_holds": held,
            "bands_tested": [int(min(v["tested"] for v in found)), int(np.median([v["tested"] for v in found])),
                             int(max(v["tested"] for v in found))],
            "p_values": [v["p"] for v in found], "per_model_seed": blocks}
        if kind == "size":  # each block's size is conditional on its one model run
            sizes = [r / t for _, r, t in blocks if t]
            each = len(found) // len(blocks)
            rows.append([f"size: right model, conditional on one model run ({each} recordings each): median over "
                         f"the {len(blocks)} model seeds", round(float(np.median(sizes)), 3),
                         f"min {min(sizes):.3f} .. max {max(sizes):.3f} over the model seeds", "", "", n])
    right = results["right"]
    shares = [v["inside"] / v["tested"] for v in right if v["tested"]]
    mean_share = float(np.mean(shares))
    pooled = sum(v["inside"] for v in right) / sum(v["tested"] for v in right)
    total = sum(v["tested"] for v in right)
    rows.append(["prediction-interval coverage, right model: mean share of tested bands inside",
                 round(mean_share, 3), "", "0.90 .. 0.98", meets(mean_share, TARGETS["coverage"]), len(shares)])
    rows.append(["prediction-interval coverage, right model: pooled over recordings and bands", round(pooled, 3),
                 f"{wilson(round(pooled * total), total)[0]:.3f} .. {wilson(round(pooled * total), total)[1]:.3f}"
                 " (bands taken as independent)", "0.90 .. 0.98", meets(pooled, TARGETS["coverage"]), total])
    for name, label in (("right", "right model"), ("level", "model 3 dB low")):
        c = data["cases"][name]
        rows.append([f"level offset, {label}: mean (truth {c['offset_truth_db']:+.2f} dB); share of its 95 % "
                     "intervals holding the truth", round(c["offset_mean_db"], 3),
                     f"{c['offset_interval_holds'] / len(results[name]):.3f} hold the truth", "", "",
                     len(results[name])])
    per = band_coverage(right)
    data["band_coverage"] = {str(c): x for c, x in sorted(per.items())}
    low = sorted(per.items(), key=lambda x: x[1][1] / x[1][0])[:5]
    note = ("Lowest per-band coverage of the right model's recordings (with the mean half-width of that band's "
            "prediction interval): " + ", ".join(f"{c:g} Hz {k / n:.3f} (+-{w:.3g} dB)" for c, (n, k, w) in low)
            + ". ")
    data["coverage"] = {"mean_share": mean_share, "pooled": pooled, "band_tests": total}
    return rows, data, note


def make_models(a, work):
    """[(study seed, file)]: the model run at the template's seed + j, j = 0 .. S - 1."""
    run(a.bin, ["init", "ball-on-beam", "--out", "rig.ini"], work)
    base = int(study_value(work, "study", "seed"))
    if base + a.model_seeds > RECORDING_SEEDS:
        raise BenchError(f"--model-seeds {a.model_seeds}: the model seeds {base} .. {base + a.model_seeds - 1} "
                         f"would meet the recordings' (from {RECORDING_SEEDS}); allowed: S <= "
                         f"{RECORDING_SEEDS - base}", EX_USAGE)
    models = []
    for seed in range(base, base + a.model_seeds):
        models.append((seed, f"model-seed{seed}.h5"))
        run(a.bin, ["run", "rig.ini", "--out", models[-1][1], "--quiet"]
            + sets(a.edits + a.model_sets + [f"study.seed={seed}"]), work)
    return models


def study_value(work, section, key):
    """The template's value of [section] key (rig.ini as `init` wrote it: set, or commented out at its default)."""
    current = None
    for line in (work / "rig.ini").read_text().splitlines():
        if line.startswith("["):
            current = line.strip()[1:-1]
        elif current == section and re.match(rf"(# )?{key} = ", line):
            return line.split("=", 1)[1].strip()
    raise BenchError(f"rig.ini written by init has no [{section}] {key}", EX_DATAERR)


def main():
    p = Parser(description=__doc__.splitlines()[0])
    p.add_argument("--bin", default=os.environ.get("ROLLSPEC_BIN", str(ROOT / "build" / "werror" / "rollspec")))
    p.add_argument("--recordings", type=int, default=200, help="N recordings per case (default 200)")
    p.add_argument("--rolls", type=int, default=5, help="M rolls per recording, one CSV each (default 5)")
    p.add_argument("--noise-db", default="-140", help="white logger noise, dB re 1 (m/s^2)^2/Hz, or none")
    p.add_argument("--realisations", type=int, help="K of the model (default: the template's)")
    p.add_argument("--model-seeds", type=int, default=10,
                   help="S model runs, one per block of N / S recordings (default 10; 1: one model for all)")
    p.add_argument("--work", help="keep the model and the verdicts here (default: a temporary folder)")
    p.add_argument("--record", default=str(ROOT / "bench" / "records" / "recording-verdict.json"))
    a = p.parse_args()
    if a.recordings < 1 or not 1 <= a.rolls <= MAX_HISTORIES:
        fail(f"--recordings {a.recordings} --rolls {a.rolls}: allowed: N >= 1 and 1 <= M <= {MAX_HISTORIES}", EX_USAGE)
    if not 1 <= a.model_seeds <= a.recordings or a.recordings % a.model_seeds:
        fail(f"--model-seeds {a.model_seeds} --recordings {a.recordings}: allowed: S from 1 to N that divides N "
             "(S equal blocks of recordings)", EX_USAGE)
    if a.realisations is not None and a.realisations < 2:
        fail(f"--realisations {a.realisations}: allowed: a whole number >= 2", EX_USAGE)
    try:
        noise_db = None if a.noise_db == "none" else float(a.noise_db)
    except ValueError:
        fail(f"--noise-db {a.noise_db}: allowed: a level in dB re 1 (m/s^2)^2/Hz, or none", EX_USAGE)
    if noise_db is not None and not -300 < noise_db < 100:
        fail(f"--noise-db {a.noise_db}: allowed: a finite level in (-300, 100) dB, or none", EX_USAGE)
    a.bin = os.path.abspath(require_program(a.bin, "--bin"))  # the runs work in the work folder
    try:
        bench_record.check_target(a.record, own=bench_record.is_record)
    except bench_record.RecordError as e:
        fail(f"--record {e}", EX_CANTCREAT)
    work = Path(own_folder(a.work, "bench_recording_verdict") if a.work
                else tempfile.mkdtemp(prefix="recording-verdict-"))
    try:
        return measure(a, work, noise_db)
    finally:
        if not a.work:
            shutil.rmtree(work, ignore_errors=True)


def measure(a, work, noise_db):
    start, cpu0, busy0 = time.monotonic(), bench_record.own_cpu(), bench_record.busy_seconds()
    a.edits = [f"{s}.{k}={v}" for s, k, v in readme_edits()]
    a.model_sets = [f"study.realisations={a.realisations}"] if a.realisations else []
    a.models = make_models(a, work)
    k_model = a.realisations or int(study_value(work, "study", "realisations"))
    seeds = [s for s, _ in a.models]

    def noise_sigma(fs):  # white noise of one-sided level G: sigma^2 = G fs / 2
        return 0.0 if noise_db is None else math.sqrt(10 ** (noise_db / 10) * fs / 2)

    results, f1, changed = {}, {}, {}
    for case in CASES:
        results[case[0]], f1[case[0]], changed[case[0]] = run_case(a, case, work, noise_sigma)
    rows, data, note = figures(results, f1)
    for name in changed:
        data["cases"][name]["set"] = changed[name]
    wall, cpu = time.monotonic() - start, bench_record.own_cpu() - cpu0
    noise = "no logger noise" if noise_db is None else (
        f"white logger noise at {noise_db:g} dB re 1 (m/s^2)^2/Hz in every roll and in one quiet recording per "
        "case (ten rolls long), given to compare as --noise")
    per_batch = MAX_HISTORIES // a.rolls
    settings = (f"The README's ten-minute rig ({', '.join(a.edits)}; Hertz contact, no random table), model "
                f"K = {k_model}, run anew for each of S = {len(seeds)} equal blocks of a case's recordings "
                f"(block j at study seed {seeds[0]} + j: seeds {seeds[0]} .. {seeds[-1]}, the same runs for every "
                "case), so the size and the power are over a new model run and a new recording, the question the "
                f"test's level answers; {a.recordings} recordings per case of M = {a.rolls} rolls each (one CSV "
                f"per roll, Time (s), Acc (m/s^2)), from runs of up to {per_batch} recordings at study seed "
                f"{RECORDING_SEEDS} + 1000 case + batch; {noise}; compare --format json at level {LEVEL}, "
                f"intervals: Wilson 95 %. First mode {f1['right']:.2f} Hz, {f1['mode']:.2f} Hz in the shifted "
                f"case. The whole command took {wall / 60:.1f} min wall, {cpu / 60:.1f} min CPU.")
    data |= {"K": k_model, "M": a.rolls, "N": a.recordings, "model_seeds": seeds, "noise_db": noise_db,
             "wall_s": wall, "cpu_s": cpu}
    tested = data["cases"]["right"]["bands_tested"]
    left = {u: sum(b[1] == u for v in results["right"] for b in v["bands"]) for u in ("noise floor", "flat floor")}
    note += (f"Bands tested per recording of the right model (min, median, max): {tested[0]}, {tested[1]}, "
             f"{tested[2]}; left out over all its recordings: {left['noise floor']} band-recordings by the noise "
             f"recording, {left['flat floor']} by the flat-floor rule.")
    bench_record.write(
        a.record, title="The verdict on recordings: size, power and prediction-interval coverage of compare "
                        "on the README's rig, " + ("without logger noise" if noise_db is None else
                                                   f"logger noise {noise_db:g} dB"),
        argv=sys.argv, builds={"rollspec": {"description": "the build measured",
                                            "version": bench_record.build_version(a.bin)}},
        settings=settings, columns=["figure", "value", "95 % interval", "target", "met", "recordings"],
        rows=rows, notes=note, data=data, other_cores=bench_record.other_work(busy0, cpu, wall))
    for row in rows:
        print(" | ".join(str(c) for c in row))
    return 0


if __name__ == "__main__":
    script_main(main)
