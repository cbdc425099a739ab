"""Stages are objects: `rollspec plan` prints the same inspection `rollspec run` acts on. A table a
run builds shows as cached in the next plan, and the next run reuses it, for every table stage."""
import re
import shutil

import h5py
import pytest

from conftest import SOURCE, run

SMOOTH_STRIP = ["contact.blocked_force=solver", "texture.rms=1e-12", "surface.spacing=4e-6",
                "texture.short_wavelength=8e-6", "surface.ny=64", "blocked_force.window=64",
                "blocked_force.strip_length=1e-3", "blocked_force.step=4", "blocked_force.segment=16", "ball.end=0.12"]
PATH_LAW = ["contact.law=path", "texture.rms=1e-20", "surface.spacing=12e-6", "texture.short_wavelength=24e-6",
            "ball.start=0.1", "ball.end=0.106", "spectrum.segment=128"]
TABLE_LAW = ["contact.law=table", "surface.nx=64", "surface.ny=64", "stiffness.approach_max=3e-6", "ball.end=0.12"]

# (study, the table stage, the --set list, the command that builds it)
CASES = [
    ("hertz.ini", "stiffness_table", [], "stiffness"),
    # The table alone: its jackknife's sub-tables (table_error's default) are another build (test_table_jackknife).
    ("seed002-rig-1ms.ini", "stiffness_table", TABLE_LAW + ["stiffness.table_error=none"], "run"),
    ("seed002-rig-1ms.ini", "blocked_force", SMOOTH_STRIP, "run"),
    ("seed002-rig-1ms.ini", "path_table", PATH_LAW, "run"),
]


# The line each table build always ends with in a log (the stiffness table's is its progress counter's).
FINAL_LINE = {"stiffness_table": r"^stiffness realisations: \d+/\d+ .* took \d",
              "blocked_force": r"^blocked force: \d+ paths .*, \d+ solves, .* s wall",
              "path_table": r"^path table: \d+ approaches .*, \d+ solves, .* s wall"}


def stage_status(plan_stdout, stage):
    rows = [line.split(None, 2) for line in plan_stdout.splitlines()]
    row = next(r for r in rows if r and r[0] == stage)
    return row[1], row[2] if len(row) > 2 else ""


@pytest.mark.parametrize("study,stage,sets,command", CASES, ids=["stiffness-scene", "ball-on-beam-table", "blocked-force", "path-table"])
def test_a_table_built_by_a_run_is_cached_in_the_next_plan(tmp_path, study, stage, sets, command):
    shutil.copy(SOURCE / "studies" / study, tmp_path / study)
    s = tmp_path / study
    args = [a for kv in sets for a in ("--set", kv)]
    plan = run(["plan", s, *args])
    assert plan.returncode == 0, plan.stderr
    status, reason = stage_status(plan.stdout, stage)
    assert status == "run" and "no " in reason and "input hash" in reason, plan.stdout
    out = ["--out", tmp_path / "r.h5"] if command == "run" else []
    extra = ["--set", "study.realisations=2"] if command == "run" else []
    first = run([command, s, *args, *extra, *out])
    assert first.returncode == 0, first.stderr
    assert "built " in first.stderr + first.stdout
    # Not a terminal (a log): every build ends in one line with its count and the time it took, whether or
    # not its progress showed; a progress counter (the stiffness realisations always, the path table's
    # solves and a blocked-force path's positions only after 2 s) ends in one "took" line of its own.
    final = [line for line in first.stderr.splitlines() if re.search(FINAL_LINE[stage], line)]
    assert len(final) == 1, first.stderr
    counters = {}
    for line in first.stderr.splitlines():
        m = re.match(r"(.+?): \d+/\d+  \S+/s  (ETA|took) ", line)
        if m and m.group(1) != "realisations":  # the ensemble's counter runs again for each jackknife pass
            counters.setdefault(m.group(1), []).append(m.group(2))
    for label, states in counters.items():
        assert states[-1] == "took" and states.count("took") == 1, (label, first.stderr)
    again = run(["plan", s, *args])
    status, reason = stage_status(again.stdout, stage)
    assert status == "cached", again.stdout
    table = reason.split(" (input hash ")[0]
    assert (tmp_path / table).is_file()
    second = run([command, s, *args, *extra, *out, "--force"] if command == "run" else [command, s, *args])
    assert second.returncode == 0, second.stderr
    assert "cached " + table in second.stderr + second.stdout
    # An edited table: the plan says the run will refuse it, and the run does (unless --rebuild).
    with h5py.File(tmp_path / table, "r+") as f:
        column = f[{"stiffness_table": "/stiffness/force_mean", "path_table": "/path_table/position"}.get(stage, "/blocked_force/force")]
        column[1] = column[1] * (1 + 1e-12)
    damaged = run(["plan", s, *args])
    status, reason = stage_status(damaged.stdout, stage)
    assert status == "run" and reason.startswith("REFUSED unless --rebuild"), damaged.stdout
    refused = run([command, s, *args, *extra, *out, "--force"] if command == "run" else [command, s, *args])
    assert refused.returncode == 65, refused.stderr


@pytest.mark.parametrize("sets,expected", [([], "run"), (["--set", "output.reference=false"], "skipped"),
                                           (["--set", "contact.law=hertz"], "skipped")])
def test_the_reference_is_a_stage_and_runs_as_planned(tmp_path, sets, expected):
    # The frequency-domain reference of the linearised law: listed by plan, written exactly when
    # the plan says it runs; no other result changes with it.
    study = SOURCE / "studies" / "seed002-rig-1ms.ini"
    common = ["--set", "study.realisations=2", "--set", "ball.end=0.12"]
    plan = run(["plan", study, *common, *sets])
    assert plan.returncode == 0, plan.stderr
    assert stage_status(plan.stdout, "reference")[0] == expected, plan.stdout
    out = tmp_path / "r.h5"
    r = run(["run", study, "--out", out, "--quiet", *common, *sets])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        assert ("/reference/psd" in f) == (expected == "run")
        psd = f["/psd/mean"][:]
    if sets and sets[1] == "output.reference=false":
        with_ref = tmp_path / "with.h5"
        assert run(["run", study, "--out", with_ref, "--quiet", *common]).returncode == 0
        with h5py.File(with_ref) as f:
            assert f["/psd/mean"][:].tobytes() == psd.tobytes()
