"""python-post's band comparison is `rollspec compare`'s: same default sensor, same intervals, same
question, same numbers (kernels/spectral D-21, D-22), in the ΔL panel and the report."""
import io
import json
import subprocess

import h5py
import numpy as np
import pytest

from conftest import BIN, SOURCE, is_png_with_content, post


@pytest.fixture(scope="module")
def beam(tmp_path_factory):
    d = tmp_path_factory.mktemp("rule")
    files = {}
    for name, seed in (("model", 11), ("measured", 12)):
        out = d / f"{name}.h5"
        r = subprocess.run([BIN, "run", SOURCE / "studies" / "seed001-beam-s-hertz.ini", "--out", out, "--quiet",
                            "--set", f"study.seed={seed}"], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        files[name] = out
    with h5py.File(files["measured"]) as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][-1, 1:]
    files["csv"] = d / "m.csv"
    np.savetxt(files["csv"], np.c_[freq, psd], delimiter=",", header="frequency_hz,level", comments="", fmt="%.17g")
    return files


def engine(beam, *args):
    r = subprocess.run([BIN, "compare", beam["model"], beam["csv"], "--column", "level", "--format", "json", *map(str, args)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


@pytest.mark.parametrize("extra", [[], ["--measured-averages", 25], ["--sensor", "sensor_2", "--fmin", 200],
                                   ["--sensor", "3"]])
def test_python_and_engine_give_the_same_bands_and_answers(beam, extra):
    from rollspec_post.measurement import compare_bands, read_bands, read_measurement
    j = engine(beam, *extra)
    opts = dict(zip(extra[::2], extra[1::2]))
    with h5py.File(beam["model"]) as f:
        bands = read_bands(f)
    cmp = compare_bands(read_measurement(beam["csv"], "level"), bands, opts.get("--sensor"),
                        float(opts.get("--fmin", 0.0)), np.inf, opts.get("--measured-averages"))
    assert cmp["sensor"] == j["sensor"] and cmp["question"] in j["question"]
    if opts.get("--sensor") == "3":  # a number is the K of sensor_K in both
        assert j["sensor"] == "sensor_3"
    used = cmp["used"]
    assert used.sum() == len(j["bands"]) and cmp["inside_count"] == j["inside"] and cmp["judged"] == j["judged"]
    np.testing.assert_allclose(cmp["measured_db"][used], [b["measured_db"] for b in j["bands"]], atol=1e-9)
    key = "prediction" if "--measured-averages" in opts else "ci"
    np.testing.assert_allclose(cmp["lower_db"][used], [b[f"{key}_lower_db"] for b in j["bands"]], atol=1e-6)
    np.testing.assert_allclose(cmp["upper_db"][used], [b[f"{key}_upper_db"] for b in j["bands"]], atol=1e-6)
    np.testing.assert_allclose(cmp["rms_db_error"], j["rms_db_error"], rtol=1e-9)


def test_report_and_plot_state_the_same_figures(beam, tmp_path):
    j = engine(beam, "--measured-averages", 25)
    out = tmp_path / "r.html"
    r = post("report", beam["model"], "--measurement", beam["csv"], "--column", "level", "--measured-averages", 25,
             "--out", out)
    assert r.returncode == 0, r.stderr
    page = out.read_text()
    assert f"{j['inside']} of {j['judged']} bands" in page and "prediction interval" in page
    assert "sensor sensor_mean" in page
    # The ΔL panel (embedded in the report) states the same count for the same band range.
    from rollspec_post.psd_plot import plot_psd
    cmp = plot_psd(beam["model"], io.BytesIO(), beam["csv"], True, None, "level", 25, 100.0, 5000.0)["comparison"]
    j2 = engine(beam, "--measured-averages", 25, "--fmin", 100, "--fmax", 5000)
    assert (cmp["sensor"], cmp["inside_count"], cmp["judged"]) == (j2["sensor"], j2["inside"], j2["judged"])
    png = tmp_path / "p.png"
    r = post("psd", beam["model"], "--bands", "--measurement", beam["csv"], "--column", "level",
             "--measured-averages", 25, "--out", png)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(png)
    r = post("report", beam["model"], "--measurement", beam["csv"], "--column", "level", "--measured-averages", 0,
             "--out", out)
    assert r.returncode == 64 and "--measured-averages 0" in r.stderr


def test_a_semicolon_export_with_decimal_commas_reads_as_compare_reads_it(beam, tmp_path):
    # The rule of rollspec's CSV reader: delimiter from the header, decimal comma with ';', quotes, CRLF.
    from rollspec_post.measurement import read_measurement
    from rollspec_post.result_file import PostError
    f, p = read_measurement(beam["csv"], "level")
    semi = tmp_path / "m-semi.csv"
    semi.write_text('"frequency_hz";"level"\r\n' + "".join(f"{a:.17g};{b:.17g}\r\n".replace(".", ",") for a, b in zip(f, p)))
    f2, p2 = read_measurement(semi, "level")
    assert f2.tobytes() == f.tobytes() and p2.tobytes() == p.tobytes()
    tab = tmp_path / "m-tab.csv"
    tab.write_text("frequency_hz\tlevel\n" + "".join(f"{a:.17g}\t{b:.17g}\n" for a, b in zip(f, p)))
    assert read_measurement(tab, "level")[1].tobytes() == p.tobytes()
    mixed = tmp_path / "m-mixed.csv"
    mixed.write_text("frequency_hz;level\n10;0,5\n20,5;0.25\n")
    with pytest.raises(PostError, match=r"m-mixed.csv:3: column 'level' value '0.25' has another decimal mark than line 2"):
        read_measurement(mixed, "level")
    model = json.loads(subprocess.run([BIN, "compare", beam["model"], semi, "--column", "level", "--format", "json"],
                                      capture_output=True, text=True, check=True).stdout)
    assert model["rms_db_error"] == engine(beam)["rms_db_error"]
