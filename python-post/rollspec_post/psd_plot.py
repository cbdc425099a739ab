"""`psd`: the acceleration PSD of one row of a result (by default the sensor mean) with its interval,
the reference dashed, a measurement solid black, and (with --bands) the third-octave levels and a
ΔL panel. The measurement is drawn as `rollspec compare` saw it (its JSON: the recordings through the
model's estimator, or the PSD table as read; the noise recording; each band tested or left out and why):
python-post never judges a measurement itself. Made for a paper: level in dB re 1 (m/s²)²/Hz (the seeds'
"dB re 1 m/s²"), a linear frequency axis over the study's band range by default, a legend of at most six
entries above the axes, PNG, PDF or SVG by the file name."""
import os

import numpy as np
from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerTuple

from .engine_compare import CompareOptions, left_out, run_compare, tested
from .log_ticks import label_log_axes
from .result_file import (EX_DATAERR, EX_USAGE, PostError, attr, open_rollspec, point_label, read_bands, read_rows,
                          sensor_labels, sensor_row, strings, text_attr)
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
        loss = loss_said(f)
    shape = (len(names), freq.size)
    if freq.size < 2 or any(v.shape != shape for v in (mean, lo, hi) + ((ref,) if ref is not None else ())):
        raise PostError(f"{result}: /psd/mean, ci_lower, ci_upper (and /reference/psd) must be sensors x "
                        f"frequencies = {shape[0]} x {shape[1]}, with at least 2 frequencies", EX_DATAERR)
    if not np.any(np.isfinite(mean) & (mean > 0)):
        raise PostError(f"{result}: /psd/mean holds no positive finite value (all zero or NaN); "
                        "nothing to draw on a dB scale", EX_DATAERR)
    return freq, mean, lo, hi, names, labels, ref, ref_label, units, k, level, band_data, loss


LOSS_DRAWN_SHARE = 0.05  # a note of loss of contact is drawn above this share (a warning always is)


def loss_said(f):
    """What the run said of its loss of contact that the figure must carry: ("warning", text) when it warned
    (what the loss moved exceeds the bands' intervals, kernels/spectral D-35), ("note", text) when it noted a
    loss above LOSS_DRAWN_SHARE (the ball flies; a law that models it), else None."""
    if "/contact" not in f:
        return None
    warning = text_attr(f["/contact"], "loss_of_contact_warning")
    if warning:
        return "warning", warning
    note = text_attr(f["/contact"], "loss_of_contact_note")
    share = f["/contact/loss_of_contact_share"][()] if "/contact/loss_of_contact_share" in f else None
    share = float(np.ravel(share)[0]) if share is not None and np.size(share) else 0.0
    return ("note", note) if note and share > LOSS_DRAWN_SHARE else None


def loss_note(ax, said):
    """The run's loss-of-contact warning (red) or note (grey) on the PSD axes, at the top: a figure sent on
    alone still says that its levels are those of a ball that flies (or of a linearised law past its validity)."""
    kind, text = said
    red = kind == "warning"
    return ax.text(0.5, 0.97, ("LOSS OF CONTACT: " if red else "Loss of contact: ") + text, transform=ax.transAxes,
                   ha="center", va="top", fontsize=7.5, color="#7b1d12" if red else "#333333", wrap=True, zorder=10,
                   bbox={"boxstyle": "round", "facecolor": "#fdecea" if red else "#f2f2f2",
                         "edgecolor": "#c0392b" if red else "#888888", "lw": 1.5 if red else 1.0})


STYLES = ("default", "seed")


def curve_styles(style):
    """Line styles of the simulated mean and the measurement. `seed`: the seeds' figures (seed 001
    Fig. 8, seed 002 Figs. 10-11): computed dotted in colour, measured solid black."""
    if style == "seed":
        return {"color": "C3", "ls": ":", "lw": 1.4}, {"color": "k", "ls": "-", "lw": 1.0}
    return {"color": "C0", "ls": "-", "lw": 1.0}, {"color": "k", "ls": "-", "lw": 1.0}


def measurements_of(measurement):
    """A path or a list of paths (one recording per roll, or one PSD table) as a list."""
    if measurement is None:
        return []
    return [measurement] if isinstance(measurement, (str, os.PathLike)) else list(measurement)


def answer_for(result, measurement, options, row_name, fmin, fmax):
    """compare's JSON for the drawn row, over the drawn range where the caller bounded it."""
    o = CompareOptions(**vars(options)) if options is not None else CompareOptions()
    o.sensor = row_name
    o.fmin = fmin if o.fmin is None else o.fmin
    o.fmax = fmax if o.fmax is None else o.fmax
    return run_compare(result, measurements_of(measurement), o)


def plot_psd(result, out, measurement=None, bands=False, sensor=None, options=None, fmin=None, fmax=None,
             xscale="linear", sensors_all=False, dpi=150, kind=None, title=None, label=None, ylim=None,
             style="default", measurement_label=None, answer=None):
    """`sensor` (a name, or K for sensor_K) picks the row drawn and compared (default: the row `rollspec compare`
    uses, sensor_mean when present). `measurement`: recordings (one per roll) or a PSD table, put through
    `rollspec compare` with `options` (a CompareOptions: columns, unit, noise, ...), or `answer`, compare's JSON
    already made. `sensors_all` adds every sensor as a thin grey line. fmin/fmax bound the axis and the compared
    bands (default: the study's band range, from 0 Hz on a linear axis). `label`, `measurement_label`: legend
    names of the simulated mean and the measurement; `ylim` (low, high) in dB; `style` default or seed. Returns
    {"legend": labels, "comparison": compare's JSON or None, "loss_note": the loss-of-contact note drawn on the
    figure or None}. A result whose run warned of loss of contact (/contact@loss_of_contact_warning) gets that
    warning drawn on the axes in red; one that noted a loss above 5 % of the time, the note in grey."""
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
    if answer is None and measurements_of(measurement):
        answer = answer_for(result, measurement, options, names[row], fmin, fmax)
    if fmin is None:
        fmin = band_data["lower_frequency"][0] if (xscale == "log" and have_bands) else (freq[1] if xscale == "log" else 0.0)
    if fmax is None:
        fmax = band_data["upper_frequency"][-1] if have_bands else freq[-1]
    if not (np.isfinite(fmin) and np.isfinite(fmax) and 0 <= fmin < fmax):
        raise PostError(f"--fmin {fmin:g} --fmax {fmax:g}: allowed: 0 <= fmin < fmax, both finite", EX_USAGE)
    delta_panel = bands and answer is not None
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
    if answer is not None:
        draw_spectrum(ax, answer["measured_psd"], fmin, fmax, meas_label, meas_style)
        draw_spectrum(ax, answer.get("noise_psd"), fmin, fmax, "noise recording (rig at rest)",
                      {"color": "0.45", "ls": "--", "lw": 0.8})
    band_handles = []
    if bands and have_bands:
        inb = (band_data["lower_frequency"] >= fmin) & (band_data["upper_frequency"] <= fmax)
        band_handles.append(ax.hlines(band_data["level_db"][row][inb], band_data["lower_frequency"][inb],
                                      band_data["upper_frequency"][inb], color="C1", lw=2.0))
    if bands and answer is not None:  # the measured band levels the ΔL panel subtracts; left-out ones dotted grey
        for chosen, style_of in ((tested(answer), {"color": "k", "lw": 2.0}),
                                 (left_out(answer), {"color": "0.5", "lw": 2.0, "linestyles": ":"})):
            if chosen:
                band_handles.append(ax.hlines([b["measured_db"] for b in chosen], [b["lower_hz"] for b in chosen],
                                              [b["upper_hz"] for b in chosen], **style_of))
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
    if band_handles:  # one entry for every band set: the legend stays at six entries at most
        handles.append(tuple(band_handles))
        labels.append("third-octave bands" + (f": simulated, {meas_label}" if len(band_handles) > 1 else "")
                      + (" (dotted: left out)" if len(band_handles) > 2 else ""))
    # Above the axes, so it never covers data.
    ax.legend(handles, labels, loc="lower left", bbox_to_anchor=(0.0, 1.01, 1.0, 0.1), mode="expand", ncol=2,
              fontsize=8, frameon=False, borderaxespad=0.0, handler_map={tuple: HandlerTuple(ndivide=None)})
    note = loss_note(ax, loss) if loss else None
    if delta_panel:
        delta_axes(fig.add_subplot(2, 1, 2), answer, meas_label)
    emit_figure(fig, out, fmt, dpi)
    return {"legend": labels, "comparison": answer, "figure": fig, "loss_note": note.get_text() if note else None}


def draw_spectrum(ax, spectrum, fmin, fmax, label, style):
    """A spectrum of compare's JSON (measured_psd, noise_psd) over [fmin, fmax], bins with power only."""
    if not spectrum:
        return
    f, p = np.asarray(spectrum["frequency_hz"], float), np.asarray(spectrum["psd"], float)
    m = (f > 0) & (f >= fmin) & (f <= fmax) & (p > 0)
    ax.plot(f[m], db(p[m]), label=label, **style)


def headline(answer):
    """The level offset with its interval and the combined test's verdict, over the tested bands (one or two
    lines), or what compare says instead."""
    o, t = answer.get("level_offset"), answer["combined_test"]
    pct = f"{100 * answer['confidence_level']:.0f} %"
    if o is None:
        return f"no level offset: {answer['question']}"
    verdict = ("model rejected" if t["rejected"] else "not rejected") if t["defined"] else "none"
    p = f", p = {answer['p_value']:.2g}" if t["defined"] else ""
    return (f"level offset, model − measurement: {o['estimate_db']:+.2f} dB ({pct} interval {o['lower_db']:+.2f} … "
            f"{o['upper_db']:+.2f} dB) over {o['bands']} tested bands; combined test at level {t['level']:g}: "
            f"{verdict}{p}")


def delta_axes(ax2, answer, meas_label):
    """ΔL per compared band: tested bands coloured by compare's answer over the interval it allows (grey),
    left-out bands grey and hatched, named below the axis."""
    bands = answer["bands"]
    x = np.arange(len(bands))
    predicted = answer.get("measured_averages") is not None
    key = "prediction" if predicted else "ci"
    lo = np.array([b[f"{key}_lower_db"] if b[f"{key}_lower_db"] is not None else np.nan for b in bands], float)
    hi = np.array([b[f"{key}_upper_db"] if b[f"{key}_upper_db"] is not None else np.nan for b in bands], float)
    sim = np.array([b["simulated_db"] for b in bands], float)
    delta = np.array([b["delta_db"] for b in bands], float)
    test = np.array([b["use"] == "test" for b in bands])
    inside = np.array([bool(b["inside"]) for b in bands])
    if np.isfinite(hi).any():
        ax2.bar(x[test], (hi - lo)[test], bottom=(sim - hi)[test], width=0.8, color="0.85")
    ax2.bar(x[test], delta[test], width=0.4, color=np.where(inside[test], "C0", "C3"))
    if (~test).any():
        ax2.bar(x[~test], delta[~test], width=0.4, color="none", edgecolor="0.5", hatch="////", lw=0.6,
                label="left out: " + ", ".join(sorted({b["use"] for b in bands if b["use"] != "test"})))
        ax2.legend(loc="upper left", fontsize=7, frameon=False)
    ax2.set_xticks(x)
    ax2.set_xticklabels([f"{b['centre_hz']:g}" for b in bands], rotation=90, fontsize=7)
    ax2.axhline(0, color="k", lw=0.8)
    o = answer.get("level_offset")
    if o is not None:
        ax2.axhline(o["estimate_db"], color="C2", lw=0.8, ls="--")
    # The scale of the tested bands: a left-out band 50 dB under its floor would flatten them (it is hatched,
    # clipped at the edge, and in the report's table).
    shown = np.concatenate([delta[test], (sim - hi)[test], (sim - lo)[test], [0.0]])
    shown = shown[np.isfinite(shown)]
    if (~test).any() and shown.size:
        low, high = shown.min(), shown.max()
        pad = max(2.0, 0.15 * (high - low))
        ax2.set_ylim(low - pad, high + pad)
    ax2.set_ylabel(f"ΔL simulated − {meas_label} (dB)", fontsize=9)
    kind = "prediction interval" if predicted else "interval of the mean"
    ax2.set_title(headline(answer).replace("; combined", ";\ncombined") + f"; inside the {kind} (grey) in "
                  f"{answer['inside']}/{answer['judged']} tested bands (blue: inside, red: outside; dashed green: the "
                  "level offset)", fontsize=8, wrap=True)
    ax2.set_xlabel("third-octave band (Hz)")
    ax2.grid(True, axis="y", alpha=0.3)
