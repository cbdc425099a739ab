"""Opening rollspec HDF5 files with the checks every reader makes: the file exists, is HDF5, carries
the expected filetype and a schema major version this package reads (OpenMC state_point habit).
h5py is imported on first use, so a Python without it gets one line from __main__, not a traceback."""
import numpy as np

# PostError and the exit codes live in post_error (which safe_output imports too); named here as well, where
# the package's modules and notebook users have always imported them.
from .post_error import (EX_CANTCREAT, EX_DATAERR, EX_IOERR, EX_NOINPUT, EX_SOFTWARE,  # noqa: F401
                         EX_UNAVAILABLE, EX_USAGE, PostError)
from .safe_output import check_input

# Every filetype the engine writes (grep '"rollspec-' src): the result (io/provenance.hpp), the texture
# (cli/texture_command.cpp) and the cached tables (stiffness/cached_table.cpp, schema "1.0").
KNOWN_SCHEMA_MAJOR = {"rollspec-result": 2, "rollspec-texture": 1, "rollspec-stiffness-table": 1,
                      "rollspec-blocked-force": 1, "rollspec-path-table": 1, "rollspec-equivalent-roughness": 1}


def as_text(v):
    """Bytes or a string h5py decoded with surrogate escapes, as printable text (bad bytes replaced)."""
    if isinstance(v, bytes):
        return v.decode("utf-8", errors="replace")
    if isinstance(v, str):
        return v.encode("utf-8", errors="surrogateescape").decode("utf-8", errors="replace")
    return v


def text_attr(obj, name, default=None):
    """An attribute as text (a one-element array as its element); a clear error for one that cannot be read."""
    try:
        if name not in obj.attrs:
            return default
        v = obj.attrs[name]
    except (OSError, RuntimeError, KeyError, TypeError, UnicodeError) as e:
        raise PostError(f"{getattr(obj.file, 'filename', '?')}: attribute {name} cannot be read ({e})",
                        EX_DATAERR) from None
    if hasattr(v, "shape") and v.shape == (1,):
        v = v[0]
    return as_text(v)


def open_rollspec(path, filetypes=("rollspec-result",)):
    import h5py
    check_input(path, "a rollspec HDF5 file")  # a FIFO or device would block or never end
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise PostError(f"{path}: not a readable HDF5 file ({e})", EX_DATAERR) from None
    try:
        filetype = text_attr(f, "filetype")
    except PostError:
        f.close()
        raise
    if not isinstance(filetype, str) or filetype not in filetypes:
        f.close()
        raise PostError(f"{path}: not a rollspec file of type {' or '.join(filetypes)} (filetype: {filetype!r})",
                        EX_DATAERR)
    try:
        version = str(text_attr(f, "schema_version", ""))
    except PostError:
        f.close()
        raise
    major = int(version.split(".")[0]) if version.split(".")[0].isdigit() else -1
    if major != KNOWN_SCHEMA_MAJOR[filetype]:
        f.close()
        raise PostError(f"{path}: schema_version {version!r} is not readable by rollspec_post "
                        f"(reads major version {KNOWN_SCHEMA_MAJOR[filetype]})", EX_DATAERR)
    if _POINT[0] is not None and "/sweep" not in f:
        f.close()
        raise PostError(f"--point {_POINT[0]}: {path} is not a sweep result (no /sweep); allowed: no --point",
                        EX_USAGE)
    return f


# The sweep point the commands read (--point): K (1-based, run order) or section.key=value[,...].
_POINT = [None]


def select_point(spec):
    _POINT[0] = spec


def sweep_axes(f):
    """(zipped, [(dimension, key, values)]) of a sweep result's /sweep, or None for a result that is no sweep."""
    if "/sweep" not in f:
        return None
    g = f["/sweep"]
    zipped = text_attr(g, "mode", "crossed") == "zipped"
    axes = []
    for d in [k.strip() for k in str(text_attr(g, "keys", "")).split(",") if k.strip()]:
        if d not in g:
            raise PostError(f"{f.filename}: /sweep@keys names {d}, but /sweep/{d} is missing", EX_DATAERR)
        key = str(text_attr(g[d], "description", ""))
        key = key[len("swept study key "):] if key.startswith("swept study key ") else d
        values = np.reshape(read_plain(f, f"/sweep/{d}"), -1)
        axes.append((d, key, [as_text(v) if isinstance(v, (bytes, str)) else v for v in values]))
    if not axes:
        raise PostError(f"{f.filename}: /sweep names no swept key", EX_DATAERR)
    return zipped, axes


def describe_sweep(zipped, axes):
    n = len(axes[0][2]) if zipped else int(np.prod([len(a[2]) for a in axes]))
    text = (" with " if zipped else " x ").join(
        f"{key} = {', '.join(show(v) for v in values[:8])}"
        + (", ..." if len(values) > 8 else "") for _, key, values in axes)
    return n, f"{n} points ({'zipped' if zipped else 'crossed'}: {text})"


def show(value):
    return f"{value:g}" if isinstance(value, (float, np.floating)) else str(value)


def _same(value, text):
    if isinstance(value, (int, float, np.number)):
        try:
            return float(text) == float(value)
        except ValueError:
            return False
    return str(value) == text


def sweep_point(f, spec):
    """(shape of the leading axes, offset in run order, label) of the point `spec` names."""
    zipped, axes = sweep_axes(f)
    n, what = describe_sweep(zipped, axes)
    shape = [len(axes[0][2])] if zipped else [len(a[2]) for a in axes]
    allowed = f"; allowed: --point K (1 to {n}, run order) or --point section.key=value[,...]"
    if spec is None:
        raise PostError(f"{f.filename} is a sweep result of {what}: choose one point{allowed}", EX_USAGE)
    spec = str(spec).strip()
    if spec.isdigit():
        if not 1 <= int(spec) <= n:
            raise PostError(f"--point {spec}: {f.filename} has {what}{allowed}", EX_USAGE)
        offset = int(spec) - 1
    else:
        index = [None] * len(shape)
        for item in spec.split(","):
            key, _, value = (x.strip() for x in item.partition("="))
            hit = [a for a, (d, k, _) in enumerate(axes) if key in (d, k)]
            if not hit or not _:
                raise PostError(f"--point {spec}: {item.strip()!r} names no swept key of {f.filename} ({what})"
                                f"{allowed}", EX_USAGE)
            found = [i for i, v in enumerate(axes[hit[0]][2]) if _same(v, value)]
            slot = 0 if zipped else hit[0]
            if not found or index[slot] not in (None, found[0]):
                raise PostError(f"--point {spec}: {key} = {value} is no point of {f.filename} ({what}){allowed}",
                                EX_USAGE)
            index[slot] = found[0]
        if None in index:
            missing = axes[index.index(None)][1]
            raise PostError(f"--point {spec}: names no value of {missing} ({what}){allowed}", EX_USAGE)
        offset = int(np.ravel_multi_index(index, shape))
    at = np.unravel_index(offset, shape)
    label = ", ".join(f"{k}={show(v[at[0] if zipped else at[a]])}" for a, (_, k, v) in enumerate(axes))
    return shape, offset, label


def point_label(f):
    """The selected point of a sweep result ("ball.speed=3"), or None for a result that is no sweep."""
    return sweep_point(f, _POINT[0])[2] if "/sweep" in f else None


def _stacked(f, ds):
    """Whether dataset `ds` carries the sweep's leading axes (its first dimension's scale is the sweep's)."""
    try:
        axes = sweep_axes(f)[1]
        return ds.ndim >= 1 and len(ds.dims[0]) > 0 and ds.dims[0][0].name.rsplit("/", 1)[-1] == axes[0][0]
    except (PostError, RuntimeError, KeyError, OSError):  # a /sweep without keys: nothing is stacked by it
        return False


def read_plain(f, name):
    """Dataset `name` as stored; a clear error (not a KeyError) when the file lacks it."""
    try:
        if name not in f:
            raise PostError(f"{f.filename}: has no {name}", EX_DATAERR)
        return f[name][()]
    except (OSError, KeyError, TypeError, AttributeError, RuntimeError, UnicodeError) as e:
        # a group, a damaged dataset, a soft link that loops
        raise PostError(f"{f.filename}: {name} cannot be read as a dataset ({e})", EX_DATAERR) from None


def read(f, name):
    """Dataset `name` as an array; of a sweep result, the selected point's block of a stacked dataset."""
    v = read_plain(f, name)
    if "/sweep" in f and not name.startswith("/sweep/"):
        ds = f[name]
        shape, offset, _ = sweep_point(f, _POINT[0]) if _stacked(f, ds) else (None, 0, None)
        if shape is not None:
            if tuple(np.shape(v)[:len(shape)]) != tuple(shape):
                raise PostError(f"{f.filename}: {name} has shape {np.shape(v)}; its leading axes are not the sweep's "
                                f"{tuple(shape)}", EX_DATAERR)
            v = np.reshape(v, (-1,) + np.shape(v)[len(shape):])[offset]
    return v


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
    return [str(as_text(v)) for v in np.reshape(read(f, name), -1)]


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
