"""rollspec psd reads a channel's unit from its column name or a units row (`Acc (g)`, `a [g]`,
`Acceleration [m/s²]`, `acc [mm/s^2]`, `acc_g`, a `[g]` under the header), --unit overrides it, and every
choice is one line on stderr: a bare name, a sound file or a .mat variable without a unit is taken as m/s²
in a line that names --unit. Values in g read as m/s² would put the PSD 19.8 dB low without a word."""
import json

import numpy as np
import pandas as pd
import scipy.io
import scipy.io.wavfile

from conftest import EX_DATAERR, assert_refused, run

G = 9.80665
FS = 1024.0


def quantised(n=4096, seed=4):
    """Values printed exactly with three decimals, so every file holds the same doubles."""
    rng = np.random.default_rng(seed)
    return np.round(rng.standard_normal(n) * 1000) / 1000


def write(path, header, x, units=None, delimiter=","):
    rows = [delimiter.join(["time_s", header])] + ([delimiter.join(["s", units])] if units else [])
    rows += [f"{i / FS:.10f}{delimiter}{v:.3f}" for i, v in enumerate(x)]
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")


def psd(path, tmp_path, *args, name="out.csv"):
    out = tmp_path / name
    r = run(["psd", path, "--segment", 256, *args, "--out", out])
    assert r.returncode == 0, r.stderr
    return pd.read_csv(out).to_numpy(), r.stderr, out


def test_units_in_names_and_units_rows_read_as_the_right_unit_would(tmp_path):
    x = quantised()
    bare = tmp_path / "bare.csv"
    write(bare, "acc", x)
    plain, err, _ = psd(bare, tmp_path, name="plain.csv")
    assert "'acc': no unit in the column name or a units row: taken as m/s^2; --unit g if it holds g" in err
    cases = [("Acc (g)", None, "g", "g"), ("a [g]", None, "g", "g"), ("Acceleration [m/s²]", None, "m/s2", "m/s^2"),
             ("acc [mm/s^2]", None, "mm/s2", "mm/s^2"), ("acc_g", None, "g", "g"), ("a/(m/s^2)", None, "m/s2", "m/s^2"),
             ("Acc", "[g]", "g", "g"), ("Acc", "mm/s²", "mm/s2", "mm/s^2")]
    for k, (header, units, option, said) in enumerate(cases):
        f = tmp_path / f"named{k}.csv"
        write(f, header, x, units)
        got, err, out = psd(f, tmp_path, name=f"named{k}-psd.csv")
        want, _, _ = psd(bare, tmp_path, "--unit", option, name=f"want{k}.csv")
        np.testing.assert_array_equal(got, want)  # the same bits as with the right --unit
        where = "by its name" if units is None else "by the units row (line 2)"
        assert f"'{header}': read in {said}" in err and where in err, err
        meta = json.loads((tmp_path / f"named{k}-psd.csv-metadata.json").read_text())
        column = meta["tableSchema"]["columns"][1]
        assert (column["rollspec:channel"], column["rollspec:signal_unit"]) == (header, said)
        assert column["rollspec:signal_unit_origin"] == where.removeprefix("by ")
    assert not np.array_equal(want, plain)


def test_unit_overrides_the_file_and_says_so(tmp_path):
    x = quantised()
    f, bare = tmp_path / "g.csv", tmp_path / "bare.csv"
    write(f, "Acc (g)", x)
    write(bare, "acc", x)
    got, err, _ = psd(f, tmp_path, "--unit", "m/s2")
    np.testing.assert_array_equal(got, psd(bare, tmp_path, "--unit", "m/s2", name="b.csv")[0])
    assert "'Acc (g)': read in m/s^2 (--unit; it overrides g by its name)" in err
    _, err, _ = psd(f, tmp_path, "--unit", "g", name="same.csv")
    assert "(--unit; its name says so too)" in err


def test_a_channel_in_another_quantity_is_refused_unless_picked_away(tmp_path):
    x = quantised()
    f = tmp_path / "force.csv"
    f.write_text("time_s,F [N],acc [g]\n" + "".join(f"{i / FS:.10f},{v:.3f},{v:.3f}\n" for i, v in enumerate(x)))
    assert_refused(run(["psd", f, "--segment", 256]), EX_DATAERR,
                   ["force.csv: channel 'F [N]' is in N by its name, not an acceleration", "--column", "--unit UNIT"])
    got, _, _ = psd(f, tmp_path, "--column", "acc [g]")
    assert got.shape[1] == 2


def test_sound_and_mat_files_without_a_unit_say_what_they_assume(tmp_path):
    x = quantised()
    wav = tmp_path / "logger.wav"
    scipy.io.wavfile.write(wav, int(FS), np.round(x * 3000).astype(np.int16))
    _, err, _ = psd(wav, tmp_path, "--scale", 50)
    assert ("'channel_1': a sound file carries no unit: full scale (--scale 50) taken as 50 m/s^2; --unit g if the "
            "recorder's full scale is 50 g") in err
    flt = tmp_path / "float.wav"
    scipy.io.wavfile.write(flt, int(FS), x.astype(np.float32))
    _, err, _ = psd(flt, tmp_path, name="f.csv")
    assert "'channel_1': a sound file carries no unit: taken as m/s^2; --unit g if it holds g" in err
    mat = tmp_path / "rec.mat"
    scipy.io.savemat(mat, {"acc_g": x, "acc": x, "fs": FS})
    got, err, _ = psd(mat, tmp_path, name="m.csv")
    assert "'acc_g': read in g (9.80665 m/s^2 per g) by the name" in err
    assert "'acc': no unit in the variable's name: taken as m/s^2" in err
    np.testing.assert_allclose(got[:, 1], G**2 * got[:, 2], rtol=1e-12)
