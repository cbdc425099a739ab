"""A result whose ball lost contact says so wherever it is read, with what the loss moved
(kernels/spectral D-35). Under a law that models the loss (hertz, table) it is a note of its share.
Under law = linearised, which assumes a closed contact, `run` measures what the loss moved: the same
realisations again with a contact that never opens ([contact] loss = closed), band by band; it warns
only where a band moves by more than its interval, with how many and how far, and otherwise notes the
share with the largest shift. `compare` repeats the warning before its table, and the note as a note."""
import json

import h5py
import numpy as np
import pytest

from conftest import SOURCE, measurement_from, run


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    d = tmp_path_factory.mktemp("loss")
    r = run(["init", "ball-on-beam", "--out", d / "rig.ini"])
    assert r.returncode == 0, r.stderr
    out = {}
    for name, sets in {"hertz": ["texture.rms=1e-6"], "linearised": ["texture.rms=1e-7", "contact.law=linearised"],
                       "smooth": ["texture.rms=1e-9"]}.items():
        out[name] = d / f"{name}.h5"
        args = [a for kv in ["study.realisations=2", *sets] for a in ("--set", kv)]
        r = run(["run", d / "rig.ini", "--out", out[name], "--quiet", *args])
        assert r.returncode == 0, r.stderr
    out["meas"] = measurement_from(out["smooth"], d / "meas.csv")
    return out


def stored(path):
    with h5py.File(path) as f:
        a = f["/contact"].attrs
        get = lambda k: a[k].decode() if k in a else None  # noqa: E731
        return float(f["/contact/loss_of_contact_share"][0]), get("loss_of_contact_warning"), \
            get("loss_of_contact_note")


@pytest.mark.parametrize("name", ["hertz", "linearised"])
def test_a_loss_without_a_measured_effect_is_a_note(results, name):
    # Two realisations: no interval to judge a band by, so nothing is claimed either way.
    share, warning, note = stored(results[name])
    assert share > 0.0 and warning is None and note and "lost contact" in note, (share, warning, note)
    r = run(["compare", results[name], results["meas"]])
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert lines[1] == "note: " + note and lines[2].startswith("question:"), r.stdout
    assert "WARNING" not in r.stdout + r.stderr
    j = json.loads(run(["compare", results[name], results["meas"], "--format", "json"]).stdout)
    assert j["loss_of_contact_note"] == note and j["loss_of_contact_warning"] is None
    assert j["loss_of_contact_share"] == pytest.approx(share, rel=1e-9)


def test_compare_of_a_smooth_result_says_nothing(results):
    share, warning, note = stored(results["smooth"])
    assert share == 0.0 and warning is None and note is None
    r = run(["compare", results["smooth"], results["meas"]])
    assert r.returncode == 0 and "WARNING" not in r.stdout + r.stderr and "note:" not in r.stdout
    j = json.loads(run(["compare", results["smooth"], results["meas"], "--format", "json"]).stdout)
    assert j["loss_of_contact_warning"] is None and j["loss_of_contact_share"] == 0.0


RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"


def test_the_default_rig_notes_its_rare_loss_and_warns_nothing(tmp_path):
    r = run(["run", RIG, "--out", tmp_path / "rig.h5", "--quiet"])
    assert r.returncode == 0 and "WARNING" not in r.stderr, r.stderr
    share, warning, note = stored(tmp_path / "rig.h5")
    assert 0.0 < share < 0.001 and warning is None
    assert "moves none of the" in note and "[contact] loss = closed" in note


def test_a_rougher_rig_warns_with_the_size_it_measured_pair_by_pair(tmp_path):
    """rms 0.25 um: a few per cent of loss. The shift the result stores is the level as run minus the level
    of the same realisations with a contact that never opens, as two separate runs give it."""
    sets = ["--set", "texture.rms=0.25e-6", "--set", "study.realisations=12"]
    r = run(["run", RIG, "--out", tmp_path / "open.h5", "--quiet", *sets])
    assert r.returncode == 0, r.stderr
    share, warning, _ = stored(tmp_path / "open.h5")
    assert 0.01 < share < 0.06 and warning and "WARNING" in r.stderr
    assert "row-bands by more than their interval (up to" in warning and "law = hertz or table" in warning
    r = run(["run", RIG, "--out", tmp_path / "closed.h5", "--quiet", *sets, "--set", "contact.loss=closed"])
    assert r.returncode == 0, r.stderr
    with h5py.File(tmp_path / "open.h5") as o, h5py.File(tmp_path / "closed.h5") as c:
        shift = o["bands/loss_of_contact_shift_db"][:]
        expected = o["bands/level_db"][:] - c["bands/level_db"][:]
        np.testing.assert_allclose(shift, expected, atol=1e-9)
        moved = np.abs(shift) > np.maximum((o["bands/ci_upper_db"][:] - o["bands/ci_lower_db"][:]) / 2.0, 0)
        assert moved.any()
    count = int(warning.split("which moves ")[1].split(" of")[0])
    assert count >= 1


def test_a_closed_contact_is_the_linear_laws_alone(tmp_path):
    study = tmp_path / "s.ini"
    study.write_text(RIG.read_text().replace("law = linearised", "law = hertz"))
    r = run(["run", study, "--out", tmp_path / "x.h5", "--set", "contact.loss=closed"])
    assert r.returncode == 78 and "[contact] loss = closed" in r.stderr and "damping_only or zero" in r.stderr
