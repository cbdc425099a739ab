"""rollspec: the kernels and engine functions of the rollspec command on numpy arrays.

rollspec.spectra  Welch PSD and third-octave bands, as `rollspec psd` and a study compute them, and the
                  measurement reader of `rollspec psd` and `compare` (CSV, WAV/FLAC, .mat).
rollspec.contact  the elastic and elastic-plastic half-space contact solve of the stiffness tables, and
                  the tables a study builds (Table.read, stiffness_table, tables) with their input hash.
rollspec.surfaces line textures and isotropic surfaces from a PSD or from measured profiles (and their
                  PSD, as [texture] source = profiles makes it), on `rollspec texture`'s random streams.
rollspec.studies  a study (a file, text or a dict) planned and run in-process, as `rollspec plan` and
                  `rollspec run` do (the same result bits), its result opened as xarray and compared.

SI units throughout; help(rollspec.contact.solve) and the others say each argument's unit.
"""
import sys as _sys

from rollspec._arguments import wrap_module as _wrap_module
from rollspec._core import __version__, contact, spectra, studies, surfaces

# An argument pybind11 cannot convert is a TypeError of one line naming it, as the module's other errors.
for _name, _module in (("contact", contact), ("spectra", spectra), ("studies", studies), ("surfaces", surfaces)):
    _wrap_module(_module, "rollspec." + _name)

# `import rollspec.contact` and `from rollspec.spectra import welch` as for any package's modules.


def _open(path, group=None):
    """Opens the rollspec result (or texture or table file) `path` as xarray: with `group` ("psd",
    "bands", "run", ...), that group's xarray.Dataset, its coordinates (frequency in Hz, sensor, bands'
    nominal_frequency ...) and attributes (units in each variable's `units`); without, a dict {group:
    Dataset} of every group, "/" holding the file's own attributes (provenance, the resolved study). The
    data are loaded and the file is closed. It reads with rollspec_post's open_result (python-post/, on
    the path): OSError for a file missing or not readable, ValueError for one that is not a rollspec
    file of a schema it reads, KeyError for a group the file lacks."""
    try:
        from rollspec_post.notebook import open_result
        from rollspec_post.post_error import EX_IOERR, EX_NOINPUT, EX_UNAVAILABLE, PostError
    except ImportError:
        raise ImportError("rollspec.studies.open reads results with rollspec_post: put python-post/ on PYTHONPATH "
                          "or install it (pip install --no-build-isolation ./python-post)") from None
    try:
        groups = open_result(path)
    except PostError as e:
        kind = {EX_NOINPUT: OSError, EX_IOERR: OSError, EX_UNAVAILABLE: ImportError}.get(e.exit_code, ValueError)
        raise kind(str(e)) from None
    if group is None:
        return groups
    name = str(group).strip("/") or "/"
    if name not in groups:
        raise KeyError(f"{path}: has no group {group!r}; allowed: {', '.join(sorted(groups))}")
    return groups[name]


studies.open = _open
studies.open.__name__ = studies.open.__qualname__ = "open"
studies.open.__module__ = "rollspec.studies"
del _open

_sys.modules[__name__ + ".contact"] = contact
_sys.modules[__name__ + ".spectra"] = spectra
_sys.modules[__name__ + ".studies"] = studies
_sys.modules[__name__ + ".surfaces"] = surfaces

__all__ = ["__version__", "contact", "spectra", "studies", "surfaces"]
