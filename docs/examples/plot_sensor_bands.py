"""
Third-octave bands with their intervals
=======================================

The seed 002 rig (a 40 mm ball rolling at 1 m/s over a clamped steel beam) with 40 realisations:
the sensor-mean acceleration level in each third-octave band and its 95 % interval for the
ensemble mean. The interval narrows as the number of realisations grows (as one over its square
root); the study file says how each key was chosen.
"""
import os
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import rollspec_post as rp
from rollspec_post.script_main import one_line_errors

one_line_errors()  # run as python3 FILE: a failure is one line, not a traceback

# The repository: $ROLLSPEC_SOURCE when the site is built, else this file's checkout.
REPO = Path(os.environ.get("ROLLSPEC_SOURCE") or Path(__file__).resolve().parents[2])
study = REPO / "studies" / "seed002-rig-1ms.ini"

with tempfile.TemporaryDirectory() as scratch:
    result = rp.run(study, Path(scratch) / "rig.h5", set={"study.realisations": 40})
    bands = result["bands"].sel(sensor="sensor_mean")
    f = bands["centre_frequency"].values
    fig, ax = plt.subplots(figsize=(7, 3.8))
    ax.fill_between(f, bands["ci_lower_db"], bands["ci_upper_db"], step="mid", alpha=0.3, label="95 % interval")
    ax.step(f, bands["level_db"], where="mid", label="sensor mean, 40 realisations")
    ax.set_xscale("log")
    ax.set_xlabel("third-octave band centre frequency (Hz)")
    ax.set_ylabel("acceleration level (dB re 1 (m/s²)²)")
    ax.legend()
    fig.tight_layout()
    print("widest interval:", float((bands["ci_upper_db"] - bands["ci_lower_db"]).max()), "dB")
