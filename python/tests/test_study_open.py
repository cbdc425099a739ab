"""rollspec.studies.open against h5py on the same result file: every group is an xarray Dataset whose variables
hold the file's datasets bit for bit, whose coordinates are the file's dimension scales (frequency, sensor, the
bands' nominal frequency) and whose attributes are the file's."""
import os
import subprocess

import h5py
import numpy as np
import pytest
import xarray

from rollspec import studies

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "ensemble.chunk_size=16",
        "study.realisations=16"]


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    out = tmp_path_factory.mktemp("open") / "oscillator.h5"
    r = subprocess.run([ROLLSPEC, "run", os.path.join(SOURCE, "studies", "random-oscillator.ini"), "--out", str(out),
                        "--quiet", *[a for s in FAST for a in ("--set", s)]], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return out


def same_attrs(a, h):
    assert set(a) == set(h.attrs)
    for k, v in h.attrs.items():
        v = v.decode() if isinstance(v, bytes) else v
        # xarray keeps a one-element attribute as its element
        assert np.array_equal(np.ravel(a[k]), np.ravel(v)) and np.size(a[k]) == np.size(v), k


def test_each_group_is_the_files_data_coordinates_and_attributes(result):
    groups = studies.open(result)
    with h5py.File(result) as f:
        names = ["/"] + [g for g, o in f.items() if isinstance(o, h5py.Group)]
        assert set(groups) >= set(names) and "psd" in groups and "bands" in groups
        same_attrs(groups["/"].attrs, f)
        for g in names[1:]:
            ds = studies.open(result, g)
            assert isinstance(ds, xarray.Dataset) and ds.identical(groups[g])
            same_attrs(ds.attrs, f[g])
            for name, h in f[g].items():
                if not isinstance(h, h5py.Dataset):
                    continue
                v = ds[name]
                assert v.dtype == h.dtype or h.dtype.kind in "SO", (g, name)
                if h.dtype.kind not in "SO":
                    assert v.values.tobytes() == h[()].tobytes(), (g, name)
                # a dataset's dimension scales are its coordinates, by name
                for axis, dim in enumerate(h.dims):
                    if len(dim):
                        assert v.dims[axis] == dim[0].name.rsplit("/", 1)[-1], (g, name)
        psd = studies.open(result, "/psd")
        assert "frequency" in psd.coords and psd["frequency"].attrs["units"] == "Hz"
        assert psd["frequency"].values.tobytes() == f["/psd/frequency"][()].tobytes()
        assert psd["mean"].dims == ("sensor", "frequency")


def test_open_errors(result, tmp_path):
    with pytest.raises(KeyError, match="has no group 'nope'"):
        studies.open(result, "nope")
    with pytest.raises(OSError, match="no-such.h5"):
        studies.open(tmp_path / "no-such.h5")
    (tmp_path / "text.h5").write_text("not hdf5")
    with pytest.raises(ValueError, match="not a readable HDF5 file"):
        studies.open(tmp_path / "text.h5")
