"""Converts three measured line scans from SurfaceTopography's test data (MIT licence, see
README.md) into rollspec profile files (position_m,height_m), each scan cut into two halves, the
two profiles a PSD estimate needs.

    /usr/bin/python3 make_measured_profiles.py DIR   # DIR holds dektak-1.csv, opdx-3.txt, xy-4.txt
"""
import io
import os
import pathlib
import sys

import numpy as np


def dektak(path):
    """Bruker Dektak stylus export: 1500 um scan, 9600 samples; lateral column rounded to 0.1 um,
    so positions come from the stated length; heights in um."""
    lines = path.read_text(encoding="latin-1").splitlines()
    start = lines.index("Lateral um,Raw Micrometer,") + 1
    z = np.array([float(l.split(",")[1]) for l in lines[start:] if l[:1] and l[0] in "-0123456789"]) * 1e-6
    return np.arange(z.size) * 1500e-6 / z.size, z


def opdx(path):
    """Bruker OPDx stylus export: position and height in m."""
    d = np.loadtxt(path)
    return d[:, 0], d[:, 1]


def xy4(path):
    """Stylus line scan, position and height in um (as SurfaceTopography's own tests read it)."""
    d = np.loadtxt(path)
    x = (d[:, 0] - d[0, 0]) * 1e-6
    return np.arange(x.size) * (x[-1] / (x.size - 1)), d[:, 1] * 1e-6


def main(src):
    src = pathlib.Path(src)
    names = [f"{name}-{part}.csv" for name in ("dektak-1", "opdx-3", "xy-4") for part in "ab"]
    targets = {n: check_output_file(pathlib.Path(__file__).with_name(n), "profile", own=starts_with(b"position_m,height_m"))
               for n in names}  # every output checked before any is written
    for name, reader, file in [("dektak-1", dektak, "dektak-1.csv"), ("opdx-3", opdx, "opdx-3.txt"), ("xy-4", xy4, "xy-4.txt")]:
        x, z = reader(src / file)
        n = z.size // 2
        dx = (x[-1] - x[0]) / (x.size - 1)
        for part, sl in (("a", slice(0, n)), ("b", slice(n, 2 * n))):
            text = io.StringIO()
            np.savetxt(text, np.c_[np.arange(n) * dx, z[sl]], delimiter=",", header="position_m,height_m", comments="",
                       fmt="%.10e")
            write_output_file(targets[f"{name}-{part}.csv"], text.getvalue().encode())


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../python-post"))
from rollspec_post.script_main import check_output_file, starts_with, write_output_file, script_main  # noqa: E402  (one line per failure, no traceback)


def checked_main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit("make_measured_profiles: error: usage: make_measured_profiles.py SOURCE_DIR (the folder of "
                 "dektak-1.csv, opdx-3.txt and xy-4.txt)")
    main(sys.argv[1])


if __name__ == "__main__":
    script_main(checked_main)
