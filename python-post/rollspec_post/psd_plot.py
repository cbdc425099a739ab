"""`psd`: the acceleration PSD of one row of a result (by default the sensor mean) with its interval,
the reference dashed, a measurement solid black, and (with --bands) the third-octave levels and a
ΔL panel that judges the measurement by the rule of `rollspec compare`. Made for a paper: level in
dB re 1 (m/s²)²/Hz (the seeds' "dB re 1 m/s²"), a linear frequency axis over the study's band range
by default, a legend of at most six entries above the axes, PNG, PDF or SVG by the file name."""
import os

import numpy as np
from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerTuple

from .log_ticks import label_log_axes
from .measurement import compare_bands, read_bands, read_measurement, sensor_row
from .result_file import (EX_DATAERR, EX_USAGE, PostError, attr, open_rollspec, point_label, read_rows, sensor_labels,
                          strings, text_attr)
from .safe_output import emit_figure, picture_kind


def db(x):
    with np.errstate(divide="ignore"):
        return 10.0 * np.log10(x)


def output_format(out):
    """png, pdf or svg from the file name; PNG for a buffer (the report embeds one)."""
    return picture_kind(out) if isinstance(out, (str, os.PathLike)) else "png"


def short(label):
    """A legend label without its parenthesised explanation."""
    return label.split(" (")[0]


def read_psd(result):
    """The /psd rows with their interval, the reference, the bands, the rows' legend labels (with the
    sensors' positions); checked for shape and for data."""
    with open_rollspec(result) as f:
        freq = read_rows(f, "/psd/frequency", 1)
        mean, lo, hi = (read_rows(f, "/psd/" + n, 2) for n in ("mean", "ci_lower", "ci_upper"))
        names = strings(f, "/psd/sensor")
        labels = sensor_labels(f)
        point = point_label(f)  # a sweep result: the point read (--point)
        labels = [f"{label} at {point}" for label in labels] if point else labels
        ref = read_rows(f, "/reference/psd", 2) if "/reference/psd" in f else None
        ref_label = text_attr(f["/reference/psd"], "label", "reference") if ref is not None else None
        units = text_attr(f["/psd/mean"], "units")
        k = attr(f, "/psd", "realisations", int)
        level = attr(f, "/psd", "confidence_level")
        band_data = read_bands(f)
        loss = text_attr(f["/contact"], "loss_of_contact_warning") if "/contact" in f else None
    shape = (len(names), freq.size)
    if freq.size < 2 or any(v.shape != shape for v in (mean, lo, hi) + ((ref,) if ref is not None else ())):
        raise PostError(f"{result}: /psd/mean, ci_lower, ci_upper (and /reference/psd) must be sensors x "
                        f"frequencies = {shape[0]} x {shape[1]}, with at least 2 frequencies", EX_DATAERR)
    if not np.any(np.isfinite(mean) & (mean > 0)):
        raise PostError(f"{result}: /psd/mean holds no positive finite value (all zero or NaN); "
                        "nothing to draw on a dB scale", EX_DATAERR)
    return freq, mean, lo, hi, names, labels, ref, ref_label, units, k, level, band_data, loss


def loss_note(ax, warning):
    """The run's loss-of-contact warning on the PSD axes, in red at the top: a figure sent on alone
    still says that its levels are those of a ball that flies (or of a linearised law past its validity)."""
    return ax.text(0.5, 0.97, "LOSS OF CONTACT: " + warning, transform=ax.transAxes, ha="center", va="top",
                   fontsize=7.5, color="#7b1d12", wrap=True, zorder=10,
                   bbox={"boxstyle": "round", "facecolor": "#fdecea", "edgecolor": "#c0392b", "lw": 1.5})


STYLES = ("default", "seed")


def curve_styles(style):
    """Line styles of the simulated mean and the measurement. `seed`: the seeds' figures (seed 001
    Fig. 8, seed 002 Figs. 10-11): computed dotted in colour, measured solid black."""
    if style == "seed":
        return {"color": "C3", "ls": ":", "lw": 1.4}, {"color": "k", "ls": "-", "lw": 1.0}
    return {"color": "C0", "ls": "-", "lw": 1.0}, {"color": "k", "ls": "-", "lw": 1.0}


def plot_psd(result, out, measurement=None, bands=False, sensor=None, column=None, measured_averages=None,
             fmin=None, fmax=None, xscale="linear", sensors_all=False, dpi=150, kind=None, title=None, label=None,
             ylim=None, style="default", measurement_label=None):
    """`sensor` (a name, or K for sensor_K) picks the row drawn and compared (default: the row `rollspec compare`
    uses, sensor_mean when present). `sensors_all` adds every sensor as a thin grey line. fmin/fmax
    bound the axis and the compared bands (default: the study's band range, from 0 Hz on a linear
    axis). `label`, `measurement_label`: legend names of the simulated mean and the measurement;
    `ylim` (low, high) in dB; `style` default or seed. Returns {"legend": labels, "comparison":
    compare_bands(...) or None, "loss_note": the loss-of-contact note drawn on the figure or None}.
    A result whose run warned of loss of contact (/contact@loss_of_contact_warning) gets that warning
    drawn on the axes in red."""
    if xscale not in ("linear", "log"):
        raise PostError(f"--xscale {xscale}: allowed: linear or log", EX_USAGE)
    if style not in STYLES:
        raise PostError(f"--style {style}: allowed: {' or '.join(STYLES)}", EX_USAGE)
    if ylim is not None and not (len(ylim) == 2 and np.all(np.isfinite(ylim)) and ylim[0] < ylim[1]):
        raise PostError(f"--ylim {' '.join(map(str, ylim))}: allowed: two finite levels LOW < HIGH (dB)", EX_USAGE)
    fmt = kind or output_format(out)
    freq, mean, lo, hi, names, labels, ref, ref_label, units, k, level, band_data, loss = read_psd(result)
    row = sensor_row(names, sensor)
    have_bands = band_data["lower_frequency"].size > 0
    if fmin is None:
        fmin = band_data["lower_frequency"][0] if (xscale == "log" and have_bands) else (freq[1] if xscale == "log" else 0.0)
    if fmax is None:
        fmax = band_data["upper_frequency"][-1] if have_bands else freq[-1]
    if not (np.isfinite(fmin) and np.isfinite(fmax) and 0 <= fmin < fmax):
        raise PostError(f"--fmin {fmin:g} --fmax {fmax:g}: allowed: 0 <= fmin < fmax, both finite", EX_USAGE)
    meas = read_measurement(measurement, column) if measurement else None
    delta_panel = bands and meas is not None
    cmp = compare_bands(meas, band_data, names[row], fmin, fmax, measured_averages) if delta_panel else None
    sim_style, meas_style = curve_styles(style)
    sim_label = label or (f"computed, mean of {k}" if style == "seed" else f"{labels[row]}, mean of {k}")
    meas_label = measurement_label or ("measured" if style == "seed" else "measurement")
    fig = Figure(figsize=(7.5, 6.6 if delta_panel else 4.6), layout="constrained")
    if title:
        fig.suptitle(title)
    ax = fig.add_subplot(2, 1, 1) if delta_panel else fig.add_subplot(1, 1, 1)
    sel = (freq > 0) & (freq >= fmin) & (freq <= fmax)
    if sensors_all:
        for s in range(len(names)):
            if s != row:
                ax.plot(freq[sel], db(mean[s, sel]), color="0.6", lw=0.5,
                        label="individual sensors" if s == (1 if row == 0 else 0) else None)
    if np.isfinite(hi[row, sel]).any():  # fewer than 5 realisations give no interval
        ax.fill_between(freq[sel], db(lo[row, sel]), db(hi[row, sel]), color=sim_style["color"], alpha=0.2, lw=0,
                        label=f"{100 * level:.0f} % interval of the mean")
    ax.plot(freq[sel], db(mean[row, sel]), label=sim_label, **sim_style)
    if ref is not None:
        ax.plot(freq[sel], db(ref[row, sel]), "--", color="0.25", lw=0.8, label=short(ref_label))
    if meas is not None:
        m = (meas[0] > 0) & (meas[0] >= fmin) & (meas[0] <= fmax)
        ax.plot(meas[0][m], db(meas[1][m]), label=meas_label, **meas_style)
    band_handles = []
    if bands and have_bands:
        inb = (band_data["lower_frequency"] >= fmin) & (band_data["upper_frequency"] <= fmax)
        band_handles.append(ax.hlines(band_data["level_db"][row][inb], band_data["lower_frequency"][inb],
                                      band_data["upper_frequency"][inb], color="C1", lw=2.0))
    if cmp is not None and cmp["count"]:  # the measured band levels the ΔL panel subtracts
        ok = cmp["used"]
        band_handles.append(ax.hlines(cmp["measured_db"][ok], band_data["lower_frequency"][ok],
                                      band_data["upper_frequency"][ok], color="k", lw=2.0))
    # y from the data inside the band range: the bins next to 0 Hz on a linear axis carry no power
    # worth the scale.
    lowest = max(fmin, band_data["lower_frequency"][0]) if have_bands else fmin
    inside = sel & (freq >= lowest)
    if ylim is not None:
        ax.set_ylim(*ylim)
    elif inside.any():
        shown = [db(lo[row, inside]), db(hi[row, inside])] + ([db(ref[row, inside])] if ref is not None else [])
        finite = np.concatenate([v[np.isfinite(v)] for v in shown])
        if finite.size:
            ax.set_ylim(finite.min() - 3.0, finite.max() + 3.0)
    ax.set_xscale(xscale)
    ax.set_xlim(fmin if xscale == "linear" else max(fmin, freq[1]), fmax)
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel(f"PSD level (dB re 1 {str(units).replace('^2', '²')})")
    ax.grid(True, which="both", alpha=0.3)
    label_log_axes(ax, plain="x")
    handles, labels = ax.get_legend_handles_labels()
    if band_handles:  # one entry for both band sets: the legend stays at six entries at most
        handles.append(tuple(band_handles))
        labels.append("third-octave bands" + (f": simulated, {meas_label}" if len(band_handles) > 1 else ""))
    # Above the axes, so it never covers data.
    ax.legend(handles, labels, loc="lower left", bbox_to_anchor=(0.0, 1.01, 1.0, 0.1), mode="expand", ncol=2,
              fontsize=8, frameon=False, borderaxespad=0.0, handler_map={tuple: HandlerTuple(ndivide=None)})
    note = loss_note(ax, loss) if loss else None
    if delta_panel:
        delta_axes(fig.add_subplot(2, 1, 2), cmp, band_data, row, meas_label)
    emit_figure(fig, out, fmt, dpi)
    return {"legend": labels, "comparison": cmp, "figure": fig, "loss_note": note.get_text() if note else None}


def delta_axes(ax2, cmp, band_data, row, meas_label):
    """ΔL per band, coloured by the answer of `rollspec compare`, over the interval it allows (grey)."""
    ok = cmp["used"]
    x = np.arange(ok.sum())
    lvl = band_data["level_db"][row][ok]
    if cmp["judged"]:
        ax2.bar(x, cmp["upper_db"][ok] - cmp["lower_db"][ok], bottom=lvl - cmp["upper_db"][ok], width=0.8,
                color="0.85")
    ax2.bar(x, cmp["delta_db"][ok], width=0.4, color=np.where(cmp["inside"][ok], "C0", "C3"))
    ax2.set_xticks(x)
    ax2.set_xticklabels([f"{v:g}" for v in band_data["nominal_frequency"][ok]], rotation=90, fontsize=7)
    ax2.axhline(0, color="k", lw=0.8)
    ax2.set_ylabel(f"ΔL simulated − {meas_label} (dB)", fontsize=9)
    kind = "prediction interval" if "prediction" in cmp["question"] else "interval of the mean"
    ax2.set_title(f"mean ΔL {cmp['bias_db']:+.2f} dB, rms about it {cmp['spread_db']:.2f} dB; inside the {kind} (grey) in {cmp['inside_count']}/"
                  f"{cmp['judged']} bands (blue: inside, red: outside)"
                  + (f"\ncombined test: {cmp['combined_test']['verdict']}" if cmp.get("combined_test") else "")
                  if cmp["count"] else f"the {meas_label} covers none of the bands", fontsize=8)
    ax2.set_xlabel("third-octave band (Hz)")
    ax2.grid(True, axis="y", alpha=0.3)
