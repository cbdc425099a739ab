#!/usr/bin/python3
"""The path table's approach rows above each position's own first contact (kernels/beam B43b, `[path_table]
ladder = first_contact`) against one set of rows from the mean plane (B43, `ladder = plane`, the method before
it), in one run, at the answer: the seed 002 rig's band levels on a 50 mm section under `[contact] law = path`.

  /usr/bin/python3 bench/contact/bench_path_ladder.py [--bin build/werror/rollspec] [--threads 2] \
      [--textures rig,rougher,untested] [--record bench/records/validation/path-ladder.json]

Whole `rollspec run` commands of studies/seed002-rig-1ms.ini with contact.law = path, the ball from 20 to 70 mm
(a 51.2 mm strip, 3439 positions a/4 apart with the linear rule in xi, B45), one realisation (every realisation rolls over the one strip), Welch segments
of 512, each from an empty table directory, on the textures asked for: the rig's, a rougher one (rms x 2) and
one no test uses (H = 0.7, roll-off 2 mm, rms 0.15 um). Per texture three tables of the same strip: the plane
ladder at 8 approaches (its default before B43b), the first-contact ladder at 8 (the default) and at 16, the
converged reference (its node spacing halved). Per run: the table's wall seconds, solves and CG iterations
(its summary line), and the sensor-mean band levels (/bands/level_db) against the reference's, 100 Hz - 5 kHz,
and the loss-of-contact share.
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
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

STUDY = ROOT / "studies" / "seed002-rig-1ms.ini"
COMMON = ["contact.law=path", "contact.filter=none", "ball.end=0.07", "study.realisations=1",
          "spectrum.segment=512", "path_table.strip_length=0.0512"]
TEXTURES = {
    "rig": [],
    "rougher": ["texture.rms=0.246e-6"],
    "untested": ["texture.hurst=0.7", "texture.rolloff_wavelength=2e-3", "texture.rms=0.15e-6"],
}
# The ladders are compared on B45's positions (a/4, linear in xi), the table they were measured on first;
# bench_path_positions.py measures the positions and the rule in xi.
LADDER_COMMON = COMMON + ["path_table.interpolation=linear"]
METHODS = {"plane, 8": ["path_table.ladder=plane", "path_table.approaches=8"],
           "first contact, 8": ["path_table.ladder=first_contact", "path_table.approaches=8"],
           "first contact, 16 (reference)": ["path_table.ladder=first_contact", "path_table.approaches=16"]}
REFERENCE = "first contact, 16 (reference)"
TITLE = ("The path table's approach rows above each position's first contact (B43b) against one set from the "
         "mean plane (B43), at the answer")
SETTINGS = ("Whole `rollspec run` commands of studies/seed002-rig-1ms.ini with {common} (a 50 mm section: 3439 "
            "positions 14.6 um apart), OMP_NUM_THREADS={threads}, one run per table from an empty table directory. "
            "The reference is the first-contact ladder at 16 approaches (node spacing 3 delta_H / 16); its own error "
            "is not measured here.")
NOTES = ("Band levels: /bands/level_db of the sensor mean, third octaves 100 Hz - 5 kHz, minus the reference's. The "
         "bands below 250 Hz hold the beam's first mode (181 Hz), which a 50 ms record cannot resolve: its level "
         "there is mostly the start's ringing, and moves with the table's slope at the start position (B46).")
TABLE_LINE = re.compile(r"path table: (\d+) approaches .*?, (\d+) solves, (\d+) CG iterations, ([\d.]+) s wall")


def run_once(binary, settings, threads):
    with bench_record.study_run(binary, STUDY, settings, threads, "bench-path-ladder-") as (path, stderr, wall, _):
        m = TABLE_LINE.search(stderr)
        if not m:
            fail(f"{binary} run {' '.join(settings)}: no path table summary line in its output", 1)
        with h5py.File(path) as f:
            b = f["/bands"]
            return {"wall": wall, "rows": int(m.group(1)), "solves": int(m.group(2)),
                    "iterations": int(m.group(3)), "table_wall": float(m.group(4)),
                    "nominal": b["nominal_frequency"][:], "level": b["level_db"][-1],
                    "loss": float(np.ravel(f["/contact/loss_of_contact_share"][:])[0])}


def section_arguments(description):
    """The section benches' command line (--bin, --record, --threads, --textures), checked: (arguments, binary,
    textures)."""
    parser = bench_record.record_script_parser(description, ROOT / "build" / "werror" / "rollspec")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--textures", default="rig,rougher,untested",
                        help=f"comma-separated, of {', '.join(TEXTURES)}")
    a, binary = bench_record.record_script_arguments(parser)
    textures = [t for t in a.textures.split(",") if t]
    for t in textures:
        if t not in TEXTURES:
            fail(f"--textures: {t!r} is not one of {', '.join(TEXTURES)}", 64)
    return a, binary, textures


def print_and_record(a, binary, title, settings, notes, columns, rows, others, data):
    """The section benches' table on stdout, and in a record where --record asks for one."""
    for r in rows:
        print(" | ".join(r))
    if a.record:
        bench_record.write_measured(a.record, binary, title=title, argv=sys.argv, settings=settings, columns=columns,
                                    rows=rows, other_cores=others, components=["contact", "beam", "engine"],
                                    notes=notes, data={"textures": data, "threads": a.threads})
        print(f"wrote {a.record}")


def main():
    a, binary, textures = section_arguments(__doc__.split("\n")[0])
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    rows, data = [], {}
    for texture in textures:
        runs = {m: run_once(binary, LADDER_COMMON + TEXTURES[texture] + keys, a.threads) for m, keys in METHODS.items()}
        ref = runs[REFERENCE]
        sel = (ref["nominal"] >= 100) & (ref["nominal"] <= 5000)
        data[texture] = {"nominal_frequency": ref["nominal"][sel].tolist()}
        for method, run in runs.items():
            diff = run["level"][sel] - ref["level"][sel]
            worst = int(np.argmax(np.abs(diff)))
            data[texture][method] = {"table_wall": run["table_wall"], "solves": run["solves"],
                                     "iterations": run["iterations"], "rows": run["rows"], "loss": run["loss"],
                                     "band_db": diff.tolist()}
            rows.append([texture, method, f"{run['table_wall']:.0f}",
                         f"{run['table_wall'] / runs['plane, 8']['table_wall']:.2f}",
                         f"{run['solves']} ({run['iterations'] / run['solves']:.1f})",
                         "-" if method == REFERENCE else
                         f"{abs(diff[worst]):.3f} at {ref['nominal'][sel][worst]:.0f} Hz",
                         "-" if method == REFERENCE else
                         f"{float(np.max(np.abs(diff[ref['nominal'][sel] >= 250]))):.3f}",
                         f"{run['loss']:.4f}"])
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    columns = ["texture", "table", "table wall (s)", "over the plane's", "solves (CG iterations each)",
               "band level max |difference| from the reference (dB)", "the same from 250 Hz (dB)",
               "loss of contact"]
    print_and_record(a, binary, TITLE, SETTINGS.format(common=", ".join(LADDER_COMMON), threads=a.threads), NOTES,
                     columns, rows, others, data)


if __name__ == "__main__":
    script_main(main)
