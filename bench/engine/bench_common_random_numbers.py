#!/usr/bin/python3
"""Where common random numbers hold: how much of the noise of a difference between two runs of one study at
two values of a key survives when both runs keep the study's seed (a sweep's points, a fit's evaluations).

For each scene, four study seeds run the study at the key's value x and at x (1 + step). With a seed's
difference D = L(x (1 + step)) - L(x) of each band's level, the variance of D over the seeds is the noise
of one seed's difference (the true change is common to all), against V_K(x) + V_K(x') for runs of independent seeds
(V_K: the variance of the log of a K-realisation mean, from the run's own band-log covariance). Their ratio
of variances, averaged over the bands, is the share of the difference's noise that a shared seed does not
remove: near 0 where common random numbers hold, near 1 where the runs are chaotic in the key (impacts).
Writes bench/records/common-random-numbers.json and the section between the markers in
docs/howto/sweeps.md (from the record; `--render` alone rewrites the section from the existing record).

    /usr/bin/python3 bench/engine/bench_common_random_numbers.py [--binary build/werror/rollspec] [--render]
"""
import argparse
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

RECORD = ROOT / "bench" / "records" / "common-random-numbers.json"
DOC = ROOT / "docs" / "howto" / "sweeps.md"
BEGIN = "<!-- common-random-numbers: begin (bench/engine/bench_common_random_numbers.py) -->"
END = "<!-- common-random-numbers: end -->"
STUDIES = ROOT / "studies"
K = 30
SEEDS = (101, 202, 303, 404)
STEPS = (1e-4, 3e-3, 0.1)
# scene, study, its --set, the key stepped, its value, the bands compared (Hz)
SCENES = [
    ("random oscillator (linear)", "random-oscillator.ini",
     ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
      "spectrum.band_max=200"], "oscillator.damping_ratio", 0.05, (20, 200)),
    ("seed 002 rig, linearised contact, half its roll", "seed002-rig-1ms.ini", ["ball.end=0.2"], "beam.loss_factor",
     0.01, (100, 5000)),
    ("seed 001 beam S, Hertz contact", "seed001-beam-s-hertz.ini", [], "beam.loss_factor", 0.01, (100, 5000)),
    ("seed 001 beam R, Hertz contact", "seed001-beam-r-hertz.ini", [], "beam.loss_factor", 0.01, (100, 5000)),
]
# No apostrophes: the docs' smart quotes would print them otherwise than the record holds them.
COLUMNS = ["scene", "loss of contact", "step of the key", "band-level change, mean over the seeds (dB rms)",
           "noise of the difference with a shared seed (dB rms)", "noise of the difference of independent runs (dB rms)",
           "share of the noise a shared seed leaves"]


def run(binary, study, sets, out):
    args = [binary, "run", STUDIES / study, "--out", out, "--quiet", "--force"]
    for kv in sets:
        args += ["--set", kv]
    subprocess.run(args, check=True, capture_output=True)
    with h5py.File(out) as f:
        nominal = f["/bands/nominal_frequency"][:]
        level = f["/bands/level_db"][-1] * np.log(10) / 10  # ln of the mean band power, sensor mean
        s = np.diag(f["/bands/log_level_covariance"][-1])
        loss = float(f["/contact/loss_of_contact_share"][0]) if "/contact/loss_of_contact_share" in f else None
    vk = np.log1p(np.expm1(s) / K)  # D-26a: variance of the log of a K-realisation mean
    return nominal, level, vk, loss


def measure(binary, work):
    rows, data = [], []
    for name, study, sets, key, value, (lo, hi) in SCENES:
        base = sets + [f"study.realisations={K}"]
        at = {}
        for seed in SEEDS:
            at[(seed, 0.0)] = run(binary, study, base + [f"{key}={value!r}", f"study.seed={seed}"], work / "r.h5")
            for step in STEPS:
                at[(seed, step)] = run(binary, study, base + [f"{key}={value * (1 + step)!r}", f"study.seed={seed}"],
                                       work / "r.h5")
        nominal = at[(SEEDS[0], 0.0)][0]
        sel = (nominal >= lo) & (nominal <= hi)
        loss = at[(SEEDS[0], 0.0)][3]
        db = 10 / np.log(10)
        for step in STEPS:
            d = np.array([at[(s, step)][1][sel] - at[(s, 0.0)][1][sel] for s in SEEDS])
            noise = d.var(axis=0, ddof=1)  # one seed's difference noise, per band (ln^2)
            independent = np.mean([at[(s, 0.0)][2][sel] + at[(s, step)][2][sel] for s in SEEDS], axis=0)
            share = float(np.mean(noise / independent))
            change = float(db * np.sqrt(np.mean(d.mean(axis=0) ** 2)))
            rows.append([name, "no contact" if loss is None else f"{100 * loss:.3g} %", f"{step:g}", round(change, 3),
                         round(float(db * np.sqrt(np.mean(noise))), 3),
                         round(float(db * np.sqrt(np.mean(independent))), 3), round(share, 3)])
            data.append({"scene": name, "study": study, "key": key, "value": value, "step": step, "loss": loss,
                         "share": share, "bands": int(sel.sum())})
            print(" | ".join(str(c) for c in rows[-1]), flush=True)
    return rows, data


TITLE = "# Sweeping"  # the page's title: the page before its first block


def check_doc():
    """Before any work: the page is one this script may rewrite (else one line, no measurement lost)."""
    bench_record.check_target(DOC, bench_record.generated_block_owner(BEGIN, TITLE))


def render():
    """The section of docs/howto/sweeps.md, from the record."""
    rec = bench_record.load(RECORD)
    shares = {}
    for d in rec["data"]:
        shares.setdefault(d["scene"], []).append(d)
    lines = [BEGIN, "", "## Where common random numbers hold", "",
             "Measured by `" + rec["command"] + "` (" + rec["date"] + "; K = " + str(K) + " realisations per run, the "
             "sensor mean's third-octave bands): each scene run at a key's value x and at x (1 + step) with four "
             "study seeds. The noise of one seed's difference D between the two points is D's scatter over the "
             "seeds (the true change is common to all); runs of independent seeds would have "
             "sqrt(V_K(x) + V_K(x')), from each run's own band scatter. The last column is the ratio of the two variances, averaged over the bands: "
             "the share of the difference's noise that a shared seed does not remove.", "",
             "| " + " | ".join(rec["columns"]) + " |", "|" + "---|" * len(rec["columns"])]
    lines += ["| " + " | ".join(bench_record.cell(c) for c in row) + " |" for row in rec["rows"]]
    held = [s for s, ds in shares.items() if max(d["share"] for d in ds) < 0.05]
    lost = [s for s, ds in shares.items() if min(d["share"] for d in ds if d["step"] <= 3e-3) > 0.5]
    small = [d["share"] for s in lost for d in shares[s] if d["step"] <= 1e-4]
    loss = [d["loss"] for s in lost for d in shares[s][:1]]
    lines += ["", "Common random numbers hold on the " + "; the ".join(held) + ": there the difference between two "
              "points scatters far less than either point, even for a step of 10 %. They do not hold on the " +
              "; the ".join(lost) + f": the ball loses contact {100 * min(loss):.0f}-{100 * max(loss):.0f} % of the "
              "time there, its impacts make each realisation chaotic in the key, and a change of the key by 0.01 % "
              f"leaves {min(small):.2f}-{max(small):.2f} of the noise variance of independent seeds in the "
              "difference. There, judge a difference as that of independent ensembles (each point's interval); "
              "`rollspec fit` finds this out at its start and smooths its likelihood instead (docs/howto/fit.md).",
              "", END]
    check_doc()
    bench_record.splice_block(DOC, lines, BEGIN, END, TITLE)
    print(f"wrote {DOC}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.environ.get("ROLLSPEC_BIN", str(ROOT / "build/werror/rollspec")))
    ap.add_argument("--render", action="store_true", help="only rewrite the docs section from the existing record")
    a = ap.parse_args()
    if a.render:
        return render()
    require_program(a.binary, "--binary")
    bench_record.check_target(RECORD, bench_record.is_record)
    check_doc()
    start, cpu0, busy0 = time.time(), bench_record.own_cpu(), bench_record.busy_seconds()
    with tempfile.TemporaryDirectory() as work:
        rows, data = measure(a.binary, Path(work))
    wall = time.time() - start
    cpu = bench_record.own_cpu() - cpu0
    bench_record.write(RECORD, title="Common random numbers: the noise of a difference between two points of a key",
                       argv=sys.argv, builds={"current": {"description": "the build measured",
                                                          "version": bench_record.build_version(a.binary)}},
                       settings=f"K = {K} realisations per run, study seeds {SEEDS[0]} and {SEEDS[1]}; the whole "
                                f"command took {wall:.0f} s wall, {cpu:.0f} s CPU.",
                       columns=COLUMNS, rows=rows, data=data,
                       other_cores=bench_record.other_work(busy0, cpu, wall))
    render()
    return 0


def guarded():
    try:
        return main()
    except bench_record.RecordError as e:
        sys.exit(f"bench_common_random_numbers: {e}")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, str(ROOT / "python-post"))
from rollspec_post.script_main import require_program, script_main  # noqa: E402

if __name__ == "__main__":
    script_main(guarded)
