"""Every group of every file rollspec writes opens in xarray (h5netcdf engine) with named
dimensions: results of each ensemble and single-run scene, texture files, stiffness and
blocked-force tables. Bands carry their IEC nominal frequency as a coordinate."""
import glob
import shutil
import warnings

import h5py
import pytest

from conftest import SMALL_PIPE, SOURCE, run

xr = pytest.importorskip("xarray")


def groups(path):
    names = ["/"]
    with h5py.File(path) as f:
        f.visititems(lambda n, o: names.append("/" + n) if isinstance(o, h5py.Group) else None)
    return names


def assert_opens(path):
    for g in groups(path):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            with xr.open_dataset(path, engine="h5netcdf", group=g) as ds:
                for v in ds.variables.values():
                    assert all(not d.startswith("phony_dim") for d in v.dims), (g, v.dims)


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("files")
    study = lambda name: SOURCE / "studies" / name  # noqa: E731
    out = {}

    def ok(args):
        r = run(args)
        assert r.returncode == 0, r.stderr
    out["oscillator"] = d / "ro.h5"
    ok(["run", study("random-oscillator.ini"), "--out", out["oscillator"], "--quiet", "--set", "study.realisations=5"])
    out["ball_on_beam"] = d / "bb.h5"
    ok(["run", study("seed001-beam-s-hertz.ini"), "--out", out["ball_on_beam"], "--quiet", "--set", "study.realisations=5",
        "--set", "output.time_histories=2"])
    out["rolling_beam"] = d / "disc.h5"
    ok(["run", study("seed000-disc.ini"), "--out", out["rolling_beam"], "--quiet"])
    pipe = d / "pipe.ini"
    pipe.write_text(SMALL_PIPE.format(realisations=5, chunk=4, kind="isotropic"))
    out["rolling_pipe"] = d / "pipe.h5"
    ok(["run", pipe, "--out", out["rolling_pipe"], "--quiet", "--set", "roll.distance=0.03", "--set",
        "spectrum.skip_start=0.01", "--set", "spectrum.segment=128"])
    out["texture"] = d / "texture.h5"
    ok(["texture", study("texture-demo.ini"), "--out", out["texture"]])
    out["stiffness"] = d / "hertz.h5"
    ok(["stiffness", study("hertz.ini"), "--out", out["stiffness"]])
    rig = d / "rig" / "rig.ini"
    rig.parent.mkdir()
    shutil.copy(study("seed002-rig-1ms.ini"), rig)
    ok(["run", rig, "--out", d / "rig" / "r.h5", "--quiet", "--set", "contact.blocked_force=solver", "--set",
        "study.realisations=1", "--set", "ball.end=0.12", "--set", "texture.rms=1e-12", "--set", "surface.spacing=4e-6",
        "--set", "texture.short_wavelength=8e-6", "--set", "surface.ny=64", "--set", "blocked_force.window=64", "--set",
        "blocked_force.strip_length=1e-3", "--set", "blocked_force.step=4", "--set", "blocked_force.segment=16"])
    tables = [p for p in glob.glob(str(d / "rig" / "**" / "*.h5"), recursive=True) if not p.endswith("r.h5")]
    assert tables, "the blocked-force table was not written beside the study"
    out["blocked_force"] = tables[0]
    return out


@pytest.mark.parametrize("kind", ["oscillator", "ball_on_beam", "rolling_beam", "rolling_pipe", "texture", "stiffness",
                                  "blocked_force"])
def test_every_group_opens_with_named_dimensions(files, kind):
    assert_opens(files[kind])


@pytest.mark.parametrize("kind", ["oscillator", "ball_on_beam", "rolling_beam", "rolling_pipe", "texture", "stiffness",
                                  "blocked_force"])
def test_echoed_study_is_valid_ini_and_provenance_says_when_where_how(files, kind):
    import configparser
    with h5py.File(files[kind]) as f:
        text = {k: (v.decode() if isinstance(v, bytes) else str(v)) for k, v in f.attrs.items()}
    parser = configparser.ConfigParser()
    parser.read_string(text["study"])  # a repeated section would raise DuplicateSectionError
    assert parser.sections()[0] == "study" and "scene" in parser["study"]
    assert text["created"].endswith("Z") and text["host"] and " --out " in text["command_line"]


def test_bands_carry_the_nominal_frequency_as_a_coordinate(files):
    with xr.open_dataset(files["ball_on_beam"], engine="h5netcdf", group="bands") as b:
        assert "nominal_frequency" in b["level_db"].coords
        assert b["level_db"].dims == ("sensor", "centre_frequency")
        assert 1000.0 in b["level_db"].coords["nominal_frequency"].values
    with xr.open_dataset(files["ball_on_beam"], engine="h5netcdf", group="beam") as beam:
        assert beam["modal_frequency"].dims == ("modal_frequency_index",)


@pytest.mark.parametrize("kind", ["oscillator", "texture", "stiffness", "blocked_force"])
def test_open_result_gives_every_group(files, kind):
    from rollspec_post import open_result
    r = open_result(files[kind])
    assert set(r) == {g.strip("/") or "/" for g in groups(files[kind])}
    assert r["/"].attrs["filetype"].startswith("rollspec-")


def test_run_from_python(tmp_path):
    from rollspec_post import run as run_study
    from rollspec_post.result_file import PostError
    r = run_study(SOURCE / "studies" / "seed001-beam-s-hertz.ini", out=tmp_path / "r.h5", set={"study.realisations": 6})
    level = r["bands"]["level_db"].sel(sensor="sensor_mean")
    assert level.dims == ("centre_frequency",) and int(r["psd"].attrs["realisations"]) == 6
    with pytest.raises(PostError) as e:
        run_study(SOURCE / "studies" / "seed001-beam-s-hertz.ini", out=tmp_path / "x.h5", set={"study.realisations": -1})
    assert e.value.exit_code == 78 and "realisations = -1" in str(e.value)
    assert not (tmp_path / "x.h5").exists()
