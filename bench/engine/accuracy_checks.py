#!/usr/bin/python3
"""The accuracy page's cheap checks through the command, measured and recorded.

usage: /usr/bin/python3 bench/engine/accuracy_checks.py [--bin build/werror/rollspec]
           [--record bench/records/validation/accuracy-checks.json]

  - `rollspec psd` against scipy.signal.welch (Hann, half overlap, density) on a sine plus white noise
    (2^16 samples at 25.6 kHz, segment 4096; numpy's Philox generator, key 5): the largest relative
    difference over the bins;
  - studies/random-oscillator.ini with 200 realisations: the share of bins from 10 to 250 Hz whose 95 %
    interval holds the exact PSD (/reference/psd), and the mean of 10 log10(mean / exact) over them;
  - `rollspec stiffness studies/hertz.ini`: the table's k at the ball's weight against smooth Hertz.

Runs in a scratch directory; --record writes the table as a record that the documentation's accuracy
page renders (bench/bench_record.py). A few seconds.
"""
import pathlib
import re
import subprocess
import sys
import tempfile

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

COMPONENTS = ["engine", "spectral", "contact", "integrators"]


def rollspec(binary, *args, cwd=None):
    r = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    if r.returncode:
        fail(f"rollspec {args[0]}: exit {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}", 70)
    return r.stdout


def welch_against_scipy(binary, work):
    import scipy.signal
    fs, n, segment = 25600.0, 2**16, 4096
    rng = np.random.Generator(np.random.Philox(5))
    t = np.arange(n) / fs
    x = 2.0 * np.sin(2 * np.pi * 1234.5 * t) + 0.5 * rng.standard_normal(n)
    signal = work / "signal.csv"
    signal.write_text("time_s,acc\n" + "\n".join(f"{ti:.17g},{xi:.17g}" for ti, xi in zip(t, x)) + "\n")
    out = work / "psd.csv"
    rollspec(binary, "psd", signal, "--segment", segment, "--out", out, "--quiet", cwd=work)
    ours = np.genfromtxt(out, delimiter=",", names=True)
    _, theirs = scipy.signal.welch(x, fs=fs, window="hann", nperseg=segment, noverlap=segment // 2)
    col = ours.dtype.names[1]
    rel = np.abs(ours[col] - theirs) / np.maximum(np.abs(theirs), np.finfo(float).tiny)
    return [f"`rollspec psd` against `scipy.signal.welch` (sine plus white noise, {n} samples, segment {segment})",
            f"largest relative difference {rel.max():.2g}"]


def oscillator_coverage(binary, work):
    import h5py
    out = work / "oscillator.h5"
    rollspec(binary, "run", ROOT / "studies" / "random-oscillator.ini", "--out", out, "--quiet",
             "--set", "study.realisations=200", cwd=work)
    with h5py.File(out) as f:
        freq = f["/psd/frequency"][:]
        sel = (freq >= 10.0) & (freq <= 250.0)
        lo, hi, mean = (f[f"/psd/{d}"][0, sel] for d in ("ci_lower", "ci_upper", "mean"))
        exact = f["/reference/psd"][0, sel]
    inside = np.mean((lo <= exact) & (exact <= hi))
    return ["random oscillator (`random-oscillator.ini`), 200 realisations: bins 10–250 Hz whose 95 % interval "
            "holds the exact PSD", f"{100 * inside:.1f} % of {sel.sum()} bins; mean 10 log10(mean / exact) "
            f"{np.mean(10 * np.log10(mean / exact)):+.3f} dB"]


def hertz_stiffness(binary, work):
    text = rollspec(binary, "stiffness", ROOT / "studies" / "hertz.ini", "--out", work / "hertz.h5", cwd=work)
    m = re.search(r"k = ([0-9.eE+-]+) N/m \(smooth Hertz: approach [0-9.eE+-]+ m, k = ([0-9.eE+-]+) N/m\)", text)
    if not m:
        fail("rollspec stiffness studies/hertz.ini: no line 'at the ball's weight ... k = ... (smooth Hertz: ...)'", 70)
    k, hertz = float(m.group(1)), float(m.group(2))
    return ["Hertz table through `rollspec stiffness studies/hertz.ini`: k at the ball's weight against smooth Hertz",
            f"{k:.6g} against {hertz:.6g} N/m ({k / hertz - 1:+.1e} relative)"]


def main():
    p = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    a, binary = bench_record.record_script_arguments(p)
    with tempfile.TemporaryDirectory(prefix="accuracy-") as tmp:
        work = pathlib.Path(tmp)
        rows = [welch_against_scipy(binary, work), oscillator_coverage(binary, work), hertz_stiffness(binary, work)]
    for row in rows:
        print(" | ".join(row), flush=True)
    if a.record:
        version = subprocess.run([binary, "version"], capture_output=True, text=True).stdout.strip()
        try:
            bench_record.write(
                a.record, title="Checks through the command", argv=sys.argv,
                builds={"current": {"description": "the build measured", "version": version}},
                settings="each command once, in a scratch directory", columns=["check", "result"], rows=rows,
                components=COMPONENTS)
        except bench_record.RecordError as e:
            fail(e, 73)


if __name__ == "__main__":
    script_main(main)
