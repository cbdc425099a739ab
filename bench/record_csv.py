#!/usr/bin/python3
"""Runs a benchmark that prints CSV on stdout (bench_ensemble, bench_texture, bench_contact,
bench_scaling.py, ...) and keeps its first CSV table as a benchmark record (bench/bench_record.py),
which the documentation's benchmarks page renders under this command; stdout is passed through.

  /usr/bin/python3 bench/record_csv.py --record bench/records/NAME.json --title TEXT \
      --describe "the build in words" [--env NAME=VALUE ...] [--notes TEXT] -- COMMAND [ARG ...]

The first line of stdout that has a comma and no '#' opens the table (its headings); the table ends
at the first blank line, comment or line with fewer cells (more: the last cell held a comma). The build described is the
first argument of COMMAND that is an executable rollspec binary or bench program; its `version` line
is kept in the record when it has one (not printed on the page). Cells are kept as printed.
"""
import argparse
import csv
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_record  # noqa: E402
from bench_record import fail, flush_stdout, script_main  # noqa: E402


def first_table(text):
    """The first CSV block of a text: (headings, rows)."""
    lines = text.splitlines()
    start = next((i for i, l in enumerate(lines) if "," in l and not l.lstrip().startswith("#")), None)
    if start is None:
        fail("the command printed no CSV table", 65)
    head = next(csv.reader([lines[start]]))
    rows = []
    for line in lines[start + 1:]:
        if not line.strip() or line.lstrip().startswith("#"):
            break
        row = next(csv.reader([line]))
        if len(row) > len(head):  # an unquoted comma in the last (free-text) cell
            row = row[:len(head) - 1] + [",".join(row[len(head) - 1:])]
        if len(row) != len(head):
            break
        rows.append(row)
    return head, rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--record", required=True)
    ap.add_argument("--title", required=True)
    ap.add_argument("--describe", required=True, help="the build measured, in words")
    ap.add_argument("--env", action="append", default=[], help="NAME=VALUE set for the command (shown on the page)")
    ap.add_argument("--notes", default="")
    ap.add_argument("command", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    command = a.command[1:] if a.command[:1] == ["--"] else a.command
    if not command:
        fail("no command after --", 64)
    try:
        bench_record.check_target(a.record, bench_record.is_record)
    except bench_record.RecordError as e:
        fail(e, 73)
    bad = [e for e in a.env if "=" not in e or not e.split("=", 1)[0]]
    if bad:
        fail(f"--env {bad[0]!r}: allowed: NAME=VALUE", 64)
    env = dict(os.environ, **dict(e.split("=", 1) for e in a.env))
    busy, own = bench_record.busy_seconds(), bench_record.own_cpu()
    child = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    try:
        r = subprocess.run(command, capture_output=True, text=True, errors="replace", env=env)
    except OSError as e:  # no such command, not executable
        fail(f"cannot run {command[0]}: {e.strerror}", 66 if isinstance(e, FileNotFoundError) else 69)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime - child.ru_utime + after.ru_stime - child.ru_stime
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, wall)
    sys.stdout.write(r.stdout)
    if r.returncode != 0:
        last = (r.stderr.strip().splitlines() or [""])[-1]
        fail(f"{' '.join(command)} exited {r.returncode}: {last}", 70)
    head, rows = first_table(r.stdout)
    binary = next((c for c in command if Path(c).name in ("rollspec",) and os.access(c, os.X_OK)), None)
    build = {"description": a.describe}
    if binary:
        build["version"] = bench_record.build_version(binary)
    took = f"whole command took {wall:.0f} s wall, {cpu:.0f} s CPU."
    settings = f"Environment {', '.join(a.env)}; the {took}" if a.env else f"The {took}"
    try:
        bench_record.write(a.record, title=a.title, argv=sys.argv, builds={"measured": build}, settings=settings,
                           columns=[h.replace("_", " ") for h in head], rows=rows,
                           notes=a.notes, other_cores=others)
    except bench_record.RecordError as e:
        fail(e, 73)
    flush_stdout()


if __name__ == "__main__":
    script_main(main)
