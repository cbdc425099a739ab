#!/usr/bin/python3
"""Seed 002's rig: the beam's modes and the response's peaks against the resonances the seed measured.

usage: /usr/bin/python3 bench/engine/seed002_modes.py [--bin build/werror/rollspec]
           [--record bench/records/validation/seed002-modes.json]

`rollspec modes studies/seed002-rig-1ms.ini` gives the clamped-clamped beam's modes; the seed's three
resonances (504, 2419, 4465 Hz, its Table 2) are the nearest modes. The study, run as shipped in a
scratch directory, gives the sensor mean's PSD; its peak within 15 % of each resonance is the response
peak (the rolling ball's mass loads the beam). --record writes the table as a record that the
documentation's seeds page renders (bench/bench_record.py). A few seconds.
"""
import pathlib
import subprocess
import sys
import tempfile

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

PUBLISHED = (504.0, 2419.0, 4465.0)  # seed 002's measured resonances (Hz)
STUDY = ROOT / "studies" / "seed002-rig-1ms.ini"
COMPONENTS = ["engine", "beam", "integrators", "spectral", "texture"]


def rollspec(binary, *args, cwd=None):
    r = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    if r.returncode:
        fail(f"rollspec {args[0]}: exit {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}", 70)
    return r.stdout


def modes(binary):
    rows = [line.split() for line in rollspec(binary, "modes", STUDY).splitlines() if line.strip()[:1].isdigit()]
    return np.array([float(r[1]) for r in rows])


def peaks(binary):
    import h5py
    with tempfile.TemporaryDirectory(prefix="seed002-modes-") as tmp:
        out = pathlib.Path(tmp) / "rig.h5"
        rollspec(binary, "run", STUDY, "--out", out, "--quiet", cwd=tmp)
        with h5py.File(out) as f:
            names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["/psd/sensor"][:]]
            freq, psd = f["/psd/frequency"][:], f["/psd/mean"][names.index("sensor_mean")]
            realisations = int(np.ravel(f.attrs["realisations"])[0]) if "realisations" in f.attrs else None
    found = []
    for p in PUBLISHED:
        near = (freq >= 0.85 * p) & (freq <= 1.15 * p)
        found.append(float(freq[near][np.argmax(psd[near])]))
    return found, realisations


def main():
    p = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    a, binary = bench_record.record_script_arguments(p)
    f_modes = modes(binary)
    response, k = peaks(binary)
    rows = []
    for published, peak in zip(PUBLISHED, response):
        i = int(np.argmin(np.abs(f_modes - published)))
        rows.append([f"{published:g} Hz", f"mode {i + 1}: {f_modes[i]:.1f} Hz ({100 * (f_modes[i] / published - 1):+.1f} %)",
                     f"{peak:.0f} Hz ({100 * (peak / published - 1):+.1f} %)"])
        print(" | ".join(rows[-1]), flush=True)
    if a.record:
        bench_record.write_measured(
            a.record, binary, title="Seed 002's rig: modes and response peaks against the measured resonances",
            argv=sys.argv,
            settings=f"`rollspec modes` and one run of studies/seed002-rig-1ms.ini as shipped"
                     + (f" ({k} realisations)" if k else "") + "; a peak is the sensor mean PSD's largest "
                     "bin within 15 % of the resonance",
            columns=["seed 002 measured", "nearest mode of the beam", "response peak (1 m/s)"], rows=rows,
            components=COMPONENTS)


if __name__ == "__main__":
    script_main(main)
