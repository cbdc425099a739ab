"""The contact-solver blocked force works by default on both seed 002 studies: no [surface] or
[blocked_force] key, the stage derives its strip grid from the Hertz contact radius and the
texture, plan names it, and the run builds exactly that table. Each builds a table of 1024 path
positions (about a minute): label `studies`, outside the sanitizer pass."""
import glob
import re
import shutil

import h5py
import numpy as np
import pytest

from conftest import SOURCE, run
from test_blocked_force import blocked_force_row


# A shorter traverse keeps the test short; at 3 m/s the record still holds a 1024-sample segment.
@pytest.mark.parametrize("name,end", [("seed002-rig-1ms.ini", 0.12), ("seed002-rig-3ms.ini", 0.2)])
def test_solver_blocked_force_works_with_the_derived_grid(tmp_path, name, end):
    # No [surface] or [blocked_force] key: the stage derives its grid from the Hertz contact radius
    # (a = 69.5 um) and the texture, and the plan names it.
    study = tmp_path / name
    shutil.copy(SOURCE / "studies" / name, study)
    plan = run(["plan", study, "--set", "contact.blocked_force=solver"])
    assert plan.returncode == 0, plan.stderr
    _, status, reason = blocked_force_row(plan.stdout)
    assert status == "run", plan.stdout
    grid = reason.split("; ", 1)[1]
    for word in ("cell ", "window ", "strip ", "wide", "long", "step ", "positions", "Welch segment", "a = 69.5 um",
                 "build about"):
        assert word in grid, grid
    cell = float(re.search(r"cell ([\d.]+) um", grid).group(1)) * 1e-6
    window = int(re.search(r"window (\d+) cells", grid).group(1))
    assert cell <= 69.5e-6 / 8 and window * cell >= 3 * 69.5e-6, grid
    r = run(["run", study, "--out", tmp_path / "r.h5", "--set", "contact.blocked_force=solver", "--set",
             "study.realisations=2", "--set", f"ball.end={end}"])
    assert r.returncode == 0, r.stderr
    assert "blocked force table: built" in r.stderr and "blocked force grid: " + grid in r.stderr, r.stderr
    with h5py.File(glob.glob(str(tmp_path / "tables" / "blocked-force-*.h5"))[0]) as t:
        assert len(t["/blocked_force/force"]) == int(re.search(r"(\d+) positions", grid).group(1))
        k0 = t["/blocked_force"].attrs["k0"]
    with h5py.File(tmp_path / "r.h5") as f:
        assert f["/contact"].attrs["k0"][0] == k0 and k0 > 0
        assert np.isfinite(f["/psd/mean"][:]).all()
    again = run(["plan", study, "--set", "contact.blocked_force=solver"])
    assert blocked_force_row(again.stdout)[1] == "cached", again.stdout


