"""Parameter sweeps: [sweep] / --sweep run every point and stack them into one file whose points equal,
bit for bit, single runs with the same --set values; named sweep axes; resume; refusals."""
import signal
import subprocess
import time

import h5py
import numpy as np

from conftest import BIN, EX_CONFIG, EX_INTERRUPTED, assert_refused, result_datasets, run, study_result

MASSES, FREQUENCIES = ["1", "2.5"], ["30", "45"]


def sweep_study(small_study, sweep, realisations=6, duration=4, chunk=2):
    study = small_study(realisations=realisations, chunk=chunk, duration=duration)
    study.write_text(study.read_text() + "\n[sweep]\n" + sweep)
    return study


def single(small_study, tmp_path, name, sets, realisations=6, duration=4, chunk=2):
    study = small_study(realisations=realisations, chunk=chunk, duration=duration, name="plain.ini")
    return result_datasets(study_result(study, tmp_path, name, *sets))


def assert_same(got, want, name):
    got, want = np.asarray(got), np.asarray(want)
    if want.dtype.kind == "f":
        assert got.tobytes() == want.tobytes(), f"{name} differs"
    else:
        assert np.array_equal(got, want), f"{name} differs"


def assert_point_equals(stacked, index, point):
    """Every dataset of the single run equals the stacked file at `index` (or whole, when kept once)."""
    for name, want in point.items():
        got = np.asarray(stacked[name])
        want = np.asarray(want)
        if got.shape != want.shape:
            got = got[index]
        assert got.shape == want.shape, name
        assert_same(got, want, f"{name} at point {index}")


def test_crossed_sweep_points_equal_single_runs_bit_for_bit(small_study, tmp_path):
    study = sweep_study(small_study, f"oscillator.mass = {', '.join(MASSES)}\n"
                                     f"oscillator.natural_frequency = {', '.join(FREQUENCIES)}\n")
    out = tmp_path / "sweep.h5"
    r = run(["run", study, "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    assert not (tmp_path / "sweep.h5.sweep").exists(), "the work directory is removed after the merge"
    stacked = result_datasets(out)
    for i, m in enumerate(MASSES):
        for j, fn in enumerate(FREQUENCIES):
            point = single(small_study, tmp_path, f"p{i}{j}",
                           [f"oscillator.mass={m}", f"oscillator.natural_frequency={fn}"])
            assert_point_equals(stacked, (i, j), point)
    with h5py.File(out) as f:
        mean = f["/psd/mean"]
        assert [list(d.keys()) for d in mean.dims][:2] == [["oscillator_mass"], ["oscillator_natural_frequency"]]
        assert mean.shape[:2] == (2, 2)
        assert list(mean.dims[0][0][()]) == [1.0, 2.5]
        assert list(mean.dims[1][0][()]) == [30.0, 45.0]
        assert mean.dims[0][0].attrs["units"] in (b"kg", "kg")
        assert mean.dims[1][0].attrs["units"] in (b"Hz", "Hz")
        # identical at every point: written once, without the sweep axes
        assert f["/psd/frequency"].ndim == 1
        assert f["/sweep"].attrs["mode"] in (b"crossed", "crossed")
        study_text = f.attrs["study"]
        assert "[sweep]" in (study_text.decode() if isinstance(study_text, bytes) else study_text)
    # the frequency separates the points: the sweep is not a copy of one point
    assert not np.array_equal(stacked["psd/mean"][0, 0], stacked["psd/mean"][0, 1])


def test_zipped_sweep_has_one_axis_and_the_other_keys_as_coordinates(small_study, tmp_path):
    study = sweep_study(small_study, "mode = zipped\noscillator.mass = 1, 2.5\noscillator.natural_frequency = 30, 45\n")
    out = tmp_path / "zip.h5"
    r = run(["run", study, "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    stacked = result_datasets(out)
    for i in range(2):
        point = single(small_study, tmp_path, f"z{i}",
                       [f"oscillator.mass={MASSES[i]}", f"oscillator.natural_frequency={FREQUENCIES[i]}"])
        assert_point_equals(stacked, i, point)
    with h5py.File(out) as f:
        mean = f["/psd/mean"]
        assert list(mean.dims[0].keys()) == ["oscillator_mass"] and mean.shape[0] == 2
        assert list(f["/psd/oscillator_natural_frequency"][()]) == [30.0, 45.0]
        assert "oscillator_natural_frequency" in str(mean.attrs["coordinates"])


def test_command_line_sweep_equals_the_section(small_study, tmp_path):
    study = sweep_study(small_study, "oscillator.mass = 1, 2.5\n")
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    assert run(["run", study, "--out", a, "--quiet"]).returncode == 0
    plain = small_study(realisations=6, chunk=2, duration=4, name="plain.ini")
    r = run(["run", plain, "--out", b, "--quiet", "--sweep", "oscillator.mass=1,2.5"])
    assert r.returncode == 0, r.stderr
    da, db = result_datasets(a), result_datasets(b)
    assert sorted(da) == sorted(db)
    for k in da:
        assert_same(da[k], db[k], k)


def test_plan_lists_the_points(small_study):
    study = sweep_study(small_study, "oscillator.mass = 1, 2.5\noscillator.natural_frequency = 30, 45\n")
    r = run(["plan", study, "--probe"])
    assert r.returncode == 0, r.stderr
    assert "4 points" in r.stdout
    assert "point 4: oscillator.mass=2.5, oscillator.natural_frequency=45" in r.stdout
    assert "run time: about" in r.stdout


def interrupt_in_second_point(cmd, work, timeout=120):
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + timeout
    while time.time() < deadline and proc.poll() is None:
        if len(list((work / "point_0001.h5.checkpoint").glob("chunk_*.bin"))) >= 1:
            break
        time.sleep(0.01)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=timeout)
    return proc.returncode, err


def test_interrupted_sweep_resumes_to_the_identical_file(small_study, tmp_path):
    for duration in (256, 1024, 4096):
        study = sweep_study(small_study, "oscillator.mass = 1, 2.5, 4\n", realisations=24, duration=duration)
        out = tmp_path / f"int-{duration}.h5"
        work = tmp_path / f"int-{duration}.h5.sweep"
        code, err = interrupt_in_second_point([BIN, "run", str(study), "--out", str(out)], work)
        if code != 0:
            break
    assert code == EX_INTERRUPTED, err
    assert not out.exists() and (work / "point_0000.h5").exists()
    plain = run(["run", study, "--out", out])
    assert_refused(plain, 73, ["--resume", "--restart"])
    r = run(["run", study, "--out", out, "--resume"])
    assert r.returncode == 0, r.stderr
    assert "finished before: kept" in r.stdout
    assert not work.exists()
    ref = tmp_path / "ref.h5"
    assert run(["run", study, "--out", ref, "--quiet"]).returncode == 0
    da, db = result_datasets(ref), result_datasets(out)
    assert sorted(da) == sorted(db)
    for k in da:
        assert_same(da[k], db[k], k)


def test_unknown_swept_key_is_refused_with_file_line_and_allowed_keys(small_study, tmp_path):
    study = sweep_study(small_study, "oscillator.mas = 1, 2\n")
    r = run(["run", study, "--out", tmp_path / "x.h5"])
    line = study.read_text().splitlines().index("oscillator.mas = 1, 2") + 1
    assert_refused(r, EX_CONFIG, [f"{study}:{line}", "oscillator.mas", "allowed", "natural_frequency"])
    assert not (tmp_path / "x.h5.sweep").exists()


def test_bad_swept_value_is_refused_before_any_work(small_study, tmp_path):
    study = sweep_study(small_study, "oscillator.mass = 1, -2\n")
    r = run(["run", study, "--out", tmp_path / "x.h5"])
    assert_refused(r, EX_CONFIG, ["[sweep] oscillator.mass", "-2", "out of range"])
    assert not (tmp_path / "x.h5.sweep").exists()


def test_zipped_lists_of_unequal_length_are_refused(small_study, tmp_path):
    study = sweep_study(small_study, "mode = zipped\noscillator.mass = 1, 2\noscillator.natural_frequency = 30, 40, 50\n")
    r = run(["run", study, "--out", tmp_path / "x.h5"])
    assert_refused(r, EX_CONFIG, ["zipped", "oscillator.mass has 2 values", "oscillator.natural_frequency has 3"])


def test_shape_changing_key_is_refused_by_plan_and_run_before_any_point(small_study, tmp_path):
    study = sweep_study(small_study, "spectrum.segment = 1024, 512, 256\n")
    line = study.read_text().splitlines().index("spectrum.segment = 1024, 512, 256") + 1
    # the key, its values, and the shapes of both points (513 and 257 bins of segments 1024 and 512)
    words = [f"{study}:{line}", "[sweep] spectrum.segment = 1024, 512, 256", "shape",
             "at spectrum.segment=1024 /psd/mean 1 x 513", "at spectrum.segment=512 /psd/mean 1 x 257"]
    assert_refused(run(["plan", study]), EX_CONFIG, words)
    out = tmp_path / "x.h5"
    assert_refused(run(["run", study, "--out", out, "--quiet"]), EX_CONFIG, words)
    assert not out.exists()
    assert not (tmp_path / "x.h5.sweep").exists(), "refused before the first point, not after the second"


def test_key_that_moves_the_frequency_grid_is_refused_before_any_point(small_study, tmp_path):
    # Same number of bins, other frequencies: the stacked /psd/frequency could not be one coordinate.
    study = small_study(realisations=6, chunk=2, duration=4)
    out = tmp_path / "x.h5"
    r = run(["run", study, "--out", out, "--quiet", "--sweep", "signal.sample_rate=1024,2048",
             "--sweep", "oscillator.mass=1,2"])
    assert_refused(r, EX_CONFIG, ["command line", "[sweep] signal.sample_rate", "0 .. 512 Hz", "0 .. 1024 Hz"])
    assert "oscillator.mass = " not in r.stderr, "only the key that changes the grid is named"
    assert not (tmp_path / "x.h5.sweep").exists()


def test_speed_sweep_keeps_grids_that_follow_the_speed_per_point(tmp_path):
    # The roughness diagnostics' wavenumber grid follows the record length, so the speed: that group is
    # kept per point, while /psd and /bands stack; every point still equals its single run.
    from conftest import SOURCE
    study = SOURCE / "studies" / "seed002-rig-1ms.ini"
    out = tmp_path / "speeds.h5"
    base = ["--set", "study.realisations=3", "--set", "ensemble.chunk_size=4"]
    r = run(["run", study, "--out", out, "--quiet", "--sweep", "ball.speed=1,3", *base])
    assert r.returncode == 0, r.stderr
    stacked = result_datasets(out)
    for i, speed in enumerate(("1", "3")):
        single_out = tmp_path / f"v{speed}.h5"
        assert run(["run", study, "--out", single_out, "--quiet", "--set", f"ball.speed={speed}", *base]).returncode == 0
        point = result_datasets(single_out)
        for name, want in point.items():
            if name.startswith("roughness/"):
                assert_same(stacked[f"sweep/point_{i:04d}/{name}"], want, name)
            else:
                assert_point_equals({name: stacked[name]}, i, {name: want})
    with h5py.File(out) as f:
        assert "roughness" not in f
        grids = [f[f"/sweep/point_{i:04d}/roughness/wavenumber"].shape for i in range(2)]
        assert grids[0] != grids[1]
        raw = f["/sweep/point_0001/roughness/psd_raw"]
        assert list(raw.dims[0].keys()) == ["wavenumber"]
        assert f["/bands/level_db"].shape[0] == 2
    import xarray as xr
    with xr.open_dataset(out, group="sweep/point_0001/roughness", engine="h5netcdf") as ds:
        assert ds["psd_raw"].dims == ("wavenumber",)
    with xr.open_dataset(out, group="bands", engine="h5netcdf") as ds:
        assert list(ds["ball_speed"].values) == [1.0, 3.0] and ds["ball_speed"].attrs["units"] == "m/s"
