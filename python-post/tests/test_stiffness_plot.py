"""`python3 -m rollspec_post stiffness` on a table in the engine's layout; wrong files refused."""
import numpy as np

from conftest import assert_plots, post, rollspec_ok


def test_hertz_curve():
    from rollspec_post.stiffness_plot import hertz
    d = np.array([1e-6])
    p, k = hertz(d, 0.01, 100e9)
    assert np.isclose(p[0], 4 / 3 * 100e9 * 0.1 * 1e-9) and np.isclose(k[0], 1.5 * p[0] / d[0])


def test_stiffness_plot(stiffness_table, tmp_path):
    assert_plots("stiffness", stiffness_table, tmp_path / "k.png")


def test_stiffness_refuses_a_result_file(stiffness_table, oscillator_result, tmp_path):
    # A figure from an earlier good run is neither replaced nor removed by refused ones.
    out = tmp_path / "x.png"
    assert post("stiffness", stiffness_table, "--out", out).returncode == 0
    before = out.read_bytes()
    r = post("stiffness", oscillator_result, "--out", out)
    assert r.returncode == 65 and "rollspec-stiffness-table" in r.stderr
    r = post("stiffness", tmp_path / "missing.h5", "--out", out)
    assert r.returncode == 66 and "no such file" in r.stderr
    assert out.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["stiffness.h5", "x.png"]  # no temporary file left


def test_stiffness_plot_of_an_engine_table(tmp_path):
    import h5py

    from conftest import SOURCE
    table = tmp_path / "hertz.h5"
    rollspec_ok("stiffness", SOURCE / "studies" / "hertz.ini", "--out", table, "--quiet")
    assert_plots("stiffness", table, tmp_path / "hertz.png")
    from rollspec_post.stiffness_plot import hertz, read_table
    cols, meta = read_table(str(table))
    p, _ = hertz(cols["approach"], meta["ball_radius"], meta["effective_modulus"])
    assert np.allclose(cols["force_mean"][1:], p[1:], rtol=0.02)  # the smooth ball is Hertz
    with h5py.File(table) as f:
        assert f.attrs["filetype"] in (b"rollspec-stiffness-table", "rollspec-stiffness-table")
