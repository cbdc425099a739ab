"""PSD tables drawn as curves by `panels` (CSV with `frequency_hz`, or a frequency column, and PSD columns), read by
the rule of rollspec's CSV reader. A comparison with a measurement is never made here: the report and the ΔL
panel show `rollspec compare`'s answer (engine_compare.py)."""
import numpy as np

from .result_file import EX_DATAERR, EX_NOINPUT, PostError

MAX_CSV_BYTES = 64 * 2**20  # a measured PSD of a million lines is ~40 MB


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
    check_psd_curve(path, f, p, numbers, column, "frequency_hz")
    return f, psd_values(path, column, p)


def check_psd_curve(path, f, p, numbers, name, frequency):
    """A PSD curve read from a table, or PostError: finite values, the frequencies (the column the message calls
    `frequency`) increasing strictly, no negative PSD value (its file line from `numbers` named)."""
    if not (np.all(np.isfinite(f)) and np.all(np.isfinite(p))):
        raise PostError(f"{path}: values must be finite numbers", EX_DATAERR)
    if np.any(np.diff(f) <= 0):
        raise PostError(f"{path}: {frequency} must increase strictly", EX_DATAERR)
    if np.any(p < 0):
        raise PostError(f"{path}:{numbers[np.argmax(p < 0)]}: {name} value {p[p < 0][0]:g} is negative; allowed: >= 0",
                        EX_DATAERR)
