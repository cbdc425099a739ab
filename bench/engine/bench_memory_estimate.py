#!/usr/bin/python3
"""Does `rollspec plan`'s memory estimate hold? For a sample of studies, each scaled down so that one
term of the estimate dominates (and the run takes seconds), runs `plan`, then the real `run`, and
measures the run's peak resident memory (ru_maxrss of that child alone, from wait4). Prints a
Markdown table estimate / measured / ratio; the requirement is 0.5 <= ratio <= 2 in every row.

  /usr/bin/python3 bench/engine/bench_memory_estimate.py [--bin build/werror/rollspec] [--threads 2]
      [--only NAME ...]

Exit status 1 when a row is outside the factor 2.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
STUDIES = SOURCE / "studies"

# name, study, --set overrides, the term it exercises.
CASES = [
    ("default", "random-oscillator.ini", ["study.realisations=8"], "a shipped study as it is (fewer realisations)"),
    ("chunk 256", "random-oscillator.ini",
     ["study.realisations=512", "ensemble.chunk_size=256", "spectrum.segment=65536", "signal.duration=64"],
     "one chunk of rows: chunk_size x values"),
    ("2048 chunks of 1", "random-oscillator.ini",
     ["study.realisations=2048", "ensemble.chunk_size=1", "spectrum.segment=32768", "signal.duration=16"],
     "chunk sums: flat in the number of chunks"),
    ("48 sensors + reference", "seed002-rig-3ms.ini",
     ["study.realisations=2", "sensors.positions=" + ",".join(f"{0.02 + 0.0065 * i:.4f}" for i in range(48))],
     "linearised reference, sensors^2"),
    ("path, 64 approaches", "seed002-rig-1ms.ini",
     ["contact.law=path", "path_table.approaches=64", "texture.rms=1e-20", "surface.spacing=12e-6",
      "texture.short_wavelength=24e-6", "ball.start=0.1", "ball.end=0.19", "spectrum.segment=128",
      "spectrum.band_min=400", "spectrum.band_max=5000", "study.realisations=1"],
     "path table: approaches x positions"),
    ("rolling-beam dt 2e-6", "seed000-puck.ini", ["analysis.dt=2e-6", "analysis.t_end=1", "analysis.record_every=1"],
     "rolling-beam time history (records)"),
    ("rolling-beam 20000 elements", "seed000-cantilever.ini", ["beam.elements=20000", "analysis.t_end=0.01"],
     "rolling-beam elements: model, band system, history"),
]

UNITS = {"B": 1, "KiB": 1 << 10, "MiB": 1 << 20, "GiB": 1 << 30, "TiB": 1 << 40}


def estimate(binary, study, sets, env):
    r = subprocess.run([binary, "plan", study, *[a for s in sets for a in ("--set", s)]], capture_output=True, text=True,
                       env=env)
    m = re.search(r"memory: estimated peak ([0-9.e+]+) (\w+)", r.stdout)
    if r.returncode != 0 or not m:
        sys.exit(f"plan failed for {study} {sets}:\n{r.stdout}\n{r.stderr}")
    return float(m.group(1)) * UNITS[m.group(2)]


def measured(binary, study, sets, env, out):
    """Peak RSS (bytes) and wall seconds of `rollspec run`, this child alone."""
    start = time.monotonic()
    p = subprocess.Popen([binary, "run", study, "--out", out, "--quiet", *[a for s in sets for a in ("--set", s)]],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    err = p.stderr.read().decode()
    if p.returncode != 0:
        sys.exit(f"run failed ({p.returncode}) for {study} {sets}:\n{err}")
    return usage.ru_maxrss * 1024.0, time.monotonic() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=str(SOURCE / "build" / "werror" / "rollspec"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", nargs="*", help="run only the cases whose name starts with one of these")
    args = ap.parse_args()
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    print(f"| case | term | estimate MiB | measured MiB | ratio | run s |")
    print(f"|---|---|---:|---:|---:|---:|")
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, study, sets, term in CASES:
            if args.only and not any(name.startswith(o) for o in args.only):
                continue
            # A copy, so the stage tables a study builds land in the temporary directory.
            copy = Path(tmp) / study
            shutil.copy(STUDIES / study, copy)
            for d in ("data",):
                if (STUDIES / d).exists() and not (Path(tmp) / d).exists():
                    os.symlink(STUDIES / d, Path(tmp) / d)
            est = estimate(args.bin, str(copy), sets, env)
            rss, wall = measured(args.bin, str(copy), sets, env, str(Path(tmp) / "r.h5"))
            ratio = est / rss
            ok = 0.5 <= ratio <= 2.0
            bad += not ok
            print(f"| {name} | {term} | {est / 2**20:.1f} | {rss / 2**20:.1f} | {ratio:.2f}{'' if ok else ' (outside 2x)'} "
                  f"| {wall:.1f} |", flush=True)
            (Path(tmp) / "r.h5").unlink(missing_ok=True)
    return 1 if bad else 0


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
