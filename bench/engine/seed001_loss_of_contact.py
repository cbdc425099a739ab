#!/usr/bin/python3
"""Seed 001's loss of contact on beams R and S: the seed's own model and rollspec's calibrated route.

usage: /usr/bin/python3 bench/engine/seed001_loss_of_contact.py [--bin build/werror/rollspec]
           [--seeds 1001,1002,1003,1004] [--record bench/records/validation/seed001-loss-of-contact.json]

Runs studies/seed001-beam-{r,s}-own-model.ini (the seed's Eq. 7 force at a point, no contact filter) and
studies/seed001-beam-{r,s}.ini (the stiffness table's law with the patch filter) as shipped, once per
study seed (`--set study.seed=N`; each study's realisations and its [stiffness] table_seed as shipped, so
every seed shares the study's table), in a scratch copy of studies/ (its tables built there once), and
prints the share of time out of contact (/contact/loss_of_contact_share) of each. --record writes the
table as a record that the documentation's seeds page renders (bench/bench_record.py). About 9 minutes
on the shared 2 cores, most of it the two stiffness tables.
"""
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

STUDIES = [  # (study, what the seed states)
    ("seed001-beam-r-own-model", "frequent loss of contact (beam R, its own model)"),
    ("seed001-beam-s-own-model", "nothing stated for beam S"),
    ("seed001-beam-r", "(rollspec's route, not the seed's)"),
    ("seed001-beam-s", "(rollspec's route, not the seed's)"),
]
COMPONENTS = ["engine", "beam", "contact", "integrators", "spectral", "texture"]


def loss_share(binary, study, out, seed):
    r = subprocess.run([binary, "run", str(study), "--out", str(out), "--quiet", "--set", f"study.seed={seed}"],
                       capture_output=True, text=True, cwd=study.parent)
    if r.returncode:
        fail(f"{study.name} seed {seed}: exit {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}", 70)
    import h5py
    with h5py.File(out) as f:
        share = float(f["/contact/loss_of_contact_share"][0])
        law = f["/contact"].attrs["law"]
        realisations = int(f.attrs["realisations"]) if "realisations" in f.attrs else None
    return share, (law.decode() if isinstance(law, bytes) else str(law)), realisations


def parse_seeds(text):
    try:
        seeds = [int(s) for s in text.split(",")]
    except ValueError:
        fail(f"--seeds {text!r}: not a comma-separated list of integers; allowed: e.g. 1001,1002", 64)
    if not seeds or any(s < 0 for s in seeds):
        fail(f"--seeds {text!r}: allowed: one or more non-negative integers", 64)
    return seeds


def main():
    p = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    p.add_argument("--seeds", default="1001,1002,1003,1004", help="study seeds (default 1001,1002,1003,1004)")
    a, binary = bench_record.record_script_arguments(p)
    seeds = parse_seeds(a.seeds)
    rows = []
    with bench_record.scratch_studies("seed001-loss-") as work:
        for name, states in STUDIES:
            shares, law, k = [], "", None
            for s in seeds:
                share, law, k = loss_share(binary, work / "studies" / f"{name}.ini", work / f"{name}-{s}.h5", s)
                shares.append(100 * share)
            row = [f"`{name}.ini`", law, states, " / ".join(f"{x:.1f} %" for x in shares),
                   f"{min(shares):.1f}–{max(shares):.1f} %"]
            rows.append(row)
            print(" | ".join(row), flush=True)
    header = ["study", "contact law", "seed 001 states", f"out of contact, study seeds {', '.join(map(str, seeds))}",
              "range"]
    if a.record:
        bench_record.write_measured(
            a.record, binary, title="Seed 001: share of time out of contact, beams R and S",
            argv=sys.argv,
            settings="each study as shipped (its realisations, its [stiffness] table_seed: one table per "
                     "study, shared by every study seed), one run per study seed; the share is "
                     "/contact/loss_of_contact_share",
            columns=header, rows=rows, components=COMPONENTS)


if __name__ == "__main__":
    script_main(main)
