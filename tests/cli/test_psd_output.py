"""What `rollspec psd` writes: a CSV that pandas.read_csv and numpy.genfromtxt(names=True) read at their
defaults, columns named by channel and unit, and its metadata in a W3C CSVW sidecar `<csv>-metadata.json`
(the Welch settings, the averages and their equivalent degrees of freedom, D-16, the source and its
SHA-256, the CSV's own SHA-256). An existing --out is replaced only if its sidecar records its SHA-256
(written by psd, not edited since), or it is the older marker-line format, or with --force; compare,
fit and rollspec_post read both formats. An HDF5 result given to psd is named for what it is."""
import hashlib
import json

import h5py
import numpy as np
import pandas as pd
import pytest
import scipy.signal

from conftest import EX_CANTCREAT, EX_DATAERR, EX_USAGE, assert_refused, oscillator_study, run

FS, N, SEGMENT = 1024.0, 16384, 1024
G = 9.80665
UNIT = "(m/s^2)^2/Hz"


def signal(tmp_path):
    rng = np.random.default_rng(9)
    x = np.round(rng.standard_normal((N, 2)) * 1e3) / 1e4
    sig = tmp_path / "logger.csv"
    sig.write_text("time_s;Acc (g);b [m/s²]\n" +
                   "".join(f"{i / FS:.10f};{a:.4f};{b:.4f}\n" for i, (a, b) in enumerate(x)), encoding="utf-8")
    return sig, x


def welch(x):
    return scipy.signal.welch(x, fs=FS, window="hann", nperseg=SEGMENT, noverlap=SEGMENT // 2, axis=0)


def test_the_csv_loads_in_pandas_and_numpy_at_their_defaults(tmp_path):
    sig, x = signal(tmp_path)
    out = tmp_path / "m.csv"
    r = run(["psd", sig, "--segment", SEGMENT, "--out", out])
    assert r.returncode == 0, r.stderr
    f, p = welch(x * [G, 1.0])
    table = pd.read_csv(out)
    assert list(table.columns) == ["frequency_hz", f"Acc [{UNIT}]", f"b [{UNIT}]"]
    np.testing.assert_allclose(table["frequency_hz"], f, rtol=1e-12)
    np.testing.assert_allclose(table[f"Acc [{UNIT}]"], p[:, 0], rtol=1e-10, atol=1e-10 * p[:, 0].max())
    array = np.genfromtxt(out, delimiter=",", names=True)
    assert array.dtype.names == ("frequency_hz", "Acc_ms22Hz", "b_ms22Hz")
    np.testing.assert_allclose(array["b_ms22Hz"], table[f"b [{UNIT}]"], rtol=1e-12)  # pandas' default parser is not the exact one
    # to stdout: the CSV alone, the same bytes, and no sidecar anywhere
    r = run(["psd", sig, "--segment", SEGMENT])
    assert r.returncode == 0 and r.stdout == out.read_text()
    assert not r.stdout.startswith("#")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["logger.csv", "m.csv", "m.csv-metadata.json"]


def equivalent_dof(n, segment, overlap):
    """D-16 (Percival & Walden 1993 Eq. 292b) for a Hann window, written out again."""
    w = scipy.signal.get_window("hann", segment)
    step, nb = segment - overlap, (n - overlap) // (segment - overlap)
    rho = [np.sum(w[: segment - m * step] * w[m * step:]) / np.sum(w * w) if m * step < segment else 0.0
           for m in range(1, nb)]
    return 2 * nb / (1 + 2 * sum((1 - m / nb) * r**2 for m, r in enumerate(rho, 1))), nb


def test_the_sidecar_is_csvw_with_the_welch_settings_and_hashes(tmp_path):
    sig, _ = signal(tmp_path)
    out = tmp_path / "m.csv"
    assert run(["psd", sig, "--segment", SEGMENT, "--overlap", 0.25, "--out", out]).returncode == 0
    meta = json.loads((tmp_path / "m.csv-metadata.json").read_text())
    assert meta["@context"] == "http://www.w3.org/ns/csvw" and meta["url"] == "m.csv"
    columns = meta["tableSchema"]["columns"]
    assert [c["titles"] for c in columns] == list(pd.read_csv(out).columns)
    assert [c["name"] for c in columns] == ["frequency_hz", "Acc", "b"]
    assert {c["datatype"] for c in columns} == {"double"}
    assert [c.get("rollspec:channel") for c in columns[1:]] == ["Acc (g)", "b [m/s²]"]
    assert [c.get("rollspec:signal_unit") for c in columns[1:]] == ["g", "m/s^2"]
    dof, segments = equivalent_dof(N, SEGMENT, SEGMENT // 4)
    assert (meta["rollspec:segment"], meta["rollspec:overlap"], meta["rollspec:window"]) == (SEGMENT, 256, "hann")
    assert meta["rollspec:detrend"] == "mean" and meta["rollspec:samples"] == N
    assert meta["rollspec:segments"] == segments == 21
    assert meta["rollspec:equivalent_dof"] == pytest.approx(dof, rel=1e-12)
    assert meta["rollspec:sample_rate_hz"] == FS and meta["rollspec:psd_unit"] == UNIT
    assert meta["rollspec:source"] == str(sig)
    assert meta["rollspec:source_sha256"] == hashlib.sha256(sig.read_bytes()).hexdigest()
    assert meta["rollspec:csv_sha256"] == hashlib.sha256(out.read_bytes()).hexdigest()
    assert meta["rollspec:version"].startswith(run(["version"]).stdout.split()[1])


def test_an_existing_output_is_replaced_only_if_psd_wrote_it_and_nobody_edited_it(tmp_path):
    sig, _ = signal(tmp_path)
    out, side = tmp_path / "m.csv", tmp_path / "m.csv-metadata.json"
    args = ["psd", sig, "--segment", SEGMENT, "--out", out]
    assert run(args).returncode == 0
    assert run(args).returncode == 0  # its own output: replaced
    out.write_text(out.read_text().replace("frequency_hz,", "frequency_hz,", 1) + "# my note\n")  # edited
    edited = out.read_bytes()
    assert_refused(run(args), EX_CANTCREAT, ["m.csv", "not a PSD written by rollspec psd and not edited since",
                                             "m.csv-metadata.json", "--force"])
    assert out.read_bytes() == edited
    assert run([*args, "--force"]).returncode == 0 and out.read_bytes() != edited
    # the older format, a marker line before the header, is still rollspec's
    out.write_text("# rollspec-psd-csv: one-sided PSD in (m/s^2)^2/Hz, Welch\nfrequency_hz,acc\n0,1\n")
    side.unlink()
    assert run(args).returncode == 0 and not out.read_text().startswith("#") and side.exists()
    # a file of the user's at the sidecar's name is protected as well
    other = tmp_path / "n.csv"
    (tmp_path / "n.csv-metadata.json").write_text('{"mine": true}\n')
    assert_refused(run(["psd", sig, "--segment", SEGMENT, "--out", other]), EX_CANTCREAT,
                   ["n.csv-metadata.json", "is not the metadata of a PSD written by rollspec psd", "--force"])
    assert not other.exists() and (tmp_path / "n.csv-metadata.json").read_text() == '{"mine": true}\n'
    # through a link: the file it points to is replaced, its metadata beside it
    (tmp_path / "link.csv").symlink_to("m.csv")
    assert run(["psd", sig, "--segment", 512, "--out", tmp_path / "link.csv"]).returncode == 0
    assert (tmp_path / "link.csv").is_symlink() and not (tmp_path / "link.csv-metadata.json").exists()
    assert json.loads(side.read_text())["rollspec:segment"] == 512
    assert not list(tmp_path.glob("*.tmp-*"))


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    d = tmp_path_factory.mktemp("result")
    r = d / "r.h5"
    assert run(["run", oscillator_study(d, realisations=6), "--out", r, "--quiet"]).returncode == 0
    return r


def test_compare_reads_the_columns_by_title_name_or_channel_and_says_when_metadata_is_ignored(tmp_path, result):
    sig, _ = signal(tmp_path)
    out = tmp_path / "m.csv"
    assert run(["psd", sig, "--segment", SEGMENT, "--out", out]).returncode == 0
    want = run(["compare", result, out, "--column", f"Acc [{UNIT}]", "--format", "csv"])
    assert want.returncode == 0, want.stderr
    for column in ("Acc", "Acc (g)"):
        got = run(["compare", result, out, "--column", column, "--format", "csv"])
        assert got.returncode == 0 and got.stdout == want.stdout, got.stderr
    assert_refused(run(["compare", result, out]), EX_USAGE,
                   ["m.csv: 2 PSD columns (Acc, b, each titled with its unit) and no --column", "--column NAME"])
    one = tmp_path / "one.csv"
    assert run(["psd", sig, "--segment", SEGMENT, "--column", "Acc (g)", "--out", one]).returncode == 0
    got = run(["compare", result, one, "--format", "csv"])
    assert got.returncode == 0 and f"the PSD is column 'Acc [{UNIT}]', the only one" in got.stderr
    assert got.stdout == want.stdout.replace("m.csv", "one.csv")
    # edited after psd wrote it: the numbers are still read, the metadata is not trusted, and it says so
    one.write_text(one.read_text() + "\n")
    got = run(["compare", result, one, "--format", "csv"])
    assert got.returncode == 0 and "one.csv-metadata.json is ignored: it records another SHA-256" in got.stderr
    # the older marker-line format, and a PSD titled in g^2/Hz (read times g^2)
    table = pd.read_csv(tmp_path / "m.csv")
    old, in_g = tmp_path / "old.csv", tmp_path / "in-g.csv"
    rows = "".join(f"{f!r},{p!r}\n" for f, p in zip(table.iloc[:, 0], table.iloc[:, 1]))
    old.write_text("# rollspec-psd-csv: one-sided PSD in (m/s^2)^2/Hz, Welch\nfrequency_hz,Acc (g)\n" + rows)
    in_g.write_text("frequency_hz,acc [g^2/Hz]\n" +
                    "".join(f"{f!r},{p / G**2!r}\n" for f, p in zip(table.iloc[:, 0], table.iloc[:, 1])))
    got = run(["compare", result, old, "--format", "json"])
    assert got.returncode == 0, got.stderr
    levels = [b["measured_db"] for b in json.loads(got.stdout)["bands"]]
    got = run(["compare", result, in_g, "--format", "json"])
    assert got.returncode == 0 and "read in g^2/Hz by its title" in got.stderr, got.stderr
    np.testing.assert_allclose([b["measured_db"] for b in json.loads(got.stdout)["bands"]], levels, atol=1e-9)
    bad = tmp_path / "db.csv"
    bad.write_text("frequency_hz,level [dB/Hz]\n1,2\n3,4\n")
    assert_refused(run(["compare", result, bad]), EX_DATAERR, ["column 'level [dB/Hz]' is in 'dB/Hz' by its title"])


def test_rollspec_post_reads_both_formats(tmp_path):
    from rollspec_post.psd_table import read_measurement
    from rollspec_post.panel_csv import read_panel_csv
    from rollspec_post.result_file import PostError
    sig, x = signal(tmp_path)
    out, one = tmp_path / "m.csv", tmp_path / "one.csv"
    assert run(["psd", sig, "--segment", SEGMENT, "--out", out]).returncode == 0
    assert run(["psd", sig, "--segment", SEGMENT, "--column", "b [m/s²]", "--out", one]).returncode == 0
    f, p = welch(x * [G, 1.0])
    for path, column, k in ((out, "Acc", 0), (out, f"b [{UNIT}]", 1), (one, None, 1)):
        freq, psd = read_measurement(path, column)
        np.testing.assert_allclose(psd, p[:, k], rtol=1e-10, atol=1e-10 * p[:, k].max())
        np.testing.assert_allclose(read_panel_csv(path, column)[1], psd, rtol=0)
    with pytest.raises(PostError, match=r"2 PSD columns \(Acc, b\); name one with --column"):
        read_measurement(out)
    old = tmp_path / "old.csv"
    old.write_text("# rollspec-psd-csv: one-sided PSD in (m/s^2)^2/Hz, Welch\nfrequency_hz,acc\n0,1\n1,2\n")
    np.testing.assert_array_equal(read_measurement(old)[1], [1, 2])


def test_psd_of_a_result_file_says_what_reads_it(tmp_path, result):
    r = run(["psd", result])
    assert_refused(r, EX_DATAERR, ["r.h5: a rollspec result (HDF5), not a measured signal", "rollspec compare",
                                   "python3 -m rollspec_post psd"])
    assert len(r.stderr.strip().splitlines()) == 1 and "binary data" not in r.stderr
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = np.arange(10.0)
    assert_refused(run(["psd", other, "--fs", 10]), EX_DATAERR, ["other.h5: an HDF5 file, not a measured signal"])
