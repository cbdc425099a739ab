#!/usr/bin/python3
"""The rolling pipe as a user runs it (issue 18 goal 4): whole `rollspec run studies/rolling-pipe.ini`
commands of this build and of a previous one, interleaved, CPU and wall time from /usr/bin/time,
on 1 thread, medians over the repeats. Prints a Markdown table for the README and the ratios.

  /usr/bin/python3 bench/rolling/bench_rolling_pipe.py --baseline PREVIOUS/rollspec
      [--bin build/release/rollspec] [--study studies/rolling-pipe.ini] [--realisations 2] [--repeats 3]

Per realisation: CPU time of the whole command over K (set-up, surfaces, spectra and the file
included). Per Newton iteration: each build also runs the study over half the rolling distance;
the difference of the two CPU times over the difference of their Newton iteration counts (from
/contact/newton_per_step, steps = distance / speed / dt) leaves out what does not scale with the
steps (set-up, surfaces, validity check, file). Also prints how far this build's results lie from
the previous build's (PSD means and band levels).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np


def timed(cmd):
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with tempfile.NamedTemporaryFile("r", suffix=".time") as t:
        r = subprocess.run(["/usr/bin/time", "-f", "%e %U %S", "-o", t.name, *map(str, cmd)], capture_output=True,
                           text=True, env=env)
        if r.returncode != 0:
            sys.exit(f"failed: {' '.join(map(str, cmd))}\n{r.stderr}")
        wall, user, system = t.read().split()[-3:]
    return float(wall), float(user) + float(system)


def iterations(path, K):
    with h5py.File(path) as f:
        a = {k: float(v[0]) for k, v in f["/roll"].attrs.items()}
        steps = round(a["distance"] / a["speed"] / a["dt"])
        return float(f["/contact/newton_per_step"][0]) * steps * K


def measure(binary, baseline, study, K, repeats):
    """Medians per (build, length), per-iteration µs per build, iteration counts, result differences."""
    with open(study) as f:
        distance = next(float(l.split("=")[1]) for l in f if l.replace(" ", "").startswith("distance="))
    builds = {"this": binary, "previous": baseline}
    lengths = {"full": distance, "half": distance / 2}
    with tempfile.TemporaryDirectory() as tmp:
        runs, its = {}, {}
        for _ in range(repeats):
            for b, exe in builds.items():
                for l, d in lengths.items():
                    out = Path(tmp) / f"{b}-{l}.h5"
                    cmd = [exe, "run", study, "--out", out, "--force", "--quiet", "--set", f"study.realisations={K}",
                           "--set", f"roll.distance={d}"]
                    runs.setdefault((b, l), []).append(timed(cmd))
                    its[(b, l)] = iterations(out, K)
        with h5py.File(Path(tmp) / "this-full.h5") as f, h5py.File(Path(tmp) / "previous-full.h5") as g:
            psd, psd0 = f["/psd/mean"][:], g["/psd/mean"][:]
            band, band0 = f["/bands/level_db"][:], g["/bands/level_db"][:]
    med = {k: (statistics.median(r[0] for r in v), statistics.median(r[1] for r in v)) for k, v in runs.items()}
    per_it = {b: 1e6 * (med[(b, "full")][1] - med[(b, "half")][1]) / (its[(b, "full")] - its[(b, "half")]) for b in builds}
    rel = float(np.abs(psd[:, 1:] - psd0[:, 1:]).max() / np.abs(psd0[:, 1:]).max())
    return med, per_it, its, rel, float(np.abs(band - band0).max())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/release/rollspec")
    ap.add_argument("--baseline", required=True, help="previous build's rollspec")
    ap.add_argument("--study", default="studies/rolling-pipe.ini")
    ap.add_argument("--realisations", type=int, default=2)
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    K = a.realisations
    builds = ("this", "previous")
    med, per_it, its, rel, dband = measure(a.bin, a.baseline, a.study, K, a.repeats)
    print(f"whole `rollspec run {a.study}`, {K} realisations, 1 thread, median of {a.repeats} interleaved runs "
          f"(/usr/bin/time)\n")
    print("| build | wall | CPU | CPU per realisation | Newton iterations per realisation | per Newton iteration |")
    print("|---|---|---|---|---|---|")
    for b in builds:
        w, c = med[(b, "full")]
        print(f"| {b} | {w:.2f} s | {c:.2f} s | {c / K:.3f} s | {its[(b, 'full')] / K:.0f} | {per_it[b]:.1f} µs |")
    tw, tc = med[("this", "full")]
    pw, pc = med[("previous", "full")]
    print(f"\nthis / previous: whole command wall {tw / pw:.3f}, CPU {tc / pc:.3f} (speed-up {pc / tc:.2f}); "
          f"per Newton iteration {per_it['this'] / per_it['previous']:.3f} (speed-up {per_it['previous'] / per_it['this']:.2f})")
    print(f"results: PSD means differ by at most {rel:.2e} of their largest value; band levels by at most "
          f"{dband:.2e} dB")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
