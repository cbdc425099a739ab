"""Converts measured scans from SurfaceTopography's test data (MIT licence, see README.md) into
rollspec profile files (position_m,height_m or position_m,height_um), each scan whole and with its
numbers as the instrument printed them: a length in mm or um becomes metres by moving the decimal
point, so a position keeps exactly its printed digits (and its rounding, which `[texture] source =
profiles` accepts). Only the AFM map (binary) is scaled: its integer counts times the header's factor.

    /usr/bin/python3 make_measured_profiles.py DIR   # DIR holds the files named in SOURCES
"""
import decimal
import io
import os
import pathlib
import re
import sys
import zipfile

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent


def shifted(text, places):
    """The decimal `text` times 10^-places, as text with the same digits (no binary rounding)."""
    return format(decimal.Decimal(text.strip()).scaleb(-places), "f")


def dektak(path):
    """Bruker Dektak export: lateral um (printed to 0.1 um for 0.156 um steps), raw um."""
    lines = path.read_text(encoding="latin-1").splitlines()
    start = lines.index("Lateral um,Raw Micrometer,") + 1
    rows = [line.split(",")[:2] for line in lines[start:] if line[:1] and line[0] in "-0123456789"]
    return "position_m,height_um", [(shifted(x, 6), z) for x, z in rows]


def opdx(path):
    """Bruker OPDx export: position and height in m."""
    return "position_m,height_m", [tuple(line.split()) for line in path.read_text().splitlines() if line.strip()]


def xy4(path):
    """Stylus line scan, position and height in um (as SurfaceTopography's tests read it)."""
    rows = [line.split() for line in path.read_text().splitlines() if line.strip()]
    return "position_m,height_um", [(shifted(x, 6), z) for x, z in rows]


def hfm(path):
    """Stylus export X;Y;valid in mm, printed to 1 nm; rows flagged invalid (none here) left out."""
    rows = [line.split(";") for line in path.read_text().splitlines()[2:] if line.strip()]
    return "position_m,height_m", [(shifted(x, 3), shifted(z, 3)) for x, z, valid in rows if valid.strip() == "1"]


def mitutoyo(path):
    """Mitutoyo spreadsheet: sheet 2 column E position in mm, F height in um (shortest decimals, as a
    spreadsheet shows the stored values)."""
    sheet = zipfile.ZipFile(path).read("xl/worksheets/sheet2.xml").decode()
    cells = {(c, int(r)): v for c, r, v in re.findall(r'<c r="([A-Z]+)(\d+)"[^>]*?>(?:<f>.*?</f>)?<v>(.*?)</v></c>',
                                                      sheet)}
    rows, r = [], 1
    while ("E", r) in cells:
        rows.append((shifted(repr(float(cells[("E", r)])), 3), repr(float(cells[("F", r)]))))
        r += 1
    return "position_m,height_um", rows


def wsxm_heights(path):
    """WSxM AFM map (600 nm square, 256 x 256 int16): heights in metres, rows along the fast scan axis,
    = counts * Z Amplitude / (Maximum - Minimum) as SurfaceTopography scales them."""
    data = path.read_bytes()
    header = data[:2245].decode("latin-1")
    value = lambda key: float(re.search(key + r":\s*([-0-9.eE+]+)", header).group(1))
    scale = value("Z Amplitude") * 1e-9 / (value("Maximum") - value("Minimum"))
    counts = np.frombuffer(data[2245:2245 + 2 * 256 * 256], dtype="<i2").reshape(256, 256)
    return counts.astype("<f8") * scale


def wsxm_rows(path, every=16):
    """Every 16th row of the map as a profile (pixel 600 nm / 256), heights to 6 significant digits."""
    dx = 600e-9 / 256
    for row, heights in list(enumerate(wsxm_heights(path)))[::every]:
        yield row, "position_m,height_m", [(repr(i * dx), f"{h:.6g}") for i, h in enumerate(heights)]


def wsxm_map(path):
    """The map whole, as a .npy that numpy.load reads (float64, metres)."""
    out = io.BytesIO()
    np.save(out, wsxm_heights(path))
    return out.getvalue()


def text_of(header, rows):
    return (header + "\n" + "".join(f"{a},{b}\n" for a, b in rows)).encode()


SOURCES = [("dektak-1", dektak, "dektak-1.csv"), ("opdx-3", opdx, "opdx-3.txt"), ("xy-4", xy4, "xy-4.txt"),
           ("hfm-1", hfm, "hfm-1.hfm"), ("mitutoyo-2", mitutoyo, "mitutoyo_2_mock.xlsx")]


def main(src):
    src = pathlib.Path(src)
    outputs = {f"{name}.csv": text_of(*reader(src / file)) for name, reader, file in SOURCES}
    for row, header, rows in wsxm_rows(src / "top-1.top"):
        outputs[f"top-1-rows/row-{row:03d}.csv"] = text_of(header, rows)
    outputs["top-1-map.npy"] = wsxm_map(src / "top-1.top")
    (HERE / "top-1-rows").mkdir(exist_ok=True)
    own = lambda n: starts_with(b"\x93NUMPY" if n.endswith(".npy") else b"position_m,height_")
    targets = {n: check_output_file(HERE / n, "profile", own=own(n)) for n in outputs}  # every one before any write
    for name, data in outputs.items():
        write_output_file(targets[name], data)


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../python-post"))
from rollspec_post.script_main import check_output_file, starts_with, write_output_file, script_main  # noqa: E402  (one line per failure, no traceback)


def checked_main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit("make_measured_profiles: error: usage: make_measured_profiles.py SOURCE_DIR (the folder of the "
                 "SurfaceTopography files named in SOURCES)")
    main(sys.argv[1])


if __name__ == "__main__":
    script_main(checked_main)
