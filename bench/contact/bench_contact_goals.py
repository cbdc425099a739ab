#!/usr/bin/python3
"""Issue 18, goal 3 (contact), measured as whole commands in one run, this build against the previous
one (e.g. main's), interleaved so a slow spell of the shared machine hits both alike; medians.
Prints a Markdown table for the README.

  /usr/bin/python3 bench/contact/bench_contact_goals.py --base /work/main/build/release
      [--new build/release] [--repeats 3] [--threads 2]

Goals and how each is measured:
  Hertz 512² to 1e-10 <= 0.6 s wall on 2 cores   `bench_contact --hertz` (hertz_solve: the cold solve,
      wall seconds, plans made beforehand); the previous build has no --hertz, so its hertz_solve line
      is read from `bench_contact --quick` and the process stopped there (it printed thread CPU
      seconds of the same single-threaded solve).
  seed-002 table <= 8 s wall                    `rollspec stiffness studies/seed002-table.ini --out
      NEW.h5` on 2 threads (the table stage; `rollspec run` refuses a stiffness scene), /usr/bin/time;
      the study is copied into a fresh directory for every run so the table is built, never read
      from a cache.
  CG iteration <= 1.2 x two convolutions       `bench_contact --quick` cg_iteration lines (this build,
      one thread, thread CPU time, minimum of 5 interleaved trials, same run).
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def env(threads):
    return dict(os.environ, OMP_NUM_THREADS=str(threads))


def csv_lines(cmd, threads, stop_case=None):
    """Runs a bench_contact command; returns {case: [fields...]} (stops after stop_case if given)."""
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True, env=env(threads))
    rows = {}
    for line in p.stdout:
        f = line.rstrip("\n").split(",", 5)
        rows.setdefault(f[0], []).append(f)
        if stop_case is not None and f[0] == stop_case:
            p.kill()
            break
    p.wait()
    return rows


def table_run(rollspec, threads):
    with tempfile.TemporaryDirectory() as tmp:
        study = Path(tmp) / "seed002-table.ini"
        shutil.copy(ROOT / "studies" / "seed002-table.ini", study)
        with tempfile.NamedTemporaryFile("r", suffix=".time") as t:
            r = subprocess.run(["/usr/bin/time", "-f", "%e %U %S", "-o", t.name, rollspec, "stiffness", study, "--out",
                                Path(tmp) / "t.h5", "--quiet"], capture_output=True, text=True, env=env(threads))
            if r.returncode != 0:
                sys.exit(f"failed: {rollspec} stiffness {study}\n{r.stderr}")
            wall, user, system = t.read().split()[-3:]
    return float(wall), float(user) + float(system)


def measure(new, base=None, repeats=3, threads=2):
    """Medians of the goal figures of this build (and of the previous build when `base` is given)."""
    builds = {"this": Path(new)}
    if base is not None:
        builds["previous"] = Path(base)
    hertz = {k: [] for k in builds}
    hertz1 = []  # this build on one thread: thread-CPU-like seconds, like the previous build's figure
    table = {k: [] for k in builds}
    for _ in range(repeats):
        for name, b in builds.items():
            bench = str(b / "bench" / "contact" / "bench_contact")
            if name == "this":
                rows = csv_lines([bench, "--hertz"], threads)
                one = csv_lines([bench, "--hertz"], 1)["hertz_solve"][0]
                hertz1.append(float(one[5].split(" s CPU")[0].split("; ")[-1]))
            else:
                rows = csv_lines([bench, "--quick"], threads, stop_case="hertz_solve")
            h = rows["hertz_solve"][0]
            hertz[name].append((float(h[2]), int(h[4])))
            table[name].append(table_run(str(b / "rollspec"), threads))
    iteration = csv_lines([str(builds["this"] / "bench" / "contact" / "bench_contact"), "--quick"], threads,
                          stop_case="hertz_solve")

    def med(v, i):
        return statistics.median(x[i] for x in v)

    r = {"threads": threads, "repeats": repeats, "hertz_wall": med(hertz["this"], 0),
         "hertz_iterations": hertz["this"][0][1], "hertz_cpu_1_thread": statistics.median(hertz1),
         "table_wall": med(table["this"], 0), "table_cpu": med(table["this"], 1),
         "iteration": [(int(f[1]), float(f[2]), float(f[3]), kind) for kind in ("cg_iteration", "cg_iteration_wall")
                       for f in iteration.get(kind, [])]}
    if base is not None:
        r.update(previous_hertz=med(hertz["previous"], 0), previous_hertz_iterations=hertz["previous"][0][1],
                 previous_table_wall=med(table["previous"], 0), previous_table_cpu=med(table["previous"], 1))
    return r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--base", required=True, help="previous build directory (has rollspec, bench/contact/bench_contact)")
    ap.add_argument("--new", default=str(ROOT / "build" / "release"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    r = measure(a.new, a.base, a.repeats, a.threads)
    load = os.getloadavg()
    print(f"contact goals (issue 18 goal 3), {a.threads} threads, median of {a.repeats} interleaved runs; "
          f"load average at the end {load[0]:.1f} / {load[1]:.1f} / {load[2]:.1f} on {os.cpu_count()} CPUs\n")
    print("| goal | previous build | this build | this / previous | this / goal |")
    print("|---|---|---|---|---|")
    hp, hn, h1 = r["previous_hertz"], r["hertz_wall"], r["hertz_cpu_1_thread"]
    print(f"| Hertz 512² to 1e-10, cold solve, 1 thread, CPU s | {hp:.3f} s ({r['previous_hertz_iterations']} iterations) "
          f"| {h1:.3f} s ({r['hertz_iterations']} iterations + coarse start) | {h1 / hp:.3f} | |")
    print(f"| Hertz 512² to 1e-10, cold solve ≤ 0.6 s wall on {a.threads} threads | {hp:.3f} s (1 thread) "
          f"| {hn:.3f} s | {hn / hp:.3f} | {hn / 0.6:.2f} |")
    tp, tn, cp, cn = r["previous_table_wall"], r["table_wall"], r["previous_table_cpu"], r["table_cpu"]
    print(f"| `rollspec stiffness studies/seed002-table.ini` ≤ 8 s wall | {tp:.2f} s wall, {cp:.1f} s CPU "
          f"| {tn:.2f} s wall, {cn:.1f} s CPU | {tn / tp:.3f} | {tn / 8.0:.2f} |")
    for n, seconds, ratio, kind in r["iteration"]:
        how = "1 thread CPU" if kind == "cg_iteration" else f"{a.threads} threads wall"
        print(f"| CG iteration / two convolutions ≤ 1.2, {n}² ({how}) | | {seconds * 1e3:.2f} ms "
              f"| | {ratio:.3f} / 1.2 = {ratio / 1.2:.2f} |")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
