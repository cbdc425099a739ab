#!/usr/bin/python3
"""Seed 001's contrast between beams R and S: what separates the seed's own model from rollspec's calibrated route.

usage: /usr/bin/python3 bench/engine/seed001_contrast.py [--bin build/werror/rollspec] [--seeds 1001,1002]
           [--record bench/records/validation/seed001-contrast.json]

Seed 001 (section 4) finds its own model (Eq. 7, a point force, no contact filter) close to the measured
acceleration on the rough beam R, and beam S, the smooth one, overestimated increasingly above 2 kHz; it
puts this down to the missing contact filter, which matters less on R because the ball is so often out of
contact there. The measurements are not available, so the question here is the part rollspec can answer:
how far the own model lies above the calibrated route (the stiffness table's law with the patch filter) on
each beam, and which of the two differences makes that gap. Each beam's study (studies/seed001-beam-{r,s}.ini)
runs in four variants, the two factors crossed: [contact] law literal (the seed's Eq. 7 fit) or table,
[contact] filter none or patch (the seed's own model is literal/none, the calibrated route table/patch),
each at every study seed (`--set study.seed=N`; the study's realisations and table as shipped), in a scratch
copy of studies/. Figures: the sensor mean's band levels (dB) averaged over the seeds, differences between
variants averaged over the bands from band_min to 2 kHz and from 2 kHz to 5 kHz, and each variant's share of
time out of contact. --record writes the table as a record that the documentation's seeds page renders
(bench/bench_record.py). About 10 minutes on 2 cores, the two stiffness tables included.
"""
import pathlib
import subprocess
import sys

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "python-post"))
sys.path.insert(0, str(ROOT / "bench" / "engine"))
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)
from seed001_loss_of_contact import parse_seeds  # noqa: E402

BEAMS = {"R": "seed001-beam-r", "S": "seed001-beam-s"}
VARIANTS = {  # name: (law, filter)
    "own model": ("literal", "none"),
    "own law, patch filter": ("literal", "patch"),
    "table law, no filter": ("table", "none"),
    "calibrated route": ("table", "patch"),
}
COMPARISONS = [  # (row, minuend, subtrahend)
    ("own model - calibrated route", "own model", "calibrated route"),
    ("the filter's part (own law: no filter - patch)", "own model", "own law, patch filter"),
    ("the filter's part (table law: no filter - patch)", "table law, no filter", "calibrated route"),
    ("the law's part (no filter: literal - table)", "own model", "table law, no filter"),
]
SPLIT_HZ, TOP_HZ = 2000.0, 5000.0
COMPONENTS = ["engine", "beam", "contact", "integrators", "spectral", "texture"]


def run(binary, study, out, seed, law, filt):
    r = subprocess.run([binary, "run", str(study), "--out", str(out), "--quiet", "--set", f"study.seed={seed}",
                        "--set", f"contact.law={law}", "--set", f"contact.filter={filt}"],
                       capture_output=True, text=True, cwd=study.parent)
    if r.returncode:
        fail(f"{study.name} seed {seed} ({law}, {filt}): exit {r.returncode}: "
             f"{(r.stderr.strip().splitlines() or [''])[-1]}", 70)
    with h5py.File(out) as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["/bands/sensor"][:]]
        level = f["/bands/level_db"][names.index("sensor_mean") if "sensor_mean" in names else 0]
        return (f["/bands/nominal_frequency"][:], level, float(f["/contact/loss_of_contact_share"][0]))


def main():
    p = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    p.add_argument("--seeds", default="1001,1002", help="study seeds (default 1001,1002)")
    a, binary = bench_record.record_script_arguments(p)
    seeds = parse_seeds(a.seeds)
    rows, data = [], {}
    with bench_record.scratch_studies("seed001-contrast-") as work:
        for beam, name in BEAMS.items():
            study = work / "studies" / f"{name}.ini"
            levels, loss, f = {}, {}, None
            for v, (law, filt) in VARIANTS.items():
                got = [run(binary, study, work / f"{name}-{law}-{filt}-{s}.h5", s, law, filt) for s in seeds]
                f = got[0][0]
                levels[v] = np.mean([g[1] for g in got], axis=0)
                loss[v] = 100 * float(np.mean([g[2] for g in got]))
            low, high = f < SPLIT_HZ, (f >= SPLIT_HZ) & (f <= TOP_HZ)
            data[beam] = {"nominal_frequency_hz": f.tolist(), "loss_of_contact_percent": loss,
                          "level_db": {v: x.tolist() for v, x in levels.items()}}
            for label, a_, b_ in COMPARISONS:
                d = levels[a_] - levels[b_]
                row = [f"beam {beam}", label, f"{d[low].mean():+.1f} dB", f"{d[high].mean():+.1f} dB",
                       f"{loss[a_]:.1f} % / {loss[b_]:.1f} %"]
                rows.append(row)
                print(" | ".join(row), flush=True)
    header = ["beam", "difference of the sensor mean's band levels", f"bands below {SPLIT_HZ / 1000:g} kHz (mean)",
              f"bands {SPLIT_HZ / 1000:g}-{TOP_HZ / 1000:g} kHz (mean)", "out of contact (first / second)"]
    if a.record:
        bench_record.write_measured(
            a.record, binary, title="Seed 001: the own model against the calibrated route, beams R and S",
            argv=sys.argv,
            settings=f"each beam's study as shipped (its realisations and stiffness table) with [contact] law "
                     f"and filter crossed, study seeds {', '.join(map(str, seeds))}; the sensor mean's band "
                     f"levels averaged over the seeds, then differences averaged over the bands from the "
                     f"study's band_min to {SPLIT_HZ:g} Hz and from {SPLIT_HZ:g} to {TOP_HZ:g} Hz",
            columns=header, rows=rows, data=data, components=COMPONENTS)


if __name__ == "__main__":
    script_main(main)
