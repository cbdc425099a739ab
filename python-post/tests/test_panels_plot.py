"""`python3 -m rollspec_post panels`: results side by side in the seeds' style, from engine results."""
import subprocess

import h5py
import numpy as np

from conftest import BIN, SOURCE, is_png_with_content, post


def rig(tmp_path, name, *sets):
    out = tmp_path / f"{name}.h5"
    args = [BIN, "run", SOURCE / "studies" / "seed002-rig-1ms.ini", "--out", out, "--quiet", "--set", "study.realisations=4"]
    for s in sets:
        args += ["--set", s]
    r = subprocess.run(args, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return out


def test_panels_draw_what_the_files_hold_in_decibels_up_to_fmax(tmp_path):
    from rollspec_post.panels_plot import plot_panels
    a, b = rig(tmp_path, "a"), rig(tmp_path, "b", "study.seed=7")
    drawn = plot_panels([("1 m/s", [(a, "seed 1"), (b, "seed 7")]), ("again", [(a, "seed 1")])], tmp_path / "p.png")
    assert is_png_with_content(tmp_path / "p.png")
    freq, level = drawn["1 m/s"]["seed 1 (K = 4)"]
    with h5py.File(a) as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["/psd/sensor"][:]]
        f_all, psd = f["/psd/frequency"][:], f["/psd/mean"][names.index("sensor_mean")]
    keep = (f_all > 0) & (f_all <= 5000)
    assert freq[0] > 0 and freq[-1] <= 5000 and freq.size == keep.sum()
    np.testing.assert_allclose(10 ** (level / 10), psd[keep], rtol=1e-12)
    # Another seed is another ensemble: the drawn curves differ.
    assert not np.array_equal(drawn["1 m/s"]["seed 7 (K = 4)"][1], level)


def test_panels_command_and_its_errors(tmp_path):
    a = rig(tmp_path, "a")
    out = tmp_path / "p.svg"
    r = post("panels", "--panel", "rig", f"{a}=spring F0", "--out", out)
    assert r.returncode == 0, r.stderr
    assert out.read_text().lstrip().startswith("<?xml")
    r = post("panels", "--panel", "rig", str(a), "--out", tmp_path / "x.png")
    assert r.returncode == 64 and "is not FILE=LABEL" in r.stderr
    r = post("panels", "--panel", "rig", f"{tmp_path / 'missing.h5'}=x", "--out", tmp_path / "x.png")
    assert r.returncode == 66 and "no such file" in r.stderr
    r = post("panels", "--panel", "rig", *[f"{a}=c{i}" for i in range(5)], "--out", tmp_path / "x.png")
    assert r.returncode == 64 and "at most 4" in r.stderr
    disc = tmp_path / "disc.h5"  # a rolling-beam result: time histories, no /psd
    r = subprocess.run([BIN, "run", SOURCE / "studies" / "seed000-disc.ini", "--out", disc, "--quiet",
                        "--set", "analysis.t_end=0.1"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    r = post("panels", "--panel", "t", f"{disc}=x", "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "holds no /psd" in r.stderr, r.stderr
    assert "Traceback" not in r.stderr
    assert not (tmp_path / "x.png").exists()


def test_panels_draw_measured_csvs_beside_results(tmp_path):
    """The CSV `rollspec psd` writes (frequency_hz, one column per channel titled with its unit) and a plain
    measurement CSV (frequency column, PSD column) are curves too, drawn as they are, labelled as given."""
    from rollspec_post.panels_plot import STYLES, plot_panels
    a = rig(tmp_path, "a")
    t = np.arange(0, 2, 1 / 8192)
    rng = np.random.default_rng(3)
    signal = tmp_path / "signal.csv"
    np.savetxt(signal, np.c_[t, rng.normal(size=t.size), 3 * rng.normal(size=t.size)], delimiter=",",
               header="time_s,acc_a,acc_b", comments="")
    both = tmp_path / "both.csv"
    r = subprocess.run([BIN, "psd", signal, "--out", both], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert both.read_text().startswith("frequency_hz,acc_a [(m/s^2)^2/Hz],acc_b [(m/s^2)^2/Hz]\n")
    one = tmp_path / "one.csv"
    r = subprocess.run([BIN, "psd", signal, "--column", "acc_b", "--out", one], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    table = np.loadtxt(one, delimiter=",", skiprows=1)
    plain = tmp_path / "plain.csv"
    plain.write_text("f;G\n" + "".join(f"{f:.17g};{g:.17g}\n".replace(".", ",") for f, g in table[1:]))
    drawn = plot_panels([("rig", [(one, "measured"), (a, "model")]), ("plain", [(plain, "export")])],
                        tmp_path / "p.png")
    keep = (table[:, 0] > 0) & (table[:, 0] <= 5000)
    for title, label in (("rig", "measured"), ("plain", "export")):
        freq, level = drawn[title][label]
        np.testing.assert_allclose(freq, table[keep, 0])
        np.testing.assert_allclose(10 ** (level / 10), table[keep, 1], rtol=1e-12)
    assert list(drawn["rig"]) == ["measured", "model (K = 4)"] and STYLES[0]["ls"] == "-"
    # a CSV of two channels: --column picks one, without it the error names them
    r = post("panels", "--panel", "rig", f"{both}=b", f"{a}=model", "--column", "acc_b", "--out", tmp_path / "c.png")
    assert r.returncode == 0, r.stderr
    r = post("panels", "--panel", "rig", f"{both}=b", "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "acc_a, acc_b" in r.stderr and "--column" in r.stderr, r.stderr
    assert "Traceback" not in r.stderr and not (tmp_path / "x.png").exists()
