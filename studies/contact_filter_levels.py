#!/usr/bin/env python3
"""Band levels of seed 001 beam S and the seed 002 rig under each [contact] filter (README, "Contact filter").

    ROLLSPEC_BIN=build/release/rollspec python3 studies/contact_filter_levels.py [--realisations 25] [--keep DIR]

Runs each study (the profiles chain builds its stiffness table once, about a minute, then reuses
it from studies/tables/) with --set contact.filter=none|patch|iso2d (same seed, same Philox streams: only the
line texture's PSD changes) and prints the sensor-mean third-octave levels from 2 kHz up, the power
sum of those bands and of the 100-1600 Hz bands, the differences between filters, and the rms of
the path PSD the contact sees at and above 2 kHz (from /roughness). Numbers only from the runs it makes.
"""
import argparse
import os
import pathlib
import subprocess
import sys
import tempfile

import h5py
import numpy as np

SOURCE = pathlib.Path(__file__).resolve().parents[1]
BIN = os.environ.get("ROLLSPEC_BIN", str(SOURCE / "build" / "release" / "rollspec"))
STUDIES = (("seed 001 beam S, Hertz law", "seed001-beam-s-hertz.ini"),
           ("seed 001 beam S, the seed's chain (profiles -> stiffness table law)", "seed001-beam-s.ini"),
           ("seed 002 rig 1 m/s", "seed002-rig-1ms.ini"))
FILTERS = ("none", "patch", "iso2d")
F_LOW = 2000.0


def run(study, filt, realisations, out):
    cmd = [BIN, "run", str(SOURCE / "studies" / study), "--out", str(out), "--quiet", "--force",
           "--set", f"contact.filter={filt}", "--set", f"study.realisations={realisations}"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode:
        sys.exit(f"{' '.join(cmd)} failed:\n{r.stderr}")


def levels(path):
    with h5py.File(path) as f:
        nominal = f["/bands/nominal_frequency"][:]
        level = f["/bands/level_db"][-1]  # sensor_mean (or the only sensor)
        sel = nominal >= F_LOW * 0.999  # third octaves from the 2 kHz band up
        k = f["/roughness/wavenumber"][:]
        g = {n: f[f"/roughness/psd_{n if n != 'none' else 'raw'}"][:] for n in FILTERS
             if f"/roughness/psd_{n if n != 'none' else 'raw'}" in f}
        if "none" in g:  # the point contact's line is band-limited too (B40)
            g["none"] = np.where(k <= f["/roughness"].attrs.get("band_limit_wavenumber", np.inf), g["none"], 0.0)
        speed = float(f["/ball"].attrs["speed"])
        loss = float(f["/contact/loss_of_contact_share"][0])
        low = (nominal >= 100) & (nominal <= 1600)
        low_sum = 10 * np.log10(np.sum(10 ** (level[low] / 10)))
    high = k >= 2 * np.pi * F_LOW / speed
    rms = {n: np.sqrt(np.trapz(v[high], k[high])) for n, v in g.items()}
    return nominal[sel], level[sel], 10 * np.log10(np.sum(10 ** (level[sel] / 10))), rms, loss, low_sum


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--realisations", type=int, default=25)
    ap.add_argument("--keep", help="directory for the result files (default: a temporary one)")
    args = ap.parse_args()
    tmp = pathlib.Path(args.keep or tempfile.mkdtemp(prefix="contact-filter-"))
    tmp.mkdir(parents=True, exist_ok=True)
    for title, study in STUDIES:
        res = {}
        for filt in FILTERS:
            out = tmp / f"{pathlib.Path(study).stem}-{filt}.h5"
            run(study, filt, args.realisations, out)
            res[filt] = levels(out)
        bands = res["none"][0]
        print(f"\n{title}: studies/{study}, {args.realisations} realisations, sensor mean, third-octave levels (dB)")
        print("| filter | " + " | ".join(f"{b:g} Hz" for b in bands) +
              " | sum >= 2 kHz | sum 100-1600 Hz | path rms >= 2 kHz | loss of contact |")
        print("|---|" + "---|" * (len(bands) + 4))
        for filt in FILTERS:
            _, lv, tot, rms, loss, low = res[filt]
            print(f"| {filt} | " + " | ".join(f"{v:.1f}" for v in lv) + f" | {tot:.1f} | {low:.1f} | "
                  f"{rms[filt] * 1e9:.3g} nm | {100 * loss:.3g} % |")
        for a, b in (("patch", "none"), ("iso2d", "none"), ("iso2d", "patch")):
            d = res[a][1] - res[b][1]
            print(f"| {a} − {b} | " + " | ".join(f"{v:+.1f}" for v in d) +
                  f" | {res[a][2] - res[b][2]:+.1f} | {res[a][5] - res[b][5]:+.1f} | | |")
    print(f"\nresult files: {tmp}")


if __name__ == "__main__":
    main()
