#!/usr/bin/python3
"""Seed 000's examples 4.1-4.4 (rolling beams and discs): what the shipped studies give against the
seed's analytic values and statements.

usage: /usr/bin/python3 bench/engine/seed000_examples.py [--bin build/werror/rollspec]
           [--record bench/records/validation/seed000-examples.json]

Runs studies/seed000-{disc,cantilever,cantilever-no-rolling,puck,flying-beam}.ini with the settings of
tests/cli/test_rolling_beam.py (the disc in full; the cantilevers to 2 s on 20 elements; the puck to
10.6 s with the energy-consistent option; the flying beam to 2.5 s without friction), in a scratch
directory, and prints each figure beside what the seed states. --record writes the table as a record
that the documentation's seeds page renders (bench/bench_record.py). About a minute on 2 cores.
"""
import pathlib
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

# The disc of example 4.1 (studies/seed000-disc.ini): radius, spin, speed, friction, gravity, mass.
R, W0, V0, MU, G, M = 0.2, 127.03, 2.355, 0.25, 9.81, 1000.0
COMPONENTS = ["engine", "rolling", "integrators"]


def run(binary, work, study, *sets):
    import h5py
    out = work / f"{study}-{len(list(work.glob('*.h5')))}.h5"
    args = [a for kv in sets for a in ("--set", kv)]
    r = subprocess.run([binary, "run", str(ROOT / "studies" / f"{study}.ini"), "--out", str(out), "--quiet", *args],
                       capture_output=True, text=True, cwd=work)
    if r.returncode:
        fail(f"{study}: exit {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}", 70)
    return h5py.File(out, "r")


def disc(binary, work):
    with run(binary, work, "seed000-disc", "analysis.record_every=1") as f:
        t = f["/time_history/time"][:]
        slip = f["/time_history/contact/slip"][:, 0]
        v = np.linalg.norm(f["/time_history/velocity"][:, 0, :], axis=1)
        work_f = float(f["/time_history/energy/friction_work"][-1])
    sliding = np.flatnonzero(slip == 1)
    t_roll = t[np.flatnonzero((slip == 0) & (t > t[sliding[0]]))[0]]
    v_exact = (V0 + R * W0 / 2) / 1.5
    e0 = 0.5 * M * V0**2 + 0.5 * (0.5 * M * R**2) * W0**2
    e1 = 0.5 * M * v_exact**2 + 0.5 * (0.5 * M * R**2) * (v_exact / R) ** 2
    rel = (t_roll / ((R * W0 - V0) / (3 * MU * G)) - 1, v[t > 5].mean() / v_exact - 1, work_f / (e0 - e1) - 1)
    return (f"rolling starts at {t_roll:.3f} s, {100 * rel[0]:+.2g} % from the analytic time; final speed "
            f"{100 * rel[1]:+.2g} % (mean after 5 s); friction work {100 * rel[2]:+.2g} %")


def sliding_speed(f):
    """The mean of v - R |omega| over the last second: how fast the disc's rim slides over the plane."""
    t = f["/time_history/time"][:]
    v = np.linalg.norm(f["/time_history/velocity"][:, 0, :], axis=1)
    w = np.abs(f["/time_history/angular_velocity"][:, 0, 2])
    last = t >= t[-1] - 1.0
    return float(np.mean(v[last] - R * w[last]))


def disc_no_rolling(binary, work):
    with run(binary, work, "seed000-disc-no-rolling", "analysis.record_every=1") as f:
        without = sliding_speed(f)
        t_end = float(f["/time_history/time"][-1])
    with run(binary, work, "seed000-disc", "analysis.record_every=1") as f:
        with_ = sliding_speed(f)
    return (f"the rim slides at v − R|ω| = {without:+.3g} m/s over the last second to {t_end:.3g} s "
            f"(with the correction: {with_:+.2g} m/s)")


def cantilevers(binary, work):
    sets = ("beam.elements=20", "analysis.t_end=2", "analysis.record_every=1")
    with run(binary, work, "seed000-cantilever", *sets) as a, run(binary, work, "seed000-cantilever-no-rolling", *sets) as b:
        ma, mb = a["/time_history/contact/moment"][-1], b["/time_history/contact/moment"][-1]
        ra, rb = float(a["/time_history/reaction"][-1, -1]), float(b["/time_history/reaction"][-1, -1])
    return (f"friction moments about the axis, summed over the nodes: {np.abs(ma[:, 0]).sum():.3g} N m with rolling, "
            f"{np.abs(mb).max():.3g} without; tip reaction {abs(ra):.4g} N with rolling, {abs(rb):.4g} N without")


def puck(binary, work):
    with run(binary, work, "seed000-puck", "analysis.t_end=10.6", "analysis.record_every=1",
             "analysis.integrator=energy-consistent") as f:
        t = f["/time_history/time"][:]
        e = f["/time_history/energy/kinetic"][:] + f["/time_history/energy/penalty"][:]
        active = f["/time_history/contact/active"][:].max(axis=1)
    n = int(((active[1:] == 1) & (active[:-1] == 0)).sum())
    after = t >= 0.1  # the load pulse is over
    return f"energy-consistent option: relative energy change {np.abs(e[after] / e[after][0] - 1).max():.2g} over {n} impacts"


def flying_beam(binary, work):
    with run(binary, work, "seed000-flying-beam", "analysis.t_end=2.5", "contact.friction=0") as f:
        k = f["/time_history/energy/kinetic"][:]
        balance = np.abs(f["/time_history/energy/balance_error"][:]).max() / k.max()
        hit = f["/time_history/contact/active"][:].reshape(len(k), -1, 2)[:, :, 1].max() == 1
    return (f"{'runs through the wall impact' if hit else 'never reaches the wall'}; energy balance error "
            f"{balance:.2g} of the largest kinetic energy (to 2.5 s, without friction)")


def main():
    p = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    a, binary = bench_record.record_script_arguments(p)
    with tempfile.TemporaryDirectory(prefix="seed000-") as tmp:
        work = pathlib.Path(tmp)
        rows = [
            ["4.1 disc thrown spinning: slides, then rolls from t = (Rω₀ − v₀)/(3μg) at v = (v₀ + Rω₀/2)/1.5 "
             "(analytic)", disc(binary, work), "`seed000-disc.ini`"],
            ["4.1 without the rolling correction the disc keeps slipping", disc_no_rolling(binary, work),
             "`seed000-disc-no-rolling.ini`"],
            ["4.2 cantilever pushed sideways on a plane: the friction moment twists it only with rolling; the tip "
             "reaction is lower with rolling (Fig. 12)", cantilevers(binary, work),
             "`seed000-cantilever(-no-rolling).ini`"],
            ["4.3 puck between walls: impacts", puck(binary, work), "`seed000-puck.ini`"],
            ["4.4 flying beam hitting an oblique wall", flying_beam(binary, work), "`seed000-flying-beam.ini`"],
        ]
    for row in rows:
        print(" | ".join(row), flush=True)
    if a.record:
        bench_record.write_measured(
            a.record, binary, title="Seed 000's examples 4.1–4.4", argv=sys.argv,
            settings="each study as shipped, with the end times and recording of tests/cli/test_rolling_beam.py",
            columns=["published", "rollspec", "study"], rows=rows, components=COMPONENTS)


if __name__ == "__main__":
    script_main(main)
