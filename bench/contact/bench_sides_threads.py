#!/usr/bin/python3
"""Grid sides and threads of the contact solver, as measured figures:

1. CG iteration cost at grid sides 510, 511, 512 (bench_contact --sides: one thread, thread CPU per
   iteration, minimum of 5 interleaved trials per run; the median over --repeats runs), with the
   contact on a box of the grid and filling it (every product on the padded 1024² grid).
2. The seed 002 blocked-force table (studies/seed002-rig-1ms.ini, contact.blocked_force = solver,
   2 realisations, built from scratch in a fresh directory) as whole `rollspec run` commands on
   OMP_NUM_THREADS = 1 and 2, for the current build and a reference build, interleaved, medians;
   the thread speed-up, the ratio against the reference, and whether the table files of 1 and 2
   threads hold the same bits.

  /usr/bin/python3 bench/contact/bench_sides_threads.py --reference /path/to/old/rollspec \\
      [--current build/werror/rollspec] [--bench build/werror/bench/contact/bench_contact] [--repeats 3]
"""
import argparse
import os
import pathlib
import statistics
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import bench_tables  # noqa: E402  (run_once: one whole command, its table's columns)

ROOT = pathlib.Path(__file__).resolve().parents[2]


def sides(bench, repeats):
    """{(case, n): [seconds per iteration, one per run]} from bench_contact --sides."""
    out = {}
    for _ in range(repeats):
        r = subprocess.run([bench, "--sides"], capture_output=True, text=True, check=True)
        for line in r.stdout.splitlines():
            f = line.split(",")
            if f[0].startswith("side_iteration"):
                out.setdefault((f[0], int(f[1])), []).append(float(f[2]))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--reference", required=True, help="rollspec binary to compare with (the build before)")
    ap.add_argument("--current", default=str(ROOT / "build" / "werror" / "rollspec"))
    ap.add_argument("--bench", default=str(ROOT / "build" / "werror" / "bench" / "contact" / "bench_contact"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--skip-sides", action="store_true")
    o = ap.parse_args()
    for program, option in ((o.reference, "--reference"), (o.current, "--current")) + \
            (() if o.skip_sides else ((o.bench, "--bench"),)):
        require_program(program, option)  # before the first measurement, not after an hour of them
    lines = []
    if not o.skip_sides:
        t = sides(o.bench, o.repeats)
        lines += [f"CG iteration by grid side, 1 thread, median of {o.repeats} runs (each the minimum of 5 trials)", "",
                  "| contact | side | ms per iteration | ratio to 512 |", "|---|---|---|---|"]
        for case in ("side_iteration", "side_iteration_full"):
            base = statistics.median(t[(case, 512)])
            for n in (510, 511, 512):
                m = statistics.median(t[(case, n)])
                what = "box of the grid" if case == "side_iteration" else "fills the grid"
                lines.append(f"| {what} | {n} | {1e3 * m:.2f} | {m / base:.2f} |")
        lines.append("")
    builds = {"reference": o.reference, "current": o.current}
    runs = {(b, n): [] for b in builds for n in (1, 2)}
    for rep in range(o.repeats):  # interleaved: each build and thread count once per round
        for n in (2, 1):
            for b, binary in builds.items():
                r = bench_tables.run_once(binary, "blocked_force", n)
                runs[(b, n)].append(r)
                print(f"round {rep + 1} {b:9s} {n} thread(s) {r['wall']:7.2f} s wall {r['cpu']:7.2f} s CPU",
                      file=sys.stderr, flush=True)
    load = os.getloadavg()
    med = {k: {q: statistics.median(r[q] for r in v) for q in ("wall", "cpu")} for k, v in runs.items()}
    lines += [f"Seed 002 blocked-force table (whole `rollspec run`, 2 realisations), median of {o.repeats} "
              f"interleaved runs (load average at the end {load[0]:.1f})", "",
              "| build | 1 thread wall / CPU (s) | 2 threads wall / CPU (s) | speed-up 1 -> 2 | "
              "same bits 1 and 2 threads | iterations per solve |", "|---|---|---|---|---|---|"]
    for b in builds:
        one, two = runs[(b, 1)][0]["columns"], runs[(b, 2)][0]["columns"]
        same = one.keys() == two.keys() and all(one[k].tobytes() == two[k].tobytes() for k in one)
        lines.append(f"| {b} | {med[(b, 1)]['wall']:.1f} / {med[(b, 1)]['cpu']:.1f} | {med[(b, 2)]['wall']:.1f} / "
                     f"{med[(b, 2)]['cpu']:.1f} | {med[(b, 1)]['wall'] / med[(b, 2)]['wall']:.2f} | {same} | "
                     f"{runs[(b, 2)][0]['iterations']} |")
    diff, column = bench_tables.max_rel_diff(runs[("current", 2)][0]["columns"], runs[("reference", 2)][0]["columns"])
    for n in (1, 2):
        lines.append(f"\nreference / current wall on {n} thread(s): "
                     f"{med[('reference', n)]['wall'] / med[('current', n)]['wall']:.2f}")
    lines.append(f"\ncurrent vs reference table: max rel diff {diff:.2e} ({column})")
    print("\n".join(lines))


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import require_program, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
