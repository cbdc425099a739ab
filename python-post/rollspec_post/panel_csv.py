"""Measured PSDs drawn by `panels` beside results: the CSV `rollspec psd` writes
(`frequency_hz,<channel> [(m/s^2)^2/Hz],...`, with its metadata in `<csv>-metadata.json`; older files start
with a line `# rollspec-psd-csv: ...`) or a plain measurement CSV (a frequency column, then PSD columns),
read by the rule of rollspec's CSV reader (psd_table._read_table)."""
from .psd_table import _read_table, check_psd_curve, psd_column, psd_values, split_title
from .result_file import EX_DATAERR, PostError

HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"
UNITS = "(m/s^2)^2/Hz"  # rollspec psd's unit, and the one `rollspec compare` expects of a measurement


def is_hdf5(path):
    """By content, not by name: a result renamed .csv is still a result."""
    try:
        with open(path, "rb") as fh:
            return fh.read(8) == HDF5_SIGNATURE
    except OSError:
        return False  # the reader that follows names the problem


def pick_column(path, header, column):
    """The PSD column: `column` (a title, or a title without its unit), else `psd`, else the only one beside
    the frequency."""
    others = header[1:] if "frequency_hz" not in header else [h for h in header if h != "frequency_hz"]
    if column is not None:
        if column in others:
            return column
        named = [h for h in others if split_title(h)[0] == column]
        if len(named) != 1:
            raise PostError(f"{path}: no PSD column {column!r}; columns: {', '.join(others)}", EX_DATAERR)
        return named[0]
    if "psd" in others or len(others) == 1:
        return "psd" if "psd" in others else others[0]
    return psd_column(path, header, None, others)  # the error naming --column and the channels


def read_panel_csv(path, column=None):
    """(frequency, psd, column name): frequency from `frequency_hz`, else from the first column."""
    header, data, numbers = _read_table(path)
    if len(header) < 2:
        raise PostError(f"{path}: needs a frequency column and a PSD column; found {', '.join(header)}", EX_DATAERR)
    name = pick_column(path, header, column)
    f = data[:, header.index("frequency_hz") if "frequency_hz" in header else 0]
    p = psd_values(path, name, data[:, header.index(name)])
    check_psd_curve(path, f, p, numbers, name, "the frequency column")
    return f, p, name
