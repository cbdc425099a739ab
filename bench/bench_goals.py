#!/usr/bin/python3
"""Issue 18's five speed goals, each measured as whole commands in one run (rollspec against its goal,
the floor it is compared with, or the previous build), kept in bench/goals.json; the documentation's
benchmarks page is generated from it (docs/generate_reference.py), so no figure there is typed by hand.

  /usr/bin/python3 bench/bench_goals.py measure [--goals 1,2,3,4,5] [--bin build/release]
      [--base PREVIOUS_BUILD_DIR] [--repeats 3]
  /usr/bin/python3 bench/bench_goals.py table        # print the goals table from goals.json

`measure` runs the chosen goals, replaces their entries in goals.json (each with the date, the commit,
whether the tree had changes, and the load average before and after), then prints the table.
Goals needing the previous build (1's reference ratio, 3's and 4's ratios) skip those ratios without --base.

  1  seed 002 rig, 1000 realisations, whole `rollspec run`: <= 2.0 s on 2 cores, efficiency >= 0.9
     (bench/engine/bench_whole_run.py)
  2  default accuracy <= 0.02 dB at <= 10 ms CPU per seed 002 realisation (bench_default_accuracy.py)
  3  Hertz 512² to 1e-10 <= 0.6 s wall on 2 cores; seed 002 table <= 8 s; CG iteration <= 1.2 x two
     convolutions (bench/contact/bench_contact_goals.py; the table shows this build against the goals,
     the ratio to the build before contact kernel 3 is in that script's own printout)
  4  rolling pipe: <= 30 µs per Newton iteration, >= 3x faster per realisation than the previous build
     (bench/rolling/bench_rolling_pipe.py)
  5  line texture synthesis <= 2 x a bare FFTW c2r of the same length (bench_texture --synthesis)
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "bench" / "goals.json"

for sub in ("engine", "contact", "rolling"):
    sys.path.insert(0, str(ROOT / "bench" / sub))


def commit():
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout
    # Changes to what this script writes do not change what was measured.
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no", "--", ".",
                            ":!README.md", ":!bench/goals.json"], capture_output=True, text=True).stdout
    return head.strip() + (" + changes" if dirty.strip() else "")


def goal_1(a):
    import bench_whole_run
    K = 1000
    base = need(Path(a.base) / "rollspec", "build the rollspec target of the previous build") if a.base else None
    med = bench_whole_run.measure(need(Path(a.bin) / "rollspec", "build the rollspec target"), str(ROOT / "studies" / "seed002-rig-1ms.ini"), K,
                                  a.repeats, baseline=base)
    t1, t2 = med[f"{K} realisations, 1 thread"][0], med[f"{K} realisations, 2 threads"][0]
    out = {"wall_2_threads": t2, "wall_1_thread": t1, "efficiency": t1 / (2 * t2),
           "one_realisation": med["1 realisation, 2 threads"][0],
           "no_reference_2_threads": med[f"{K} realisations, 2 threads, no reference"][0],
           "reference_wall": bench_whole_run.reference_cost(med)[0],
           "reference_cpu": bench_whole_run.reference_cost(med)[1]}
    if base:
        out["previous_reference_cpu"] = bench_whole_run.reference_cost(med, ": previous build")[1]
    return out


def goal_2(a):
    import bench_default_accuracy as acc
    study = str(ROOT / "studies" / "seed002-rig-1ms.ini")
    binary = need(Path(a.bin) / "rollspec", "build the rollspec target")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        speed, fs, setup = acc.probe(binary, study, tmp)
        error, cpu = acc.case(binary, study, "output", 4, 25, 400, speed, fs, setup, tmp)
    return {"error_db": error, "cpu_ms": 1e3 * cpu, "substeps": 4}


def need(path, what):
    """A program a goal runs: refused with a message, not a traceback, when the build lacks it."""
    if not Path(path).is_file():
        sys.exit(f"{path}: not found; {what}")
    return str(path)


def goal_3(a):
    import bench_contact_goals
    need(Path(a.bin) / "bench" / "contact" / "bench_contact", "build the bench_contact target of the measured build")
    if a.base is not None:
        need(Path(a.base) / "bench" / "contact" / "bench_contact",
             "goal 3's comparison needs the bench_contact target in --base too (or leave --base out for goal 3)")
    return bench_contact_goals.measure(a.bin, a.base, a.repeats, 2)


def goal_4(a):
    import bench_rolling_pipe
    if a.base is None:
        sys.exit("goal 4 needs --base PREVIOUS_BUILD_DIR (the ratio is against the previous build)")
    K = 2
    med, per_it, its, rel, dband = bench_rolling_pipe.measure(
        need(Path(a.bin) / "rollspec", "build the rollspec target"),
        need(Path(a.base) / "rollspec", "build the rollspec target of the previous build"), str(ROOT / "studies" / "rolling-pipe.ini"), K,
        a.repeats)
    this, prev = med[("this", "full")][1], med[("previous", "full")][1]
    return {"us_per_iteration": per_it["this"], "previous_us_per_iteration": per_it["previous"],
            "seconds_per_realisation": this / K, "speedup": prev / this, "psd_difference": rel,
            "band_difference_db": dband}


def goal_5(a):
    out = subprocess.run([need(Path(a.bin) / "bench" / "texture" / "bench_texture", "build the bench_texture target"),
                          "--synthesis", "1.0"],
                         capture_output=True, text=True, check=True).stdout
    rows = [line.split(",") for line in out.splitlines() if line[:1].isdigit()]
    return {"sizes": [int(r[0]) for r in rows], "ratio": [float(r[3]) for r in rows],
            "previous_ratio": [float(r[7]) for r in rows]}


MEASURE = {1: goal_1, 2: goal_2, 3: goal_3, 4: goal_4, 5: goal_5}


def mark(ok):
    return "met" if ok else "**missed**"


def rows(results):
    """Table rows: goal, measured, met or missed, when / commit / load."""
    out = []

    def when(r):
        return f"{r['date']}, {r['commit']}, load {r['load_before']:.1f} → {r['load_after']:.1f}"

    if "1" in results:
        r = results["1"]
        m = r["figures"]
        out.append(("1. seed 002, 1000 realisations, whole `rollspec run`: ≤ 2.0 s on 2 cores, efficiency ≥ 0.9",
                    f"{m['wall_2_threads']:.2f} s on 2 threads, {m['wall_1_thread']:.2f} s on 1 (efficiency "
                    f"{m['efficiency']:.2f}); {m['no_reference_2_threads']:.2f} s without the reference; 1 realisation "
                    f"{m['one_realisation']:.2f} s" + (
                        f"; the reference {m['reference_wall']:.2f} s wall, {m['reference_cpu']:.2f} s CPU"
                        if "reference_cpu" in m else "") + (
                        f" ({m['previous_reference_cpu'] / m['reference_cpu']:.1f}× less CPU than the previous build's)"
                        if "previous_reference_cpu" in m else ""),
                    mark(m["wall_2_threads"] <= 2.0 and m["efficiency"] >= 0.9), when(r)))
    if "2" in results:
        r = results["2"]
        m = r["figures"]
        out.append(("2. default accuracy ≤ 0.02 dB (largest band error 100 Hz–5 kHz against converged) at ≤ 10 ms CPU "
                    "per seed 002 realisation",
                    f"{m['error_db']:.4f} dB at {m['cpu_ms']:.1f} ms ({m['substeps']} substeps, the study's setting)",
                    mark(m["error_db"] <= 0.02 and m["cpu_ms"] <= 10.0), when(r)))
    if "3" in results:
        r = results["3"]
        m = r["figures"]
        it = "; ".join(f"{n}² {ratio:.2f} ({'1 thread CPU' if kind == 'cg_iteration' else '2 threads wall'})"
                       for n, _, ratio, kind in m["iteration"])
        out.append(("3. Hertz 512² to 1e-10 ≤ 0.6 s wall on 2 cores; seed 002 table ≤ 8 s; CG iteration ≤ 1.2 × two "
                    "convolutions",
                    f"Hertz {m['hertz_wall']:.3f} s ({m['hertz_iterations']} iterations + coarse start), table "
                    f"{m['table_wall']:.2f} s wall ({m['table_cpu']:.1f} s CPU); iteration / two convolutions: {it}",
                    mark(m["hertz_wall"] <= 0.6 and m["table_wall"] <= 8.0
                         and all(x[2] <= 1.2 for x in m["iteration"])), when(r)))
    if "4" in results:
        r = results["4"]
        m = r["figures"]
        ratio = m["speedup"]
        prev = (f"; {ratio:.2f}× faster per realisation than the previous build ({m['previous_us_per_iteration']:.1f} µs "
                f"per iteration; results within {m['band_difference_db']:.1e} dB)")
        out.append(("4. rolling pipe ≤ 30 µs per Newton iteration, ≥ 3× faster per realisation",
                    f"{m['us_per_iteration']:.1f} µs per Newton iteration, {m['seconds_per_realisation']:.2f} s per "
                    f"realisation{prev}",
                    mark(m["us_per_iteration"] <= 30.0 and ratio >= 3.0), when(r)))
    if "5" in results:
        r = results["5"]
        m = r["figures"]
        pairs = ", ".join(f"2^{n.bit_length() - 1}: {x:.2f}" for n, x in zip(m["sizes"], m["ratio"]))
        before = ", ".join(f"{x:.2f}" for x in m["previous_ratio"])
        out.append(("5. line texture synthesis ≤ 2 × a bare FFTW c2r of the same length",
                    f"{pairs} (the libm path in the same run: {before})", mark(all(x <= 2.0 for x in m["ratio"])),
                    when(r)))
    return out


def write_table(results):
    print("| goal | measured (whole commands, one run) | | when, commit, load average |")
    print("|---|---|---|---|")
    for g, m, ok, w in rows(results):
        print(f"| {g} | {m} | {ok} | {w} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("action", choices=["measure", "table"])
    ap.add_argument("--goals", default="1,2,3,4,5")
    ap.add_argument("--bin", default=str(ROOT / "build" / "release"), help="build directory measured")
    ap.add_argument("--base", help="previous build directory, for the ratios of goals 1 (the reference), 3 and 4")
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    if a.action == "measure":  # the goals file is this script's: checked before anything is measured
        check_output_file(RESULTS, "goals file", own=starts_with(b"{"))
    results = json.loads(RESULTS.read_text()) if RESULTS.exists() else {}
    if a.action == "measure":
        for g in sorted({int(x) for x in a.goals.split(",")}):
            if g not in MEASURE:
                sys.exit(f"--goals: {g} is not a goal; allowed 1-5")
            before = os.getloadavg()[0]
            figures = MEASURE[g](a)
            results[str(g)] = {"figures": figures, "date": datetime.date.today().isoformat(), "commit": commit(),
                               "load_before": before, "load_after": os.getloadavg()[0]}
            write_output_file(os.path.realpath(RESULTS), (json.dumps(results, indent=1, sort_keys=True) + "\n").encode())
            print(f"goal {g}: {json.dumps(figures)}", flush=True)
    write_table(results)


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../python-post"))
from rollspec_post.script_main import check_output_file, starts_with, write_output_file, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
