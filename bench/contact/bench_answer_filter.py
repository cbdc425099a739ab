#!/usr/bin/python3
"""The equivalent-roughness table of `[contact] filter = solver` by the answer's tolerance against every solve
to the full one (issue 51), in one run: `[equivalent_roughness] answer_tolerance = 1e-3` (contact ER-8: each
position's solve stopped at 1e-3, every 16th position solved again to [stiffness] tolerance) against
`answer_tolerance = 0` (the reference path).

  /usr/bin/python3 bench/contact/bench_answer_filter.py [--bin build/werror/rollspec] [--repeats 2] \
      [--threads 2] [--record bench/records/answer-filter.json]

Whole `rollspec run` commands of studies/seed002-rig-1ms.ini (contact.law = hertz, contact.filter = solver,
25 realisations), each from an empty table directory, the two methods interleaved, on the three textures of
bench_answer_tables.py (the rig's, a rougher one and one no test uses). Per texture:
  - speed: the table build's wall seconds (its last strip line) and the whole command's, medians, ratio =
    reference / answer (above 1: the answer's tolerance is faster);
  - at the answer, from each method's first run: the h_eq PSD's level over each result band as the run
    draws its lines from it (/roughness/psd_solver at the ball's speed), the stiffness ratio rho of ER-7, the
    study's band levels (/bands/level_db, against their standard error) and the loss-of-contact share, the
    answer's tolerance minus the reference;
  - the estimate the result carries (/contact/equivalent_roughness_band_error_db) over the measured error,
    rms over the bands.
"""
import pathlib
import re
import sys
import time

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "bench" / "contact"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from bench_answer_tables import STUDY, TEXTURES, interleaved, print_and_record, study_errors  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

COMMON = ["contact.law=hertz", "contact.filter=solver", "study.realisations=25"]
METHODS = {"reference": ["equivalent_roughness.answer_tolerance=0"],
           "answer": ["equivalent_roughness.answer_tolerance=1e-3"]}
TABLE_LINE = re.compile(r"equivalent roughness: strip (\d+) of \1, \d+ CG iterations, ([\d.]+) s wall")

TITLE = (
    "Contact tables by the answer's method against the exhaustive one: the equivalent-roughness table of filter = "
    'solver')
SETTINGS = (
    'Whole `rollspec run` commands of studies/seed002-rig-1ms.ini with contact.law = hertz, contact.filter = solver'
    ' and 25 realisations, OMP_NUM_THREADS={threads}, {repeats} interleaved runs per method and texture from empty '
    "table directories, medians; ratio = reference / answer (above 1: the answer's tolerance is faster). Reference:"
    ' [equivalent_roughness] answer_tolerance = 0 (every solve to [stiffness] tolerance); answer: answer_tolerance '
    '= 1e-3 (contact ER-8: every solve at 1e-3, every 16th position solved again to the full tolerance).')
NOTES = (
    "Errors are the answer's tolerance minus the reference, from the first run of each. h_eq band: the level of the"
    ' PSD the lines are drawn from over each result band (80 Hz - 6 kHz at 1 m/s); in brackets the rms of the '
    "estimate the result carries (/contact/equivalent_roughness_band_error_db, BF-9c on ER-8's residuals) over the "
    "rms of the measured error. rho: ER-7's stiffness ratio, relative. Study bands: /bands/level_db of every sensor"
    " row, in brackets the largest error over the band's standard error (the run's 95 % interval / 3.92).")


def run_once(binary, settings, threads):
    with bench_record.study_run(binary, STUDY, settings, threads, "bench-answer-filter-") as (path, stderr, wall, cpu):
        table = TABLE_LINE.search(stderr)
        if not table:
            fail(f"{binary} run {' '.join(settings)}: no equivalent-roughness table summary line in its output", 1)
        with h5py.File(path) as f:
            c, b, g = f["/contact"], f["/bands"], f["/roughness"]
            return {"wall": wall, "cpu": cpu, "table_wall": float(table.group(2)),
                    # hertz under ER-7: E*' = rho^(3/2) E*, so rho goes as E*'^(2/3)
                    "rho": float(np.ravel(c.attrs["effective_modulus"])[0]) ** (2 / 3),
                    "speed": float(np.ravel(f["/ball"].attrs["speed"])[0]),
                    "wavenumber": g["wavenumber"][:], "psd": g["psd_solver"][:],
                    "centre": b["centre_frequency"][:], "level": b["level_db"][:],
                    "se": (b["ci_upper_db"][:] - b["ci_lower_db"][:]) / (2 * 1.96),
                    "loss": float(np.ravel(c["loss_of_contact_share"][:])[0]),
                    "band_error": c["equivalent_roughness_band_error_db"][:]
                    if "equivalent_roughness_band_error_db" in c else None,
                    "warning": "equivalent_roughness_error_warning" in c.attrs}


def line_band_db(run):
    """The line PSD's level over each result band at the ball's speed, log-log between its points."""
    k, p = run["wavenumber"], run["psd"]
    keep = (k > 0) & (p > 0)
    out = []
    for c in run["centre"]:
        kk = np.geomspace(*(2 * np.pi * c * 2 ** s / run["speed"] for s in (-1 / 6, 1 / 6)), 64)
        out.append(10 * np.log10(np.mean(np.exp(np.interp(np.log(kk), np.log(k[keep]), np.log(p[keep]))))))
    return np.array(out)


def main():
    parser = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--threads", type=int, default=2)
    a, binary = bench_record.record_script_arguments(parser)
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    rows, data = [], {}
    for texture, extra in TEXTURES.items():
        runs, med = interleaved(binary, COMMON + extra, METHODS, a.repeats, a.threads, run_once, ("wall", "table_wall"))
        ref, an = runs["reference"][0], runs["answer"][0]
        line = line_band_db(an) - line_band_db(ref)
        rms_line = float(np.sqrt(np.mean(line ** 2)))
        est = an["band_error"]
        if est is None:
            fail("the answer's run wrote no /contact/equivalent_roughness_band_error_db: its table has no checks", 1)
        rms_est = float(np.sqrt(np.mean(est ** 2)))
        rho = an["rho"] / ref["rho"] - 1  # E* cancels
        bands, loss, study_cells = study_errors(an, ref)
        data[texture] = {"median": med, "line_band_db": line.tolist(), "line_band_estimate_db": est.tolist(),
                         "rho_relative": rho, "band_db": bands.tolist(), "band_se_db": ref["se"].tolist(),
                         "loss": [ref["loss"], an["loss"]], "loss_relative": loss, "warning": an["warning"],
                         "centre_frequency": ref["centre"].tolist()}
        rows.append([texture,
                     f"{med['reference']['table_wall']:.1f} / {med['answer']['table_wall']:.1f}",
                     f"{med['reference']['table_wall'] / med['answer']['table_wall']:.2f}",
                     f"{med['reference']['wall'] / med['answer']['wall']:.2f}",
                     f"{np.max(np.abs(line)):.4f} ({rms_est / rms_line:.2f})" if rms_line > 0 else "0",
                     f"{rho:+.1e}", *study_cells])
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    columns = ["texture", "table wall reference / answer (s)", "ratio wall (table)", "ratio wall (command)",
               "h_eq band max |error| dB (rms estimate / rms error)", "rho error",
               "study bands max |error| dB (max error / s.e.)", "loss of contact, relative", "run warned"]
    print_and_record(a, binary, TITLE, SETTINGS.format(threads=a.threads, repeats=a.repeats), NOTES, columns, rows,
                     others, data)


if __name__ == "__main__":
    script_main(main)
