"""Makes the stand-in "measured" profiles of seed 001's beams S and R (they are NOT measurements; README.md
here says how they relate to the unavailable ones).

    /usr/bin/python3 studies/data/make_seed001_profiles.py [ROLLSPEC]     (default: build/release/rollspec)

Seed 001 (§3.1) measured 15 profiles of 15 mm per beam. Here each beam's 15 profiles are Gaussian line
textures drawn by `rollspec texture` from a stated self-affine PSD, 15 mm long (7501 samples) at a 2 um
stylus spacing (1 um would make ~8 MB of CSV; 2 um keeps all 30 files near 4 MB and still resolves the
4 um short-wavelength cut-off):
  beam S (ground, Ra 0.29 um): H = 0.8, roll-off 50 um, cut-off 4 um, rms = Ra sqrt(pi/2) = 0.363 um
  beam R (milled, Ra 2.25 um): H = 0.8, roll-off 100 um, cut-off 4 um, rms = Ra sqrt(pi/2) = 2.820 um
Written as seed001-profiles/beam-{s,r}-NN.csv with the columns position_m,height_um (heights to 5
significant digits, as a stylus instrument exports them). The same build gives the same files.
"""
import os
import math
import pathlib
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = ROOT / "studies" / "data" / "seed001-profiles"
SPACING = 2e-6          # m, stylus spacing
LENGTH = 15e-3          # m per profile
COUNT = 15              # profiles per beam
BEAMS = {               # name: (Ra m, roll-off wavelength m, seed)
    "s": (0.29e-6, 50e-6, 11001),
    "r": (2.25e-6, 100e-6, 11002),
}

STUDY = """[study]
scene = texture
realisations = 1
seed = {seed}
description = stand-in profiles of seed 001 beam {name}
[texture]
source = self-affine
hurst = 0.8
rolloff_wavelength = {rolloff!r}
short_wavelength = 4e-6
rms_kind = height
rms = {rms!r}
amplitudes = rayleigh
[lines]
count = {count}
length = {length!r}
spacing = {spacing!r}
"""


def main():
    binary = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "build" / "release" / "rollspec")
    OUT.mkdir(exist_ok=True)
    # Every profile checked before the first texture runs: only this script's own files are replaced.
    targets = {(name, i): check_output_file(OUT / f"beam-{name}-{i + 1:02d}.csv", "profile",
                                            own=starts_with(b"position_m,height_um"))
               for name in BEAMS for i in range(COUNT)}
    samples = int(round(LENGTH / SPACING)) + 1
    with tempfile.TemporaryDirectory() as tmp:
        for name, (ra, rolloff, seed) in BEAMS.items():
            rms = ra * math.sqrt(math.pi / 2)  # Gaussian heights: Ra = rms sqrt(2 / pi)
            ini = pathlib.Path(tmp) / f"beam-{name}.ini"
            # floor(length / spacing) = samples: positions 0 .. 15 mm.
            ini.write_text(STUDY.format(seed=seed, name=name.upper(), rolloff=rolloff, rms=rms, count=COUNT,
                                        length=(samples + 0.5) * SPACING, spacing=SPACING))
            out = pathlib.Path(tmp) / f"beam-{name}.h5"
            r = subprocess.run([str(binary), "texture", str(ini), "--out", str(out), "--quiet"], stderr=subprocess.PIPE,
                               text=True, errors="replace")
            if r.returncode != 0:
                sys.exit(f"{binary} texture exited {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}")
            with h5py.File(out, "r") as f:
                x, lines = f["/texture/x"][()], f["/texture/lines"][()]
            assert lines.shape == (COUNT, samples), lines.shape
            ras = []
            for i, z in enumerate(lines):
                rows = ["position_m,height_um"] + [f"{a:.6f},{b * 1e6:.5g}" for a, b in zip(x, z)]
                write_output_file(targets[(name, i)], ("\n".join(rows) + "\n").encode())
                ras.append(np.mean(np.abs(z - z.mean())))
            print(f"beam {name.upper()}: {COUNT} profiles of {samples} samples, Ra {np.mean(ras) * 1e6:.3f} um "
                  f"(target {ra * 1e6:.2f}, profiles {min(ras) * 1e6:.3f}-{max(ras) * 1e6:.3f})")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import check_output_file, starts_with, write_output_file, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
