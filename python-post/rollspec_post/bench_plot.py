"""`bench`: work-precision plot (error against run time, log-log), one line per method, from a
benchmark CSV. `#` lines are comments, as in the bench programs' output."""
import csv
import math

from matplotlib.figure import Figure

from .log_ticks import label_log_axes
from .result_file import EX_DATAERR, EX_NOINPUT, PostError
from .safe_output import check_input, emit_figure

MAX_BYTES = 64 * 2**20  # bench programs print a few hundred lines

# accepted spellings, first match wins; the bench programs print time_s / max_band_error_db
METHOD = ("method", "integrator")
TIME = ("seconds", "time_s")
ERROR = ("error_db", "error", "max_band_error_db")


def pick(header, names, path):
    for n in names:
        if n in header:
            return n
    raise PostError(f"{path}: needs a column {' or '.join(names)} (header: {','.join(header)})", EX_DATAERR)


def _series(path, lines):
    rows = csv.DictReader([s for _, s in lines])
    header = [h.strip() for h in rows.fieldnames]
    rows.fieldnames = header
    m, t, e = pick(header, METHOD, path), pick(header, TIME, path), pick(header, ERROR, path)
    series = {}
    for (line, _), row in zip(lines[1:], rows):
        try:
            sec, err = float(row[t]), float(row[e])
        except (TypeError, ValueError):
            raise PostError(f"{path}:{line}: {t}={row[t]!r}, {e}={row[e]!r} are not numbers", EX_DATAERR) from None
        if not (math.isfinite(sec) and sec > 0 and math.isfinite(err)) or row[m] is None:
            raise PostError(f"{path}:{line}: {m} must be given, {t} > 0 and {e} finite", EX_DATAERR)
        series.setdefault(row[m].strip(), []).append((sec, abs(err)))
    return series, e


def read_bench(path):
    """{method: [(seconds, error), ...]} sorted by run time, and the error column's name."""
    check_input(path, "a benchmark CSV", MAX_BYTES)  # never /dev/zero or a FIFO
    try:
        with open(path, newline="") as fh:
            lines = [(i, s) for i, s in enumerate(fh, 1) if s.strip() and not s.lstrip().startswith("#")]
    except FileNotFoundError:
        raise PostError(f"{path}: no such file", EX_NOINPUT) from None
    except UnicodeDecodeError:
        raise PostError(f"{path}: not a text CSV file", EX_DATAERR) from None
    except (OSError, csv.Error) as e:
        raise PostError(f"{path}: cannot be read ({e})", EX_NOINPUT) from None
    if not lines:
        raise PostError(f"{path}: no CSV header", EX_DATAERR)
    try:
        series, e = _series(path, lines)
    except csv.Error as err:  # a NUL byte, an unterminated quote
        raise PostError(f"{path}: not a CSV file ({err})", EX_DATAERR) from None
    if not series:
        raise PostError(f"{path}: no data rows", EX_DATAERR)
    return {k: sorted(v) for k, v in series.items()}, e


def plot_bench(path, out, kind=None):
    series, error_name = read_bench(path)
    fig = Figure(figsize=(7.5, 5.5), constrained_layout=True)
    ax = fig.add_subplot()
    markers = "osD^v<>ph*"
    dropped = 0
    for i, (method, pts) in enumerate(series.items()):
        # an error of exactly 0 has no place on a log axis
        keep = [(s, e) for s, e in pts if e > 0]
        dropped += len(pts) - len(keep)
        if keep:
            ax.loglog(*zip(*keep), marker=markers[i % len(markers)], lw=1.2, ms=5, label=f"{method} ({len(keep)})")
    if not ax.get_lines():
        raise PostError(f"{path}: every {error_name} is 0; nothing to draw on a log axis", EX_DATAERR)
    in_db = error_name.endswith("_db")
    ax.set_xlabel("run time (s)")
    ax.set_ylabel(error_name.removesuffix("_db").replace("_", " ") + (" (dB)" if in_db else ""))
    ax.set_title("work–precision" + (f" ({dropped} zero-error runs not shown)" if dropped else ""))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    label_log_axes(ax)
    return emit_figure(fig, out, kind)
