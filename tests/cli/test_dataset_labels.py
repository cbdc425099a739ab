"""Every dataset of a result carries a CF `long_name` (the label plots and xarray show beside the units):
the start of its description, without the explanation in parentheses."""
import h5py
import pytest

from conftest import SMALL_PIPE, SOURCE, oscillator_study, study_result


def labels(path):
    out = {}
    with h5py.File(path) as f:
        f.visititems(lambda name, o: out.__setitem__(name, dict(o.attrs)) if isinstance(o, h5py.Dataset) else None)
    return out


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


@pytest.mark.parametrize("study", ["oscillator", "seed002-rig-1ms.ini", "small-pipe"])
def test_every_dataset_has_a_long_name_from_its_description(tmp_path, study):
    if study == "oscillator":
        path = study_result(oscillator_study(tmp_path), tmp_path, "r")
    elif study == "small-pipe":
        (tmp_path / "pipe.ini").write_text(SMALL_PIPE.format(realisations=2, chunk=2, kind="isotropic"))
        path = study_result(tmp_path / "pipe.ini", tmp_path, "r")
    else:
        path = study_result(SOURCE / "studies" / study, tmp_path, "r", "study.realisations=2")
    found = labels(path)
    assert len(found) > 10
    for name, attrs in found.items():
        assert "long_name" in attrs, name
        long_name, description = text(attrs["long_name"]), text(attrs.get("description", attrs["long_name"]))
        assert long_name and description.startswith(long_name), (name, long_name, description)
        assert " (" not in long_name and "; " not in long_name, (name, long_name)
    # The label xarray draws for the PSD reads as a quantity, not as its explanation.
    assert text(found["psd/mean"]["long_name"]) == "ensemble mean of the one-sided Welch PSD of the acceleration"
    assert text(found["psd/ci_lower"]["long_name"]) == "lower bound of the mean's confidence interval"
