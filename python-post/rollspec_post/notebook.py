"""Notebook access: `open_result` reads every group of a rollspec file as xarray Datasets, and
`run` runs the engine from Python (in-process through the module `rollspec` when it imports, else the
command) and opens what it wrote. Every failure of either raises one
exception type, PostError (its message one line, its exit_code the command's), never another."""
import collections.abc
import os
import subprocess

from .engine_compare import engine_binary
from .result_file import (EX_DATAERR, EX_SOFTWARE, EX_UNAVAILABLE, EX_USAGE, KNOWN_SCHEMA_MAJOR, PostError,
                          open_rollspec)

FILETYPES = tuple(KNOWN_SCHEMA_MAJOR)  # every file kind the engine writes


def one_line(text):
    return " ".join(str(text).split())


def checked_path(path, what):
    """A path as str; PostError (64) for what cannot name a file (not a path, a NUL byte)."""
    try:
        text = os.fspath(path)
    except TypeError:
        raise PostError(f"{what}: {path!r} is not a path", EX_USAGE) from None
    text = text.decode(errors="surrogateescape") if isinstance(text, bytes) else text
    if "\0" in text or not text:
        raise PostError(f"{what}: {text!r} is not a file name", EX_USAGE)
    return text


def needs(module, package):
    try:
        return __import__(module)
    except ImportError:
        raise PostError(f"open_result needs the Python module {module} (apt-get install {package})",
                        EX_UNAVAILABLE) from None


def open_result(path):
    """{group: xarray.Dataset} for every group of a rollspec file ("/" holds the root attributes:
    provenance and the resolved study). The data are loaded, the file is closed. PostError for a file
    that is missing, not regular, not a rollspec file, or has content xarray cannot read."""
    path = checked_path(path, "open_result")
    h5py = needs("h5py", "python3-h5py")
    xr = needs("xarray", "python3-xarray")
    needs("h5netcdf", "python3-h5netcdf")
    try:
        with open_rollspec(path, FILETYPES) as f:
            groups = ["/"]
            f.visititems(lambda name, obj: groups.append("/" + name) if isinstance(obj, h5py.Group) else None)
        out = {}
        for g in groups:
            # phony_dims: tables without dimension scales (the cached tables) open too
            with xr.open_dataset(path, engine="h5netcdf", group=g, phony_dims="sort") as ds:
                out[g.strip("/") or "/"] = ds.load()
        return out
    except PostError:
        raise
    except MemoryError:
        raise PostError(f"{path}: out of memory while loading it", EX_SOFTWARE) from None
    except Exception as e:  # h5py or xarray on damaged or unusual content: bad data, in one line
        raise PostError(f"{path}: cannot be read ({type(e).__name__}: {one_line(e)})", EX_DATAERR) from None


def mapping(value, what):
    if value is None:
        return {}
    if not isinstance(value, collections.abc.Mapping):
        raise PostError(f"{what}: {type(value).__name__} {value!r}: allowed: a dict {{'section.key': value}}",
                        EX_USAGE)
    return value


def in_process():
    """rollspec.studies when the module imports and no ROLLSPEC_BIN names a binary to run instead; else None."""
    if os.environ.get("ROLLSPEC_BIN"):
        return None
    try:
        from rollspec import studies
    except ImportError:
        return None
    return studies


def run(study, out, set=None, quiet=True, sweep=None):  # noqa: A002 (the engine's own word for it)
    """Runs `rollspec run STUDY --out OUT --set k=v ... --sweep k=v1,v2 ...` and returns open_result(OUT):
    in this process through rollspec.studies.run when the module `rollspec` imports (and ROLLSPEC_BIN is
    unset), the same file bits as the command's, else the command. `sweep`: {"ball.speed": [1, 2, 3]} runs
    one point per value (added to the study's [sweep]; always the command). A refused or failed run raises
    PostError with the engine's message and exit code."""
    args = [None, "run", checked_path(study, "run: study"), "--out", checked_path(out, "run: out")]
    sets = []
    for key, value in mapping(set, "set").items():
        if "=" in str(key) or "\n" in f"{key}{value}":
            raise PostError(f"set: key {key!r} = {value!r}: allowed: section.key and a one-line value", EX_USAGE)
        sets.append(f"{key}={value}")
        args += ["--set", sets[-1]]
    studies = in_process() if not sweep else None
    if studies is not None:
        if any("\0" in a for a in args[2:]):
            raise PostError("run: a --set or --sweep value holds a NUL byte", EX_USAGE)
        try:
            studies.run(args[2], args[4], set=sets, quiet=quiet)
        except (ValueError, OSError, RuntimeError) as e:  # RuntimeError: the engine failed (the command's 70)
            code = getattr(e, "exit_code", EX_DATAERR if isinstance(e, ValueError) else
                           EX_UNAVAILABLE if isinstance(e, OSError) else EX_SOFTWARE)
            raise PostError("rollspec run: error: " + one_line(e), code) from None  # the command's line
        return open_result(out)
    args[0] = engine_binary()
    for key, values in mapping(sweep, "sweep").items():
        try:
            values = [values] if isinstance(values, (str, int, float)) else list(values)
        except TypeError:
            raise PostError(f"sweep: key {key!r} = {values!r}: allowed: a list of values", EX_USAGE) from None
        text = ",".join(str(v) for v in values)
        if "=" in str(key) or "\n" in f"{key}{text}" or not values:
            raise PostError(f"sweep: key {key!r} = {values!r}: allowed: section.key and a list of values", EX_USAGE)
        args += ["--sweep", f"{key}={text}"]
    if quiet:
        args.append("--quiet")
    if any("\0" in a for a in args):
        raise PostError("run: a --set or --sweep value holds a NUL byte", EX_USAGE)
    try:
        r = subprocess.run(args, capture_output=True, text=True, errors="replace", stdin=subprocess.DEVNULL)
    except OSError as e:  # ROLLSPEC_BIN missing, a directory, not executable
        raise PostError(f"cannot run the engine {args[0]}: {e.strerror or e}; set ROLLSPEC_BIN to the rollspec binary",
                        EX_UNAVAILABLE) from None
    if r.returncode != 0:
        lines = [l for l in r.stderr.splitlines() if "error:" in l] or r.stderr.strip().splitlines()
        code = r.returncode if r.returncode > 0 else EX_SOFTWARE  # a signal: no sysexits code of its own
        raise PostError(one_line(lines[-1]) if lines else f"rollspec run exited {r.returncode}", code)
    return open_result(out)
