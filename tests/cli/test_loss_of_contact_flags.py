"""A result whose ball lost contact says so wherever it is read: `rollspec compare` puts the run's
warning before its table (`# WARNING:` in csv, on stderr) and in json as loss_of_contact_share and
loss_of_contact_warning. With law = linearised any loss of contact is flagged (4.9 % here, under
the 5 % threshold of the nonlinear laws); a smooth beam's result has neither."""
import json

import h5py
import pytest

from conftest import measurement_from, run


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
        return float(f["/contact/loss_of_contact_share"][0]), a["loss_of_contact_warning"].decode() \
            if "loss_of_contact_warning" in a else None


@pytest.mark.parametrize("name", ["hertz", "linearised"])
def test_compare_flags_a_result_that_lost_contact(results, name):
    share, warning = stored(results[name])
    assert warning and (share > 0.05 if name == "hertz" else 0.0 < share < 0.05), (share, warning)
    r = run(["compare", results[name], results["meas"]])
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert lines[1] == "WARNING: " + warning, r.stdout  # right after the source line, before the question
    assert lines[2].startswith("question:")
    assert f"rollspec compare: WARNING: {results[name]}: {warning}" in r.stderr
    r = run(["compare", results[name], results["meas"], "--format", "csv"])
    assert r.returncode == 0 and "# WARNING: " + warning + "\n" in r.stdout, r.stdout
    r = run(["compare", results[name], results["meas"], "--format", "json"])
    j = json.loads(r.stdout)
    assert j["loss_of_contact_warning"] == warning and j["loss_of_contact_share"] == pytest.approx(share, rel=1e-9)


def test_compare_of_a_smooth_result_says_nothing(results):
    share, warning = stored(results["smooth"])
    assert share == 0.0 and warning is None
    r = run(["compare", results["smooth"], results["meas"]])
    assert r.returncode == 0 and "WARNING" not in r.stdout + r.stderr, r.stdout + r.stderr
    j = json.loads(run(["compare", results["smooth"], results["meas"], "--format", "json"]).stdout)
    assert j["loss_of_contact_warning"] is None and j["loss_of_contact_share"] == 0.0
