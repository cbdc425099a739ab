#!/usr/bin/python3
"""Contact tables by the answer's method against the exhaustive one (issue 51), in one run: the seed 002
blocked-force table by one loose path checked at every 16th position (contact BF-9, `[blocked_force]
answer_tolerance = 1e-3`) against the exhaustive load search (`answer_tolerance = 0`, the reference path).

  /usr/bin/python3 bench/contact/bench_answer_tables.py [--bin build/werror/rollspec] [--repeats 2] \
      [--threads 2] [--record bench/records/answer-tables.json]

Whole `rollspec run` commands of studies/seed002-rig-1ms.ini (contact.blocked_force = solver, 25
realisations), each from an empty table directory, the two methods interleaved, on three textures: the
rig's, a rougher one (rms x 2) and one no test uses (H = 0.7, roll-off 2 mm, rms 0.15 um). Per texture:
  - speed: the table build's own wall and CPU seconds (its summary line) and the whole command's, medians,
    ratio = exhaustive / answer (above 1: the answer's method is faster);
  - at the answer, from each method's first run: F0's band level as the run draws it (its PSD along the
    path, log-log between bins, over each result band at the ball's speed), k0, the study's band levels
    (/bands/level_db, against their standard error from the run's own interval) and the loss-of-contact
    share, the answer's method minus the exhaustive one;
  - the estimate the result carries (/contact/blocked_force_band_error_db, @blocked_force_k0_error) over
    the measured error: rms over the bands for F0, |error| for k0.
"""
import pathlib
import re
import statistics
import sys
import time

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)

STUDY = ROOT / "studies" / "seed002-rig-1ms.ini"
COMMON = ["contact.blocked_force=solver", "study.realisations=25"]
TEXTURES = {
    "rig": [],
    "rougher (rms x 2)": ["texture.rms=0.246e-6"],
    "untested (H 0.7, 2 mm, 0.15 um)": ["texture.hurst=0.7", "texture.rolloff_wavelength=2e-3", "texture.rms=0.15e-6"],
}
METHODS = {"exhaustive": ["blocked_force.answer_tolerance=0"], "answer": ["blocked_force.answer_tolerance=1e-3"]}
TABLE_LINE = re.compile(r"blocked force: \d+ paths .*?, ([\d.]+) s wall, ([\d.]+) s CPU")

TITLE = (
    "Contact tables by the answer's method against the exhaustive one: the seed 002 blocked-force table")
SETTINGS = (
    'Whole `rollspec run` commands of studies/seed002-rig-1ms.ini with contact.blocked_force = solver and 25 '
    'realisations, OMP_NUM_THREADS={threads}, {repeats} interleaved runs per method and texture from empty table '
    "directories, medians; ratio = exhaustive / answer (above 1: the answer's method is faster). Exhaustive: "
    '[blocked_force] answer_tolerance = 0 (the load search, every position to the full tolerance, the reference '
    'path); answer: answer_tolerance = 1e-3 (contact BF-9: one path at 1e-3, put on the load to first order, every '
    '16th position solved again to the full tolerance).')
NOTES = (
    "Errors are the answer's method minus the exhaustive one, from the first run of each. F0 band: F0's level over "
    'each result band (80 Hz - 6 kHz at 1 m/s) as the run draws it; in brackets the rms of the estimate the result '
    'carries (/contact/blocked_force_band_error_db, BF-9c) over the rms of the measured error. k0: relative, in '
    "brackets the result's estimate (@blocked_force_k0_error, the control variate's standard error, BF-9a). Study "
    "bands: /bands/level_db of every sensor row, in brackets the largest error over the band's standard error (the "
    "run's 95 % interval / 3.92).")


def run_once(binary, settings, threads):
    with bench_record.study_run(binary, STUDY, settings, threads, "bench-answer-tables-") as (path, stderr, wall, cpu):
        m = TABLE_LINE.search(stderr)
        with h5py.File(path) as f:
            c, b = f["/contact"], f["/bands"]
            out = {"wall": wall, "cpu": cpu,
                   "table_wall": float(m.group(1)), "table_cpu": float(m.group(2)),
                   "k0": float(np.ravel(c.attrs["k0"])[0]), "speed": float(np.ravel(f["/ball"].attrs["speed"])[0]),
                   "wavenumber": c["blocked_force_wavenumber"][:], "f0_psd": c["blocked_force_psd"][:],
                   "centre": b["centre_frequency"][:], "level": b["level_db"][:],
                   "se": (b["ci_upper_db"][:] - b["ci_lower_db"][:]) / (2 * 1.96),
                   "loss": float(np.ravel(c["loss_of_contact_share"][:])[0]),
                   "band_error": c["blocked_force_band_error_db"][:] if "blocked_force_band_error_db" in c else None,
                   "k0_error": float(np.ravel(c.attrs["blocked_force_k0_error"])[0])
                   if "blocked_force_k0_error" in c.attrs else float("nan"),
                   "warning": "blocked_force_error_warning" in c.attrs}
        return out


def f0_band_db(run, centre):
    """F0's level over each result band as the run draws it: log-log between the PSD's bins, held at bin 3
    below it (the run scales the texture's shape to bin 3 there, the same for both methods)."""
    k, p = run["wavenumber"], run["f0_psd"]
    out = []
    for c in centre:
        lo, hi = (2 * np.pi * c * 2 ** s / run["speed"] for s in (-1 / 6, 1 / 6))
        kk = np.maximum(np.geomspace(lo, hi, 64), k[3])
        out.append(10 * np.log10(np.mean(np.exp(np.interp(np.log(kk), np.log(k[1:]), np.log(p[1:]))))))
    return np.array(out)


def interleaved(binary, settings, methods, repeats, threads, run_once, quantities):
    """Each method's runs (A B A B ...) of the same settings, and the medians of `quantities` over them."""
    runs = {m: [] for m in methods}
    for _ in range(repeats):
        for method, keys in methods.items():
            runs[method].append(run_once(binary, settings + keys, threads))
    return runs, {m: {q: statistics.median(r[q] for r in runs[m]) for q in quantities} for m in methods}


def study_errors(answer, reference):
    """The study's band levels and loss-of-contact share, answer minus reference: (band differences, relative
    loss difference, the table's cells: worst band (over its standard error), loss, whether the run warned)."""
    bands = answer["level"] - reference["level"]
    worst = np.unravel_index(np.argmax(np.abs(bands)), bands.shape)
    loss = answer["loss"] / reference["loss"] - 1 if reference["loss"] > 0 else 0.0
    return bands, loss, [f"{abs(bands[worst]):.3f} at {reference['centre'][worst[-1]]:.0f} Hz "
                         f"({float(np.max(np.abs(bands) / reference['se'])):.3f})",
                         f"{loss:+.1e}", "yes" if answer["warning"] else "no"]


def print_and_record(a, binary, title, settings, notes, columns, rows, others, data):
    """The answer benches' table on stdout, and in a record (this build, its textures, threads and repeats) where
    --record asks for one."""
    for r in rows:
        print(" | ".join(r))
    if a.record:
        bench_record.write(a.record, title=title, argv=sys.argv,
                           builds={"current": {"description": "this build",
                                               "version": bench_record.build_version(binary)}},
                           settings=settings, columns=columns, rows=rows, other_cores=others,
                           components=["contact", "engine", "spectral"], notes=notes,
                           data={"textures": data, "threads": a.threads, "repeats": a.repeats})
        print(f"wrote {a.record}")


def main():
    parser = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--threads", type=int, default=2)
    a, binary = bench_record.record_script_arguments(parser)
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    rows, data = [], {}
    for texture, extra in TEXTURES.items():
        runs, med = interleaved(binary, COMMON + extra, METHODS, a.repeats, a.threads, run_once,
                                ("wall", "cpu", "table_wall", "table_cpu"))
        ex, an = runs["exhaustive"][0], runs["answer"][0]
        f0 = f0_band_db(an, an["centre"]) - f0_band_db(ex, ex["centre"])
        rms_f0 = float(np.sqrt(np.mean(f0 ** 2)))
        est_f0 = float(np.sqrt(np.mean(an["band_error"] ** 2)))
        k0 = an["k0"] / ex["k0"] - 1
        bands, loss, study_cells = study_errors(an, ex)
        entry = {"median": med, "f0_band_db": f0.tolist(), "f0_band_estimate_db": an["band_error"].tolist(),
                 "k0_relative": k0, "k0_estimate": an["k0_error"], "band_db": bands.tolist(),
                 "band_se_db": ex["se"].tolist(), "loss_relative": loss, "warning": an["warning"],
                 "centre_frequency": ex["centre"].tolist()}
        data[texture] = entry
        rows.append([texture,
                     f"{med['exhaustive']['table_wall']:.1f} / {med['answer']['table_wall']:.1f}",
                     f"{med['exhaustive']['table_wall'] / med['answer']['table_wall']:.2f} / "
                     f"{med['exhaustive']['table_cpu'] / med['answer']['table_cpu']:.2f}",
                     f"{med['exhaustive']['wall'] / med['answer']['wall']:.2f}",
                     f"{np.max(np.abs(f0)):.4f} ({est_f0 / rms_f0:.2f})" if rms_f0 > 0 else "0",
                     f"{k0:+.1e} ({an['k0_error']:.1e})", *study_cells])
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    columns = ["texture", "table wall exhaustive / answer (s)", "ratio wall / CPU (table)", "ratio wall (command)",
               "F0 band max |error| dB (rms estimate / rms error)", "k0 error (estimate)",
               "study bands max |error| dB (max error / s.e.)", "loss of contact, relative", "run warned"]
    print_and_record(a, binary, TITLE, SETTINGS.format(threads=a.threads, repeats=a.repeats), NOTES, columns, rows,
                     others, data)


if __name__ == "__main__":
    script_main(main)
