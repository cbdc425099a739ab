#!/usr/bin/python3
"""Seed 002's facts (§5) from the calibrated rig studies and from the seed's own route, side by side.

usage: /usr/bin/python3 bench/engine/seed002_routes.py [--bin build/werror/rollspec] [--realisations 100]
                                                      [--record bench/records/validation/seed002-routes.json]

Runs studies/seed002-rig-{1,3}ms.ini (the line roughness calibrated to give the seed's speed trend)
and studies/seed002-rig-{1,3}ms-seed-route.ini (F0 and k0 from the contact solver on a 0.35 m strip, the traverse,
of the rig's Ra 0.3 um finish, nothing tuned) with --realisations each, in a scratch directory (the
seed-route table is built there once and shared by both speeds), and prints, for the sensor mean's
third-octave bands, the facts the seed states beside what each route gives. --record writes the
table as a record that the documentation's seeds page renders (bench/bench_record.py).
"""
import argparse
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "bench"))
import bench_record  # noqa: E402

ROUTES = {"calibrated": "seed002-rig-{v}ms.ini", "seed's route": "seed002-rig-{v}ms-seed-route.ini"}


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def result(binary, study, out, realisations):
    r = subprocess.run([binary, "run", study, "--out", out, "--quiet", "--set", f"study.realisations={realisations}"],
                       capture_output=True, text=True)
    if r.returncode:
        sys.exit(f"seed002_routes: {study.name}: exit {r.returncode}: {r.stderr.strip().splitlines()[-1]}")
    with h5py.File(out) as f:
        names = [text(n) for n in f["/bands/sensor"][:]]
        i = names.index("sensor_mean")
        nominal = f["/bands/nominal_frequency"][:]
        level, lo, hi = (f[f"/bands/{d}"][i] for d in ("level_db", "ci_lower_db", "ci_upper_db"))
        c = f["/contact"].attrs
        return {"level": dict(zip(nominal, level)), "half": dict(zip(nominal, (hi - lo) / 2)),
                "loss": float(f["/contact/loss_of_contact_share"][0]), "k0": float(c["k0"][0]),
                "includes": text(f["/bands"].attrs["interval_includes"])}


# The bounds tests/cli/test_seed002_speed_trend.py holds the calibrated studies to: a fact is met when its
# figure lies within them (the seed's own words are in the table beside them).
BOUNDS = ["+7 … +13 dB", "within ±3 dB", "at least 15 dB at both speeds", "below 1 % at both speeds", "—", "—"]


def verdict(text, met):
    return text if met is None else f"{text}: {'meets' if met else 'misses'}"


def facts(r1, r3):
    low = [f for f in r1["level"] if 100.0 <= f <= 800.0]
    rise = r3["level"][5000.0] - r1["level"][5000.0]
    rise_half = np.hypot(r1["half"][5000.0], r3["half"][5000.0])
    change = np.mean([r3["level"][f] - r1["level"][f] for f in low])
    fall = (r1["level"][800.0] - r1["level"][200.0], r3["level"][800.0] - r3["level"][200.0])
    return [
        verdict(f"{rise:+.1f} dB (intervals ±{r1['half'][5000.0]:.1f} / ±{r3['half'][5000.0]:.1f} dB; "
                f"rise ±{rise_half:.1f} dB if independent)", 7.0 <= rise <= 13.0),
        verdict(f"{change:+.1f} dB", abs(change) <= 3.0),
        verdict(f"{fall[0]:.1f} / {fall[1]:.1f} dB", min(fall) >= 15.0),
        verdict(f"{100 * r1['loss']:.2g} % / {100 * r3['loss']:.2g} %", max(r1["loss"], r3["loss"]) < 0.01),
        f"{r1['k0']:.3g} N/m ({r1['k0'] / 6.8e6:.2f} × the seed's)",
        r1["includes"],
    ]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bin", default=str(ROOT / "build" / "werror" / "rollspec"))
    p.add_argument("--realisations", type=int, default=100)
    p.add_argument("--record", help="write the table as a record (bench/records/validation/*.json)")
    a = p.parse_args()
    bench_record.check_record_target(a.record, code=1)  # 1: this script's exit for a refused target
    binary = str(pathlib.Path(a.bin).resolve())
    if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
        sys.exit(f"seed002_routes: --bin {a.bin}: not an executable file; allowed: a rollspec binary")
    work = pathlib.Path(tempfile.mkdtemp(prefix="seed002-routes-"))
    try:
        columns = {}
        for name, pattern in ROUTES.items():
            runs = []
            for v in (1, 3):
                study = work / pattern.format(v=v)
                shutil.copy(ROOT / "studies" / study.name, study)
                runs.append(result(binary, study, work / f"{study.stem}.h5", a.realisations))
            columns[name] = facts(*runs)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    seed = ["about +10 dB", "no significant change", "falls off rapidly below 800 Hz",
            "contact maintained (the linearisation assumes it)", "6.8e6 N/m (from its contact computation)", "-"]
    rows = [["5 kHz band, 1 → 3 m/s"], ["bands 100–800 Hz, mean change 1 → 3 m/s"],
            ["800 Hz band above the 200 Hz band, 1 / 3 m/s"], ["loss of contact, 1 / 3 m/s"], ["k0"],
            ["the intervals include"]]
    for row, s, bound, cal, own in zip(rows, seed, BOUNDS, columns["calibrated"], columns["seed's route"]):
        row += [s, bound, cal, own]
    header = ["fact (sensor mean, third-octave bands)", "seed 002 states", "met within (the calibration test's bound)",
              "calibrated studies", "seed's route"]
    print("| " + " | ".join(header) + " |\n|" + "---|" * len(header))
    for row in rows:
        print("| " + " | ".join(row) + " |")
    if a.record:
        bench_record.write_measured(
            a.record, binary, title="Seed 002's facts: the calibrated studies and the seed's own route",
            argv=sys.argv,
            settings=f"{a.realisations} realisations per study, each study's own seed; the seed-route table "
                     "built once ([stiffness] table_seed = 1) and shared by both speeds",
            columns=header, rows=rows, components=["engine", "beam", "contact", "integrators", "spectral",
                                                   "texture"])


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
