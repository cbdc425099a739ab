"""`python3 -m rollspec_post psd` on a result made by the engine; clear errors for wrong files."""
import h5py
import numpy as np

from conftest import is_png_with_content, post


def test_psd_plot_with_bands_and_measurement(oscillator_result, tmp_path):
    out = tmp_path / "psd.png"
    r = post("psd", oscillator_result, "--bands", "--out", out)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)
    with h5py.File(oscillator_result) as f:
        freq, ref = f["/psd/frequency"][1:], f["/reference/psd"][0, 1:]
    meas = tmp_path / "meas.csv"
    np.savetxt(meas, np.c_[freq, ref], delimiter=",", header="frequency_hz,psd", comments="")
    out2 = tmp_path / "psd_meas.png"
    r = post("psd", oscillator_result, "--bands", "--measurement", meas, "--out", out2)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out2)


def test_wrong_files_give_clear_errors(tmp_path):
    r = post("psd", tmp_path / "missing.h5", "--out", tmp_path / "x.png")
    assert r.returncode == 66 and "no such file" in r.stderr
    junk = tmp_path / "junk.h5"
    junk.write_bytes(b"not hdf5 at all")
    r = post("psd", junk, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "not a readable HDF5 file" in r.stderr
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f.attrs["filetype"] = "something-else"
    r = post("psd", other, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "not a rollspec file" in r.stderr
    future = tmp_path / "future.h5"
    with h5py.File(future, "w") as f:
        f.attrs["filetype"] = "rollspec-result"
        f.attrs["schema_version"] = "7.0"
    r = post("psd", future, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "schema_version '7.0'" in r.stderr
    assert not (tmp_path / "x.png").exists()
