"""The linearised law's blocked force from the contact solver (seed 002 §4.2): Hertz on a smooth
strip, a cached table for a rough one, F0(t) realisations from its PSD."""
import glob
import re
import shutil

import h5py
import numpy as np
import pytest

from conftest import SOURCE, run

E_STAR = 1.0 / (2 * (1 - 0.3**2) / 210e9)
R = 0.02
W = 4 / 3 * np.pi * R**3 * 7850 * 9.81


def rig(tmp_path, *sets, realisations=4):
    study = tmp_path / "rig.ini"
    shutil.copy(SOURCE / "studies" / "seed002-rig-1ms.ini", study)
    out = tmp_path / "r.h5"
    args = [a for kv in sets for a in ("--set", kv)]
    r = run(["run", study, "--out", out, "--set", "contact.blocked_force=solver", "--set", f"study.realisations={realisations}",
             "--set", "ball.end=0.12", *args])
    return r, out


@pytest.mark.parametrize("method", ["exhaustive", "answer"])
def test_smooth_strip_gives_hertz(tmp_path, method):
    # 4 um cells: 17 cells per Hertz contact radius at the weight (a = 69 um). Both methods: the exhaustive load
    # search (answer_tolerance = 0) and the default, the answer's (contact BF-9: one loose path put on the load).
    r, out = rig(tmp_path, "texture.rms=1e-12", "surface.spacing=4e-6", "texture.short_wavelength=8e-6",
                 "surface.ny=64", "blocked_force.window=64", "blocked_force.strip_length=1e-3", "blocked_force.step=4",
                 "blocked_force.segment=16", *(["blocked_force.answer_tolerance=0"] if method == "exhaustive" else []))
    assert r.returncode == 0, r.stderr
    # One progress line per path; the exhaustive search's last meets the load (BlockedForceOptions).
    paths = [l for l in r.stderr.splitlines() if l.startswith("blocked force: path ")]
    assert paths and paths[0].startswith("blocked force: path 1 on "), r.stderr
    if method == "exhaustive":
        assert float(paths[-1].rsplit(" ", 1)[1]) <= 1e-10, paths
    else:
        assert len(paths) == 1, paths
    d_hertz = (3 * W / (4 * E_STAR * np.sqrt(R))) ** (2 / 3)
    k_hertz = 2 * E_STAR * np.sqrt(R * d_hertz)
    with h5py.File(out) as f:
        k0, d0 = f["/contact"].attrs["k0"][0], f["/contact"].attrs["blocked_force_approach"][0]
        assert abs(k0 / k_hertz - 1) < 5e-3, (k0, k_hertz)
        assert abs(d0 / d_hertz - 1) < 2e-3, (d0, d_hertz)
        # A smooth strip has no force fluctuation: the ball rides on its weight, never losing contact.
        assert f["/contact/loss_of_contact_share"][0] == 0.0


def test_rough_strip_table_is_built_once_and_reused(tmp_path):
    common = ["surface.spacing=8e-6", "texture.short_wavelength=16e-6", "surface.ny=96", "blocked_force.window=96",
              "blocked_force.strip_length=3e-3", "stiffness.hardness=6e9", "blocked_force.segment=64"]
    r, out = rig(tmp_path, *common)
    assert r.returncode == 0, r.stderr
    assert "blocked force table: built" in r.stderr
    tables = glob.glob(str(tmp_path / "tables" / "blocked-force-*.h5"))
    assert len(tables) == 1
    with h5py.File(tables[0]) as t:
        f0 = t["/blocked_force/force"][:]
        assert abs(f0.mean() / W - 1) < 1e-8  # d0 puts the mean blocked force at the ball's weight
        assert f0.std() > 0.01 * W
        k0 = t["/blocked_force"].attrs["k0"]
        assert (t["/blocked_force/psd"][1:] > 0).all()
    with h5py.File(out) as f:
        assert f["/contact"].attrs["k0"][0] == k0
        assert "/reference/psd" in f
    r, out = rig(tmp_path, *common)
    assert r.returncode == 0 and "blocked force table: cached" in r.stderr


def blocked_force_row(plan_stdout):
    row = next(l for l in plan_stdout.splitlines() if l.startswith("blocked_force "))
    return row.split(None, 2)


def test_a_key_the_study_sets_is_honoured_over_the_derived_value(tmp_path):
    study = tmp_path / "rig.ini"
    shutil.copy(SOURCE / "studies" / "seed002-rig-1ms.ini", study)
    base = ["plan", study, "--set", "contact.blocked_force=solver"]
    derived = blocked_force_row(run(base).stdout)[2]
    # A window alone: the cell grows so that the window still holds the contact.
    window = blocked_force_row(run([*base, "--set", "blocked_force.window=96"]).stdout)[2]
    assert "window 96 cells" in window and "window 96 cells" not in derived, window
    assert float(re.search(r"cell ([\d.]+) um", window).group(1)) > float(re.search(r"cell ([\d.]+) um", derived).group(1))
    # The cell and strip keys: used as given, the rest derived from them.
    r = run([*base, "--set", "surface.spacing=2e-6", "--set", "surface.ny=300", "--set", "blocked_force.step=7",
             "--set", "blocked_force.segment=32", "--set", "blocked_force.strip_length=2e-3"])
    grid = blocked_force_row(r.stdout)[2]
    for text in ("cell 2 um", "strip 300 x 1000 cells", "step 7 cells", "Welch segment 32"):
        assert text in grid, grid
    assert "dropped" not in grid  # a cell the study sets resolves the texture's 4 um cut-off
    hashes = {re.search(r"input hash (\w+)", g).group(1) for g in (derived, window, grid)}
    assert len(hashes) == 3  # the derived grid is part of the table's inputs
    keys = run(["keys", "ball-on-beam"]).stdout
    assert "0: derived" in keys


@pytest.mark.parametrize("method", ["exhaustive", "answer"])
def test_table_has_the_same_bits_on_one_and_two_threads(tmp_path, method):
    # Fixed chunks of positions (contact BF-6c), each on its own thread's solver: the thread count
    # does not enter the table. 12 um cells, a 48-cell window, 3 mm strip: 6 chunks of 64 positions.
    # The answer's method (BF-9) too: its checks and their levels come from the estimates alone.
    common = ["surface.spacing=12e-6", "texture.short_wavelength=24e-6", "surface.ny=48", "blocked_force.window=48",
              "blocked_force.strip_length=5e-3", "blocked_force.step=1", "stiffness.hardness=6e9",
              "blocked_force.segment=64", "study.realisations=1",
              f"blocked_force.answer_tolerance={1e-3 if method == 'answer' else 0}"]
    names = ("position", "force", "stiffness", "psd") + (("check_position", "check_residual") if method == "answer" else ())
    tables = {}
    for threads in (1, 2):
        d = tmp_path / f"t{threads}"
        d.mkdir()
        study = d / "rig.ini"
        shutil.copy(SOURCE / "studies" / "seed002-rig-1ms.ini", study)
        args = [a for kv in ["contact.blocked_force=solver", "ball.end=0.12", *common] for a in ("--set", kv)]
        r = run(["run", study, "--out", d / "r.h5", *args], env={"OMP_NUM_THREADS": str(threads)})
        assert r.returncode == 0, r.stderr
        assert re.search(r"blocked force: path 1 on \d+ positions \([\d.]+ \+ [\d.]+ CG \+ stiffness iterations", r.stderr), r.stderr
        (path,) = glob.glob(str(d / "tables" / "blocked-force-*.h5"))
        with h5py.File(path) as t:
            tables[threads] = {k: t[f"/blocked_force/{k}"][:] for k in names}
            tables[threads]["attrs"] = np.array([t["/blocked_force"].attrs[a] for a in ("approach", "k0", "mean_force")])
    assert len(tables[1]["position"]) > 256  # more than four chunks
    for k, v in tables[1].items():
        assert v.tobytes() == tables[2][k].tobytes(), k


def test_answer_tolerance_table_matches_the_exhaustive_one_within_its_estimate(tmp_path):
    # [blocked_force] answer_tolerance (contact BF-8, BF-9; the default, 1e-3) against the exhaustive search
    # (answer_tolerance = 0, the reference path) on the same strip:
    # the mean force on the load, each F0 within 3x its recorded estimate, k0 and the F0 PSD close, and the
    # result's own estimates (BF-9c, BF-9a) within a factor 3 of the measured errors.
    common = ["surface.spacing=8e-6", "texture.short_wavelength=16e-6", "surface.ny=96", "blocked_force.window=96",
              "blocked_force.strip_length=3e-3", "stiffness.hardness=6e9", "blocked_force.segment=64"]
    tables, results = {}, {}
    for name, extra in (("exhaustive", ["blocked_force.answer_tolerance=0"]), ("answer", []),
                        ("loose", ["blocked_force.answer_tolerance=3e-2"])):
        (tmp_path / name).mkdir()
        r, out = rig(tmp_path / name, *common, *extra, realisations=1)
        assert r.returncode == 0, r.stderr
        # Within its targets no warning; solved to 3e-2, F0's high bands are estimated above 0.1 dB: a warning
        # naming the band, the size and the key.
        if name == "loose":
            assert re.search(r"WARNING: blocked-force table: F0's level at \d+ Hz has an estimated error of [\d.]+ dB, "
                             r"above the 0.1 dB target .*answer_tolerance", r.stderr), r.stderr
        else:
            assert "blocked-force table:" not in r.stderr, r.stderr
        (path,) = glob.glob(str(tmp_path / name / "tables" / "blocked-force-*.h5"))
        with h5py.File(path) as t:
            g = t["/blocked_force"]
            tables[name] = {k: g[k][:] for k in g} | {k: g.attrs[k] for k in ("k0", "mean_force", "load")}
            if name != "exhaustive":
                tables[name]["k0_error"] = g.attrs["k0_error"][0]
                tables[name]["answer_tolerance"] = g.attrs["answer_tolerance"]
        with h5py.File(out) as f:
            c = f["/contact"]
            results[name] = {k: c[k][:] for k in ("blocked_force_wavenumber", "blocked_force_psd")}
            results[name]["speed"] = f["/ball"].attrs["speed"][0]
            results[name]["bands"] = (f["/bands/lower_frequency"][:], f["/bands/upper_frequency"][:])
            if name != "exhaustive":
                results[name]["band_error"] = c["blocked_force_band_error_db"][:]
                assert ("blocked_force_error_warning" in c.attrs) == (name == "loose")
                assert c.attrs["blocked_force_k0_error"][0] == tables[name]["k0_error"] / tables[name]["k0"][0]
            else:
                assert "blocked_force_band_error_db" not in c
    assert tables["answer"]["answer_tolerance"][0] == 1e-3
    ref, ans = tables["exhaustive"], tables["answer"]
    assert "force_error" not in ref
    assert abs(ans["mean_force"][0] / ans["load"][0] - 1) < 1e-12
    err = np.abs(ans["force"] - ref["force"])
    assert np.all(err <= 3 * ans["force_error"]), np.max(err / ans["force_error"])
    assert abs(ans["k0"][0] / ref["k0"][0] - 1) < 2e-3
    # F0's PSD over the study's bands (to 6 kHz at 1 m/s): the solves' 1e-3 shows only far above them,
    # some 70 dB down near the path's Nyquist wavenumber.
    band = (ref["psd_wavenumber"] > 0) & (ref["psd_wavenumber"] <= 2 * np.pi * 6000)
    assert band.sum() >= 6
    assert np.max(np.abs(10 * np.log10(ans["psd"][band] / ref["psd"][band]))) < 0.1
    # BF-9: the checks (every 16th position) and their residuals' spread against the error over every position.
    assert len(ans["check_position"]) >= len(ans["position"]) // 16
    spread, error = np.std(ans["check_residual"], ddof=1), np.std(ans["force"] - ref["force"])
    assert error / 3 < spread < 3 * error, (spread, error)
    # The result's band errors (BF-9c) against F0's band levels measured between the two tables as the run draws
    # them, rms over the bands (below the PSD's third bin both take that bin's level times the texture's shape);
    # the loose table's warning is not a false alarm: its measured error passes the target in some band too.
    for name in ("answer", "loose"):
        res, v = results[name], results[name]["speed"]
        k3 = res["blocked_force_wavenumber"][3]
        measured = []
        for a, b in zip(*res["bands"]):
            kk = np.maximum(np.geomspace(2 * np.pi * a / v, 2 * np.pi * b / v, 64), k3)
            levels = [np.mean(np.exp(np.interp(np.log(kk), np.log(x["blocked_force_wavenumber"][1:]),
                                               np.log(x["blocked_force_psd"][1:])))) for x in (res, results["exhaustive"])]
            measured.append(10 * np.log10(levels[0] / levels[1]))
        est, meas = np.sqrt(np.mean(res["band_error"] ** 2)), np.sqrt(np.mean(np.square(measured)))
        if name == "answer":
            assert meas / 3 < est < 3 * meas, (name, est, meas)
        else:  # solved to 3e-2 the errors are far from white: the estimate stays on the safe side (4.5x here)
            assert est > meas / 3, (name, est, meas)
            assert np.max(np.abs(measured)) > 0.1, measured
