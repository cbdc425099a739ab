"""[contact] filter = solver of the ball-on-beam scene (issue 19; kernels/contact README ER-1..ER-6):
the equivalent-roughness table stage runs, is cached, the plan lists it; the line PSD it gives lies
below the raw path PSD where the patch filters (ER-3, ka > 1.5); bad combinations are refused."""
import glob
import re
import shutil

import h5py
import numpy as np
import pytest

from conftest import EX_CONFIG, SOURCE, assert_refused, hertz_radius, run, run_copied_study

RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"
# The seed 002 rig's surface under the Hertz law, on a coarse strip: 12 um cells (a / 5.8, the
# texture cut at 24 um), Welch segments of 128 positions (1.5 mm) and four of them along a 6.6 mm
# strip, 2 strips: ~1000 force-controlled solves on a ~36-cell window, seconds. A 6 mm path.
SOLVER = ["contact.law=hertz", "contact.filter=solver", "surface.spacing=12e-6", "texture.short_wavelength=24e-6",
          "blocked_force.segment=128", "blocked_force.strip_length=6.6e-3", "ball.start=0.1", "ball.end=0.106",
          "spectrum.segment=128", "spectrum.band_min=400", "spectrum.band_max=5000", "study.realisations=2"]


def rig(tmp_path, *sets, name="r.h5", command="run"):
    return run_copied_study("seed002-rig-1ms.ini", tmp_path, *sets, out=name, command=command)


def stage_row(stdout, name):
    return next(l for l in stdout.splitlines() if l.startswith(name + " "))


def test_runs_is_cached_and_filters_below_the_patch_scale(tmp_path):
    p, _ = rig(tmp_path, *SOLVER, command="plan")
    assert p.returncode == 0, p.stderr
    row = stage_row(p.stdout, "equivalent_roughness")
    assert " run " in row or row.split()[1] == "run", row
    for text in ("2 strips", "cells", "positions", "build about"):
        assert text in row, row

    r, out = rig(tmp_path, *SOLVER)
    assert r.returncode == 0, r.stderr
    assert "equivalent roughness table: built" in r.stderr, r.stderr
    tables = glob.glob(str(tmp_path / "tables" / "equivalent-roughness-*.h5"))
    assert len(tables) == 1
    with h5py.File(tables[0]) as t:
        h = t["/equivalent_roughness/height"][:]
        assert h.shape == (2, t["/equivalent_roughness/position"].shape[0])
        assert np.all(np.isfinite(h)) and np.std(h) > 0.0

    with h5py.File(out) as f:
        g = f["/roughness"]
        k, raw, solver, iso = g["wavenumber"][:], g["psd_raw"][:], g["psd_solver"][:], g["psd_iso2d"][:]
        assert g.attrs["filter"] in (b"solver", "solver")
    ka = k * hertz_radius()
    # ER-3: h_eq averages the roughness over the patch; where ka > 1.5 it carries less than the raw line
    # (sinc^2(1.5) = 0.44 in 1D, less still in 2D), and the table has power there below the band limit.
    high = (ka > 1.5) & (raw > 0.0)  # the texture ends at 24 um, the line at its Nyquist wavenumber
    assert np.all(solver[high] < raw[high]), (ka[high][solver[high] >= raw[high]])
    assert np.any(solver[high] > 0.0)
    # Long waves: h_eq is the flat-punch average of ER-3, whose path PSD is G_eq (ER-5); below the
    # table's third bin the line follows G_eq's shape. The rig's waviness has its power at wavelengths
    # far above 2a, so there G_eq, and the line, keep the raw PSD.
    low = ka < 0.2
    assert np.all(np.abs(10 * np.log10(solver[low] / iso[low])) < 0.5)
    assert np.all(np.abs(10 * np.log10(solver[low] / raw[low])) < 0.5)

    p2, _ = rig(tmp_path, *SOLVER, command="plan")
    assert p2.returncode == 0, p2.stderr
    assert "cached" in stage_row(p2.stdout, "equivalent_roughness"), p2.stdout
    r2, _ = rig(tmp_path, *SOLVER, name="again.h5")
    assert r2.returncode == 0 and "equivalent roughness table: cached" in r2.stderr, r2.stderr


def test_the_table_has_the_same_bits_on_one_and_two_threads(tmp_path):
    # Every dataset and number attribute of the table (h_eq, its PSD, the stiffness k_eq), bit for bit.
    tables = []
    for n in (1, 2):
        d = tmp_path / f"t{n}"
        d.mkdir()
        shutil.copy(RIG, d / "rig.ini")
        args = [a for kv in SOLVER for a in ("--set", kv)]
        r = run(["run", d / "rig.ini", "--out", d / "r.h5", *args], env={"OMP_NUM_THREADS": str(n)}, cwd=d)
        assert r.returncode == 0, r.stderr
        with h5py.File(glob.glob(str(d / "tables" / "equivalent-roughness-*.h5"))[0]) as t:
            g = t["/equivalent_roughness"]
            table = {k: v[...].tobytes() for k, v in g.items() if isinstance(v, h5py.Dataset)}
            table.update({"@" + k: np.asarray(v).tobytes() for k, v in g.attrs.items() if np.asarray(v).dtype.kind == "f"})
            tables.append(table)
    assert {"height", "psd", "stiffness"} <= tables[0].keys()
    assert tables[0].keys() == tables[1].keys()
    for k in tables[0]:
        assert tables[0][k] == tables[1][k], k


def test_bad_combinations_are_refused(tmp_path):
    for extra, named in ((["contact.law=path"], "law = path"),
                         (["contact.law=linearised", "contact.blocked_force=solver"], "blocked_force = solver"),
                         (["contact.law=linearised"], "law = linearised")):
        r, _ = rig(tmp_path, *SOLVER, *extra, command="plan")
        assert_refused(r, EX_CONFIG, ["[contact] filter = solver", "allowed", named])
    r, _ = rig(tmp_path, *SOLVER, "equivalent_roughness.strips=0", command="plan")
    assert r.returncode != 0 and "strips" in r.stderr, r.stderr


PROBE_LINE = (r"^table equivalent_roughness: about ([\d.e+-]+) s CPU, ([\d.e+-]+) s wall on (\d+) threads? "
              r"\(probe: the first (\d+) positions of strip 0 solved in ([\d.e+-]+) s CPU\)$")


@pytest.mark.parametrize("flags", [[], ["--probe"]], ids=["plan", "plan --probe"])
def test_plan_times_the_first_chunk_of_a_missing_table_and_writes_nothing(tmp_path, flags):
    """plan (when the model puts the chunk at 5 s or less, as here) and plan --probe: the
    equivalent-roughness table's build is estimated from its first chunk of solves (64 positions of
    strip 0, as the build solves them), scaled to every position of every strip; no table is written;
    once the table is cached there is nothing to probe (and --probe times realisation 0 instead)."""
    study = tmp_path / "rig.ini"
    shutil.copy(RIG, study)
    sets = [a for kv in SOLVER for a in ("--set", kv)]
    p = run(["plan", study, *flags, *sets])
    assert p.returncode == 0, p.stderr
    row = stage_row(p.stdout, "equivalent_roughness")
    assert "(from the window; plan times its first solves)" in row, row
    positions = int(re.search(r"(\d+) positions per strip", row).group(1))
    m = re.search(PROBE_LINE, p.stdout, re.M)
    assert m, p.stdout
    total, wall, threads, probed, probe = (float(m.group(i)) for i in range(1, 6))
    assert probed == min(64, positions)
    # Two strips, each positions / probed chunks' worth of the probe (the figures are printed to 2 digits).
    assert abs(total - 2 * probe * positions / probed) <= 0.1 * total, (total, probe, positions, probed)
    assert abs(wall - total / threads) <= 0.1 * wall
    assert ("run time: not probed (the stage tables are not built yet" in p.stdout) == bool(flags), p.stdout
    assert not list(tmp_path.rglob("*.h5")), list(tmp_path.rglob("*"))

    r = run(["run", study, "--out", tmp_path / "r.h5", *sets])
    assert r.returncode == 0, r.stderr
    p = run(["plan", study, *flags, *sets])
    assert p.returncode == 0, p.stderr
    assert "table equivalent_roughness:" not in p.stdout, p.stdout
    assert ("s per realisation (probe of realisation 0)" in p.stdout) == bool(flags), p.stdout


def test_plan_leaves_a_long_probe_to_plan_probe(tmp_path):
    """A 256-cell window on the seed 002 rig: the model puts the first 64 positions at about 6 s, over the
    5 s plan spends unasked, so plan prints the model's estimate alone, at once."""
    study = tmp_path / "rig.ini"
    shutil.copy(RIG, study)
    p = run(["plan", study, "--set", "contact.law=hertz", "--set", "contact.filter=solver",
             "--set", "blocked_force.window=256"])
    assert p.returncode == 0, p.stderr
    assert "(from the window; plan --probe times its first solves)" in stage_row(p.stdout, "equivalent_roughness")
    assert "table equivalent_roughness:" not in p.stdout, p.stdout
    assert not list(tmp_path.rglob("*.h5")), list(tmp_path.rglob("*"))


@pytest.mark.parametrize("probe", [[], ["--probe"]], ids=["plan", "plan --probe"])
def test_plan_of_a_sweep_probes_each_missing_table_once_and_builds_none(tmp_path, probe):
    """plan (--probe) of a sweep: a table that several points share (the same cache file) is probed once,
    under the first point that needs it; no point's realisation 0 is run while a table is missing (that
    would build it), and nothing is written."""
    study = tmp_path / "rig.ini"
    shutil.copy(RIG, study)
    sets = [a for kv in SOLVER for a in ("--set", kv)]
    p = run(["plan", study, *probe, *sets, "--sweep", "ball.speed=1,0.8"])
    assert p.returncode == 0, p.stderr
    assert "tables (one build each, shared by the points listed):\n  points 1, 2: equivalent_roughness:" in p.stdout
    lines = re.findall(r"^  point (\d+): table equivalent_roughness: about [\d.e+-]+ s CPU, .*\(probe: the first "
                       r"\d+ positions of strip 0 solved in [\d.e+-]+ s CPU\)$", p.stdout, re.M)
    assert lines == ["1"], p.stdout
    assert ("run time: not probed" in p.stdout) == bool(probe), p.stdout
    assert not list(tmp_path.rglob("*.h5")), list(tmp_path.rglob("*"))


def table_band_db(table, lower, upper):
    """The table's h_eq PSD averaged over [lower, upper] rad/m, its bins as steps of width dk (band_average's rule)."""
    k, p = table["/equivalent_roughness/psd_wavenumber"][:], table["/equivalent_roughness/psd"][:]
    dk = k[1] - k[0]
    width = np.clip(np.minimum(upper, k + dk / 2) - np.maximum(lower, k - dk / 2), 0.0, None)
    return 10 * np.log10(np.sum(p * width) / np.sum(width))


def test_answer_tolerance_measures_its_own_error_and_keeps_the_answer(tmp_path):
    # contact ER-8: every solve stopped at 1e-2 (the loosest allowed), every 16th position checked at the
    # full tolerance; against every solve at the full tolerance on the same strips. The estimate the
    # result carries (BF-9c on the checks' residuals) is an rms over realisations of the error: one strip
    # pair gives one draw per band, so its rms over the bands is what can be held to a factor of 3.
    runs = {}
    for tol in ("0", "1e-2"):
        r, out = rig(tmp_path, *SOLVER, f"equivalent_roughness.answer_tolerance={tol}", name=f"t{tol}.h5")
        assert r.returncode == 0, r.stderr
        runs[tol] = out
    tables = {}
    for path in glob.glob(str(tmp_path / "tables" / "equivalent-roughness-*.h5")):
        t = h5py.File(path)
        tables["1e-2" if "/equivalent_roughness/check_residual" in t else "0"] = t
    assert sorted(tables) == ["0", "1e-2"]
    with h5py.File(runs["0"]) as full, h5py.File(runs["1e-2"]) as loose:
        assert "equivalent_roughness_band_error_db" not in full["/contact"]
        estimate = loose["/contact/equivalent_roughness_band_error_db"][:]
        centre = loose["/bands/centre_frequency"][:]
        assert "equivalent_roughness_error_warning" not in loose["/contact"].attrs
        speed = float(np.ravel(loose["/ball"].attrs["speed"])[0])
        # ER-7 under hertz: E*' = rho^(3/2) E*, so the ratio of rho is that of E*'^(2/3)
        rho = (float(loose["/contact"].attrs["effective_modulus"]) /
               float(full["/contact"].attrs["effective_modulus"])) ** (2 / 3)
    positions = tables["1e-2"]["/equivalent_roughness/position"].shape[0]
    assert tables["1e-2"]["/equivalent_roughness/check_residual"].shape[0] == 2 * len(range(8, positions, 16))
    error = np.array([table_band_db(tables["1e-2"], *(2 * np.pi * c * 2 ** s / speed for s in (-1 / 6, 1 / 6))) -
                      table_band_db(tables["0"], *(2 * np.pi * c * 2 ** s / speed for s in (-1 / 6, 1 / 6)))
                      for c in centre])
    for t in tables.values():
        t.close()
    rms_error, rms_estimate = np.sqrt(np.mean(error ** 2)), np.sqrt(np.mean(estimate ** 2))
    print(f"h_eq band error up to {np.max(np.abs(error)):.5f} dB, rms {rms_error:.5f}; estimate rms {rms_estimate:.5f}; "
          f"rho {rho - 1:+.2e}")
    assert np.all(np.isfinite(estimate)) and np.all(estimate > 0.0)
    assert np.max(np.abs(error)) < 0.1  # the answer: within the run's 0.1 dB target
    assert rms_error > 0.0  # the loose table does differ
    assert 1 / 3 < rms_estimate / rms_error < 3
    assert abs(rho - 1) < 1e-2


def test_answer_tolerance_is_refused_where_no_table_uses_it(tmp_path):
    for extra, named in ((["contact.filter=patch"], "filter = patch"),
                         (["equivalent_roughness.line=strip"], "line = strip")):
        r, _ = rig(tmp_path, *SOLVER, *extra, "equivalent_roughness.answer_tolerance=1e-3", command="plan")
        assert_refused(r, EX_CONFIG, ["answer_tolerance", "allowed", named])
