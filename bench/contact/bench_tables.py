#!/usr/bin/python3
"""Contact-solver tables of the seed 002 rig as whole commands: the current build against a
reference build (e.g. the build before a change), interleaved runs, medians, ratios, CG iterations
per position, and the agreement of the table values.

  /usr/bin/python3 bench/contact/bench_tables.py --reference /path/to/old/rollspec \
      [--current build/werror/rollspec] [--repeats 3] [--threads 2] [--kinds blocked_force,filter,path] \
      [--json out.json] [--markdown out.md] [--record bench/records/contact-tables.json \
       --describe-reference TEXT --describe-current TEXT]

Cases (studies/seed002-rig-1ms.ini, 2 realisations, tables built from scratch in a fresh directory
every run):
  blocked_force  contact.blocked_force = solver (the load search over 1024 positions, BF-3)
  blocked_force_answer  the same with [blocked_force] answer_tolerance = 1e-3 (BF-9: one loose path, checked)
  filter         contact.law = hertz, contact.filter = solver (2 strips of 1024 positions, ER-1)
  path           contact.law = path on a short path (ball 20 -> 20.5 mm: 37 positions x 8+ approaches)
Wall seconds by the clock, CPU seconds from the children's rusage; ratio = reference / current
(above 1: the current build is faster). "max rel diff" compares every float column of the two
builds' tables (first run of each), relative to the column's largest magnitude; "repeat bits"
says whether every run of a build wrote the same table bits; "estimate / measured CPU" is the
table's "build about X s CPU" (the same figure `rollspec plan` shows) over the whole command's CPU.
--record writes the table as a benchmark record (bench/bench_record.py) that the documentation's
benchmarks page renders, with this command above it and the two builds described in words.
"""
import argparse
import glob
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

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, str(ROOT / "bench"))
import bench_record  # noqa: E402  (it puts python-post on the path too)
from rollspec_post.script_main import script_main, starts_with  # noqa: E402  (one line per failure, no traceback)
STUDY = ROOT / "studies" / "seed002-rig-1ms.ini"

CASES = {
    "blocked_force": ["contact.blocked_force=solver", "blocked_force.answer_tolerance=0", "study.realisations=2"],
    # the answer's method (contact BF-9): one loose path with its checks
    "blocked_force_answer": ["contact.blocked_force=solver", "blocked_force.answer_tolerance=1e-3",
                             "study.realisations=2"],
    "filter": ["contact.law=hertz", "contact.filter=solver", "study.realisations=2"],
    "path": ["contact.law=path", "ball.end=0.0205", "signal.sample_rate=51200", "spectrum.segment=16",
             "spectrum.band_min=1000", "spectrum.band_max=5000", "study.realisations=1"],
}
GROUPS = {"blocked_force": "/blocked_force", "blocked_force_answer": "/blocked_force", "filter": "/equivalent_roughness", "path": "/path_table"}


def iterations_per_position(kind, stderr):
    """CG iterations per solve (blocked force: + stiffness iterations) from the progress lines."""
    if kind.startswith("blocked_force"):
        m = re.search(r"(\d+) solves, ([\d.]+) \+ ([\d.]+) CG \+ stiffness iterations per solve", stderr)
        return f"{m.group(2)} + {m.group(3)}" if m else "n/a"
    if kind == "filter":
        its = [int(x) for x in re.findall(r"equivalent roughness: strip \d+ of \d+, (\d+) CG iterations", stderr)]
        pos = re.search(r"(\d+) positions per strip", stderr)
        return f"{sum(its) / (len(its) * int(pos.group(1))):.1f}" if its and pos else "n/a"
    m = re.search(r"path table: \d+ approaches .*?, (\d+) solves, (\d+) CG iterations", stderr)
    return f"{int(m.group(2)) / int(m.group(1)):.1f}" if m else "n/a"


def run_once(binary, kind, threads):
    work = pathlib.Path(tempfile.mkdtemp(prefix=f"bench-tables-{kind}-"))
    study = work / "rig.ini"
    shutil.copy(STUDY, study)
    args = [a for kv in CASES[kind] for a in ("--set", kv)]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run([binary, "run", study, "--out", work / "r.h5", *args], capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        sys.exit(f"{binary} {kind} failed ({r.returncode}):\n{r.stderr[-3000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    (table,) = [p for p in glob.glob(str(work / "tables" / "*.h5")) if GROUPS[kind][1:].replace("_", "-") in p]
    columns = {}
    with h5py.File(table) as f:
        g = f[GROUPS[kind]]
        for name, d in g.items():
            # Values only: not the dimension scales (*_index, *_dim0, ...).
            if isinstance(d, h5py.Dataset) and d.dtype.kind == "f" and not re.search(r"_(index|dim\d+)$", name):
                columns[name] = d[...].copy()
        for name, v in g.attrs.items():
            a = np.asarray(v)
            if a.dtype.kind == "f" and name not in ("kernel_version", "schema_version"):
                columns["@" + name] = a.copy()
    shutil.rmtree(work)
    est = re.search(r"build about ([\d.e+]+) s CPU, ([\d.e+]+) s wall", r.stderr)
    return {"wall": wall, "cpu": cpu, "iterations": iterations_per_position(kind, r.stderr), "columns": columns,
            "estimate_cpu": float(est.group(1)) if est else float("nan"),
            "estimate_wall": float(est.group(2)) if est else float("nan")}


def max_rel_diff(a, b):
    """Largest |a - b| / max |b| over the float columns, and that column's name."""
    worst, where = 0.0, "-"
    for name in a:
        if name not in b or a[name].shape != b[name].shape:
            return float("nan"), name
        x, y = a[name], b[name]
        ok = np.isfinite(x) & np.isfinite(y)
        scale = np.max(np.abs(y[ok])) if ok.any() else 0.0
        if scale > 0.0 and float(np.max(np.abs(x[ok] - y[ok])) / scale) > worst:
            worst, where = float(np.max(np.abs(x[ok] - y[ok])) / scale), name
    return worst, where


def same_bits(runs):
    first = runs[0]["columns"]
    return all(r["columns"].keys() == first.keys() and all(r["columns"][k].tobytes() == first[k].tobytes() for k in first)
               for r in runs[1:])


def title(reference):
    """The record's heading: the tables against the reference build, named by its description's first clause."""
    return f"Contact-solver tables of the seed 002 rig against {reference.split(' (')[0].split(',')[0]}"


MARKDOWN_HEAD = b"Seed 002 rig tables, OMP_NUM_THREADS="


def is_own_json(path):
    """A --json file this script wrote (its summary object), which a new run may replace."""
    try:
        with open(path) as f:
            return isinstance(json.load(f), dict)
    except (OSError, ValueError):
        return False


# A --markdown file this script wrote: it starts with the title line its tables open with.
is_own_markdown = starts_with(MARKDOWN_HEAD)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--reference", required=True, help="rollspec binary to compare with (the build before)")
    ap.add_argument("--current", default=str(ROOT / "build" / "werror" / "rollspec"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--kinds", default="blocked_force,filter,path")
    ap.add_argument("--json")
    ap.add_argument("--markdown")
    ap.add_argument("--record", help="write a benchmark record (bench/records/NAME.json) for the documentation")
    ap.add_argument("--describe-reference", default="the reference build", help="the reference build in words")
    ap.add_argument("--describe-current", default="the current build", help="the current build in words")
    o = ap.parse_args()
    # refused before hours of measurement, not after; only files this script wrote are replaced (exit 1, as always)
    bench_record.check_targets([(o.json, is_own_json), (o.markdown, is_own_markdown),
                                (o.record, bench_record.is_record)], code=1)
    kinds = o.kinds.split(",")
    builds = {"reference": o.reference, "current": o.current}
    runs = {k: {b: [] for b in builds} for k in kinds}
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    for rep in range(o.repeats):  # interleaved: every kind and build once per round
        for k in kinds:
            for b, binary in builds.items():
                r = run_once(binary, k, o.threads)
                runs[k][b].append(r)
                print(f"round {rep + 1} {k:13s} {b:9s} {r['wall']:8.2f} s wall {r['cpu']:8.2f} s CPU  "
                      f"iterations/position {r['iterations']}", file=sys.stderr, flush=True)
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    summary = {"reference": o.reference, "current": o.current, "threads": o.threads, "repeats": o.repeats,
               "kinds": {}}
    cells = []
    lines = [f"Seed 002 rig tables, OMP_NUM_THREADS={o.threads}, {o.repeats} interleaved runs per build, medians", "",
             "| table | reference wall / CPU (s) | current wall / CPU (s) | ratio wall / CPU | iterations per position ref / cur | max rel diff | repeat bits ref / cur | estimate / measured CPU (current) |",
             "|---|---|---|---|---|---|---|---|"]
    for k in kinds:
        med = {b: {q: statistics.median(r[q] for r in runs[k][b]) for q in ("wall", "cpu")} for b in builds}
        diff, column = max_rel_diff(runs[k]["current"][0]["columns"], runs[k]["reference"][0]["columns"])
        row = {"median": med, "ratio_wall": med["reference"]["wall"] / med["current"]["wall"],
               "ratio_cpu": med["reference"]["cpu"] / med["current"]["cpu"],
               "iterations": {b: runs[k][b][0]["iterations"] for b in builds}, "max_rel_diff": diff,
               "max_rel_diff_column": column,
               "repeat_bits": {b: same_bits(runs[k][b]) for b in builds},
               "estimate_ratio_cpu": runs[k]["current"][0]["estimate_cpu"] / med["current"]["cpu"],
               "runs": {b: [{q: r[q] for q in ("wall", "cpu", "iterations", "estimate_cpu", "estimate_wall")}
                            for r in runs[k][b]] for b in builds}}
        summary["kinds"][k] = row
        cells.append([k, f"{med['reference']['wall']:.1f} / {med['reference']['cpu']:.1f}",
                      f"{med['current']['wall']:.1f} / {med['current']['cpu']:.1f}",
                      f"{row['ratio_wall']:.2f} / {row['ratio_cpu']:.2f}",
                      f"{row['iterations']['reference']} / {row['iterations']['current']}", f"{diff:.2e} ({column})",
                      f"{row['repeat_bits']['reference']} / {row['repeat_bits']['current']}",
                      f"{runs[k]['current'][0]['estimate_cpu']:.3g} / {med['current']['cpu']:.3g} = "
                      f"{row['estimate_ratio_cpu']:.2f}"])
        lines.append("| " + " | ".join(cells[-1]) + " |")
    text = "\n".join(lines)
    print(text)
    if o.json:
        bench_record.replace_text(o.json, json.dumps(summary, indent=1), own=is_own_json)
    if o.markdown:
        bench_record.replace_text(o.markdown, text + "\n", own=is_own_markdown)
    if o.record:
        bench_record.write(
            o.record, title=title(o.describe_reference),
            argv=sys.argv, settings=f"Whole `rollspec run` commands of studies/seed002-rig-1ms.ini from an empty "
            f"table directory, OMP_NUM_THREADS={o.threads}, {o.repeats} interleaved runs per build, medians; "
            "ratio = reference / current (above 1: the current build is faster).",
            builds={"reference": {"description": o.describe_reference, "version": bench_record.build_version(o.reference)},
                    "current": {"description": o.describe_current, "version": bench_record.build_version(o.current)}},
            columns=["table", "reference wall / CPU (s)", "current wall / CPU (s)", "ratio wall / CPU",
                     "iterations per position ref / cur", "max rel diff", "repeat bits ref / cur",
                     "estimate / measured CPU (current)"],
            rows=cells, notes="Iterations per position: CG iterations per solve (blocked force: + stiffness "
            "iterations). Max rel diff: the largest difference of the two builds' table values, relative to "
            "each column's largest magnitude. Repeat bits: every run of a build wrote the same table bits. "
            "Estimate: the table's \"build about X s CPU\" (what `rollspec plan` shows) over the measured CPU.",
            data=summary, other_cores=others)


def checked_main():
    try:
        main()
    except bench_record.RecordError as e:  # a write that failed at the end (full disk): one line, the old files whole
        sys.exit(f"bench_tables: {e}")


if __name__ == "__main__":
    script_main(checked_main)
