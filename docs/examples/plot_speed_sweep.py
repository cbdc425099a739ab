"""
A three-speed sweep
===================

One command, one file: the seed 002 rig at 1, 2 and 3 m/s as a sweep of ``ball.speed`` (see the
how-to *Sweeping a study key*). Every point uses the study's seed, so the points share their
sampling noise (common random numbers). Left: the sensor-mean band level of 20 realisations
against the speed, one line per band; right: the three spectra.
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

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
with tempfile.TemporaryDirectory() as scratch:
    result = rp.run(REPO / "studies" / "seed002-rig-1ms.ini", Path(scratch) / "speeds.h5",
                    set={"study.realisations": 20}, sweep={"ball.speed": [1, 2, 3]})
bands = result["bands"]["level_db"].sel(sensor="sensor_mean")  # dims: ball_speed, centre_frequency
speeds = bands["ball_speed"].values
for f in bands["centre_frequency"].values[::3]:
    left.plot(speeds, bands.sel(centre_frequency=f), marker="o", label=f"{f:.0f} Hz")
left.set_xticks(speeds)
left.set_xlabel("ball speed (m/s)")
left.set_ylabel("band level (dB re 1 (m/s²)²)")
left.legend(fontsize=7, title="band")
psd = result["psd"]["mean"].sel(sensor="sensor_mean")
for v in speeds:
    right.semilogy(psd["frequency"], psd.sel(ball_speed=v), lw=0.8, label=f"{v:g} m/s")
    print(f"{v:g} m/s: mean band level", round(float(bands.sel(ball_speed=v).mean()), 2), "dB")
right.set_xlabel("frequency (Hz)")
right.set_ylabel("PSD ((m/s²)²/Hz)")
right.legend(title="speed")
fig.tight_layout()
