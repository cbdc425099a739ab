"""Measured PSDs (CSV `frequency_hz,psd`) and band averages on any frequency grid."""
import numpy as np

from .result_file import EX_DATAERR, EX_NOINPUT, PostError


def read_measurement(path):
    try:
        with open(path) as fh:
            header = [c.strip() for c in fh.readline().strip().split(",")]
    except FileNotFoundError:
        raise PostError(f"{path}: no such file", EX_NOINPUT) from None
    if header[:2] != ["frequency_hz", "psd"]:
        raise PostError(f"{path}:1: header must be 'frequency_hz,psd', found {','.join(header)!r}", EX_DATAERR)
    try:
        data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    except ValueError as e:
        raise PostError(f"{path}: not numeric CSV ({e})", EX_DATAERR) from None
    f, p = data[:, 0], data[:, 1]
    if np.any(np.diff(f) <= 0):
        raise PostError(f"{path}: frequency_hz must increase strictly", EX_DATAERR)
    return f, p


def band_average(f, p, lower, upper):
    """Mean of the piecewise-linear PSD over [lower, upper]; NaN when the grid does not cover it
    (the same rule as the engine's band_average_irregular)."""
    if f[0] > lower or f[-1] < upper:
        return np.nan
    grid = np.concatenate(([lower], f[(f > lower) & (f < upper)], [upper]))
    return np.trapz(np.interp(grid, f, p), grid) / (upper - lower)
