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
    if np.any(p < 0):
        raise PostError(f"{path}:{np.argmax(p < 0) + 2}: psd value {p[p < 0][0]:g} is negative; allowed: >= 0",
                        EX_DATAERR)
    return f, p


def band_average(f, p, lower, upper):
    """Mean of the piecewise-linear PSD over [lower, upper]; NaN when the grid does not cover it
    (the same rule as the engine's band_average_irregular)."""
    if f[0] > lower or f[-1] < upper:
        return np.nan
    grid = np.concatenate(([lower], f[(f > lower) & (f < upper)], [upper]))
    return np.trapz(np.interp(grid, f, p), grid) / (upper - lower)


def compare_bands(meas, bands, sensor=0, fmin=0.0, fmax=np.inf):
    """Simulated band levels of one sensor against a measurement, by the rule of `rollspec compare`:
    bands inside [fmin, fmax] that the measurement covers with a positive average count; a band is
    inside when the measured level lies in [ci_lower_db, ci_upper_db]. `bands` maps the /bands names."""
    lower, upper = bands["lower_frequency"], bands["upper_frequency"]
    measured = np.array([band_average(meas[0], meas[1], a, b) for a, b in zip(lower, upper)])
    used = (lower >= fmin) & (upper <= fmax) & np.isfinite(measured) & (measured > 0)
    measured_db = np.full(lower.shape, np.nan)
    measured_db[used] = 10.0 * np.log10(measured[used])
    level = bands["level_db"][sensor]
    delta = level - measured_db
    inside = used & (measured_db >= bands["ci_lower_db"][sensor]) & (measured_db <= bands["ci_upper_db"][sensor])
    count = int(used.sum())
    rms = float(np.sqrt(np.mean(delta[used] ** 2))) if count else np.nan
    return {"used": used, "measured_db": measured_db, "delta_db": delta, "inside": inside,
            "count": count, "inside_count": int(inside.sum()), "rms_db_error": rms}
