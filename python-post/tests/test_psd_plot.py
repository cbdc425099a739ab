"""`python3 -m rollspec_post psd` on a result made by the engine; clear errors for wrong files."""
import h5py
import numpy as np

from conftest import hdf5_with_attributes, is_png_with_content, post, write_measurement


def test_psd_plot_with_bands_and_measurement(oscillator_result, tmp_path):
    out = tmp_path / "psd.png"
    r = post("psd", oscillator_result, "--bands", "--out", out)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)
    meas = write_measurement(oscillator_result, tmp_path / "meas.csv")
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
    other = hdf5_with_attributes(tmp_path / "other.h5", filetype="something-else")
    r = post("psd", other, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "not a rollspec file" in r.stderr
    future = hdf5_with_attributes(tmp_path / "future.h5", filetype="rollspec-result", schema_version="7.0")
    r = post("psd", future, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "schema_version '7.0'" in r.stderr
    assert not (tmp_path / "x.png").exists()


def test_default_plot_is_fit_for_a_paper(tmp_path):
    """Seed 002 rig with a measurement: one row (the sensor mean) with its interval, the reference,
    the measurement in black, bands; a legend of at most six entries; real PDF and SVG."""
    import subprocess
    import xml.dom.minidom
    from conftest import BIN, SOURCE
    from rollspec_post.psd_plot import plot_psd
    rig, other = tmp_path / "rig.h5", tmp_path / "other.h5"
    for out, seed in ((rig, 1), (other, 2)):
        r = subprocess.run([BIN, "run", SOURCE / "studies" / "seed002-rig-1ms.ini", "--out", out, "--quiet",
                            "--set", "study.realisations=8", "--set", f"study.seed={seed}"], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
    with h5py.File(other) as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][-1, 1:]
    meas = tmp_path / "m.csv"
    np.savetxt(meas, np.c_[freq, psd], delimiter=",", header="frequency_hz,psd", comments="")
    shown = plot_psd(rig, tmp_path / "p.png", meas, True)
    assert len(shown["legend"]) <= 6 and shown["legend"][1] == "sensor_mean, mean of 8"
    assert shown["comparison"]["sensor"] == "sensor_mean"
    with_all = plot_psd(rig, tmp_path / "all.png", meas, True, sensors_all=True)
    assert "individual sensors" in with_all["legend"] and len(with_all["legend"]) <= 6
    r = post("psd", rig, "--bands", "--measurement", meas, "--out", tmp_path / "p.pdf")
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "p.pdf").read_bytes()[:5] == b"%PDF-"
    r = post("psd", rig, "--xscale", "log", "--sensors", "all", "--out", tmp_path / "p.svg")
    assert r.returncode == 0, r.stderr
    assert xml.dom.minidom.parse(str(tmp_path / "p.svg")).documentElement.tagName == "svg"
    r = post("psd", rig, "--out", tmp_path / "p.jpg")
    assert r.returncode == 64 and "allowed: .png, .pdf, .svg" in r.stderr and not (tmp_path / "p.jpg").exists()
    r = post("psd", rig, "--fmin", 500, "--fmax", 100, "--out", tmp_path / "q.png")
    assert r.returncode == 64 and not (tmp_path / "q.png").exists()
