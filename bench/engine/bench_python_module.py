#!/usr/bin/python3
"""The Python module's cost against C++ and the command, measured interleaved in one run (issue 52).

usage: bench_python_module.py [--bin B] [--rounds R] [--repeats M] [--realisations K] [--contact-threads T,...]
                              [--study-threads N] [--study STUDY] [--record FILE]

1. Contact: one solve on a 512 x 512 gap map (a 20 mm ball, rollspec.contact.ball_gap, on an isotropic
   rough flat, rollspec.surfaces.isotropic, PSD flat to 1 / (10 um) then q^-4, scaled to rms 0.3 um, 1 um
   cells, approach 0.5 um past first contact, E* = 115.4 GPa), elastic (the binding's defaults of hardness,
   tolerance, max_iterations and stiffness) and elastic-plastic (hardness 5 GPa), (A) through
   rollspec.contact.solve in a Python process, (B) by bench/contact/bench_contact_solve, the same solve
   the binding makes, in C++, with the same options. Each side is a fresh process per round on
   OMP_NUM_THREADS = T that reads the gap map, solves once untimed, then times M solves: the Python call
   (A), the solve from the gap's copy to the loaded gap (B). Their forces must agree bit for bit.
2. Study: STUDY (default studies/seed002-rig-1ms.ini) at study.realisations = K, (A)
   rollspec.studies.run(..., quiet=True, threads=N) in this process, (B) `rollspec run ... --quiet` as a
   subprocess on OMP_NUM_THREADS = N; the whole call timed. The two result files must hold the same
   datasets bit for bit (but /run/wall_seconds and /run/reduce_seconds).
A and B alternate in each round, which goes first alternating with the round, so drift of the shared
machine falls on both; medians, min and max over the R rounds (R x M solves), the ratio of the medians
A / B (the goal's figure) and that of the minima (the least disturbed solve of each side).
The module is the one beside the binary (BINDIR/python), the C++ solve BINDIR/bench/contact/.
Writes bench/records/python-module.json (or --record) through the bench record writer.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))
sys.dont_write_bytecode = True  # nothing written into the sources
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, require_program, script_main  # noqa: E402

EX_USAGE, EX_NOINPUT, EX_SOFTWARE, EX_CANTCREAT = 64, 66, 70, 73
GOAL = 1.05  # issue 52: the module at most 1.05 x the time of C++ and of the command
N, DX, RADIUS, E_STAR = 512, 1e-6, 0.02, 115.4e9  # grid, cell (m), ball radius (m), E* (Pa)
SIGMA, CORRELATION, PAST_CONTACT, HARDNESS = 3e-7, 1e-5, 5e-7, 5e9  # m, m, m, Pa
IGNORED_DATASETS = {"run/wall_seconds", "run/reduce_seconds"}  # timings, not results


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line and exit 64, not argparse's usage block
        fail(message, EX_USAGE)


def binding_defaults(solve):
    """{option: value} of rollspec.contact.solve's defaults, as its signature line prints them."""
    line = solve.__doc__.splitlines()[0]
    found = dict(re.findall(r"(hardness|tolerance|max_iterations|stiffness): \w+ = ([^,)]+)", line))
    if set(found) != {"hardness", "tolerance", "max_iterations", "stiffness"}:
        fail(f"rollspec.contact.solve's signature '{line}': cannot read its defaults", EX_SOFTWARE)
    return {"hardness": float(found["hardness"]), "tolerance": float(found["tolerance"]),
            "max_iterations": int(found["max_iterations"]), "stiffness": found["stiffness"] == "True"}


def import_module(folder):
    sys.path.insert(0, str(folder))
    import rollspec
    return rollspec


def solve_in_python(a):
    """The worker of side A (a process of its own): solve once untimed, then time `repeats` calls."""
    import numpy as np
    rollspec = import_module(a.module)
    gap = np.fromfile(a.python_solve, dtype=np.float64).reshape(N, N)
    extra = {} if a.hardness is None else {"hardness": a.hardness}
    first = rollspec.contact.solve(gap, DX, e_star=E_STAR, approach=a.approach, **extra)
    seconds = []
    for _ in range(a.repeats):
        t0 = time.perf_counter()
        r = rollspec.contact.solve(gap, DX, e_star=E_STAR, approach=a.approach, **extra)
        seconds.append(time.perf_counter() - t0)
        if r["force"] != first["force"]:
            fail(f"a repeat gave force {r['force'].hex()}, the first {first['force'].hex()}", EX_SOFTWARE)
    print(f"seconds={','.join(f'{x:.9f}' for x in seconds)} force={float(first['force']).hex()} "
          f"iterations={first['iterations']} converged={int(first['converged'])}", flush=True)
    return 0


def parse_solve(text, who):
    m = re.fullmatch(r"seconds=([0-9.,]+) force=(\S+) iterations=(\d+) converged=([01])\s*", text)
    if not m:
        fail(f"{who} printed '{text.strip()[:200]}', not 'seconds=S,... force=F iterations=N converged=C'",
             EX_SOFTWARE)
    return {"seconds": [float(x) for x in m.group(1).split(",")], "force": float.fromhex(m.group(2)),
            "iterations": int(m.group(3)), "converged": m.group(4) == "1"}


def run_side(argv, threads, who):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    r = subprocess.run(argv, capture_output=True, text=True, env=env)
    if r.returncode:
        last = (r.stderr.strip().splitlines() or [""])[-1]
        fail(f"{who} exited {r.returncode}: {last}", EX_SOFTWARE)
    return parse_solve(r.stdout, who)


def gap_map(rollspec, work):
    """The ball on the rough flat: s = ball gap - heights, written for both sides; the approach."""
    import numpy as np
    q = np.geomspace(1e3, 3e6, 200)  # rad/m; a roll-off at 1 / correlation length, then q^-4
    h = rollspec.surfaces.isotropic(q, (1 + (q * CORRELATION) ** 2) ** -2, DX, N, seed=52)["heights"]
    h *= SIGMA / h.std()
    gap = np.ascontiguousarray(rollspec.contact.ball_gap(RADIUS, DX, N, N) - h, dtype=np.float64)
    path = work / "gap.bin"
    gap.tofile(path)
    return path, float(gap.min()) + PAST_CONTACT


def datasets(path):
    import h5py
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and name not in IGNORED_DATASETS:
                out[name] = obj[()]
        f.visititems(visit)
    return out


def same_datasets(first, second):
    """Names of the datasets that differ bit for bit (or exist in one file only)."""
    import numpy as np
    a, b = datasets(first), datasets(second)
    differ = sorted(set(a) ^ set(b))
    for name in sorted(set(a) & set(b)):
        x, y = np.asarray(a[name]), np.asarray(b[name])
        if x.dtype != y.dtype or x.shape != y.shape or (
                x.tolist() != y.tolist() if x.dtype.kind == "O" else x.tobytes() != y.tobytes()):  # strings: values
            differ.append(name)
    return differ, len(a)


def spread(values):
    return statistics.median(values), min(values), max(values)


def row(case, threads, a, b, against):
    ma, lo_a, hi_a = spread(a)
    mb, lo_b, hi_b = spread(b)
    ratio = ma / mb
    return [case, threads, len(a), round(ma, 4), f"{lo_a:.4f} .. {hi_a:.4f}", against, round(mb, 4),
            f"{lo_b:.4f} .. {hi_b:.4f}", round(ratio, 4), round(lo_a / lo_b, 4), f"<= {GOAL}",
            "yes" if ratio <= GOAL else "no"]


def main():
    p = Parser(description=__doc__.splitlines()[0])
    p.add_argument("--bin", default=os.environ.get("ROLLSPEC_BIN", str(ROOT / "build" / "werror" / "rollspec")))
    p.add_argument("--rounds", type=int, default=7, help="R interleaved rounds (default 7)")
    p.add_argument("--repeats", type=int, default=3, help="M timed contact solves per process (default 3)")
    p.add_argument("--realisations", type=int, default=1000, help="K of the study (default 1000)")
    p.add_argument("--contact-threads", default="2,1", help="OMP_NUM_THREADS of the contact rows (default 2,1)")
    p.add_argument("--study-threads", type=int, default=2, help="threads of the study runs (default 2)")
    p.add_argument("--study", default=str(ROOT / "studies" / "seed002-rig-1ms.ini"))
    p.add_argument("--record", default=str(ROOT / "bench" / "records" / "python-module.json"))
    p.add_argument("--python-solve", help=argparse.SUPPRESS)  # side A's worker: the gap map's file
    p.add_argument("--module", help=argparse.SUPPRESS)
    p.add_argument("--approach", type=float, help=argparse.SUPPRESS)
    p.add_argument("--hardness", type=float, help=argparse.SUPPRESS)
    a = p.parse_args()
    if a.python_solve:
        return solve_in_python(a)
    try:
        threads = [int(t) for t in a.contact_threads.split(",")]
    except ValueError:
        threads = []
    if not threads or min(threads) < 1:
        fail(f"--contact-threads {a.contact_threads}: allowed: whole numbers >= 1, comma-separated", EX_USAGE)
    if a.rounds < 1 or a.repeats < 1 or a.realisations < 2 or a.study_threads < 1:
        fail(f"--rounds {a.rounds} --repeats {a.repeats} --realisations {a.realisations} --study-threads "
             f"{a.study_threads}: allowed: R >= 1, M >= 1, K >= 2, N >= 1", EX_USAGE)
    a.bin = os.path.abspath(require_program(a.bin, "--bin"))
    bindir = Path(a.bin).parent
    a.solver = require_program(str(bindir / "bench" / "contact" / "bench_contact_solve"), "the C++ solve")
    a.module = bindir / "python"
    if not (a.module / "rollspec" / "__init__.py").is_file():
        fail(f"{a.module}: no rollspec module beside the binary; allowed: a build with its python/ folder",
             EX_NOINPUT)
    if not os.path.isfile(a.study):
        fail(f"--study {a.study}: no such file", EX_NOINPUT)
    try:
        bench_record.check_target(a.record, own=bench_record.is_record)
    except bench_record.RecordError as e:
        fail(f"--record {e}", EX_CANTCREAT)
    work = Path(tempfile.mkdtemp(prefix="python-module-"))
    try:
        return measure(a, threads, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def measure(a, threads, work):
    start, cpu0, busy0 = time.monotonic(), bench_record.own_cpu(), bench_record.busy_seconds()
    rollspec = import_module(a.module)
    defaults = binding_defaults(rollspec.contact.solve)
    gap, approach = gap_map(rollspec, work)
    cases = [("elastic", None, defaults["hardness"]), ("elastic-plastic", HARDNESS, HARDNESS)]
    times = {(c[0], t, side): [] for c in cases for t in threads for side in "AB"}
    forces, iterations = {}, {}
    study = os.path.abspath(a.study)
    sets = [f"study.realisations={a.realisations}"]
    study_times = {"A": [], "B": []}
    differ, compared = None, 0
    for r in range(a.rounds):
        order = "AB" if r % 2 == 0 else "BA"
        for name, python_hardness, hardness in cases:
            for t in threads:
                for side in order:
                    if side == "A":
                        argv = [sys.executable, __file__, "--python-solve", str(gap), "--module", str(a.module),
                                "--approach", repr(approach), "--repeats", str(a.repeats)]
                        argv += [] if python_hardness is None else ["--hardness", repr(python_hardness)]
                        got = run_side(argv, t, "the Python solve")
                    else:
                        argv = [a.solver, str(gap), str(N), str(N), repr(DX), repr(E_STAR), repr(approach),
                                repr(hardness), repr(defaults["tolerance"]), str(defaults["max_iterations"]),
                                str(int(defaults["stiffness"])), str(a.repeats)]
                        got = run_side(argv, t, "bench_contact_solve")
                    times[(name, t, side)] += got["seconds"]
                    forces.setdefault(name, {}).setdefault(side, set()).add(got["force"])
                    iterations.setdefault(name, set()).add(got["iterations"])
                    if not got["converged"]:
                        fail(f"{name} solve on {t} threads ({side}): not converged", EX_SOFTWARE)
        out = {"A": work / "module.h5", "B": work / "command.h5"}
        for side in order:
            out[side].unlink(missing_ok=True)
            t0 = time.perf_counter()
            if side == "A":
                rollspec.studies.run(study, str(out["A"]), set=sets, quiet=True, threads=a.study_threads)
            else:
                p = subprocess.run([a.bin, "run", study, "--out", str(out["B"]), "--quiet",
                                    *sum((["--set", s] for s in sets), [])], capture_output=True, text=True,
                                   env=dict(os.environ, OMP_NUM_THREADS=str(a.study_threads)))
                if p.returncode:
                    fail(f"rollspec run exited {p.returncode}: {(p.stderr.strip().splitlines() or [''])[-1]}",
                         EX_SOFTWARE)
            study_times[side].append(time.perf_counter() - t0)
            if side == order[1]:
                differ, compared = same_datasets(out["A"], out["B"])
                if differ:
                    fail(f"round {r + 1}: the module's and the command's result files differ in {differ[:5]}",
                         EX_SOFTWARE)
        print(f"round {r + 1}/{a.rounds} done", file=sys.stderr, flush=True)
    for name, sides in forces.items():
        if len(sides["A"] | sides["B"]) != 1:
            fail(f"{name}: the forces differ: {sorted(float.hex(f) for f in sides['A'] | sides['B'])}", EX_SOFTWARE)
    rows = [row(f"contact solve {N}x{N}, {name}", t, times[(name, t, "A")], times[(name, t, "B")],
                "C++ (bench_contact_solve)") for name, _, _ in cases for t in threads]
    rows.append(row(f"{Path(a.study).name}, K = {a.realisations}", a.study_threads, study_times["A"],
                    study_times["B"], "rollspec run --quiet"))
    wall, cpu = time.monotonic() - start, bench_record.own_cpu() - cpu0
    other = bench_record.other_work(busy0, cpu, wall)
    settings = (f"{a.rounds} rounds, A and B alternating (which first alternating with the round), medians, min "
                f"and max over the rounds; ratio = median A / median B. Contact: a {N} x {N} gap map (a "
                f"{RADIUS * 1e3:g} mm ball on a rough flat, PSD flat to 1 / ({CORRELATION * 1e6:g} um) then "
                f"q^-4, rms {SIGMA * 1e6:g} um, {DX * 1e6:g} um cells, approach {PAST_CONTACT * 1e6:g} um past "
                f"first contact, E* {E_STAR / 1e9:g} GPa), the binding's default options (hardness "
                f"{defaults['hardness']:g}, tolerance {defaults['tolerance']:g}, max_iterations "
                f"{defaults['max_iterations']}, stiffness {defaults['stiffness']}) and hardness {HARDNESS / 1e9:g} "
                "GPa for the elastic-plastic row; each side a fresh process per round that solves once untimed and "
                f"times {a.repeats} solves (the Python call; the C++ solve from the gap's copy to the loaded gap), "
                "OMP_NUM_THREADS as the threads column. Study: the whole call, rollspec.studies.run(quiet=True, "
                f"threads={a.study_threads}) in the bench's process against the command as a subprocess on "
                f"OMP_NUM_THREADS={a.study_threads}. The whole bench took {wall / 60:.1f} min wall.")
    notes = (f"Same work checked: each contact case gave one force, bit for bit, on both sides, every round and "
             f"thread count (CG iterations {', '.join(f'{k} {sorted(v)}' for k, v in iterations.items())}); the two "
             f"result files of every round held the same {compared} datasets bit for bit (but "
             f"{', '.join(sorted(IGNORED_DATASETS))}). Other work on the machine: the record's "
             "other-work figure (cores it kept busy); the ratios are of interleaved rounds, so drift falls on "
             "both sides.")
    data = {"contact": {f"{k[0]}|{k[1]}|{k[2]}": v for k, v in times.items()}, "study": study_times,
            "forces": {k: float(next(iter(v["A"]))).hex() for k, v in forces.items()},
            "approach": approach, "defaults": defaults, "wall_s": wall, "cpu_s": cpu}
    bench_record.write(
        a.record, title="The Python module against C++ and the command: a contact solve and a seed 002 run",
        argv=sys.argv, builds={"rollspec": {"description": "the build measured, its python/ module and "
                                                           "bench/contact/bench_contact_solve",
                                            "version": bench_record.build_version(a.bin)}},
        settings=settings, columns=["case", "threads", "timings per side", "Python (A) median s", "A min .. max s",
                                    "against (B)", "B median s", "B min .. max s", "A / B medians",
                                    "A / B minima", "goal (medians)", "met"],
        rows=rows, notes=notes, data=data, other_cores=other)
    for r in rows:
        print(" | ".join(str(c) for c in r))
    return 0


if __name__ == "__main__":
    script_main(main)
