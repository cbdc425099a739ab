"""Every CSV rollspec writes loads with pandas.read_csv(path) and numpy.genfromtxt(path, delimiter=',',
names=True) at their defaults: the header is the first line, one name per column, the same numbers in
both. The writers: `rollspec psd` (--out and stdout, channel names with delimiters, '#', µ and units),
the benchmark scripts' measured PSDs (bench/engine/bench_compare_power.py), and the CSV files the
repository's scripts made (studies/data, python-post/docs). `compare --format csv` has its own test
(test_compare.py). The other commands print tables for people (modes, stiffness, texture, fit), not CSV."""
import importlib.util
import io

import numpy as np
import pandas as pd
import pytest

from conftest import SOURCE, oscillator_study, run


def assert_both_readers_load(path_or_text, columns=None):
    """pandas and numpy at their defaults: the same shape, names and numbers (pandas' default float parser
    is not the exact one: it may miss 17-digit values by 1e-13 relative)."""
    source = (lambda: io.StringIO(path_or_text)) if isinstance(path_or_text, str) else (lambda: path_or_text)
    table = pd.read_csv(source())
    array = np.genfromtxt(source(), delimiter=",", names=True)
    assert len(array.dtype.names) == table.shape[1], (array.dtype.names, list(table.columns))
    assert all(t.kind == "f" for t, *_ in array.dtype.fields.values())
    assert all(pd.api.types.is_numeric_dtype(t) for t in table.dtypes)
    values = np.column_stack([array[n] for n in array.dtype.names]).reshape(table.shape)
    np.testing.assert_allclose(values, table.to_numpy(dtype=float), rtol=1e-12, atol=0)
    assert not np.isnan(values).any()
    if columns is not None:
        assert list(table.columns) == columns
    return table


def test_psd_output_to_a_file_and_to_stdout(tmp_path):
    rng = np.random.default_rng(11)
    sig = tmp_path / "export.csv"
    names = ["Zeit [ms]", "Sensor #1 (g)", "a; b [m/s²]", 'say "x" [µm/s^2]', "acc (g)", "acc [mm/s2]"]
    x = np.round(rng.standard_normal((4096, 5)) * 1e3) / 1e3
    sig.write_text("\t".join(names) + "\n" + "".join(
        "\t".join([f"{i:.1f}"] + [f"{v:.3f}" for v in row]) + "\n" for i, row in enumerate(x)), encoding="utf-8")
    out = tmp_path / "m.csv"
    r = run(["psd", sig, "--segment", 512, "--out", out])
    assert r.returncode == 0, r.stderr
    unit = " [(m/s^2)^2/Hz]"
    table = assert_both_readers_load(out, ["frequency_hz", "Sensor _1" + unit, "a_ b" + unit, "say _x_" + unit,
                                           "acc (g)" + unit, "acc [mm/s2]" + unit])
    assert table.shape == (257, 6)
    r = run(["psd", sig, "--segment", 512])
    assert r.returncode == 0
    assert_both_readers_load(r.stdout, list(table.columns))


def test_the_benchmarks_measured_psd(tmp_path):
    spec = importlib.util.spec_from_file_location("bench_compare_power",
                                                  SOURCE / "bench" / "engine" / "bench_compare_power.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    result = tmp_path / "r.h5"
    assert run(["run", oscillator_study(tmp_path), "--out", result, "--quiet"]).returncode == 0
    bench.measurement_csv(result, tmp_path / "m.csv")
    assert_both_readers_load(tmp_path / "m.csv", ["frequency_hz", "psd"])


@pytest.mark.parametrize("name", ["studies/data/measured-psd.csv", "studies/data/seed001-profiles/beam-s-01.csv",
                                  "studies/data/seed001-profiles/beam-r-15.csv", "python-post/docs/work-precision.csv"])
def test_the_csv_files_the_repository_scripts_made(name):
    path = SOURCE / name
    if name.endswith("work-precision.csv"):  # text columns (the method) beside the numbers: NaN in numpy
        table = pd.read_csv(path)
        array = np.genfromtxt(path, delimiter=",", names=True)
        assert list(array.dtype.names) == list(table.columns) and len(array) == len(table)
        for c in table.select_dtypes("number"):
            np.testing.assert_allclose(array[c], table[c], rtol=1e-12)
        return
    assert_both_readers_load(path)
