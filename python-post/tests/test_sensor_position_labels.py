"""The sensors' positions (/psd/sensor_position, m) name the drawn row: the PSD legend and the
report's card say "sensor_2 (0.2 m)", the notebook's xarray Datasets carry the coordinate; the
sensor mean, and a result written before positions were a coordinate, keep the name alone."""
import shutil
import subprocess

import h5py
import numpy as np
import pytest

from conftest import BIN, SOURCE


@pytest.fixture(scope="module")
def beam_results(tmp_path_factory):
    d = tmp_path_factory.mktemp("positions")
    new = d / "beam.h5"
    r = subprocess.run([BIN, "run", SOURCE / "studies" / "seed001-beam-s-hertz.ini", "--out", new, "--quiet",
                        "--set", "study.realisations=2"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    old = d / "old.h5"
    shutil.copy(new, old)
    with h5py.File(old, "r+") as f:
        for g in ("psd", "bands"):
            del f[g]["sensor_position"]
            del f[g].attrs["coordinates"]
    return new, old


def test_the_psd_legend_and_the_report_name_the_sensor_with_its_position(beam_results, tmp_path):
    from rollspec_post.psd_plot import plot_psd
    from rollspec_post.report_page import report_html
    new, old = beam_results
    assert plot_psd(new, tmp_path / "a.png", sensor=2)["legend"][0] == "sensor_2 (0.2 m), mean of 2"
    assert plot_psd(new, tmp_path / "b.png", sensor="sensor_3")["legend"][0] == "sensor_3 (0.3 m), mean of 2"
    assert plot_psd(new, tmp_path / "c.png")["legend"][0] == "sensor_mean, mean of 2"  # at no one place
    assert plot_psd(old, tmp_path / "d.png", sensor=2)["legend"][0] == "sensor_2, mean of 2"
    assert "sensor sensor_2 (0.2 m)" in report_html(new, sensor=2)


def test_the_notebook_datasets_carry_the_positions(beam_results):
    pytest.importorskip("xarray")
    pytest.importorskip("h5netcdf")
    from rollspec_post.notebook import open_result
    groups = open_result(beam_results[0])
    for g in ("psd", "bands"):
        pos = groups[g].coords["sensor_position"]
        assert pos.dims == ("sensor",) and pos.attrs["units"] == "m"
        np.testing.assert_array_equal(pos.values, [0.1, 0.2, 0.3, np.nan])
