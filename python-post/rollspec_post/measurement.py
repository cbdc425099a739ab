"""Measured PSDs (CSV with `frequency_hz` and a PSD column) and their comparison with a result's
bands by the rule of `rollspec compare` (kernels/spectral/README.md D-21, D-22): the same bands,
the same sensor by default, the same intervals and the same question."""
import numpy as np
from scipy import stats

from .result_file import EX_DATAERR, EX_NOINPUT, EX_USAGE, PostError, attr, read, strings, text_attr

MAX_CSV_BYTES = 64 * 2**20  # a measured PSD of a million lines is ~40 MB
MIN_REALISATIONS = 5  # kernels/spectral kMinRealisationsForInterval
BANDS = ("nominal_frequency", "lower_frequency", "upper_frequency", "level_db", "ci_lower_db", "ci_upper_db", "std",
         "log_std")


def _cells(line, delimiter):
    """Cells of a line, trimmed, one pair of enclosing double quotes removed (spreadsheet exports)."""
    out = []
    for c in line.split(delimiter):
        c = c.strip(" \t\r")
        if len(c) >= 2 and c[0] == c[-1] == '"':
            c = c[1:-1].strip(" \t\r")
        out.append(c)
    return out


def _read_table(path):
    """(header, values[row, column], file line of each row) by the rule of rollspec's CSV reader (src/io/csv_table.hpp): the
    delimiter from the header line (tab, else ';', else ','); with ';' a decimal comma, one decimal mark
    per file; blank lines and '#' lines skipped."""
    from .safe_output import check_input
    check_input(path, "a measurement CSV", MAX_CSV_BYTES)  # never /dev/zero, a FIFO or a 5 GB file
    try:
        with open(path, encoding="utf-8-sig") as fh:
            text = fh.read(MAX_CSV_BYTES + 1)  # a file that grows, or a /proc file that claims 0 bytes
        if len(text) > MAX_CSV_BYTES:
            raise PostError(f"{path}: more than {MAX_CSV_BYTES // 2**20} MiB; allowed: a measurement CSV up to that",
                            EX_DATAERR)
        lines = text.split("\n")
    except FileNotFoundError:
        raise PostError(f"{path}: no such file", EX_NOINPUT) from None
    except (UnicodeDecodeError, IsADirectoryError) as e:
        raise PostError(f"{path}: not a CSV text file ({e})", EX_DATAERR) from None
    except OSError as e:
        raise PostError(f"{path}: cannot be read ({e.strerror})", EX_NOINPUT) from None
    header, delimiter, mark, rows, numbers = None, ",", None, [], []
    for n, line in enumerate(lines, 1):
        s = line.strip(" \r")
        if not s.strip() or s.startswith("#"):
            continue
        if header is None:
            delimiter = "\t" if "\t" in s else ";" if ";" in s else ","
            header = _cells(s, delimiter)
            continue
        cells = _cells(s, delimiter)
        if len(cells) != len(header):
            raise PostError(f"{path}:{n}: {len(cells)} values, but the header names {len(header)} columns; "
                            "allowed: one value per column", EX_DATAERR)
        row = []
        for name, c in zip(header, cells):
            text = c
            if delimiter == ";":
                if "," in c and "." in c:
                    raise PostError(f"{path}:{n}: column {name!r} value {c!r} holds both ',' and '.'; allowed: one "
                                    "decimal mark and no thousands separator", EX_DATAERR)
                used = "," if "," in c else "." if "." in c else None
                if used and mark and used != mark[0]:
                    raise PostError(f"{path}:{n}: column {name!r} value {c!r} has another decimal mark than line "
                                    f"{mark[1]}; allowed: one decimal mark in a file", EX_DATAERR)
                if used and not mark:
                    mark = (used, n)
                text = c.replace(",", ".", 1)
            try:
                row.append(float(text))
            except ValueError:
                raise PostError(f"{path}:{n}: column {name!r} value {c!r} is not a number", EX_DATAERR) from None
        rows.append(row)
        numbers.append(n)
    if header is None or not rows:
        raise PostError(f"{path}: expected a header and rows of numbers under it", EX_DATAERR)
    return header, np.array(rows, dtype=float), numbers


PSD_UNIT = "(m/s^2)^2/Hz"  # what `rollspec psd` writes and `rollspec compare` expects
G = 9.80665
_LENGTHS = {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "in": 0.0254, "ft": 0.3048}
# PSD units of an acceleration a column title may state, normalised (_unit_key), in (m/s^2)^2/Hz each
PSD_UNITS = {"g2/hz": G**2, "(g)2/hz": G**2, "gn2/hz": G**2, "m2/s4/hz": 1.0,
             **{f"({k}/s2)2/hz": v**2 for k, v in _LENGTHS.items()}}
MARKER = "# rollspec-psd-csv"  # the first line of `rollspec psd` output before its CSVW sidecar


def _unit_key(text):
    for a, b in (("\u00b2", "2"), ("\u00b5", "u"), ("\u03bc", "u"), ("^", ""), ("*", ""), (" ", "")):
        text = text.replace(a, b)
    return text.lower()


def split_title(title):
    """(name, unit written, factor to (m/s^2)^2/Hz) of a PSD column title such as `acc [(m/s^2)^2/Hz]` or
    `psd (g^2/Hz)`: a last bracket holding '/Hz' is a unit (factor None if it is no acceleration PSD);
    without one the title is the name, in (m/s^2)^2/Hz (factor 1, unit None)."""
    close = title[-1:] if title[-1:] in ")]" else None
    if close:
        opening, depth = "(" if close == ")" else "[", 0
        for i in range(len(title) - 1, -1, -1):
            depth += title[i] == close
            if title[i] == opening:
                depth -= 1
                if depth == 0:
                    unit = title[i + 1:-1].strip()
                    if "/hz" in unit.lower() and title[:i].strip():
                        return title[:i].strip(), unit, PSD_UNITS.get(_unit_key(unit))
                    break
    return title, None, 1.0


def written_by_psd(path):
    """True if `rollspec psd` wrote `path` and it was not edited: its CSVW sidecar `<path>-metadata.json`
    records its SHA-256, or (files written before the sidecar) it starts with the marker line."""
    import hashlib
    import json
    try:
        with open(path, "rb") as fh:
            data = fh.read(MAX_CSV_BYTES + 1)
        if data.lstrip(b"\xef\xbb\xbf").startswith(MARKER.encode()):
            return True
        with open(f"{path}-metadata.json", encoding="utf-8") as fh:
            meta = json.load(fh)
        return (isinstance(meta, dict) and meta.get("rollspec:kind") == "rollspec-psd-csv"
                and meta.get("rollspec:csv_sha256") == hashlib.sha256(data).hexdigest())
    except (OSError, ValueError):
        return False


def psd_column(path, header, column, candidates):
    """The PSD column among `candidates` (titles): `column` by title or by its name without the unit; else
    `psd`; else, in `rollspec psd` output or where the titles state a PSD unit, the only one. Several and
    no `column`: an error naming --column and the channels."""
    if column is not None:
        if column in candidates:
            return column
        named = [c for c in candidates if split_title(c)[0] == column]
        if len(named) == 1:
            return named[0]
        raise PostError(f"{path}:1: no PSD column {column!r}; columns found: {', '.join(header)}", EX_DATAERR)
    if "psd" in candidates:
        return "psd"
    stated = bool(candidates) and all(split_title(c)[1] is not None for c in candidates)
    if len(candidates) == 1 and (stated or written_by_psd(path)):
        return candidates[0]
    if len(candidates) > 1:
        names = ", ".join(split_title(c)[0] for c in candidates)
        raise PostError(f"{path}: {len(candidates)} PSD columns ({names}); name one with --column", EX_DATAERR)
    raise PostError(f"{path}:1: no column 'psd'; columns found: {', '.join(header)}; allowed: a column named psd, "
                    "or --column NAME", EX_DATAERR)


def psd_values(path, name, values):
    """The column's values in (m/s^2)^2/Hz, by the unit its title states."""
    _, unit, factor = split_title(name)
    if factor is None:
        raise PostError(f"{path}:1: column {name!r} is in {unit!r} by its title, which is no PSD of an acceleration; "
                        f"allowed: {PSD_UNIT}, g^2/Hz, (mm/s^2)^2/Hz, ...", EX_DATAERR)
    return values * factor


def read_measurement(path, column=None):
    """(frequency, psd) from a CSV with a header: frequency_hz and the PSD column (psd_column: `column`, by
    title or name, else `psd`, else the only one in `rollspec psd` output), in (m/s^2)^2/Hz (a g^2/Hz title is
    converted). Delimiters and decimal commas as `rollspec compare`."""
    header, data, numbers = _read_table(path)
    if "frequency_hz" not in header:
        raise PostError(f"{path}:1: no column 'frequency_hz'; columns found: {', '.join(header)}", EX_DATAERR)
    column = psd_column(path, header, column, [h for h in header if h != "frequency_hz"])
    f, p = data[:, header.index("frequency_hz")], data[:, header.index(column)]
    if not (np.all(np.isfinite(f)) and np.all(np.isfinite(p))):
        raise PostError(f"{path}: values must be finite numbers", EX_DATAERR)
    if np.any(np.diff(f) <= 0):
        raise PostError(f"{path}: frequency_hz must increase strictly", EX_DATAERR)
    if np.any(p < 0):
        raise PostError(f"{path}:{numbers[np.argmax(p < 0)]}: {column} value {p[p < 0][0]:g} is negative; allowed: >= 0",
                        EX_DATAERR)
    return f, psd_values(path, column, p)


def sensor_row(names, sensor=None):
    """The row `rollspec compare` uses: a name, or the number K of the name sensor_K (1-based, as the
    names and the study's [sensors] positions count); by default sensor_mean if present, else the first."""
    if not names:
        raise PostError("the result names no sensors (/psd/sensor is empty); nothing to draw or compare", EX_DATAERR)
    if sensor is None:
        return names.index("sensor_mean") if "sensor_mean" in names else 0
    name = f"sensor_{int(sensor)}" if str(sensor).isdigit() else str(sensor)
    if name in names:
        return names.index(name)
    raise PostError(f"--sensor {sensor}: the result has the sensors {', '.join(names)}; allowed: a name, or the "
                    "number K of sensor_K", EX_USAGE)


def read_bands(f):
    """The /bands datasets `compare_bands` needs, the sensor names and the interval settings."""
    bands = {n: _floats(f, "/bands/" + n) for n in BANDS}
    bands["sensor"] = strings(f, "/bands/sensor")
    bands["realisations"] = attr(f, "/psd", "realisations", int)
    bands["confidence"] = attr(f, "/psd", "confidence_level") if "confidence_level" in f["/psd"].attrs else 0.95
    bands["interval_method"] = str(text_attr(f["/psd"], "interval_method", ""))
    # D-26's between-band covariance of the band logs; results written before it lack it
    cov = "/bands/log_level_covariance"
    bands["log_level_covariance"] = _floats(f, cov) if cov in f else None
    n, rows = bands["lower_frequency"].shape, (len(bands["sensor"]),) + bands["lower_frequency"].shape
    wrong = [b for b in BANDS[:3] if bands[b].shape != n or bands[b].ndim != 1] + \
            [b for b in BANDS[3:] if bands[b].shape != rows]
    if wrong:
        raise PostError(f"{f.filename}: /bands/{wrong[0]} has shape {bands[wrong[0]].shape}; expected "
                        f"{n if wrong[0] in BANDS[:3] else rows} (sensors x bands)", EX_DATAERR)
    return bands


def _floats(f, name):
    try:
        return np.asarray(read(f, name), float)
    except (TypeError, ValueError):
        raise PostError(f"{f.filename}: {name} is not numeric", EX_DATAERR) from None


def band_average(f, p, lower, upper):
    """Mean of the piecewise-linear PSD over [lower, upper]; NaN when the grid does not cover it
    (the same rule as the engine's band_average_irregular)."""
    if f[0] > lower or f[-1] < upper:
        return np.nan
    grid = np.concatenate(([lower], f[(f > lower) & (f < upper)], [upper]))
    return np.trapz(np.interp(grid, f, p), grid) / (upper - lower)


def prediction_factors(mean, std, log_std, realisations, records, level):
    """D-22, the union of two laws of one realisation's value: (a) gamma, m_M / m_K ~ F(M nu_1, K nu_1),
    nu_1 = 2 m^2 / s^2, quantiles widened by t_{K-1}/z in log space; (b) lognormal, both means
    lognormal with their moments, CV^2 = exp(s_y^2) - 1, t_{K-1} on the log ratio."""
    a, K, M = 1.0 - level, realisations, records
    t = stats.t.ppf(1 - a / 2, K - 1)
    w = t / stats.norm.ppf(1 - a / 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        nu1 = np.where(std > 0, 2.0 * (mean / std) ** 2, np.inf)
    nu1 = np.minimum(nu1, 1e12 / max(K, M))
    gamma = (mean > 0) & (K * nu1 < 1e12)
    lo = np.where(gamma, stats.f.ppf(a / 2, M * nu1, K * nu1) ** w, 1.0)
    hi = np.where(gamma, stats.f.ppf(1 - a / 2, M * nu1, K * nu1) ** w, 1.0)
    cv2 = np.expm1(np.square(np.where(np.isfinite(log_std), log_std, 0.0)))
    vm, vk = np.log1p(cv2 / M), np.log1p(cv2 / K)
    half, centre = t * np.sqrt(vm + vk), (vk - vm) / 2
    lognormal = (mean > 0) & np.isfinite(log_std) & (log_std > 0)
    lo = np.where(lognormal, np.minimum(lo, np.exp(centre - half)), lo)
    hi = np.where(lognormal, np.maximum(hi, np.exp(centre + half)), hi)
    return lo, hi


EXTRA_REALISATIONS = 4  # kernels/spectral kExtraRealisations: the test needs K >= bands + 4


def combined_test(measured_db, level_db, cov, realisations, records, test_level=0.05):
    """D-26, as `rollspec compare` prints it: Hotelling T^2 of the measured band logs against the model
    with the covariance of an M-record mean plus the K-realisation mean's (the realisations' between-band
    covariance of ln x scaled band by band to each band's Fenton-Wilkinson variance), F(p, K - p). Returns a dict with p_value
    (None when the test is not defined) and the verdict line."""
    p, K, M = len(measured_db), realisations, records
    out = {"p_value": None, "rejected": None, "level": test_level}
    if cov is None:
        out["verdict"] = "none (the result has no /bands/log_level_covariance: re-run it with this rollspec)"
        return out
    if K < p + EXTRA_REALISATIONS:
        out["verdict"] = (f"none ({p} bands need K >= {p + EXTRA_REALISATIONS} realisations, the result has {K}; "
                          "run more or choose fewer bands with --fmin/--fmax)")
        return out
    s = np.diag(cov)
    vm, vk = np.log1p(np.expm1(s) / M), np.log1p(np.expm1(s) / K)
    # V = G S G: each band's variance from Fenton-Wilkinson, the correlations those of S (T^2 keeps
    # Hotelling's law; the elementwise ln(1 + (e^S - 1)/n) of a noisy S does not).
    g = np.where(s > 0, np.sqrt((vm + vk) / np.where(s > 0, s, 1.0)), np.sqrt(1.0 / M + 1.0 / K))
    d = measured_db * np.log(10) / 10 - (level_db * np.log(10) / 10 + (vk - vm) / 2)
    t2 = float(d @ np.linalg.solve(cov * np.outer(g, g), d))
    nu = K - 1
    f = (nu - p + 1) / (nu * p) * t2
    out.update(p_value=float(stats.f.sf(f, p, nu - p + 1)), t2=t2, f=f, dof=(p, nu - p + 1))
    out["rejected"] = out["p_value"] < test_level
    out["verdict"] = (f"{'REJECTED' if out['rejected'] else 'not rejected'} at level {test_level:g}: "
                      f"p = {out['p_value']:.3g} (T2 = {t2:.4g}, F = {f:.4g} on {p}, {nu - p + 1} dof, {p} bands)")
    return out


def question(bands, measured_averages=None):
    pct = f"{100 * bands['confidence']:.0f} %"
    if bands["realisations"] < MIN_REALISATIONS:
        return "none: " + bands["interval_method"]
    if measured_averages:
        return (f"is the measured level inside the {pct} prediction interval of a measurement averaged over "
                f"M = {measured_averages:g} independent records?")
    return f"is the measured level inside the {pct} interval of the simulated mean?"


def compare_bands(meas, bands, sensor=None, fmin=0.0, fmax=np.inf, measured_averages=None):
    """Band levels of one row against a measurement, by the rule of `rollspec compare`: bands inside
    [fmin, fmax] that the measurement covers with a positive average; `inside` answers the question
    `question()` states (the interval of the simulated mean, or with `measured_averages` M the
    prediction interval for a measurement of M independent records). `bands` is read_bands()."""
    if measured_averages is not None and not (np.isfinite(measured_averages) and measured_averages >= 1):
        raise PostError(f"--measured-averages {measured_averages:g}: allowed: a finite count >= 1 of independent records",
                        EX_USAGE)
    s = sensor_row(bands["sensor"], sensor)
    lower, upper = bands["lower_frequency"], bands["upper_frequency"]
    measured = np.array([band_average(meas[0], meas[1], a, b) for a, b in zip(lower, upper)])
    used = (lower >= fmin) & (upper <= fmax) & np.isfinite(measured) & (measured > 0)
    measured_db = np.full(lower.shape, np.nan)
    measured_db[used] = 10.0 * np.log10(measured[used])
    level = bands["level_db"][s]
    delta = level - measured_db
    judged = bands["realisations"] >= MIN_REALISATIONS
    lo_db, hi_db = bands["ci_lower_db"][s], bands["ci_upper_db"][s]
    if measured_averages and judged:
        lo, hi = prediction_factors(10.0 ** (level / 10.0), bands["std"][s], bands["log_std"][s],
                                    bands["realisations"], float(measured_averages), bands["confidence"])
        lo_db, hi_db = level + 10.0 * np.log10(lo), level + 10.0 * np.log10(hi)
    inside = used & judged & (measured_db >= lo_db) & (measured_db <= hi_db)
    count = int(used.sum())
    rms = float(np.sqrt(np.mean(delta[used] ** 2))) if count else np.nan
    # rms² = bias² + spread²: a constant offset (a gain, a mass) and a shape error are told apart
    bias = float(np.mean(delta[used])) if count else np.nan
    spread = float(np.sqrt(np.mean((delta[used] - bias) ** 2))) if count else np.nan
    test = None
    if measured_averages and count:
        cov = bands.get("log_level_covariance")
        cov = cov[s][np.ix_(used, used)] if cov is not None else None
        test = combined_test(measured_db[used], level[used], cov, bands["realisations"], float(measured_averages))
    return {"row": s, "sensor": bands["sensor"][s], "used": used, "measured_db": measured_db, "delta_db": delta,
            "lower_db": lo_db, "upper_db": hi_db, "inside": inside, "count": count,
            "judged": count if judged else 0, "inside_count": int(inside.sum()), "rms_db_error": rms,
            "bias_db": bias, "spread_db": spread, "combined_test": test,
            "question": question(bands, measured_averages)}
