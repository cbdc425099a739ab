"""`panels`: results side by side in the seeds' own figure style (seed 001 Fig. 8, seed 002 Figs. 10-11):
one panel per case, narrow-band acceleration PSD level in dB re 1 (m/s²)²/Hz (the seeds' "dB re 1 m/s²")
on a linear 0-5 kHz axis, the first curve of a panel solid black (the seeds' measured line), the
others dotted or dashed in colour (their simulated lines), one level range shared by all panels.
A curve is a result file or a measured PSD CSV (panel_csv.py), told apart by content."""
import numpy as np
from matplotlib.figure import Figure

from .panel_csv import UNITS, is_hdf5, read_panel_csv
from .psd_plot import db, output_format
from .result_file import (EX_DATAERR, EX_USAGE, PostError, attr, open_rollspec, read_rows, sensor_row, strings,
                          text_attr)
from .safe_output import emit_figure

STYLES = ({"color": "black", "ls": "-", "lw": 0.9}, {"color": "C3", "ls": ":", "lw": 1.3},
          {"color": "C0", "ls": "--", "lw": 1.0}, {"color": "C2", "ls": "-.", "lw": 1.0})


def parse_panel(words):
    """`TITLE FILE=LABEL ...` (from --panel) -> (title, [(file, label)])."""
    if len(words) < 2:
        raise PostError(f"--panel {' '.join(words)}: needs a title and at least one FILE=LABEL", EX_USAGE)
    curves = []
    for w in words[1:]:
        path, sep, label = w.partition("=")
        if not sep or not path or not label:
            raise PostError(f"--panel {words[0]!r}: {w!r} is not FILE=LABEL", EX_USAGE)
        curves.append((path, label))
    if len(curves) > len(STYLES):
        raise PostError(f"--panel {words[0]!r}: {len(curves)} curves; allowed: at most {len(STYLES)}", EX_USAGE)
    return words[0], curves


def read_level(path, sensor=None, column=None):
    """Frequency, the level in dB of one row (sensor_mean by default), its units and realisation count
    (None for a measured CSV)."""
    if not is_hdf5(path):
        freq, psd, _ = read_panel_csv(path, column)
        return freq, db(psd), UNITS, None
    with open_rollspec(path) as f:
        if "/psd/mean" not in f:
            raise PostError(f"{path}: holds no /psd (a time-history result?); panels draws acceleration PSDs", EX_DATAERR)
        names = strings(f, "/psd/sensor")
        row = sensor_row(names, sensor)
        freq, mean = read_rows(f, "/psd/frequency", 1), read_rows(f, "/psd/mean", 2)
        if mean.shape != (len(names), freq.size):
            raise PostError(f"{path}: /psd/mean is {mean.shape}; expected sensors x frequencies = "
                            f"{len(names)} x {freq.size}", EX_DATAERR)
        return freq, db(mean[row]), text_attr(f["/psd/mean"], "units"), attr(f, "/psd", "realisations", int)


def plot_panels(panels, out, fmax=5000.0, sensor=None, dpi=150, kind=None, column=None):
    """panels: [(title, [(file, label), ...]), ...]; `column`: the PSD column of a CSV with several.
    Returns {title: {label: (frequency, level_db)}} as drawn (a result's label gets its K)."""
    if not panels:
        raise PostError("panels: give at least one --panel", EX_USAGE)
    if not (fmax > 0 and np.isfinite(fmax)):
        raise PostError(f"--fmax {fmax}: allowed: a finite frequency > 0 Hz", EX_USAGE)
    fmt = kind or output_format(out)
    drawn, units = {}, None
    for title, curves in panels:
        drawn[title] = {}
        for path, label in curves:
            freq, level, curve_units, k = read_level(path, sensor, column)
            units = curve_units if units is None or k is not None else units  # a result's units first
            keep = (freq > 0) & (freq <= fmax)
            drawn[title][label if k is None else f"{label} (K = {k})"] = (freq[keep], level[keep])
    finite = np.concatenate([lv[np.isfinite(lv)] for p in drawn.values() for _, lv in p.values()])
    if not finite.size:  # an all-zero PSD has no level in dB
        files = ", ".join(path for _, curves in panels for path, _ in curves)
        raise PostError(f"{files}: no positive PSD value up to {fmax:g} Hz (all zero?); nothing to draw in dB",
                        EX_DATAERR)
    top = 10 * np.ceil(finite.max() / 10 + 0.05)
    bottom = max(10 * np.floor(np.percentile(finite, 0.5) / 10), top - 100)  # the seeds show ~80-100 dB
    fig = Figure(figsize=(4.2 * len(panels), 3.6), layout="constrained")
    axes = fig.subplots(1, len(panels), sharey=True, squeeze=False)[0]
    for ax, (title, curves) in zip(axes, drawn.items()):
        for style, (label, (freq, level)) in zip(STYLES, curves.items()):
            ax.plot(freq, level, label=label, **style)
        ax.set_title(title, fontsize=10)
        ax.set_xlim(0, fmax)
        ax.set_ylim(bottom, top)
        ax.set_xlabel("frequency (Hz)")
        ax.grid(True, lw=0.3, alpha=0.5)
        ax.legend(loc="lower right", fontsize=7, frameon=False)
    axes[0].set_ylabel(f"acceleration PSD (dB re 1 {str(units).replace('^2', '²')})")
    emit_figure(fig, out, fmt, dpi)
    return drawn
