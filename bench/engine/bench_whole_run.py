#!/usr/bin/python3
"""Whole `rollspec run` commands as a user waits for them: wall and CPU time from /usr/bin/time,
each case repeated and interleaved with the others (so a slow spell of the machine hits all of them
alike), medians reported. Prints a Markdown table for the README.

  /usr/bin/python3 bench/engine/bench_whole_run.py [--bin build/release/rollspec]
      [--study studies/seed002-rig-1ms.ini] [--realisations 1000] [--repeats 5]

Cases: 1 realisation (the fixed cost: set-up, the reference, the file), K realisations on 1 and on
2 threads (parallel efficiency t1 / (2 t2)), and K on 2 threads without the reference.

  --baseline OTHER_BIN   also runs the K-realisation 1-thread command (no reference) with the
                         previous build, interleaved with this one, and prints the ratio
                         this / previous and the ms per realisation per core of each (issue 18:
                         whole-command ratios in one run). With --only-baseline, only that pair.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path


def timed(cmd, threads):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    with tempfile.NamedTemporaryFile("r", suffix=".time") as t:
        r = subprocess.run(["/usr/bin/time", "-f", "%e %U %S %M", "-o", t.name, *cmd], capture_output=True, text=True,
                           env=env)
        if r.returncode != 0:
            sys.exit(f"failed: {' '.join(map(str, cmd))}\n{r.stderr}")
        wall, user, system, rss = t.read().split()[-4:]
    return float(wall), float(user) + float(system), int(rss)


def measure(binary, study, K, repeats, baseline=None, only_baseline=False):
    """Median (wall, CPU) seconds per case, cases interleaved; keys as printed."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "r.h5"
        base = [binary, "run", study, "--out", out, "--force", "--quiet"]
        cases = {} if only_baseline else {
            "1 realisation, 2 threads": (base + ["--set", "study.realisations=1"], 2),
            "1 realisation, 2 threads, no reference": (base + ["--set", "study.realisations=1", "--set",
                                                               "output.reference=false"], 2),
            f"{K} realisations, 1 thread": (base + ["--set", f"study.realisations={K}"], 1),
            f"{K} realisations, 2 threads": (base + ["--set", f"study.realisations={K}"], 2),
            f"{K} realisations, 2 threads, no reference": (
                base + ["--set", f"study.realisations={K}", "--set", "output.reference=false"], 2),
        }
        pair = ["--set", f"study.realisations={K}", "--set", "output.reference=false"]
        if baseline:
            cases[f"{K} realisations, 1 thread, no reference: this build"] = (base + pair, 1)
            cases[f"{K} realisations, 1 thread, no reference: previous build"] = (
                [baseline, "run", study, "--out", out, "--force", "--quiet"] + pair, 1)
            if not only_baseline:  # the reference's own cost in the previous build: 1 realisation with and without
                prev = [baseline, "run", study, "--out", out, "--force", "--quiet", "--set", "study.realisations=1"]
                cases["1 realisation, 2 threads: previous build"] = (prev, 2)
                cases["1 realisation, 2 threads, no reference: previous build"] = (
                    prev + ["--set", "output.reference=false"], 2)
        runs = {name: [] for name in cases}
        for _ in range(repeats):
            for name, (cmd, threads) in cases.items():
                runs[name].append(timed(cmd, threads))
    return {n: (statistics.median(r[0] for r in v), statistics.median(r[1] for r in v)) for n, v in runs.items()}


def whole_run_parser(realisations):
    """The options of a script that times whole `rollspec run` commands: --bin, --study, --realisations (K);
    the script adds its own."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/release/rollspec")
    ap.add_argument("--study", default="studies/seed002-rig-1ms.ini")
    ap.add_argument("--realisations", type=int, default=realisations)
    return ap


def main():
    ap = whole_run_parser(1000)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--baseline", help="previous build's rollspec, run interleaved for a ratio")
    ap.add_argument("--only-baseline", action="store_true", help="only the this-vs-previous pair")
    a = ap.parse_args()
    if a.only_baseline and not a.baseline:
        sys.exit("--only-baseline needs --baseline")
    K = a.realisations
    med = measure(a.bin, a.study, K, a.repeats, a.baseline, a.only_baseline)
    print(f"whole `rollspec run {a.study}`, median of {a.repeats} interleaved runs (/usr/bin/time)\n")
    print("| case | wall | CPU |")
    print("|---|---|---|")
    for n, (w, c) in med.items():
        print(f"| {n} | {w:.2f} s | {c:.2f} s |")
    if a.baseline:
        this = med[f"{K} realisations, 1 thread, no reference: this build"]
        prev = med[f"{K} realisations, 1 thread, no reference: previous build"]
        print(f"\nthis / previous build, {K} realisations on 1 thread: wall {this[0] / prev[0]:.3f}, "
              f"CPU {this[1] / prev[1]:.3f}; per realisation per core {1e3 * this[1] / K:.2f} ms against "
              f"{1e3 * prev[1] / K:.2f} ms (CPU time over K, set-up included)")
    if a.only_baseline:
        return
    t1, t2 = med[f"{K} realisations, 1 thread"][0], med[f"{K} realisations, 2 threads"][0]
    print(f"\nparallel efficiency of the whole command: {t1 / (2 * t2):.2f}")
    for build, suffix in (("this build", ""), ("previous build", ": previous build")):
        if f"1 realisation, 2 threads{suffix}" in med:
            w, c = reference_cost(med, suffix)
            print(f"the reference, {build} (1 realisation with it minus without): {w:.3f} s wall, {c:.3f} s CPU")


def reference_cost(med, suffix=""):
    """(wall, CPU) of the reference: the 1-realisation run with it minus the same without it."""
    a, b = med[f"1 realisation, 2 threads{suffix}"], med[f"1 realisation, 2 threads, no reference{suffix}"]
    return a[0] - b[0], a[1] - b[1]


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
