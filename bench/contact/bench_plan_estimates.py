#!/usr/bin/python3
"""`rollspec plan`'s estimates of the contact-solver tables against their measured builds, on textures
the models were fitted on and on textures they were not.

  /usr/bin/python3 bench/contact/bench_plan_estimates.py [--binary build/werror/rollspec]
      [--textures rig,rough,smooth,mid,flat] [--kinds blocked_force,filter,path] [--repeats 3] [--json out.json]
      [--record bench/records/plan-estimates.json]

For each texture (studies/seed002-rig-1ms.ini with the --set below) and table kind (the cases of
bench_tables.py): `rollspec plan` (its "build about X s CPU"), for the equivalent roughness also
`rollspec plan --probe` (its first chunk of solves timed), then the whole `rollspec run` from an
empty table directory on one thread (OMP_NUM_THREADS=1, CPU seconds from the child's rusage) less
the same run again with the table cached: the table's build. Medians of --repeats such runs.
Ratio = estimate / measured CPU; the models' constants were fitted on rig, rough and smooth (mid
and flat are held out); the probe is fitted on nothing.
"""
import argparse
import json
import os
import pathlib
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, str(ROOT / "bench"))
import bench_record  # noqa: E402
sys.path.insert(0, str(ROOT / "bench" / "contact"))
from bench_tables import CASES, STUDY  # noqa: E402  (the same three table cases)

HURST = ["texture.hurst=0.8", "texture.rolloff_wavelength=50e-6"]
TEXTURES = {  # name: (--set, fitted on it)
    "rig": ([], True),
    "rough": (["texture.rms=0.38e-6", *HURST], True),
    "smooth": (["texture.rms=0.05e-6", *HURST], True),
    "mid": (["texture.rms=0.15e-6", *HURST], False),
    "flat": (["texture.rms=0.1e-6", "texture.hurst=0.5", "texture.rolloff_wavelength=100e-6"], False),
}
STAGES = {"blocked_force": "blocked_force", "blocked_force_answer": "blocked_force", "filter": "equivalent_roughness", "path": "path_table"}


def run(binary, args, env):
    r = subprocess.run([str(binary), *map(str, args)], capture_output=True, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"bench_plan_estimates: {binary} {args[0]} failed ({r.returncode}): {r.stderr.strip()[-500:]}")
    return r


def measure(binary, texture, kind):
    """(plan's model estimate, plan --probe's estimate or None, measured CPU seconds) of one table."""
    work = pathlib.Path(tempfile.mkdtemp(prefix=f"bench-plan-{kind}-"))
    try:
        study = work / "rig.ini"
        shutil.copy(STUDY, study)
        sets = [a for kv in [*TEXTURES[texture][0], *CASES[kind]] for a in ("--set", kv)]
        env = dict(os.environ, OMP_NUM_THREADS="1")
        plan = run(binary, ["plan", study, *sets], env).stdout
        row = next((l for l in plan.splitlines() if l.startswith(STAGES[kind] + " ")), "")
        model = re.search(r"build about ([\d.e+-]+) s", row)
        probe = None
        if kind == "filter":
            p = re.search(r"^table equivalent_roughness: about ([\d.e+-]+) s CPU",
                          run(binary, ["plan", study, "--probe", *sets], env).stdout, re.M)
            probe = float(p.group(1)) if p else float("nan")
        def cpu_of_run(out):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            run(binary, ["run", study, "--out", work / out, "--quiet", *sets], env)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        # The table's build: the run that builds it less the same run with the table cached.
        cpu = cpu_of_run("r.h5") - cpu_of_run("cached.h5")
        return (float(model.group(1)) if model else float("nan")), probe, cpu
    finally:
        shutil.rmtree(work, ignore_errors=True)


def is_own_json(path):
    """A --json file this script wrote (a list of its cases), which a new run may replace."""
    try:
        with open(path) as f:
            d = json.load(f)
        return isinstance(d, list) and all(isinstance(x, dict) and {"texture", "kind", "cpu"} <= x.keys() for x in d)
    except (OSError, ValueError):
        return False


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=str(ROOT / "build" / "werror" / "rollspec"))
    ap.add_argument("--textures", default=",".join(TEXTURES))
    ap.add_argument("--kinds", default=",".join(CASES))
    ap.add_argument("--repeats", type=int, default=3, help="runs per case (medians)")
    ap.add_argument("--json")
    ap.add_argument("--record", help="write a benchmark record (bench/records/NAME.json) for the documentation")
    o = ap.parse_args()
    textures, kinds = o.textures.split(","), o.kinds.split(",")
    for name, known in ((textures, TEXTURES), (kinds, CASES)):
        if unknown := [n for n in name if n not in known]:
            sys.exit(f"bench_plan_estimates: unknown {unknown}; allowed: {', '.join(known)}")
    if o.repeats < 1:
        sys.exit(f"bench_plan_estimates: --repeats {o.repeats}; allowed: 1 or more")
    if not os.access(o.binary, os.X_OK):
        sys.exit(f"bench_plan_estimates: no rollspec binary at {o.binary}; allowed: a built rollspec (--binary)")
    # refused before the measurement, not after (exit 1, as always)
    bench_record.check_targets([(o.json, is_own_json), (o.record, bench_record.is_record)], code=1)
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    rows, data = [], []
    for t in textures:
        for k in kinds:
            runs = [measure(o.binary, t, k) for _ in range(o.repeats)]  # medians: the probe and the build vary
            model = runs[0][0]
            probe = None if runs[0][1] is None else statistics.median(r[1] for r in runs)
            cpu = statistics.median(r[2] for r in runs)
            fitted = "fitted" if TEXTURES[t][1] else "held out"
            data.append({"texture": t, "kind": k, "fitted": TEXTURES[t][1], "model": model, "probe": probe, "cpu": cpu})
            rows.append([t, fitted, k, f"{cpu:.3g}", f"{model:.2g} ({model / cpu:.2f})",
                         "-" if probe is None else f"{probe:.2g} ({probe / cpu:.2f})"])
            print(" | ".join(rows[-1]), file=sys.stderr, flush=True)
    columns = ["texture", "model constants", "table", "build CPU (s)", "model estimate (ratio)", "probe estimate (ratio)"]
    text = "\n".join(["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)] +
                     ["| " + " | ".join(r) + " |" for r in rows])
    print(text)
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    if o.json:
        bench_record.replace_text(o.json, json.dumps(data, indent=1), own=is_own_json)
    if o.record:
        bench_record.write(
            o.record, title="Table build estimates of rollspec plan against the measured builds", argv=sys.argv,
            builds={"current": {"description": "the build measured", "version": bench_record.build_version(o.binary)}},
            settings="studies/seed002-rig-1ms.ini with each texture's settings and each table's case, one thread "
            "(OMP_NUM_THREADS=1): the CPU seconds of the whole `rollspec run` from an empty table directory less those of "
            "the same run with the table cached, median of " + str(o.repeats) + " runs per case; "
            "ratio = estimate / measured.",
            columns=columns, rows=rows,
            notes="Textures: rig = the study's own; rough = rms 0.38 um, Hurst 0.8, roll-off 50 um (the rig's stated "
            "Ra 0.3 um finish); smooth = the same at rms 0.05 um; mid = at rms 0.15 um; flat = rms 0.1 um, Hurst "
            "0.5, roll-off 100 um. The models' constants were fitted on rig, rough and smooth; mid and flat test "
            "them. plan --probe times the equivalent-roughness table's first chunk of solves and fits nothing.",
            data={"runs": data}, other_cores=others)


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


def checked_main():
    try:
        main()
    except bench_record.RecordError as e:  # a write that failed at the end: one line, the old file whole
        sys.exit(f"bench_plan_estimates: {e}")


if __name__ == "__main__":
    script_main(checked_main)  # an interrupt removes the case's temporary directory on the way out
