"""Opening rollspec HDF5 files with the checks every reader makes: the file exists, is HDF5, carries
the expected filetype and a schema major version this package reads (OpenMC state_point habit)."""
import os

import h5py

EX_USAGE, EX_DATAERR, EX_NOINPUT, EX_CANTCREAT = 64, 65, 66, 73
KNOWN_SCHEMA_MAJOR = {"rollspec-result": 2, "rollspec-texture": 1, "rollspec-stiffness-table": 1,
                      "rollspec-blocked-force": 1}


class PostError(Exception):
    """A user-facing error with the exit code the command returns."""

    def __init__(self, message, exit_code):
        super().__init__(message)
        self.exit_code = exit_code


def text_attr(obj, name, default=None):
    if name not in obj.attrs:
        return default
    v = obj.attrs[name]
    if isinstance(v, bytes):
        return v.decode()
    if hasattr(v, "shape") and v.shape == (1,):
        return v[0]
    return v


def open_rollspec(path, filetypes=("rollspec-result",)):
    if not os.path.exists(path):
        raise PostError(f"{path}: no such file", EX_NOINPUT)
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise PostError(f"{path}: not a readable HDF5 file ({e})", EX_DATAERR) from None
    filetype = text_attr(f, "filetype")
    if filetype not in filetypes:
        f.close()
        raise PostError(f"{path}: not a rollspec file of type {' or '.join(filetypes)} (filetype: {filetype!r})",
                        EX_DATAERR)
    version = str(text_attr(f, "schema_version", ""))
    major = int(version.split(".")[0]) if version.split(".")[0].isdigit() else -1
    if major != KNOWN_SCHEMA_MAJOR[filetype]:
        f.close()
        raise PostError(f"{path}: schema_version {version!r} is not readable by rollspec_post "
                        f"(reads major version {KNOWN_SCHEMA_MAJOR[filetype]})", EX_DATAERR)
    return f


def read(f, name):
    """Dataset `name` as an array; a clear error (not a KeyError) when the file lacks it."""
    if name not in f:
        raise PostError(f"{f.filename}: has no {name}", EX_DATAERR)
    return f[name][()]


def scalar(f, name, default=None):
    """A one-element dataset as a float, or `default` when absent (optional key figures)."""
    if name not in f:
        return default
    return float(f[name][()].reshape(-1)[0])
