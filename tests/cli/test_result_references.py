"""The papers and theory-note equations a run used reach its result: /provenance/references, one
"id | citation | doi" string per reference, read through h5py (src/io/references.cpp, src/scenes/scene_registry.cpp, each scene's references in its folder);
`compare --format json` lists them with its own (src/compare/verdict_references.cpp)."""
import json
import shutil

import h5py

from conftest import SOURCE, measurement_from, oscillator_study, run, study_result

RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"
CHEAP = ("study.realisations=2", "ball.end=0.2", "spectrum.segment=1024")


def references(path):
    with h5py.File(path, "r") as h:
        rows = [x.decode() if isinstance(x, bytes) else x for x in h["/provenance/references"][()]]
    fields = [r.split(" | ") for r in rows]
    assert all(len(f) == 3 for f in fields), rows  # no citation holds the separator
    ids = [f[0] for f in fields]
    assert len(set(ids)) == len(ids), ids
    return {f[0]: (f[1], f[2]) for f in fields}


def test_hertz_ball_on_beam_lists_hertz_and_not_the_linearised_model(tmp_path):
    refs = references(study_result(RIG, tmp_path, "hertz", *CHEAP, "contact.law=hertz", "texture.rms=0.05e-6"))
    for must in ("seed 001", "D-1", "D-8", "D-9", "D-10", "Johnson 1985", "B35", "Welch 1967", "D-15", "D-17"):
        assert must in refs, (must, sorted(refs))
    for must_not in ("seed 002", "D-11", "Polonsky-Keer 1999", "BF-1..BF-7", "ER-1..ER-7", "D-21", "seed 000"):
        assert must_not not in refs, (must_not, sorted(refs))
    assert refs["Johnson 1985"][1] == "10.1017/CBO9781139171731"
    assert refs["Welch 1967"][1] == "10.1109/TAU.1967.1161901"
    assert refs["seed 001"][1] == ""  # the paper prints no DOI, and none is made up


def test_linearised_seed002_lists_the_blocked_force_model_and_not_the_nonlinear_law(tmp_path):
    refs = references(study_result(RIG, tmp_path, "linearised", *CHEAP))
    for must in ("seed 002", "D-11", "B35", "Welch 1967", "D-16"):
        assert must in refs, (must, sorted(refs))
    for must_not in ("D-10", "Polonsky-Keer 1999", "BF-1..BF-7", "D-21"):
        assert must_not not in refs, (must_not, sorted(refs))
    # without the patch filter the line texture is unfiltered, and the list says so
    refs = references(study_result(RIG, tmp_path, "unfiltered", *CHEAP, "contact.filter=none"))
    assert "B35" not in refs and "D-11" in refs, sorted(refs)


def test_interval_reference_only_with_enough_realisations_for_an_interval(tmp_path):
    few = references(study_result(oscillator_study(tmp_path, realisations=4), tmp_path, "few"))
    enough = references(study_result(oscillator_study(tmp_path, realisations=5), tmp_path, "enough"))
    assert "D-21" not in few and "D-21" in enough
    assert {"D-18", "D-19", "Welch 1967"} <= set(enough) and "seed 001" not in enough


def test_compare_json_lists_the_results_references_and_its_own(tmp_path):
    result = study_result(oscillator_study(tmp_path, realisations=6), tmp_path, "model")
    meas = measurement_from(result, tmp_path / "meas.csv")
    r = run(["compare", result, meas, "--measured-averages", 25, "--format", "json"])
    assert r.returncode == 0, r.stderr
    refs = json.loads(r.stdout)["references"]
    ids = [x["id"] for x in refs]
    assert len(set(ids)) == len(ids), ids
    assert list(references(result)) == ids[:len(references(result))]  # the result's own, as its file lists them
    assert {"D-19", "D-32", "D-33", "D-22", "D-34"} <= set(ids), ids
    assert "D-26" not in ids  # 16 bands and 6 realisations: no combined test, so none cited
    r = run(["compare", result, meas, "--measured-averages", 25, "--format", "json", "--fmin", 20, "--fmax", 40])
    j = json.loads(r.stdout)
    ids = [x["id"] for x in j["references"]]
    assert j["combined_test"]["defined"] and "D-26" in ids and "D-31" not in ids, ids  # the F law, no table term
    assert next(x for x in refs if x["id"] == "Welch 1967")["doi"] == "10.1109/TAU.1967.1161901"
    # without M there is no prediction interval, test or offset to cite
    r = run(["compare", result, meas, "--format", "json"])
    ids = [x["id"] for x in json.loads(r.stdout)["references"]]
    assert "D-32" in ids and not {"D-22", "D-26", "D-34"} & set(ids), ids


def test_a_stiffness_table_records_the_solver_it_was_built_with(tmp_path):
    study = tmp_path / "hertz.ini"
    shutil.copy(SOURCE / "studies" / "hertz.ini", study)
    r = run(["stiffness", study, "--set", "stiffness.realisations=2", "-q"])
    assert r.returncode == 0, r.stderr
    (table,) = (tmp_path / "tables").glob("stiffness-*.h5")
    refs = references(table)
    assert {"Polonsky-Keer 1999", "D-6", "D-7"} <= set(refs) and "Welch 1967" not in refs, sorted(refs)
    assert refs["Polonsky-Keer 1999"][1] == "10.1016/S0043-1648(99)00113-1"
