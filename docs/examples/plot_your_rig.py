"""
Your own rig, from a template to a fitted roughness
====================================================

The whole path of the tutorial *Your own rig from a template*, run: a study written by
``rollspec init``, edited for a 1 m beam with a 30 mm ball at 2 m/s and three accelerometers,
checked by ``plan``, run; a logger export turned into a PSD by ``rollspec psd``; the two compared
band by band with ``rollspec compare``; and the roughness level that the measurement asks for
estimated with ``rollspec fit``.

The "logger export" here is a stand-in made by rollspec itself (one roll of the same rig with twice
the roughness, another seed and accelerometer noise, written like a logger's file), so the answer is
known: the fit should find an rms near 2e-8 m where the template assumed 1e-8 m.
"""
import json
import re
import subprocess
import tempfile
from pathlib import Path

import h5py
import matplotlib.pyplot as plt
import numpy as np
from rollspec_post.notebook import engine_binary
from rollspec_post.script_main import one_line_errors

one_line_errors()  # run as python3 FILE: a failure is one line, not a traceback

ROLLSPEC = engine_binary()
G = 9.80665  # m/s^2 per g


def rollspec(*args):
    """One rollspec command; its standard output (a failure stops the example with the engine's message)."""
    r = subprocess.run([ROLLSPEC, *map(str, args)], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"rollspec {args[0]} failed ({r.returncode}): {r.stderr.strip()}")
    return r.stdout


def stand_in_logger_file(study, out):
    """One roll of the rig with rms 2e-8 m and seed 77, sensors in g plus white noise of 1e-10
    (m/s^2)^2/Hz, as a ';'-delimited export with decimal commas, a preamble line and a time column."""
    roll = out.with_suffix(".h5")
    rollspec("run", study, "--out", roll, "--quiet", "--set", "study.realisations=1", "--set", "study.seed=77",
             "--set", "texture.rms=2e-8", "--set", "output.time_histories=1")
    with h5py.File(roll, "r") as f:
        t = f["/time_history/time"][()]
        acc = f["/time_history/sensor_acceleration"][0]
    fs = 1.0 / (t[1] - t[0])
    acc = acc + np.random.default_rng(5).standard_normal(acc.shape) * np.sqrt(1e-10 * fs / 2)
    rows = ["logger 4711, exported 2026-11-27", "Time (s);acc_1;acc_2;acc_3"]
    rows += [";".join([f"{ti:.7f}"] + [f"{a / G:.6g}" for a in acc[:, i]]).replace(".", ",") for i, ti in enumerate(t)]
    out.write_text("\n".join(rows) + "\n")


with tempfile.TemporaryDirectory() as scratch:
    work = Path(scratch)
    # 1. A commented study of the scene, then the keys of this rig (SI units).
    study = work / "my-rig.ini"
    rollspec("init", "ball-on-beam", "--out", study)
    text = study.read_text()
    for key, value in [("length", "1.0"), ("radius", "0.015"), ("speed", "2"), ("end", "0.95"),
                       ("rms", "1e-8"), ("positions", "0.25, 0.5, 0.75"), ("realisations", "40")]:
        text = re.sub(rf"^{key} = .*$", f"{key} = {value}", text, count=1, flags=re.M)
    study.write_text(text)

    # 2. Look before running: the stages that will run, and why the others are skipped.
    plan = rollspec("plan", study)
    for line in plan.splitlines():
        if re.match(r"(stage|texture|surface|stiffness_table|blocked_force|dynamics|spectra|reference) ", line):
            print(" ".join(line.split()[:2]))  # the stage and whether it runs; plan says why

    # 3. The ensemble.
    rollspec("run", study, "--out", work / "my-rig.h5", "--quiet")

    # 4. The logger file's Welch PSD, with the model's segment so that the resolutions match.
    logger = work / "logger.csv"
    stand_in_logger_file(study, logger)
    rollspec("psd", logger, "--unit", "g", "--segment", 4096, "--out", work / "measured.csv", "--quiet")

    # 5. Band by band against the prediction interval of a one-roll measurement at x = 0.5 m.
    where = ["--column", "acc_2", "--measured-position", 0.5, "--measured-averages", 1, "--fmin", 100, "--fmax", 5000]
    cmp = json.loads(rollspec("compare", work / "my-rig.h5", work / "measured.csv", *where, "--format", "json"))
    print(f"compare: {cmp['inside']} of {cmp['bands_compared']} bands inside, combined test p = {cmp['p_value']:.2g}")

    # 6. The roughness level the measurement asks for, with its 95 % interval.
    fit = json.loads(rollspec("fit", study, work / "measured.csv", *where, "--vary", "texture.rms=3e-9:1e-7:log",
                              "--format", "json"))
    rms = fit["parameters"]["texture.rms"]
    print(f"fit: texture.rms = {rms['estimate']:.3g} m, 95 % interval {rms['interval'][0]:.3g} .. "
          f"{rms['interval'][1]:.3g} m (the stand-in was made with 2e-8 m)")

bands = cmp["bands"]
f = np.array([b["centre_hz"] for b in bands])
fig, ax = plt.subplots(figsize=(7, 3.8))
ax.fill_between(f, [b["prediction_lower_db"] for b in bands], [b["prediction_upper_db"] for b in bands], step="mid",
                alpha=0.3, label="model: 95 % interval of one roll")
ax.step(f, [b["simulated_db"] for b in bands], where="mid", label="model mean (rms 1e-8 m)")
ax.plot(f, [b["measured_db"] for b in bands], "o", ms=4, label="logger file, sensor at 0.5 m")
ax.set_xscale("log")
ax.set_xlabel("third-octave band centre frequency (Hz)")
ax.set_ylabel("acceleration level (dB re 1 (m/s²)²)")
ax.legend(fontsize=8)
fig.tight_layout()
