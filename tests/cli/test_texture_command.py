"""rollspec texture: the file it writes, reproducibility, and refused PSD / profile inputs."""
import h5py
import numpy as np
import pytest

from conftest import EX_CONFIG, EX_DATAERR, EX_NOINPUT, SOURCE, run, texture_study

DEMO = SOURCE / "studies" / "texture-demo.ini"


def test_texture_file_layout_statistics_and_reproducibility(tmp_path):
    out = tmp_path / "t.h5"
    r = run(["texture", DEMO, "--out", out, "--count", 12, "--list"])
    assert r.returncode == 0, r.stderr
    rows = [l.split() for l in r.stdout.splitlines()]
    assert sum(1 for l in rows if l[0] == "line") == 12 and sum(1 for l in rows if l[0] == "surface") == 12
    assert any(l[0] == "line_mean" for l in rows) and any(l[0] == "surf_mean" for l in rows)
    # The summary's spread is the sample standard deviation of the listed rows.
    listed = np.array([float(l[2]) for l in rows if l[0] == "line"])
    std_row = next(l for l in rows if l[0] == "line_std")
    assert float(std_row[2]) == pytest.approx(listed.std(ddof=1), rel=1e-3)
    with h5py.File(out) as f:
        assert f.attrs["filetype"] in (b"rollspec-texture", "rollspec-texture")
        lines = f["/texture/lines"][:]
        assert lines.shape == (12, f["/texture/x"].shape[0])
        assert f["/surface/heights"].shape == (12, 256, 256)
        for name in ("/texture/x", "/texture/lines", "/texture/psd_wavenumber", "/texture/psd_target", "/surface/x",
                     "/surface/y", "/surface/heights"):
            assert "units" in f[name].attrs
        target_rms = f["/texture"].attrs["target_rms"]
        # 0.3 um requested; the synthesis keeps the harmonics the line period resolves.
        assert abs(target_rms - 0.3e-6) / 0.3e-6 < 0.02
        assert abs(lines.std() - target_rms) / target_rms < 0.05
    out2 = tmp_path / "t2.h5"
    assert run(["texture", DEMO, "--out", out2, "--count", 12]).returncode == 0
    with h5py.File(out) as a, h5py.File(out2) as b:
        assert a["/texture/lines"][:].tobytes() == b["/texture/lines"][:].tobytes()
        assert a["/surface/heights"][:].tobytes() == b["/surface/heights"][:].tobytes()
        assert not np.array_equal(a["/texture/lines"][0], a["/texture/lines"][1])


def table_study(tmp_path, table_text):
    (tmp_path / "psd.csv").write_text(table_text)
    s = tmp_path / "s.ini"
    s.write_text(texture_study(1, {"source": "table", "table": "psd.csv", "table_extension": "zero"},
                               {"count": 2, "length": "1e-3", "spacing": "1e-6"}))
    return s


GOOD_TABLE = "wavenumber_rad_per_m,psd_m3\n1e3,1e-18\n1e5,1e-20\n1e6,1e-23\n"


def test_psd_table_study_works(tmp_path):
    s = table_study(tmp_path, GOOD_TABLE)
    r = run(["texture", s, "--out", tmp_path / "o.h5"])
    assert r.returncode == 0, r.stderr
    s = table_study(tmp_path, "spatial_frequency_cycles_per_m,psd_um2_m\n100,1e-6\n1e4,1e-9\n1.5e5,1e-12\n")
    assert run(["texture", s, "--out", tmp_path / "o2.h5"]).returncode == 0


BAD_TABLES = [
    ("negative psd", "wavenumber_rad_per_m,psd_m3\n1e3,1e-18\n1e5,-1e-20\n1e6,1e-23\n", "psd.csv:3", "negative"),
    ("non-increasing", "wavenumber_rad_per_m,psd_m3\n1e3,1e-18\n1e3,1e-20\n1e6,1e-23\n", "psd.csv:3", "does not increase"),
    ("nan", "wavenumber_rad_per_m,psd_m3\n1e3,1e-18\n1e5,nan\n1e6,1e-23\n", "psd.csv:3", "not finite"),
    ("unit missing", "k,psd\n1e3,1e-18\n1e6,1e-23\n", "psd.csv:1", "does not state its unit"),
    ("psd unit missing", "wavenumber_rad_per_m,psd\n1e3,1e-18\n1e6,1e-23\n", "psd.csv:1", "does not state its unit"),
    ("not a number", "wavenumber_rad_per_m,psd_m3\n1e3,abc\n1e6,1e-23\n", "psd.csv:2", "not a number"),
    ("empty", "", "psd.csv", "empty"),
]


@pytest.mark.parametrize("name,text,where,what", BAD_TABLES, ids=[b[0] for b in BAD_TABLES])
def test_bad_psd_tables_are_refused(tmp_path, name, text, where, what):
    s = table_study(tmp_path, text)
    out = tmp_path / "o.h5"
    r = run(["texture", s, "--out", out])
    assert r.returncode == EX_DATAERR, r.stderr
    assert where in r.stderr and what in r.stderr, r.stderr
    assert not list(tmp_path.glob("o.h5*"))


def profile_study(tmp_path, profiles):
    names = []
    for i, z in enumerate(profiles):
        p = tmp_path / f"p{i}.csv"
        x = np.arange(len(z)) * 1e-6
        np.savetxt(p, np.c_[x, z], delimiter=",", header="position_m,height_m", comments="")
        names.append(p.name)
    s = tmp_path / "s.ini"
    s.write_text(texture_study(1, {"source": "profiles", "profiles": ", ".join(names), "table_extension": "zero"},
                               {"count": 2, "length": "1e-4", "spacing": "1e-6"}))
    return s


def test_profiles(tmp_path):
    rng = np.random.default_rng(0)
    good = profile_study(tmp_path, [rng.standard_normal(256) * 1e-7 for _ in range(3)])
    assert run(["texture", good, "--out", tmp_path / "o.h5"]).returncode == 0
    one = profile_study(tmp_path, [rng.standard_normal(256) * 1e-7])  # one scan is used whole
    r = run(["texture", one, "--out", tmp_path / "o1.h5"])
    assert r.returncode == 0 and "[texture] profiles: 1 scan of 256 samples at 1 um" in r.stderr, r.stderr
    short = profile_study(tmp_path, [rng.standard_normal(256) * 1e-7, rng.standard_normal(6) * 1e-7])
    r = run(["texture", short, "--out", tmp_path / "o2.h5"])
    assert r.returncode == EX_DATAERR and "p1.csv" in r.stderr and "at least 8" in r.stderr
    missing = tmp_path / "m.ini"
    missing.write_text(good.read_text().replace("p0.csv", "nope.csv"))
    r = run(["texture", missing, "--out", tmp_path / "o3.h5"])
    assert r.returncode == EX_NOINPUT and "nope.csv" in r.stderr


def test_texture_refuses_other_scenes(tmp_path, small_study):
    r = run(["texture", small_study(), "--out", tmp_path / "o.h5"])
    assert r.returncode == EX_CONFIG and "scene texture" in r.stderr


def test_texture_summarises_by_default_lists_on_request_and_is_quiet_with_q(tmp_path):
    r = run(["texture", DEMO, "--out", tmp_path / "a.h5"])
    assert r.returncode == 0, r.stderr
    kinds = [l.split()[0] for l in r.stdout.splitlines()]
    assert kinds == ["kind", "line_mean", "line_std", "surf_mean", "surf_std"]
    assert "(200 lines, 20 surfaces)" in r.stderr
    q = run(["texture", DEMO, "--out", tmp_path / "b.h5", "-q"])
    assert q.returncode == 0 and q.stdout == "" and q.stderr == ""
    with h5py.File(tmp_path / "a.h5") as a, h5py.File(tmp_path / "b.h5") as b:
        assert a["/texture/lines"][:].tobytes() == b["/texture/lines"][:].tobytes()
    one = run(["texture", DEMO, "--out", tmp_path / "c.h5", "--count", 1])
    assert one.returncode == 0 and "(1 line, 1 surface)" in one.stderr
    assert [l.split()[0] for l in one.stdout.splitlines()] == ["kind", "line_mean", "surf_mean"]  # no spread of one
    both = run(["texture", DEMO, "--out", tmp_path / "d.h5", "--list", "--quiet"])
    assert both.returncode == 64 and "--list and --quiet" in both.stderr
