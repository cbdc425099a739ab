"""
Your own rig, from a template to a fitted roughness
====================================================

The whole path of the tutorial *Your own rig from a template*, run: a study written by
``rollspec init``, edited for a 1 m beam with a 30 mm ball at 2 m/s and three accelerometers,
checked by ``plan``, run; the logger's exports of five rolls and of the rig at rest given straight
to ``rollspec compare`` and to the report; and the roughness level that the measurement asks for
estimated with ``rollspec fit``.

The "logger exports" here are stand-ins made by rollspec itself (five rolls of the same rig with twice
the roughness, another seed and accelerometer noise, written like a logger's files), so the answer is
known: the model is 6 dB low, and the fit should find an rms near 2e-8 m where the template assumed
1e-8 m.
"""
import io
import json
import re
import subprocess
import tempfile
from pathlib import Path

import h5py
import matplotlib.pyplot as plt
import numpy as np
from rollspec_post.engine_compare import engine_binary
from rollspec_post.psd_plot import plot_psd
from rollspec_post.script_main import one_line_errors

one_line_errors()  # run as python3 FILE: a failure is one line, not a traceback

ROLLSPEC = engine_binary()
G = 9.80665  # m/s^2 per g
NOISE = 1e-8  # the accelerometer's white noise, (m/s^2)^2/Hz


def rollspec(*args):
    """One rollspec command; its standard output (a failure stops the example with the engine's message)."""
    r = subprocess.run([ROLLSPEC, *map(str, args)], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"rollspec {args[0]} failed ({r.returncode}): {r.stderr.strip()}")
    return r.stdout


def logger_file(path, t, channels):
    """A ';'-delimited export with decimal commas, a preamble line, a time column and the unit in each name."""
    names = ";".join(f"acc_{i + 1} (g)" for i in range(channels.shape[1]))  # channels: time x sensor
    rows = [";".join([f"{ti:.7f}"] + [f"{a / G:.6g}" for a in channels[i]]).replace(".", ",")
            for i, ti in enumerate(t)]
    path.write_text("\n".join(["logger 4711, exported 2026-11-27", f"Time (s);{names}", *rows]) + "\n")


def stand_in_logger_files(study, work, rolls=5):
    """Rolls of the rig with rms 2e-8 m and seed 77, each with white noise, one file per roll; and the
    rig at rest (noise alone, as long as four rolls)."""
    roll = work / "stand-in.h5"
    rollspec("run", study, "--out", roll, "--quiet", "--set", f"study.realisations={rolls}", "--set", "study.seed=77",
             "--set", "texture.rms=2e-8", "--set", f"output.time_histories={rolls}")
    with h5py.File(roll, "r") as f:
        t = f["/time_history/time"][()]
        acc = f["/time_history/sensor_acceleration"][()]  # roll x sensor x time
    fs = 1.0 / (t[1] - t[0])
    noise = np.random.default_rng(5)
    for k in range(rolls):
        logger_file(work / f"roll-{k + 1}.csv", t, acc[k].T + noise.standard_normal(acc[k].T.shape) * np.sqrt(NOISE * fs / 2))
    quiet_t = np.arange(4 * t.size) / fs
    logger_file(work / "quiet.csv", quiet_t, noise.standard_normal((quiet_t.size, acc.shape[1])) * np.sqrt(NOISE * fs / 2))


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
    result = work / "my-rig.h5"
    rollspec("run", study, "--out", result, "--quiet")

    # 4.-5. The logger's files straight into compare: one file per roll, its three channels the three
    # sensors (compared as their mean, sensor_mean), the unit from each column's name, the rig at rest
    # for the noise floor. M = 5 rolls comes from the files.
    stand_in_logger_files(study, work)
    rolls = sorted(work.glob("roll-*.csv"))
    cmp = json.loads(rollspec("compare", result, *rolls, "--noise", work / "quiet.csv", "--format", "json"))
    o, t = cmp["level_offset"], cmp["combined_test"]
    left_out = [b for b in cmp["bands"] if b["use"] != "test"]
    print(f"compare: {cmp['measured_averages_source']}; {len(left_out)} bands left out ({left_out[0]['use']}, "
          f"{left_out[0]['centre_hz']:g} to {left_out[-1]['centre_hz']:g} Hz)")
    print(f"compare: level offset {o['estimate_db']:+.2f} dB ({o['lower_db']:+.2f} .. {o['upper_db']:+.2f}) over "
          f"{o['bands']} bands; combined test {'rejects' if t['rejected'] else 'keeps'} the model, p = {cmp['p_value']:.2g}")

    # The picture the report embeds: the spectra as compare saw them, and the bands it tested.
    buffer = io.BytesIO()
    plot_psd(result, buffer, rolls, True, answer=cmp, xscale="log")
    report_picture = plt.imread(io.BytesIO(buffer.getvalue()), format="png")

    # 6. The roughness level the measurement asks for, with its 95 % interval: fit takes a PSD table, here
    # the Welch PSD of one roll's middle sensor with the model's segment, judged as one roll at x = 0.5 m.
    rollspec("psd", rolls[0], "--column", "acc_2 (g)", "--segment", 4096, "--out", work / "measured.csv", "--quiet")
    where = ["--column", "acc_2", "--measured-position", 0.5, "--measured-averages", 1, "--fmin", 400, "--fmax", 5000]
    fit = json.loads(rollspec("fit", study, work / "measured.csv", *where, "--vary", "texture.rms=3e-9:1e-7:log",
                              "--format", "json"))
    rms = fit["parameters"]["texture.rms"]
    print(f"fit: texture.rms = {rms['estimate']:.3g} m, 95 % interval {rms['interval'][0]:.3g} .. "
          f"{rms['interval'][1]:.3g} m (the stand-in was made with 2e-8 m)")

# Figure 1: compare's answer band by band: the model's prediction interval for a mean of five rolls, the
# measured band levels, tested (filled) or left out as the logger's noise floor (open).
bands = cmp["bands"]
f = np.array([b["centre_hz"] for b in bands])
tested = np.array([b["use"] == "test" for b in bands])
measured = np.array([b["measured_db"] for b in bands])
fig, ax = plt.subplots(figsize=(7, 3.8))
ax.fill_between(f, [b["prediction_lower_db"] for b in bands], [b["prediction_upper_db"] for b in bands], step="mid",
                alpha=0.3, label="model: 95 % interval of a mean of 5 rolls")
ax.step(f, [b["simulated_db"] for b in bands], where="mid", label="model mean (rms 1e-8 m)")
ax.plot(f[tested], measured[tested], "o", ms=4, color="k", label="logger files, tested")
ax.plot(f[~tested], measured[~tested], "o", ms=4, mfc="none", color="0.45", label="left out: noise floor")
ax.step(f, [b["noise_db"] for b in bands], where="mid", color="0.45", ls=":", lw=1, label="rig at rest")
ax.set_xscale("log")
ax.set_xlabel("third-octave band centre frequency (Hz)")
ax.set_ylabel("acceleration level (dB re 1 (m/s²)²)")
ax.set_title(f"level offset {o['estimate_db']:+.1f} dB over the {o['bands']} tested bands", fontsize=10)
ax.legend(fontsize=7)
fig.tight_layout()

# Figure 2: the report's own picture of the same comparison.
fig2, ax2 = plt.subplots(figsize=(7.5, 6.6))
ax2.imshow(report_picture)
ax2.set_axis_off()
fig2.tight_layout()
