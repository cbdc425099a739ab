"""rollspec: the kernels and engine functions of the rollspec command on numpy arrays.

rollspec.spectra  Welch PSD and third-octave bands, as `rollspec psd` and a study compute them, and the
                  measurement reader of `rollspec psd` and `compare` (CSV, WAV/FLAC, .mat).
rollspec.contact  the elastic and elastic-plastic half-space contact solve of the stiffness tables, and
                  the tables a study builds (Table.read, stiffness_table) with their input hash.
rollspec.surfaces line textures and isotropic surfaces from a PSD or from measured profiles (and their
                  PSD, as [texture] source = profiles makes it), on `rollspec texture`'s random streams.
rollspec.studies  a study file run in-process, as `rollspec run` runs it (the same result bits).

SI units throughout; help(rollspec.contact.solve) and the others say each argument's unit.
"""
import sys as _sys

from rollspec._core import __version__, contact, spectra, studies, surfaces

# `import rollspec.contact` and `from rollspec.spectra import welch` as for any package's modules.
_sys.modules[__name__ + ".contact"] = contact
_sys.modules[__name__ + ".spectra"] = spectra
_sys.modules[__name__ + ".studies"] = studies
_sys.modules[__name__ + ".surfaces"] = surfaces

__all__ = ["__version__", "contact", "spectra", "studies", "surfaces"]
