"""Notebook access: `open_result` reads every group of a rollspec file as xarray Datasets, and
`run` runs the engine from Python and opens what it wrote."""
import subprocess

import h5py

from .engine_compare import engine_binary
from .result_file import EX_USAGE, KNOWN_SCHEMA_MAJOR, PostError, open_rollspec

FILETYPES = tuple(KNOWN_SCHEMA_MAJOR)  # every file kind the engine writes


def open_result(path):
    """{group: xarray.Dataset} for every group of a rollspec file ("/" holds the root attributes:
    provenance and the resolved study). The data are loaded, the file is closed."""
    import xarray as xr
    with open_rollspec(path, FILETYPES) as f:
        groups = ["/"]
        f.visititems(lambda name, obj: groups.append("/" + name) if isinstance(obj, h5py.Group) else None)
    out = {}
    for g in groups:
        # phony_dims: tables without dimension scales (the cached tables) open too
        with xr.open_dataset(path, engine="h5netcdf", group=g, phony_dims="sort") as ds:
            out[g.strip("/") or "/"] = ds.load()
    return out


def run(study, out, set=None, quiet=True, sweep=None):  # noqa: A002 (the engine's own word for it)
    """Runs `rollspec run STUDY --out OUT --set k=v ... --sweep k=v1,v2 ...` and returns open_result(OUT).
    `sweep`: {"ball.speed": [1, 2, 3]} runs one point per value (added to the study's [sweep]). A
    refused or failed run raises PostError with the engine's message and exit code."""
    args = [engine_binary(), "run", str(study), "--out", str(out)]
    for key, value in (set or {}).items():
        if "=" in str(key) or "\n" in f"{key}{value}":
            raise PostError(f"set: key {key!r} = {value!r}: allowed: section.key and a one-line value", EX_USAGE)
        args += ["--set", f"{key}={value}"]
    for key, values in (sweep or {}).items():
        values = [values] if isinstance(values, (str, int, float)) else list(values)
        text = ",".join(str(v) for v in values)
        if "=" in str(key) or "\n" in f"{key}{text}" or not values:
            raise PostError(f"sweep: key {key!r} = {values!r}: allowed: section.key and a list of values", EX_USAGE)
        args += ["--sweep", f"{key}={text}"]
    if quiet:
        args.append("--quiet")
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        raise PostError(r.stderr.strip() or f"rollspec run exited {r.returncode}", r.returncode)
    return open_result(out)
