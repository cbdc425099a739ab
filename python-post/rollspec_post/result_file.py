"""Opening rollspec HDF5 files with the checks every reader makes: the file exists, is HDF5, carries
the expected filetype and a schema major version this package reads (OpenMC state_point habit).
h5py is imported on first use, so a Python without it gets one line from __main__, not a traceback."""
import numpy as np

# sysexits.h
EX_USAGE, EX_DATAERR, EX_NOINPUT, EX_UNAVAILABLE, EX_SOFTWARE, EX_CANTCREAT, EX_IOERR = 64, 65, 66, 69, 70, 73, 74
# Every filetype the engine writes (grep '"rollspec-' src): the result (io/provenance.hpp), the texture
# (cli/texture_command.cpp) and the cached tables (stiffness/cached_table.cpp, schema "1.0").
KNOWN_SCHEMA_MAJOR = {"rollspec-result": 2, "rollspec-texture": 1, "rollspec-stiffness-table": 1,
                      "rollspec-blocked-force": 1, "rollspec-path-table": 1, "rollspec-equivalent-roughness": 1}


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
    import h5py
    from .safe_output import check_input
    check_input(path, "a rollspec HDF5 file")  # a FIFO or device would block or never end
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
    try:
        return f[name][()]
    except (OSError, KeyError, TypeError, AttributeError) as e:  # a group, or a damaged dataset
        raise PostError(f"{f.filename}: {name} cannot be read as a dataset ({e})", EX_DATAERR) from None


def read_rows(f, name, ndim):
    """A dataset of `ndim` dimensions as floats (a row per sensor for the PSDs)."""
    v = read(f, name)
    try:
        v = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise PostError(f"{f.filename}: {name} is not numeric", EX_DATAERR) from None
    if v.ndim != ndim:
        raise PostError(f"{f.filename}: {name} has shape {v.shape}; expected {ndim} dimension(s)", EX_DATAERR)
    return v


def attr(f, obj, name, kind=float):
    """Attribute `name` of the group or dataset `obj` as one number; a clear error when it is missing."""
    if obj not in f:
        raise PostError(f"{f.filename}: has no {obj} (needed for its attribute {name})", EX_DATAERR)
    attrs = f[obj].attrs
    if name not in attrs:
        raise PostError(f"{f.filename}: {obj} lacks the attribute {name}", EX_DATAERR)
    try:
        return kind(np.reshape(attrs[name], -1)[0])
    except (TypeError, ValueError, IndexError, OSError):
        raise PostError(f"{f.filename}: attribute {obj}@{name} is not a number", EX_DATAERR) from None


def strings(f, name):
    """A dataset of names (sensors) as str."""
    return [v.decode(errors="replace") if isinstance(v, bytes) else str(v) for v in np.reshape(read(f, name), -1)]


def sensor_labels(f, group="/psd"):
    """The group's sensor names with their positions where the result records them ("sensor_2
    (0.2 m)", from <group>/sensor_position); the name alone for sensor_mean, which is at no one place,
    and for results written before positions were a coordinate."""
    names = strings(f, group + "/sensor")
    if group + "/sensor_position" not in f:
        return names
    pos = read_rows(f, group + "/sensor_position", 1)
    if pos.size != len(names):
        raise PostError(f"{f.filename}: {group}/sensor_position has {pos.size} values; expected {len(names)} "
                        f"(one per name of {group}/sensor)", EX_DATAERR)
    return [f"{n} ({p:g} m)" if np.isfinite(p) else n for n, p in zip(names, pos)]


def scalar(f, name, default=None):
    """A one-element dataset as a float, or `default` when absent (optional key figures)."""
    if name not in f:
        return default
    v = np.reshape(read(f, name), -1)
    try:
        return float(v[0])
    except (IndexError, TypeError, ValueError):
        raise PostError(f"{f.filename}: {name} is not one number", EX_DATAERR) from None


def is_dimension_scale(obj):
    """An HDF5 dimension scale (CLASS = DIMENSION_SCALE, e.g. the engine's `kinetic_index`): it labels
    another dataset's axis and is no data series. Debian 12's h5py has no Dataset.is_scale."""
    v = obj.attrs.get("CLASS") if hasattr(obj, "attrs") else None
    v = v.decode(errors="replace") if isinstance(v, bytes) else str(v)
    return v == "DIMENSION_SCALE"


def sensor_row(names, sensor=None):
    """The row drawn (and the one `rollspec compare` uses): a name, or the number K of the name sensor_K
    (1-based, as the names and the study's [sensors] positions count); by default sensor_mean if present,
    else the first."""
    if not names:
        raise PostError("the result names no sensors (/psd/sensor is empty); nothing to draw or compare", EX_DATAERR)
    if sensor is None:
        return names.index("sensor_mean") if "sensor_mean" in names else 0
    name = f"sensor_{int(sensor)}" if str(sensor).isdigit() else str(sensor)
    if name in names:
        return names.index(name)
    raise PostError(f"--sensor {sensor}: the result has the sensors {', '.join(names)}; allowed: a name, or the "
                    "number K of sensor_K", EX_USAGE)


BAND_EDGES = ("nominal_frequency", "lower_frequency", "upper_frequency")
BAND_ROWS = ("level_db", "ci_lower_db", "ci_upper_db")  # sensors x bands


def read_bands(f):
    """The result's third-octave bands as drawn: edges, each sensor's level and interval, the sensor names,
    the realisations and the confidence level."""
    bands = {}
    for n in BAND_EDGES + BAND_ROWS:
        try:
            bands[n] = np.asarray(read(f, "/bands/" + n), float)
        except (TypeError, ValueError):
            raise PostError(f"{f.filename}: /bands/{n} is not numeric", EX_DATAERR) from None
    bands["sensor"] = strings(f, "/bands/sensor")
    bands["realisations"] = attr(f, "/psd", "realisations", int)
    bands["confidence"] = attr(f, "/psd", "confidence_level") if "confidence_level" in f["/psd"].attrs else 0.95
    n, rows = bands["lower_frequency"].shape, (len(bands["sensor"]),) + bands["lower_frequency"].shape
    wrong = [b for b in BAND_EDGES if bands[b].shape != n or bands[b].ndim != 1] + \
            [b for b in BAND_ROWS if bands[b].shape != rows]
    if wrong:
        raise PostError(f"{f.filename}: /bands/{wrong[0]} has shape {bands[wrong[0]].shape}; expected "
                        f"{n if wrong[0] in BAND_EDGES else rows} (sensors x bands)", EX_DATAERR)
    return bands
