"""A generated corpus of logger exports in the styles vendors write, all from one known signal: preambles,
units rows, ',', ';' and tabs, decimal commas, quoted names, CRLF, a UTF-8 byte-order mark, UTF-16 (LE and
BE with a byte-order mark), stamps in s, ms and µs (by name or by units row), several time columns,
several channels, units g, m/s² and mm/s² in names and in units rows, one gap, one repeat. Each file is
either read right (its PSD equals the clean file's times the unit's factor squared, to 1e-9, and the
lines that say the rate and each channel's unit are the right ones) or refused (exit 65 or 64) with a
message that names the line and the option that fixes it; where that option exists, the file is then
read right with it.

The signal is integers q over 1000 (printed with three decimals, exact), so every export holds the same
numbers to the last bit whatever its decimal mark, and the clean file's PSD is the reference."""
import dataclasses
import itertools

import numpy as np
import pandas as pd
import pytest

from conftest import EX_DATAERR, EX_USAGE, run

FS, N, SEGMENT = 1000.0, 2048, 256
G = 9.80665
UNITS = {"g": G, "m/s^2": 1.0, "mm/s^2": 1e-3}


def signals():
    rng = np.random.default_rng(48)
    t = np.arange(N) / FS
    a = np.round(1000 * (0.3 * np.sin(2 * np.pi * 87.0 * t) + 0.2 * rng.standard_normal(N))).astype(int)
    b = np.round(1000 * (0.1 * np.sin(2 * np.pi * 230.0 * t) + 0.4 * rng.standard_normal(N))).astype(int)
    return {"a": a, "b": b}


Q = signals()


@dataclasses.dataclass
class Channel:
    name: str      # as the header writes it
    unit: str      # what it holds: g, m/s^2 or mm/s^2
    signal: str    # a or b
    row: str = ""  # its cell in a units row, if the export writes one
    said: str = "read in"  # how the unit line must say it: "read in" (file or --unit) or "taken as"


@dataclasses.dataclass
class Export:
    name: str
    channels: list
    time: tuple = ("time_s", 1.0, 3, "")  # header name, seconds per unit, decimals, units-row cell; None: none
    delimiter: str = ","
    comma: bool = False                   # decimal comma
    preamble: tuple = ()
    units_row: bool = False
    units_above: bool = False             # the units row above the header instead of under it
    encoding: str = "utf-8"               # utf-8, utf-8-sig, utf-16-le+bom, utf-16-be+bom
    crlf: bool = False
    quote: bool = False
    start: float = 0.0                    # first stamp, s
    extra_time: tuple = None              # a second time column, as `time`
    drop: int = None                      # a missing sample
    repeat: int = None                    # a repeated row
    refused: tuple = None                 # (exit code, fragments that must be in the message)
    fix: tuple = ()                       # the options the refusal names, which then read it right
    rate_line: str = None                 # the line saying the rate (default: from the time column)


def stamp_text(i, time):
    name, seconds, decimals, _ = time
    return f"{i / FS / seconds:.{decimals}f}"


def text_of(e):
    d = e.delimiter
    cells = lambda row: d.join(f'"{c}"' if e.quote else c for c in row)
    header = ([e.time[0]] if e.time else []) + ([e.extra_time[0]] if e.extra_time else []) + [c.name for c in e.channels]
    units = cells(([e.time[3]] if e.time else []) + ([e.extra_time[3]] if e.extra_time else []) +
                  [c.row for c in e.channels])
    lines = list(e.preamble) + ([units] if e.units_above else []) + [cells(header)]
    if e.units_row and not e.units_above:
        lines.append(units)
    index = [i for i in range(N) if i != e.drop]
    if e.repeat is not None:
        index.insert(index.index(e.repeat), e.repeat)
    offset = int(round(e.start * FS))
    for i in index:
        row = ([stamp_text(i + offset, e.time)] if e.time else []) + \
              ([stamp_text(i + offset, e.extra_time)] if e.extra_time else []) + \
              [f"{Q[c.signal][i] / 1000:.3f}" for c in e.channels]
        if e.comma:
            row = [c.replace(".", ",") for c in row]
        lines.append(d.join(row))
    text = ("\r\n" if e.crlf else "\n").join(lines) + ("\r\n" if e.crlf else "\n")
    if e.encoding == "utf-16-le+bom":
        return b"\xff\xfe" + text.encode("utf-16-le")
    if e.encoding == "utf-16-be+bom":
        return b"\xfe\xff" + text.encode("utf-16-be")
    return text.encode(e.encoding)


LAYOUTS = [(",", False), (";", False), (";", True), ("\t", False), ("\t", True)]
TIMES = [("time_s", 1.0, 3, ""), ("Time (s)", 1.0, 6, ""), ("t [ms]", 1e-3, 0, ""), ("zeit_ms", 1e-3, 1, ""),
         ("t [µs]", 1e-6, 0, ""), ("Time", 1.0, 4, "[s]"), ("Zeit", 1e-3, 0, "ms"), ("time/ms", 1e-3, 2, "")]
ACCELERATIONS = [  # (header, units-row cell, unit it is in, how the unit line says it)
    ("Acc (g)", "", "g", "read in"), ("a [g]", "", "g", "read in"), ("acc_g", "", "g", "read in"),
    ("Acceleration [m/s²]", "", "m/s^2", "read in"), ("acc [mm/s^2]", "", "mm/s^2", "read in"),
    ("a (m/s^2)", "", "m/s^2", "read in"), ("Acceleration", "[m/s²]", "m/s^2", "read in"),
    ("acc", "g", "g", "read in"), ("Beschleunigung", "[mm/s²]", "mm/s^2", "read in"),
    ("sensor", "", "m/s^2", "taken as")]
ENCODINGS = ["utf-8", "utf-8-sig", "utf-16-le+bom", "utf-16-be+bom"]
PREAMBLES = [(), ("Logger XY-200 serial 1234", "Date;2024-05-01;10:31:07", "Sample rate: 1000 Hz"),
             ("# exported by DAQ 7.1", "", "Device: rig 2", "Channels: 2", "")]


def mixed():
    """Styles crossed with periods that share no factor, so that every value of each meets many others."""
    out = []
    for k in range(50):
        delimiter, comma = LAYOUTS[k % 5]
        time = TIMES[k % 8]
        name, row, unit, said = ACCELERATIONS[k % 10]
        second = ACCELERATIONS[(k + 3) % 10]
        channels = [Channel(name, unit, "a", row, said)]
        if k % 3 == 0 and second[0] != name:
            channels.append(Channel(second[0], second[2], "b", second[1], second[3]))
        units_row = bool(time[3]) or any(c.row for c in channels)
        if units_row:  # a units row has a cell for every column
            time = time[:3] + (time[3] or {1.0: "s", 1e-3: "[ms]", 1e-6: "[µs]"}[time[1]],)
            for c in channels:
                if not c.row and c.said == "read in":
                    c.row = {"g": "(g)", "m/s^2": "m/s^2", "mm/s^2": "[mm/s²]"}[c.unit]
        out.append(Export(f"mixed-{k:02d}", channels, time, delimiter=delimiter, comma=comma, preamble=PREAMBLES[k % 3],
                          units_row=units_row, encoding=ENCODINGS[k % 4], crlf=k % 2 == 1, quote=k % 7 == 3,
                          start=(k % 4) * 2.5))
    return out


def special():
    acc = [Channel("Acc (g)", "g", "a")]
    fix_fs = ("--fs", FS)
    return [
        Export("gap-6-decimals", acc, ("time_s", 1.0, 6, ""), drop=500,
               refused=(EX_DATAERR, ["gap-6-decimals.csv:502: time column 'time_s' steps by 0.002", "--fs HZ"])),
        Export("gap-integer-ms", acc, ("time_ms", 1e-3, 0, ""), drop=500,
               refused=(EX_DATAERR, ["gap-integer-ms.csv:502: time column 'time_ms' steps by 2 (from 499 to 501)",
                                     "cannot show a missing or repeated sample", "--fs HZ"])),
        Export("repeat", acc, ("t [ms]", 1e-3, 1, ""), delimiter=";", comma=True, repeat=700,
               refused=(EX_DATAERR, ["repeat.csv:703: time column 't [ms]' value 700 does not increase", "--fs HZ"])),
        Export("coarse-stamps", acc, ("time_s", 1.0, 2, ""),
               refused=(EX_DATAERR, ["coarse-stamps.csv:", "stamps printed to the nearest 0.01 cannot show a missing",
                                     "--fs HZ, which overrides the time column"]), fix=fix_fs,
               rate_line="--fs 1000 Hz overrides the time column 'time_s'"),
        Export("no-time-column", acc, None,
               refused=(EX_USAGE, ["no-time-column.csv: no sample rate", "give --fs HZ"]), fix=fix_fs,
               rate_line=None),
        Export("one-column-decimal-comma", [Channel("Acc (g)", "g", "a")], None, comma=True,
               refused=(EX_USAGE, ["give --fs HZ"]), fix=fix_fs, rate_line=None),
        Export("two-time-columns", acc + [Channel("acc_y [mm/s²]", "mm/s^2", "b")], ("time_s", 1.0, 3, ""),
               extra_time=("time_ms", 1e-3, 0, ""), delimiter=";", comma=True),
        Export("two-time-columns-disagree", acc, ("time_s", 1.0, 3, ""), extra_time=("t_ms", 1e-3 / 1.01, 4, ""),
               refused=(EX_DATAERR, ["2 time columns that disagree", "--time-column NAME"]),
               fix=("--time-column", "time_s", "--column", "Acc (g)")),
        Export("three-units", [Channel("ax (g)", "g", "a"), Channel("ay [m/s²]", "m/s^2", "b"),
                               Channel("az [mm/s^2]", "mm/s^2", "a")], delimiter="\t", comma=True),
        Export("units-row-and-name-disagree", [Channel("Acc (g)", "g", "a", "[m/s²]")], ("Time", 1.0, 3, "[s]"),
               delimiter="\t", units_row=True,
               refused=(EX_DATAERR, ["units-row-and-name-disagree.csv:2: column 'Acc (g)' is in g by its name but in "
                                     "m/s^2 by the units row", "--unit UNIT"]),
               fix=("--unit", "g")),
        Export("force-channel", acc + [Channel("F [N]", "g", "b")], delimiter=";",
               refused=(EX_DATAERR, ["channel 'F [N]' is in N by its name, not an acceleration", "--column"]),
               fix=("--column", "Acc (g)")),
        Export("units-row-above-header", [Channel("acc", "g", "a", "[g]")], ("time", 1.0, 3, "[s]"), units_row=True,
               units_above=True, preamble=("Logger ZZ",)),
        Export("long-preamble-table", acc, preamble=("Calibration", "frequency,sensitivity,phase") +
               tuple(f"{10 + i},{1 + i / 1e4:.4f},{i / 100:.2f}" for i in range(1900))),
        Export("preamble-table-same-width", [Channel("acc [g]", "g", "a")],
               preamble=("Calibration", "f_hz,sens") + tuple(f"{10 + i},{1 + i / 1e4:.4f}" for i in range(1500))),
        Export("bare-t-temperature", [Channel("T", "m/s^2", "b", said="taken as"), Channel("acc (g)", "g", "a")],
               ("time_us", 1e-6, 0, ""), delimiter=";"),
        Export("ini-sections", [Channel("acc", "m/s^2", "a", said="taken as")], ("Time [s]", 1.0, 3, ""),
               preamble=("[Header]", "Device=XY-3", "[Data]"), delimiter="\t"),
        Export("crlf-quoted-bom", [Channel("Accel X (g)", "g", "a"), Channel("Accel Y (g)", "g", "b")],
               ("Time [s]", 1.0, 3, ""), encoding="utf-8-sig", crlf=True, quote=True, delimiter=";", comma=True),
    ]


CORPUS = mixed() + special()


def test_the_corpus_is_large_and_varied():
    assert len(CORPUS) >= 60
    names = {c.name for e in CORPUS for c in e.channels}
    assert {"Acc (g)", "a [g]", "acc_g", "Acceleration [m/s²]", "acc [mm/s^2]"} <= names
    for need in (lambda e: e.comma, lambda e: e.delimiter == "\t", lambda e: e.delimiter == ";", lambda e: e.units_row,
                 lambda e: e.encoding == "utf-16-le+bom", lambda e: e.encoding == "utf-16-be+bom",
                 lambda e: e.encoding == "utf-8-sig", lambda e: e.preamble, lambda e: len(e.channels) > 1,
                 lambda e: bool(e.time) and e.time[1] == 1e-6, lambda e: bool(e.time) and e.time[1] == 1e-3,
                 lambda e: e.crlf, lambda e: e.quote):
        assert sum(bool(need(e)) for e in CORPUS) >= 3


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The clean file's PSD: time_s and the two signals in m/s² (the same numbers every export prints)."""
    d = tmp_path_factory.mktemp("clean")
    clean = d / "clean.csv"
    clean.write_text("time_s,a,b\n" + "".join(f"{i / FS:.3f},{Q['a'][i] / 1000:.3f},{Q['b'][i] / 1000:.3f}\n"
                                               for i in range(N)))
    out = d / "clean-psd.csv"
    r = run(["psd", clean, "--segment", SEGMENT, "--out", out])
    assert r.returncode == 0, r.stderr
    table = pd.read_csv(out)
    return table["frequency_hz"].to_numpy(), {k: table[f"{k} [(m/s^2)^2/Hz]"].to_numpy() for k in "ab"}


def assert_read_right(e, path, args, reference, tmp_path):
    out = tmp_path / (e.name + "-psd.csv")
    r = run(["psd", path, "--segment", SEGMENT, *args, "--out", out])
    assert r.returncode == 0, f"{e.name}: {r.stderr}"
    table = pd.read_csv(out)
    freq, ref = reference
    np.testing.assert_allclose(table["frequency_hz"], freq, rtol=1e-9, atol=0)
    picked = [c for c in e.channels if "--column" not in args or c.name in args]
    assert table.shape[1] == 1 + len(picked), (e.name, list(table.columns))
    for k, c in enumerate(picked):
        factor = UNITS[c.unit] ** 2
        np.testing.assert_allclose(table.iloc[:, 1 + k], factor * ref[c.signal], rtol=1e-9,
                                   atol=1e-9 * factor * ref[c.signal].max(), err_msg=f"{e.name}: {c.name}")
        if "--unit" not in args:
            line = next((s for s in r.stderr.splitlines() if f"'{c.name}'" in s and ("read in" in s or "taken as" in s)),
                        "")
            assert f"{c.said} {c.unit}" in line, (e.name, c.name, r.stderr)
    rate = e.rate_line
    if rate is None and "--fs" in args:
        rate = "" if e.time is None else "--fs 1000 Hz overrides"
    elif rate is None and "--time-column" in args:
        rate = f"sample rate 1000 Hz from the time column '{args[args.index('--time-column') + 1]}'"
    elif rate is None:
        rate = f"sample rate 1000 Hz from the time column '{e.time[0]}'"
    assert rate in r.stderr, (e.name, r.stderr)


@pytest.mark.parametrize("e", CORPUS, ids=lambda e: e.name)
def test_each_export_is_read_right_or_refused_naming_the_fix(e, reference, tmp_path):
    path = tmp_path / (e.name + ".csv")
    path.write_bytes(text_of(e))
    if e.refused is None:
        assert_read_right(e, path, [], reference, tmp_path)
        return
    code, fragments = e.refused
    r = run(["psd", path, "--segment", SEGMENT])
    assert r.returncode == code, f"{e.name}: exit {r.returncode}: {r.stderr}"
    assert len(r.stderr.strip().splitlines()) >= 1 and "Traceback" not in r.stderr
    error = [s for s in r.stderr.splitlines() if "error:" in s]
    assert len(error) == 1, r.stderr
    for f in fragments:
        assert f in error[0], (e.name, f, error[0])
    if e.fix:
        assert e.fix[0] in error[0]
        assert_read_right(e, path, list(e.fix), reference, tmp_path)


@pytest.mark.parametrize("encoding,bom", [("utf-16-le", b""), ("utf-32", b"")])
def test_text_that_cannot_be_read_as_utf8_is_refused_naming_the_fix(encoding, bom, tmp_path):
    path = tmp_path / "wide.csv"
    path.write_bytes(bom + "time_s,acc (g)\n0.000,1.5\n0.001,1.25\n".encode(encoding))
    r = run(["psd", path, "--segment", 4])
    assert r.returncode == EX_DATAERR and "re-save the file as UTF-8" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
