"""The random-oscillator scene against its exact answer |H_a|^2 S_F, and the result-file layout."""
import h5py
import numpy as np

from conftest import SOURCE, run


def test_ensemble_mean_inside_its_interval_and_file_layout(tmp_path):
    out = tmp_path / "ro.h5"
    r = run(["run", SOURCE / "studies" / "random-oscillator.ini", "--out", out, "--quiet",
             "--set", "study.realisations=64"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        fn = f["/oscillator"].attrs["natural_frequency"]
        freq = f["/psd/frequency"][:]
        mean, lo, hi = f["/psd/mean"][0], f["/psd/ci_lower"][0], f["/psd/ci_upper"][0]
        exact = f["/reference/psd"][0]
        band = (freq >= 0.2 * fn) & (freq <= 5 * fn)
        inside = ((exact >= lo) & (exact <= hi))[band]
        assert inside.mean() >= 0.90, f"only {inside.mean():.3f} of bins inside the 95 % interval"
        # Not just wide intervals: the mean follows the exact PSD over 40 dB of dynamic range.
        assert np.abs(10 * np.log10(mean[band] / exact[band])).max() < 0.6

        # Layout and provenance (issue 2, item 10).
        attrs = f.attrs
        assert attrs["filetype"] == b"rollspec-result" or attrs["filetype"] == "rollspec-result"
        for a in ("schema_version", "rollspec_version", "git_sha", "study", "seed", "rng", "library_versions"):
            assert a in attrs
        assert f.attrs["rng"] in (b"philox4x64-10", "philox4x64-10")
        study_text = f.attrs["study"]
        study_text = study_text.decode() if isinstance(study_text, bytes) else study_text
        assert "realisations = 64" in study_text and "confidence = 0.95" in study_text  # defaults echoed
        def check_units(name, obj):
            if isinstance(obj, h5py.Dataset):
                assert "units" in obj.attrs, f"{name} has no units"
        f.visititems(check_units)
        assert f["/psd/mean"].dims[0][0].name == "/psd/sensor"
        assert f["/psd/mean"].dims[1][0].name == "/psd/frequency"
        assert f["/bands/level_db"].dims[1][0].name == "/bands/centre_frequency"
        assert f["/psd"].attrs["realisations"] == 64
        # Band levels are the band-averaged mean PSD.
        i = int(np.argmin(np.abs(f["/bands/nominal_frequency"][:] - 50.0)))
        lo_f, hi_f = f["/bands/lower_frequency"][i], f["/bands/upper_frequency"][i]
        sel = (freq >= lo_f) & (freq <= hi_f)
        assert abs(f["/bands/level_db"][0, i] - 10 * np.log10(mean[sel].mean())) < 0.2


def test_compare_against_the_exact_psd(tmp_path):
    out = tmp_path / "ro.h5"
    assert run(["run", SOURCE / "studies" / "random-oscillator.ini", "--out", out, "--quiet",
                "--set", "study.realisations=64"]).returncode == 0
    with h5py.File(out) as f:
        freq, exact = f["/psd/frequency"][:], f["/reference/psd"][0]
    meas = tmp_path / "meas.csv"
    np.savetxt(meas, np.c_[freq[1:], exact[1:]], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
    r = run(["compare", out, meas, "--fmin", 20, "--fmax", 600])
    assert r.returncode == 0, r.stderr
    last = r.stdout.strip().splitlines()[-1]
    assert last.startswith("rms_db_error:")
    rms = float(last.split()[1])
    inside, total = map(int, last.split()[3].split("/"))
    # 14 bands with 95 % intervals: P(inside <= 9) = 4e-4 under the binomial law, so >= 10 is the
    # check a correct interval passes with near certainty and a too-narrow one fails.
    assert rms < 0.1 and total == 14 and inside >= 10
    r = run(["compare", out, meas, "--format", "csv", "--fmin", 20, "--fmax", 600])
    assert r.stdout.splitlines()[0] == ("centre_hz,simulated_db,measured_db,delta_db,ci_lower_db,ci_upper_db,"
                                        "prediction_lower_db,prediction_upper_db,noise_db,use,inside")
    # A measurement 3 dB higher is seen as 3 dB off and outside the interval.
    np.savetxt(meas, np.c_[freq[1:], 2 * exact[1:]], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
    last = run(["compare", out, meas, "--fmin", 20, "--fmax", 600]).stdout.strip().splitlines()[-1]
    assert abs(float(last.split()[1]) - 3.01) < 0.1 and last.endswith(f" 0/{total}")


def test_xarray_opens_the_result_with_named_dimensions(tmp_path):
    import xarray as xr
    out = tmp_path / "ro.h5"
    assert run(["run", SOURCE / "studies" / "random-oscillator.ini", "--out", out, "--quiet",
                "--set", "study.realisations=4"]).returncode == 0
    psd = xr.open_dataset(out, engine="h5netcdf", group="psd")
    assert psd["mean"].dims == ("sensor", "frequency")
    assert float(psd["frequency"][1]) == 0.5 and str(psd["sensor"].values[0]) == "mass"
    assert psd["mean"].attrs["units"] == "(m/s^2)^2/Hz"
    bands = xr.open_dataset(out, engine="h5netcdf", group="bands")
    assert bands["level_db"].dims == ("sensor", "centre_frequency")
    ref = xr.open_dataset(out, engine="h5netcdf", group="reference")
    assert ref["psd"].dims == ("sensor", "frequency")
    # The exact PSD and the mean share coordinates, so xarray aligns them by label.
    ratio = psd["mean"].sel(frequency=slice(20, 200)) / ref["psd"].sel(frequency=slice(20, 200))
    assert ratio.dims == ("sensor", "frequency") and float(ratio.mean()) > 0.5
