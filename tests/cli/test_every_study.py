"""Every shipped study plans and runs (5 realisations where it has an ensemble: the fewest that
give confidence intervals): no study in studies/ goes untried. Each result holds finite data only
(no NaN, no inf); each table stage the plan says will run is built by the command, and is cached in
the next plan (and for the next study that uses the same table)."""
import math
import shutil

import h5py
import numpy as np
import pytest

from conftest import SOURCE, run
from rollspec_post.rig_summary import study_scene  # python-post is on PYTHONPATH (tests/cli/CMakeLists.txt)

STUDIES = sorted(p.name for p in (SOURCE / "studies").glob("*.ini"))


def scene_of(path):
    scene = study_scene(path.read_text())
    assert scene is not None, f"{path}: no scene"
    return scene


def finite_datasets(path):
    count = 0
    with h5py.File(path) as f:
        def check(name, obj):
            nonlocal count
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
                values = obj[()]
                if np.all(np.isnan(obj.attrs.get("_FillValue", 0.0))):  # NaN is its declared missing value
                    values = values[~np.isnan(values)]
                assert np.all(np.isfinite(values)), f"{name}: not finite"
                count += 1
        f.visititems(check)
    return count


@pytest.mark.parametrize("bad", [np.inf, -np.inf, np.nan])
def test_a_result_with_inf_or_nan_fails(tmp_path, bad):
    path = tmp_path / "result.h5"
    with h5py.File(path, "w") as f:
        f["psd/frequency"] = np.arange(4.0)
        f["bands/ci_upper_db"] = np.array([1.0, bad, 3.0])
    with pytest.raises(AssertionError, match="bands/ci_upper_db: not finite"):
        finite_datasets(path)


@pytest.mark.parametrize("bad,fails", [(np.nan, False), (np.inf, True)])
def test_nan_passes_only_as_a_declared_fill_value(tmp_path, bad, fails):
    path = tmp_path / "result.h5"
    with h5py.File(path, "w") as f:
        f["psd/frequency"] = np.arange(4.0)
        f["psd/sensor_position"] = np.array([0.5, bad])
        f["psd/sensor_position"].attrs["_FillValue"] = np.nan
    if fails:
        with pytest.raises(AssertionError, match="psd/sensor_position: not finite"):
            finite_datasets(path)
    else:
        assert finite_datasets(path) == 2


@pytest.fixture(scope="module")
def studies(tmp_path_factory):
    """One copy of studies/ without its shipped tables, shared by every study as a user's folder is: the
    first study that needs a table builds it, and a later study with the same table finds it cached
    (the seed 001 beam S and R studies and their own-model variants share one table and its sub-tables)."""
    studies = tmp_path_factory.mktemp("every") / "studies"
    shutil.copytree(SOURCE / "studies", studies, ignore=shutil.ignore_patterns("tables"))
    return studies


@pytest.mark.parametrize("name", STUDIES)
def test_study_plans_and_runs(tmp_path, studies, name):
    study = studies / name
    plan = run(["plan", study])
    assert plan.returncode == 0, plan.stderr
    rows = [row.split(None, 2) for row in plan.stdout.splitlines()]
    stages = {r[0]: (r[1], r[2] if len(r) > 2 else "") for r in rows if len(r) >= 2 and r[1] in ("run", "cached", "skipped")}
    assert {"dynamics", "spectra"} <= stages.keys(), plan.stdout
    scene = scene_of(study)
    out = tmp_path / "out.h5"
    if scene == "texture":
        r = run(["texture", study, "--count", 2, "--out", out, "-q"])
    elif scene == "stiffness":
        r = run(["stiffness", study, "--set", "stiffness.realisations=2", "-q"])
    elif scene == "rolling-beam":
        r = run(["run", study, "--out", out, "-q"], timeout=600)
    else:
        r = run(["run", study, "--out", out, "--set", "study.realisations=5", "-q"], timeout=600)
    assert r.returncode == 0, r.stderr
    if scene != "stiffness":
        assert finite_datasets(out) > 0
    # Table stages to build: "run" with the table's input hash (a linear-spring F0 runs per realisation).
    tables = [s for s, (status, reason) in stages.items() if status == "run" and "input hash" in reason]
    if tables:
        again = run(["plan", study, *(["--set", "stiffness.realisations=2"] if scene == "stiffness" else [])])
        for stage in tables:
            row = next(l for l in again.stdout.splitlines() if l.startswith(stage + " "))
            assert row.split()[1] == "cached", again.stdout
