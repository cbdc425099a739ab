#!/usr/bin/python3
"""The path table's positions half as many, carried in xi by Keys' six-point cubic convolution (kernels/beam B45b,
`[path_table] interpolation = cubic`, positions a/2 apart), against every position a/4 apart with linear
interpolation (B45, `interpolation = linear`, the exhaustive method before it), in one run, at the answer: the seed
002 rig's band levels on a 50 mm section under `[contact] law = path`, and plan's estimate of each table's build.

  /usr/bin/python3 bench/contact/bench_path_positions.py [--bin build/werror/rollspec] [--threads 2] \
      [--textures rig,rougher,untested] [--record bench/records/validation/path-positions.json]

The runs are bench_path_ladder.py's (the same study, section, one realisation and textures), each from an empty
table directory, both with the first-contact ladder at 8 approaches. A third run reads the reference's own table
with the cubic rule (`path_table.step` = the reference's step): the cubic rule on the same positions, which shows
how much of the difference is B45's own loss (its gain sinc^2) rather than the positions left out.
"""
import pathlib
import re
import shutil
import sys
import tempfile
import time

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "bench" / "contact"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from bench_path_ladder import COMMON, STUDY, TEXTURES, print_and_record, section_arguments  # noqa: E402,E501
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

REFERENCE = "linear, a/4 (reference)"
METHODS = {REFERENCE: ["path_table.interpolation=linear"],
           "cubic, a/2 (default)": ["path_table.interpolation=cubic"]}
SAME_POSITIONS = "cubic on the reference's positions"
TITLE = ("The path table's positions a/2 apart with cubic convolution in xi (B45b) against every position a/4 apart "
         "with linear interpolation (B45), at the answer")
SETTINGS = ("Whole `rollspec run` commands of studies/seed002-rig-1ms.ini with {common} (a 50 mm section), "
            "OMP_NUM_THREADS={threads}, each table from an empty table directory; both tables on the first-contact "
            "ladder at 8 approaches. Plan's estimate: the path table's 'build about ... wall' of the same run.")
NOTES = ("Band levels: /bands/level_db of the sensor mean, third octaves 100 Hz - 5 kHz, minus the reference's. "
         "From 250 Hz the differences are the interpolation's: B45 at a/4 passes the 5 kHz band at sinc^2 "
         "(-0.1 dB in power), so the reference itself is low there, as the cubic rule on its own positions "
         "shows. Below 250 Hz a 50 ms record of one realisation holds one or two bins of the first mode (181 Hz), "
         "and they move by tenths of a dB, more where the ball loses contact, with any change of the positions "
         "or of the rule on the same positions (the start's slope is the chord of the first interval, a/4 or a/2 "
         "long). Loss of contact: the share of samples without contact.")
TABLE_LINE = re.compile(r"path table: (\d+) approaches .*?, (\d+) solves, (\d+) CG iterations, ([\d.]+) s wall")
PLAN_LINE = re.compile(r"step (\d+) cells .*?build about ([\d.e+]+) s CPU, ([\d.e+]+) s wall")


def run_once(binary, settings, threads, cached=False):
    with bench_record.study_run(binary, STUDY, settings, threads, "bench-path-positions-") as (path, stderr, _w, _c):
        m, p = TABLE_LINE.search(stderr), PLAN_LINE.search(stderr)
        if cached and "path table: cached" not in stderr:
            fail(f"{binary} run {' '.join(settings)}: the reference's table was not read from its cache", 1)
        if not cached and (not m or not p):
            fail(f"{binary} run {' '.join(settings)}: no path table plan or summary line in its output", 1)
        with h5py.File(path) as f:
            return {"step": int(p.group(1)) if p else 0, "estimate": float(p.group(3)) if p else 0.0,
                    "solves": int(m.group(2)) if m else 0, "table_wall": float(m.group(4)) if m else 0.0,
                    "nominal": f["/bands/nominal_frequency"][:],
                    "level": f["/bands/level_db"][-1],
                    "loss": float(np.ravel(f["/contact/loss_of_contact_share"][:])[0])}


def main():
    a, binary, textures = section_arguments(__doc__.split("\n")[0])
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    rows, data = [], {}
    for texture in textures:
        base = COMMON + TEXTURES[texture]
        tables = pathlib.Path(tempfile.mkdtemp(prefix="bench-path-positions-tables-"))
        try:  # the reference's table kept for the cubic rule on its positions (read, not built again)
            shared = [f"stiffness.table_dir={tables}"]
            runs = {m: run_once(binary, base + keys + (shared if m == REFERENCE else []), a.threads)
                    for m, keys in METHODS.items()}
            ref = runs[REFERENCE]
            runs[SAME_POSITIONS] = run_once(binary, base + shared + [f"path_table.step={ref['step']}"], a.threads,
                                            cached=True)
        finally:
            shutil.rmtree(tables, ignore_errors=True)
        sel = (ref["nominal"] >= 100) & (ref["nominal"] <= 5000)
        high = ref["nominal"][sel] >= 250
        data[texture] = {"nominal_frequency": ref["nominal"][sel].tolist()}
        for method, run in runs.items():
            diff = run["level"][sel] - ref["level"][sel]
            worst = int(np.argmax(np.abs(diff)))
            data[texture][method] = {k: run[k] for k in ("step", "estimate", "solves", "table_wall", "loss")}
            data[texture][method]["band_db"] = diff.tolist()
            timing = method != SAME_POSITIONS
            rows.append([texture, method, str(run["step"] or ref["step"]), str(run["solves"]) if timing else "-",
                         f"{run['table_wall']:.0f}" if timing else "-",
                         f"{run['table_wall'] / ref['table_wall']:.2f}" if timing else "-",
                         f"{run['estimate'] / run['table_wall']:.2f}" if timing else "-",
                         "-" if method == REFERENCE else f"{abs(diff[worst]):.3f} at {ref['nominal'][sel][worst]:.0f} Hz",
                         "-" if method == REFERENCE else f"{float(np.max(np.abs(diff[high]))):.3f}",
                         "-" if method == REFERENCE else f"{diff[-1]:+.3f}",
                         f"{run['loss']:.4f}"])
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    columns = ["texture", "table", "step (cells)", "solves", "table wall (s)", "over the reference's",
               "plan's estimate over the wall", "band level max |difference| from the reference (dB)",
               "the same from 250 Hz (dB)", "at 5 kHz (dB)", "loss of contact"]
    print_and_record(a, binary, TITLE, SETTINGS.format(common=", ".join(COMMON), threads=a.threads), NOTES,
                     columns, rows, others, data)


if __name__ == "__main__":
    script_main(main)
