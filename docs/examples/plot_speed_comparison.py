"""
Two speeds of the same rig
==========================

The seed 002 rig at 1 and 3 m/s (the studies ``seed002-rig-1ms.ini`` and ``seed002-rig-3ms.ini``):
faster rolling moves the roughness's wavelengths to higher frequencies and raises the level, the
trend the seed paper reports. Each curve is the sensor-mean band level of 40 realisations.
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

fig, ax = plt.subplots(figsize=(7, 3.8))
with tempfile.TemporaryDirectory() as scratch:
    for name, speed in (("seed002-rig-1ms.ini", "1 m/s"), ("seed002-rig-3ms.ini", "3 m/s")):
        result = rp.run(REPO / "studies" / name, Path(scratch) / f"{name}.h5", set={"study.realisations": 40})
        bands = result["bands"].sel(sensor="sensor_mean")
        ax.step(bands["centre_frequency"], bands["level_db"], where="mid", label=speed)
        print(speed, "mean band level:", round(float(bands["level_db"].mean()), 2), "dB")
ax.set_xscale("log")
ax.set_xlabel("third-octave band centre frequency (Hz)")
ax.set_ylabel("acceleration level (dB re 1 (m/s²)²)")
ax.legend(title="speed")
fig.tight_layout()
