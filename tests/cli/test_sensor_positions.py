"""Sensor positions are a coordinate of the sensor axis, and `compare --measured-position X` picks
the sensor nearest X.

/psd/sensor_position and /bands/sensor_position hold the study's [sensors] positions (m; NaN for
sensor_mean, which is at no one place), on the sensor dimension scale, named as a coordinate so
that xarray shows them beside the names. --measured-position compares the same row --sensor K
would, names it on stderr, and refuses in one line a place farther than half the smallest spacing
between sensors, --sensor given too, and a result without positions."""
import shutil

import h5py
import numpy as np
import pytest

from conftest import EX_USAGE, SOURCE, measurement_from, run, study_result

STUDY = SOURCE / "studies" / "seed001-beam-s-hertz.ini"  # sensors at 0.1, 0.2, 0.3 m with their mean


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("positions")
    model = study_result(STUDY, d, "model", "study.realisations=2")
    moved = study_result(STUDY, d, "moved", "study.realisations=2", "sensors.positions=0.15, 0.4")
    one = study_result(STUDY, d, "one", "study.realisations=2", "sensors.positions=0.2")
    old = d / "old.h5"  # as written before positions were a coordinate
    shutil.copy(model, old)
    with h5py.File(old, "r+") as f:
        for g in ("psd", "bands"):
            del f[g]["sensor_position"]
            del f[g].attrs["coordinates"]
    meas = measurement_from(model, d / "measured.csv", row=1)
    return {"model": model, "moved": moved, "one": one, "old": old, "meas": meas}


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def positions(path, group):
    with h5py.File(path) as f:
        return f[f"/{group}/sensor_position"][()]


@pytest.mark.parametrize("group", ["psd", "bands"])
def test_the_positions_are_a_coordinate_of_the_sensor_axis(files, group):
    np.testing.assert_array_equal(positions(files["model"], group), [0.1, 0.2, 0.3, np.nan])
    np.testing.assert_array_equal(positions(files["moved"], group), [0.15, 0.4, np.nan])
    with h5py.File(files["model"]) as f:
        p = f[f"/{group}/sensor_position"]
        assert text(p.attrs["units"]) == "m" and "along the span" in text(p.attrs["long_name"])
        assert [[s.name for s in d.values()] for d in p.dims] == [[f"/{group}/sensor"]]
        assert text(f[f"/{group}"].attrs["coordinates"]) == "sensor_position"


def test_xarray_shows_the_positions_beside_the_names(files):
    xr = pytest.importorskip("xarray")
    pytest.importorskip("h5netcdf")
    for group, data in (("psd", "mean"), ("bands", "level_db")):
        with xr.open_dataset(files["model"], engine="h5netcdf", group=group) as ds:
            assert "sensor_position" in ds[data].coords
            assert list(ds["sensor"].values) == ["sensor_1", "sensor_2", "sensor_3", "sensor_mean"]
            np.testing.assert_array_equal(ds["sensor_position"].values, [0.1, 0.2, 0.3, np.nan])
            assert ds["sensor_position"].dims == ("sensor",)


@pytest.mark.long  # minutes under the sanitizers: their pass skips it (tests/cli/CMakeLists.txt)
def test_rolling_pipe_positions_are_the_places_of_the_sensor_nodes(tmp_path):
    """A fraction of the length is recorded at its nearest node: the coordinate is that node's place."""
    r = study_result(SOURCE / "studies" / "rolling-pipe.ini", tmp_path, "pipe", "study.realisations=2",
                     "sensors.positions=0.3, 1")
    with h5py.File(r) as f:
        length, nodes = f["/pipe"].attrs["length"][0], 2 * f["/pipe"].attrs["elements"][0] + 1
        np.testing.assert_array_equal(f["/sensors/node"][()], [2, 8])
        expected = f["/sensors/node"][()] * length / (nodes - 1)
        np.testing.assert_array_equal(f["/psd/sensor_position"][()], [*expected, np.nan])
        np.testing.assert_array_equal(f["/bands/sensor_position"][()], [0.25, 1.0, np.nan])


def compare(files, *args, result="model"):
    return run(["compare", files[result], files["meas"], *args])  # the table: its first line names the sensor


@pytest.mark.parametrize("x, k", [(0.1, 1), (0.21, 2), (0.26, 3), (0.3, 3), (0.06, 1), (0.349, 3)])
def test_measured_position_compares_the_nearest_sensor(files, x, k):
    by_place, by_name = compare(files, "--measured-position", x), compare(files, "--sensor", k)
    assert by_place.returncode == 0, by_place.stderr
    assert by_place.stdout == by_name.stdout and f"sensor sensor_{k};" in by_place.stdout
    note = [line for line in by_place.stderr.splitlines() if "--measured-position" in line]
    assert note == [f"rollspec compare: --measured-position {x:g} m: sensor_{k} at {k / 10:g} m, the nearest sensor "
                    "(within 0.05 m of a sensor (half the smallest spacing between sensors))"]


def refusal(r):
    assert r.returncode == EX_USAGE and r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    return lines[0]


def test_a_place_no_sensor_is_near_is_refused_naming_it_and_the_sensors(files):
    for x in (0.36, 0.5, -0.2):
        line = refusal(compare(files, "--measured-position", x))
        assert f"--measured-position {x:g} m: the nearest sensor" in line
        assert "has the sensors at sensor_1 0.1 m, sensor_2 0.2 m, sensor_3 0.3 m" in line
        assert "allowed: a position within 0.05 m of a sensor" in line
    # The spacing of the study's own sensors sets the tolerance: 0.125 m for sensors 0.25 m apart.
    for x in (0.03, 0.52):
        assert compare(files, "--measured-position", x, result="moved").returncode == 0
    for x in (0.02, 0.53):
        assert "within 0.125 m" in refusal(compare(files, "--measured-position", x, result="moved"))
    # One sensor: no spacing to judge a distance by, only its own place is taken.
    assert compare(files, "--measured-position", 0.2, result="one").returncode == 0
    assert "one sensor: no spacing" in refusal(compare(files, "--measured-position", 0.201, result="one"))


def test_measured_position_with_sensor_is_refused(files):
    line = refusal(compare(files, "--measured-position", 0.2, "--sensor", 2))
    assert "--sensor 2 and --measured-position 0.2 m both given; allowed: one of the two" in line


def test_a_result_without_positions_is_refused_for_measured_position(files):
    line = refusal(compare(files, "--measured-position", 0.2, result="old"))
    assert "has no sensor positions (/bands/sensor_position" in line and "allowed: --sensor NAME|K" in line
    table = compare(files, "--sensor", 2).stdout
    assert compare(files, "--sensor", 2, result="old").stdout == table.replace("model.h5", "old.h5")


def test_fit_chooses_its_sensor_through_the_same_chooser(files):
    r = run(["fit", STUDY, files["meas"], "--vary", "texture.rms=1e-7:1e-6:log", "--measured-averages", 1,
             "--set", "study.realisations=2", "--sensor", 2, "--measured-position", 0.2])
    assert "both given; allowed: one of the two" in refusal(r)
