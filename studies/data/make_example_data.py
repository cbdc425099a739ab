"""Makes the stand-in measurement files of studies/data/ from rollspec itself (they are NOT measurements;
README.md here says how they relate to one).

    /usr/bin/python3 studies/data/make_example_data.py [ROLLSPEC]     (default: build/release/rollspec)

25 rolls of studies/seed002-rig-1ms.ini with another seed (7002 instead of 2002), the first roll's time
history kept. From that run:
  example-signal.csv  roll 1, sensors 1, 3, 5 in g plus white accelerometer noise, written like a data logger's
                      export: ';'-delimited, decimal comma, a `Time (s)` column (the sample rate, 25.6 kHz),
                      six significant digits;
  example-signal.wav  the same roll's sensor 3 as 16-bit PCM, full scale = 10 g (`--scale 10 --unit g`);
  measured-psd.csv    frequency_hz,psd: the mean PSD of the 5 sensors over the 25 rolls, (m/s^2)^2/Hz, plus the
                      noise floor of that average (a measurement of 25 rolls for `compare --measured-averages 25`).
The same build gives the same files (the run is bitwise reproducible, the noise has a fixed seed)."""
import io
import os
import pathlib
import subprocess
import sys
import tempfile

import h5py
import numpy as np
import scipy.io.wavfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = ROOT / "studies" / "data"
G = 9.80665                  # m/s^2 per g
NOISE_PSD = 1e-6             # (m/s^2)^2/Hz: white noise of the stand-in accelerometers (~100 ug/sqrt(Hz))
SENSORS = (0, 2, 4)          # sensors 1, 3, 5 in the CSV
WAV_SENSOR = 2               # sensor 3 in the WAV
WAV_FULL_SCALE_G = 10.0


# Each output, and the start of the file this script writes there: it replaces only its own.
OUTPUTS = {"example-signal.csv": b"Time (s);", "example-signal.wav": b"RIFF", "measured-psd.csv": b"frequency_hz,psd"}


def main():
    binary = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "build" / "release" / "rollspec")
    targets = {n: check_output_file(OUT / n, "stand-in", own=starts_with(head)) for n, head in OUTPUTS.items()}
    with tempfile.TemporaryDirectory() as tmp:
        rolls = pathlib.Path(tmp) / "rolls.h5"
        r = subprocess.run([str(binary), "run", str(ROOT / "studies" / "seed002-rig-1ms.ini"), "--out", str(rolls),
                            "--set", "study.seed=7002", "--set", "output.time_histories=1", "--quiet"],
                           stderr=subprocess.PIPE, text=True, errors="replace")
        if r.returncode != 0:
            sys.exit(f"{binary} run exited {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}")
        with h5py.File(rolls, "r") as f:
            t = f["/time_history/time"][()]
            acc = f["/time_history/sensor_acceleration"][0]          # sensor x time, m/s^2
            names = [s.decode() for s in f["/psd/sensor"][()]]
            freq, mean = f["/psd/frequency"][()], f["/psd/mean"][names.index("sensor_mean")]
    fs = 1.0 / (t[1] - t[0])
    rng = np.random.default_rng(17002)
    noisy = acc + rng.standard_normal(acc.shape) * np.sqrt(NOISE_PSD * fs / 2)   # one-sided white PSD NOISE_PSD

    rows = ["Time (s);" + ";".join(f"sensor_{k + 1}" for k in SENSORS)]
    for i, ti in enumerate(t):
        cells = [f"{ti:.7f}"] + [f"{noisy[k, i] / G:.6g}" for k in SENSORS]
        rows.append(";".join(cells).replace(".", ","))
    write_output_file(targets["example-signal.csv"], ("\n".join(rows) + "\n").encode())

    pcm = np.round(noisy[WAV_SENSOR] / G / WAV_FULL_SCALE_G * 32768.0)
    assert np.abs(pcm).max() < 32767, "the signal clips at the chosen full scale"
    wav = io.BytesIO()
    scipy.io.wavfile.write(wav, int(round(fs)), pcm.astype(np.int16))
    write_output_file(targets["example-signal.wav"], wav.getvalue())

    # The 5 sensors' noise is independent: their mean carries a fifth of one sensor's noise PSD.
    psd = mean + NOISE_PSD / 5
    lines = ["frequency_hz,psd"] + [f"{a:.10g},{b:.6g}" for a, b in zip(freq, psd)]
    write_output_file(targets["measured-psd.csv"], ("\n".join(lines) + "\n").encode())


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import check_output_file, starts_with, write_output_file, script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
