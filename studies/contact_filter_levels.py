#!/usr/bin/env python3
"""Band levels of seed 001 beam S and the seed 002 rig under each [contact] filter (README, "Contact filter").

    ROLLSPEC_BIN=build/release/rollspec python3 studies/contact_filter_levels.py [--realisations 25] [--keep DIR]
        [--record bench/records/validation/contact-filter-levels.json]

Runs each study (the profiles chain builds its stiffness table once, about a minute, then reuses
it from studies/tables/; filter = solver builds its equivalent-roughness table once the same way) with
--set contact.filter=none|patch|iso2d|solver (same seed, same Philox streams: only the line texture's PSD
changes) and prints the sensor-mean third-octave levels from 2 kHz up, the power sum of those bands and
of the 100-1600 Hz bands, the differences between filters, and the rms of the path PSD the contact sees
at and above 2 kHz (from /roughness). The seed 002 rig's own law is linearised, which filter = solver
does not serve (it is the point laws' filter), so the rig also runs the Hertz law under patch, iso2d and
solver, and the linearised law with the solver's blocked force (seed 002 §4.2) on the same surface
statistics. Numbers only from the runs it makes. --record writes every row as a record that the
documentation's contact-filter page renders (bench/bench_record.py). About 19 minutes on 2 cores.
"""
import argparse
import os
import pathlib
import sys
import tempfile

import h5py
import numpy as np

SOURCE = pathlib.Path(__file__).resolve().parents[1]
BIN = os.environ.get("ROLLSPEC_BIN", str(SOURCE / "build" / "release" / "rollspec"))
FILTERS = ("none", "patch", "iso2d", "solver")
POINT = tuple((f, f, [f"contact.filter={f}"]) for f in FILTERS)
# (row name, the /roughness curve it used, --set values)
RIG = (tuple((f"linearised, {f}", f, [f"contact.filter={f}"]) for f in FILTERS[:3]) +
       tuple((f"hertz, {f}", f, ["contact.law=hertz", f"contact.filter={f}"]) for f in FILTERS[1:]) +
       (("linearised, blocked_force = solver", None, ["contact.blocked_force=solver"]),))
STUDIES = (("seed 001 beam S, Hertz law", "seed001-beam-s-hertz.ini", POINT,
            (("patch", "none"), ("iso2d", "none"), ("solver", "none"), ("solver", "patch"), ("solver", "iso2d"))),
           ("seed 001 beam S, the seed's chain (profiles -> stiffness table law)", "seed001-beam-s.ini", POINT,
            (("patch", "none"), ("iso2d", "none"), ("solver", "none"), ("solver", "patch"), ("solver", "iso2d"))),
           ("seed 002 rig 1 m/s", "seed002-rig-1ms.ini", RIG,
            (("linearised, iso2d", "linearised, none"), ("hertz, solver", "hertz, patch"),
             ("hertz, solver", "hertz, iso2d"), ("hertz, solver", "linearised, blocked_force = solver"))))
F_LOW = 2000.0


def run(study, sets, realisations, out):
    cmd = [BIN, "run", str(SOURCE / "studies" / study), "--out", str(out), "--quiet", "--force",
           "--set", f"study.realisations={realisations}"] + [a for kv in sets for a in ("--set", kv)]
    run_or_exit(cmd, "{command} failed:\n{stderr}")


def levels(path):
    with h5py.File(path) as f:
        nominal = f["/bands/nominal_frequency"][:]
        level = f["/bands/level_db"][-1]  # sensor_mean (or the only sensor)
        sel = nominal >= F_LOW * 0.999  # third octaves from the 2 kHz band up
        speed = float(f["/ball"].attrs["speed"])
        loss = float(f["/contact/loss_of_contact_share"][0])
        low = (nominal >= 100) & (nominal <= 1600)
        low_sum = 10 * np.log10(np.sum(10 ** (level[low] / 10)))
        rms = {}
        if "/roughness/wavenumber" in f:  # blocked_force = solver resolves the contact itself: no line
            k = f["/roughness/wavenumber"][:]
            g = {n: f[f"/roughness/psd_{n if n != 'none' else 'raw'}"][:] for n in FILTERS
                 if f"/roughness/psd_{n if n != 'none' else 'raw'}" in f}
            if "none" in g:  # the point contact's line is band-limited too (B40)
                g["none"] = np.where(k <= f["/roughness"].attrs.get("band_limit_wavenumber", np.inf), g["none"], 0.0)
            high = k >= 2 * np.pi * F_LOW / speed
            rms = {n: np.sqrt(np.trapz(v[high], k[high])) for n, v in g.items()}
    return nominal[sel], level[sel], 10 * np.log10(np.sum(10 ** (level[sel] / 10))), rms, loss, low_sum


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--realisations", type=int, default=25)
    ap.add_argument("--keep", help="directory for the result files (default: a temporary one)")
    ap.add_argument("--record", help="write the tables as a record (bench/records/validation/*.json)")
    args = ap.parse_args()
    bench_record.check_record_target(args.record)
    rows, columns = [], None
    tmp = pathlib.Path(own_folder(args.keep, "contact_filter_levels") if args.keep else tempfile.mkdtemp(prefix="contact-filter-"))
    tmp.mkdir(parents=True, exist_ok=True)
    for title, study, variants, pairs in STUDIES:
        res = {}
        for name, _, sets in variants:
            out = tmp / f"{pathlib.Path(study).stem}-{name.replace(', ', '-').replace(' ', '_')}.h5"
            run(study, sets, args.realisations, out)
            res[name] = levels(out)
        bands = res[variants[0][0]][0]
        print(f"\n{title}: studies/{study}, {args.realisations} realisations, sensor mean, third-octave levels (dB)")
        print("| law, filter | " + " | ".join(f"{b:g} Hz" for b in bands) +
              " | sum >= 2 kHz | sum 100-1600 Hz | path rms >= 2 kHz | loss of contact |")
        print("|---|" + "---|" * (len(bands) + 4))
        head = ["study", "law, filter"] + [f"{b:g} Hz" for b in bands] + ["sum ≥ 2 kHz", "sum 100–1600 Hz",
                                                                          "path rms ≥ 2 kHz", "loss of contact"]
        if columns not in (None, head):
            fail(f"{study}: its bands from 2 kHz differ from the first study's; the record needs one set", 70)
        columns = head
        for name, curve, _ in variants:
            _, lv, tot, rms, loss, low = res[name]
            path_rms = f"{rms[curve] * 1e9:.3g} nm" if curve in rms else ""
            print(f"| {name} | " + " | ".join(f"{v:.1f}" for v in lv) + f" | {tot:.1f} | {low:.1f} | "
                  f"{path_rms} | {100 * loss:.3g} % |")
            rows.append([f"`{study}`", name] + [f"{v:.1f}" for v in lv] + [f"{tot:.1f}", f"{low:.1f}",
                                                                          path_rms or "—", f"{100 * loss:.3g} %"])
        for a, b in pairs:
            d = res[a][1] - res[b][1]
            print(f"| {a} − {b} | " + " | ".join(f"{v:+.1f}" for v in d) +
                  f" | {res[a][2] - res[b][2]:+.1f} | {res[a][5] - res[b][5]:+.1f} | | |")
            rows.append([f"`{study}`", f"{a} − {b}"] + [f"{v:+.1f}" for v in d] +
                        [f"{res[a][2] - res[b][2]:+.1f}", f"{res[a][5] - res[b][5]:+.1f}", "", ""])
    print(f"\nresult files: {tmp}")
    if args.record:
        bench_record.write_measured(
            args.record, BIN, title="Band levels under each contact filter (sensor mean, dB re 1 (m/s²)²/Hz)",
            argv=sys.argv,
            settings=f"{args.realisations} realisations per run, each study's own seed (paired: the same "
                     "Philox streams under every filter)", columns=columns, rows=rows,
            components=["engine", "beam", "contact", "integrators", "spectral", "texture"])


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../bench"))
import bench_record  # noqa: E402  (the records the documentation renders; it puts python-post on the path)
from rollspec_post.script_main import fail, own_folder, run_or_exit, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
