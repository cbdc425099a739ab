#!/usr/bin/python3
"""The path table's own estimated error (kernels/beam B47: delta_W checked by load-controlled solves between
positions, carried to the bands by contact BF-9c) against the error measured at the answer, in one run: the seed 002
rig's band levels on a 50 mm section under `[contact] law = path`, each table against a reference at half the step.

  /usr/bin/python3 bench/contact/bench_path_check.py [--bin build/werror/rollspec] [--threads 2] \
      [--textures rig,rougher,untested] [--record bench/records/validation/path-check.json]

The runs are bench_path_ladder.py's (the same study, section, one realisation and textures). Per texture: the
default table (first-contact ladder, 8 approaches, cubic in xi, step a/2), the same table read at every other
position (`positions_every = 2`) and at every other row (`rows_every = 2`), no new solve, and the reference: the
cubic rule at half the default step. Each run's /contact/path_table_band_error_db is its estimate; its measured
error is its band levels minus the reference's.
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

DEFAULT = "default (a/2, 8 approaches)"
READS = {DEFAULT: [], "every other position": ["path_table.positions_every=2"],
         "every other row": ["path_table.rows_every=2"]}
TITLE = "The path table's estimated error at the answer (B47) against its measured error"
SETTINGS = ("Whole `rollspec run` commands of studies/seed002-rig-1ms.ini with {common} (a 50 mm section), "
            "OMP_NUM_THREADS={threads}, each texture's tables in an empty table directory. Reference: the cubic "
            "rule at half the default step (a/4), the same strip (strip_length set).")
NOTES = ("Estimate: /contact/path_table_band_error_db; measured: /bands/level_db of the sensor mean minus the "
         "reference's; rms over the third octaves from 315 Hz to 5 kHz, and over 100 Hz - 5 kHz. Below 315 Hz a "
         "50 ms record of one realisation holds one or two bins of the first mode (181 Hz), which move with the "
         "start (B46) rather than with the table's error at the static load. Checks' share: the B47 solves' wall "
         "over the table's.")
TABLE_LINE = re.compile(r"path table: \d+ approaches .*?, (\d+) solves, \d+ CG iterations, ([\d.]+) s wall")
CHECK_LINE = re.compile(r"path table: (\d+) checks \(B47\), \d+ CG iterations, ([\d.e+-]+) s wall")
PLAN_LINE = re.compile(r"step (\d+) cells")


def run_once(binary, settings, threads):
    with bench_record.study_run(binary, STUDY, settings, threads, "bench-path-check-") as (path, stderr, _w, _c):
        table, check, plan = TABLE_LINE.search(stderr), CHECK_LINE.search(stderr), PLAN_LINE.search(stderr)
        with h5py.File(path) as f:
            if "/contact/path_table_band_error_db" not in f and "path_table.step=" not in " ".join(settings):
                fail(f"{binary} run {' '.join(settings)}: no /contact/path_table_band_error_db in its result", 1)
            est = f["/contact/path_table_band_error_db"][:] if "/contact/path_table_band_error_db" in f else None
            return {"step": int(plan.group(1)) if plan else 0,
                    "table_wall": float(table.group(2)) if table else 0.0,
                    "checks": int(check.group(1)) if check else 0,
                    "check_wall": float(check.group(2)) if check else 0.0,
                    "nominal": f["/bands/nominal_frequency"][:], "level": f["/bands/level_db"][-1],
                    "estimate": est}


def rms(x):
    return float(np.sqrt(np.mean(np.square(x))))


def main():
    a, binary, textures = section_arguments(__doc__.split("\n")[0])
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    rows, data = [], {}
    for texture in textures:
        base = COMMON + TEXTURES[texture]
        tables = pathlib.Path(tempfile.mkdtemp(prefix="bench-path-check-tables-"))
        try:  # the default table built once, then read by the thinned runs
            shared = [f"stiffness.table_dir={tables}"]
            runs = {m: run_once(binary, base + shared + keys, a.threads) for m, keys in READS.items()}
            built = runs[DEFAULT]
            if not built["step"] or not built["checks"]:
                fail(f"{binary}: the default table's run printed no plan step or no B47 checks line", 1)
            ref = run_once(binary, base + [f"path_table.step={max(1, built['step'] // 2)}"], a.threads)
        finally:
            shutil.rmtree(tables, ignore_errors=True)
        sel = (ref["nominal"] >= 100) & (ref["nominal"] <= 5000)
        high = ref["nominal"][sel] >= 315
        data[texture] = {"nominal_frequency": ref["nominal"][sel].tolist(), "reference_step": max(1, built["step"] // 2),
                         "step": built["step"], "checks": built["checks"], "check_wall": built["check_wall"],
                         "table_wall": built["table_wall"]}
        for name, run in runs.items():
            measured = run["level"][sel] - ref["level"][sel]
            estimate = run["estimate"][sel]
            data[texture][name] = {"measured_db": measured.tolist(), "estimate_db": estimate.tolist()}
            rows.append([texture, name, f"{rms(estimate[high]):.4f}", f"{rms(measured[high]):.4f}",
                         f"{rms(estimate[high]) / rms(measured[high]):.2f}",
                         f"{rms(estimate) / rms(measured):.2f}",
                         f"{float(np.max(estimate[high])):.3f} / {float(np.max(np.abs(measured[high]))):.3f}",
                         f"{built['check_wall'] / built['table_wall']:.3f}" if name == DEFAULT else "-"])
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    columns = ["texture", "table read", "estimate rms from 315 Hz (dB)", "measured rms from 315 Hz (dB)",
               "estimate over measured", "the same from 100 Hz", "worst band from 315 Hz, estimate / measured (dB)",
               "checks' wall over the table's"]
    print_and_record(a, binary, TITLE, SETTINGS.format(common=", ".join(COMMON), threads=a.threads), NOTES,
                     columns, rows, others, data)


if __name__ == "__main__":
    script_main(main)
