#!/usr/bin/python3
"""filter = solver against its reference, the path law, on the same strip over the seed 002 rig's whole traverse
(issue 19's comparison, issue 51's whole-traverse reference), in one run: the band levels of the point law on h_eq
of that strip (`[equivalent_roughness] line = strip`, with ER-7's stiffness and without) against `law = path`.

  /usr/bin/python3 bench/contact/bench_filter_against_path.py [--bin build/werror/rollspec] [--threads 2] \
      [--record bench/records/validation/filter-against-path.json]

Whole `rollspec run` commands of studies/seed002-rig-1ms.ini, the ball over its whole traverse (20 -> 370 mm),
one realisation (each model is deterministic on the strip), the derived strip cell (2.91 um) and a strip of
0.352 m for both tables so that they draw the same strip (a strip's draw follows its length in cells). Models:
  - path law: `[contact] law = path` (kernels/beam B41-B46, its defaults: positions about a/2 apart, cubic in xi,
    8 approaches above each position's first contact);
  - point law on h_eq, ER-7: `law = hertz, filter = solver, [equivalent_roughness] line = strip` (h_eq of strip
    0 at the linear rule's positions, a/4 apart, kernels/contact ER-1, ER-2, the Hertz law stretched by rho);
  - point law on h_eq alone: the same with `[equivalent_roughness] stiffness = law`.
The two point-law runs share one equivalent-roughness table (a table directory of the bench's own). Per model:
its table's wall seconds, the loss-of-contact share, and the third-octave band levels (/bands/level_db, every
sensor and the sensor mean, 100 Hz - 5 kHz) minus the path law's.
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
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

STUDY = ROOT / "studies" / "seed002-rig-1ms.ini"
COMMON = ["study.realisations=1", "path_table.strip_length=0.352"]
POINT = ["contact.law=hertz", "contact.filter=solver", "equivalent_roughness.line=strip"]
MODELS = {"path law (reference)": ["contact.law=path", "contact.filter=none"],
          "point law on h_eq, ER-7 stiffness": POINT,
          "point law on h_eq alone": POINT + ["equivalent_roughness.stiffness=law"]}
REFERENCE = "path law (reference)"
TABLE_LINES = (re.compile(r"path table: \d+ approaches .*?, ([\d.]+) s wall"),
               re.compile(r"equivalent roughness: strip 0, \d+ CG iterations, ([\d.]+) s wall"))
RHO_LINE = re.compile(r"mean contact stiffness at the weight is ([\d.eE+-]+) of the smooth")


def run_once(binary, settings, threads):
    with bench_record.study_run(binary, STUDY, settings, threads, "bench-filter-path-") as (path, stderr, wall, _):
        table = next((float(m.group(1)) for m in (p.search(stderr) for p in TABLE_LINES) if m), float("nan"))
        if "cached" not in stderr and not np.isfinite(table):
            fail(f"{binary} run {' '.join(settings)}: no table summary line in its output", 1)
        rho = RHO_LINE.search(stderr)
        with h5py.File(path) as f:
            b = f["/bands"]
            return {"wall": wall, "table_wall": table, "rho": float(rho.group(1)) if rho else None,
                    "nominal": b["nominal_frequency"][:], "level": b["level_db"][:],
                    "rows": [s.decode() if isinstance(s, bytes) else str(s) for s in b["sensor"][:]]
                    if "sensor" in b else [],
                    "loss": float(np.ravel(f["/contact/loss_of_contact_share"][:])[0])}


def main():
    parser = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    parser.add_argument("--threads", type=int, default=2)
    a, binary = bench_record.record_script_arguments(parser)
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    tables = pathlib.Path(tempfile.mkdtemp(prefix="bench-filter-path-tables-"))
    try:
        runs = {m: run_once(binary, COMMON + keys + [f"stiffness.table_dir={tables}"], a.threads)
                for m, keys in MODELS.items()}
    finally:
        shutil.rmtree(tables, ignore_errors=True)
    ref = runs[REFERENCE]
    sel = (ref["nominal"] >= 100) & (ref["nominal"] <= 5000)
    nominal = ref["nominal"][sel]
    rows, data = [], {"nominal_frequency": nominal.tolist(), "threads": a.threads}
    for model, run in runs.items():
        diff = run["level"][:, sel] - ref["level"][:, sel]
        mean = diff[-1]  # the sensor mean, the last row
        worst = int(np.argmax(np.abs(mean)))
        data[model] = {"table_wall": run["table_wall"], "loss": run["loss"], "rho": run["rho"],
                       "level_db": run["level"][:, sel].tolist(), "band_db": diff.tolist()}
        rows.append([model, "-" if not np.isfinite(run["table_wall"]) else f"{run['table_wall']:.0f}",
                     f"{run['loss']:.4f}", "-" if run["rho"] is None else f"{run['rho']:.4g}",
                     "-" if model == REFERENCE else f"{abs(mean[worst]):.2f} at {nominal[worst]:.0f} Hz",
                     "-" if model == REFERENCE else f"{float(np.max(np.abs(mean[nominal >= 250]))):.2f}",
                     "-" if model == REFERENCE else f"{float(np.max(np.abs(diff))):.2f}"])
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    columns = ["model", "table wall (s)", "loss of contact", "rho = <k_eq>/k_s",
               "sensor mean: max |level - path law's| (dB)", "the same from 250 Hz (dB)", "any sensor (dB)"]
    for r in rows:
        print(" | ".join(r))
    if a.record:
        bench_record.write_measured(
            a.record, binary, title="filter = solver against the path law on the same strip, the seed 002 rig's "
            "whole traverse", argv=sys.argv,
            settings=f"Whole `rollspec run` commands of studies/seed002-rig-1ms.ini with {', '.join(COMMON)}, "
            f"OMP_NUM_THREADS={a.threads}, one run per model, the two point-law runs sharing one equivalent-roughness "
            "table. The ball rolls over its whole traverse (350 mm, 350 ms at 1 m/s, Welch segments of 80 ms).",
            columns=columns, rows=rows, other_cores=others, components=["contact", "beam", "engine"],
            notes="Band levels: /bands/level_db, third octaves 100 Hz - 5 kHz, minus the path law's on the same "
            "strip; 'any sensor' is the largest over the five sensors and their mean. Both models are deterministic "
            "on the strip: the differences are the model's, for this one strip (another strip of the same "
            "roughness moves them).", data=data)
        print(f"wrote {a.record}")


if __name__ == "__main__":
    script_main(main)
