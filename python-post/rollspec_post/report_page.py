"""`report`: one self-contained HTML page from a result file (the page a user sends to a colleague):
key figures, the PSD plot (embedded as a PNG data URI), the band comparison with a measurement,
provenance and the resolved study text. No scripts and no external resources."""
import base64
import html
import io
import os
import re

import numpy as np

from .measurement import compare_bands, read_bands, read_measurement, sensor_row
from .psd_plot import plot_psd
from .rig_summary import rig_parameters
from .result_file import (EX_DATAERR, PostError, as_text, attr, open_rollspec, point_label, read, scalar, sensor_labels,
                          strings, text_attr)
from .safe_output import HTML_MARKER, write_atomic
from . import __version__

LOSS_WARNING_SHARE = 0.05  # above it the ball flies part of the time: the linear reading of the PSD fails
PROVENANCE = ("filetype", "schema_version", "rollspec_version", "git_sha", "seed", "rng", "library_versions", "scene",
              "created", "host", "command_line")

STYLE = """
body { font-family: "DejaVu Sans", Arial, sans-serif; margin: 0; background: #f4f5f7; color: #1d2330; }
main { max-width: 1080px; margin: 0 auto; padding: 24px 32px 40px; background: #fff; }
h1 { font-size: 1.6em; margin: 0 0 4px; } h2 { font-size: 1.15em; margin: 28px 0 8px; border-bottom: 1px solid #dde; }
.sub { color: #556; margin: 0 0 18px; }
.cards { display: grid; grid-template-columns: repeat(3, 1fr); gap: 12px; }
.card { border: 1px solid #d6dae3; border-radius: 6px; padding: 10px 14px; background: #fafbfd; }
.card .v { font-size: 1.45em; font-weight: bold; } .card .k { color: #445; } .card .n { color: #667; font-size: .85em; }
table { border-collapse: collapse; font-size: .9em; } td, th { border: 1px solid #d6dae3; padding: 3px 8px; text-align: left; }
th { background: #eef0f5; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
tr.out td { background: #fdecec; }
.warning { border: 2px solid #c0392b; background: #fdecea; color: #7b1d12; border-radius: 6px; padding: 10px 14px;
  margin: 0 0 18px; font-size: 1.05em; } .warning strong { font-size: 1.1em; }
.card.alert { border-color: #c0392b; background: #fdecea; }
img { width: 100%; border: 1px solid #e3e6ed; }
pre { background: #f6f7f9; border: 1px solid #e3e6ed; padding: 10px; font-size: .85em; white-space: pre-wrap; }
footer { color: #778; font-size: .8em; margin-top: 28px; }
"""


def esc(value):
    return html.escape(str(value), quote=True)


def png_data_uri(render):
    """Run `render(buffer)` (a plot function writing PNG) and return the PNG as a data URI."""
    buf = io.BytesIO()
    render(buf)
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def plain(value):
    if isinstance(value, np.ndarray):
        value = value.reshape(-1)[0] if value.size == 1 else value.tolist()
    return as_text(value)


def read_result(path, sensor):
    with open_rollspec(path) as f:
        r = {"provenance": {k: plain(text_attr(f, k, "—")) for k in PROVENANCE},
             "study": plain(text_attr(f, "study", "")),
             "bands": read_bands(f),
             "sensors": strings(f, "/psd/sensor"),
             "realisations": attr(f, "/psd", "realisations", int),
             "wall_seconds": scalar(f, "/run/wall_seconds"),
             "threads": plain(f["/run"].attrs.get("threads")) if "/run" in f else None,
             "loss": scalar(f, "/contact/loss_of_contact_share"),
             "loss_std": scalar(f, "/contact/loss_of_contact_share_std"),
             "loss_warning": text_attr(f["/contact"], "loss_of_contact_warning") if "/contact" in f else None,
             "law": text_attr(f["/contact"], "law") if "/contact" in f else None,
             "point": point_label(f)}
        r["confidence"] = r["bands"]["confidence"]
        r["sensor"] = sensor = sensor_row(r["sensors"], sensor)
        r["sensor_name"] = r["sensors"][sensor]
        r["sensor_label"] = sensor_labels(f)[sensor]  # with its position along the span, where recorded
        if "/reference/psd" in f:
            # share of PSD bins over the band range whose interval holds the reference, named by what it is
            r["reference_label"] = str(text_attr(f["/reference/psd"], "label", "reference"))
            freq = read(f, "/psd/frequency")
            lo, hi, ref = (read(f, n) for n in ("/psd/ci_lower", "/psd/ci_upper", "/reference/psd"))
            if not freq.size or any(np.shape(v) != (len(r["sensors"]), freq.size) for v in (lo, hi, ref)):
                raise PostError(f"{path}: /psd/ci_lower, ci_upper and /reference/psd must be sensors x frequencies",
                                EX_DATAERR)
            lo, hi, ref = lo[sensor], hi[sensor], ref[sensor]
            b = r["bands"]
            sel = (freq >= b["lower_frequency"][0]) & (freq <= b["upper_frequency"][-1]) if b["lower_frequency"].size \
                else np.zeros(freq.shape, bool)
            if sel.any():
                r["reference"] = (int(((ref >= lo) & (ref <= hi))[sel].sum()), int(sel.sum()),
                                  freq[sel][0], freq[sel][-1])
    return r


def card(key, value, note="", alert=False):
    return f'<div class="card{" alert" if alert else ""}"><div class="k">{esc(key)}</div><div class="v">{esc(value)}</div>' \
           f'<div class="n">{esc(note)}</div></div>'


def loss_too_high(r, threshold):
    """Above `threshold`, or with law = linearised whenever the run warned (any loss of contact leaves
    that law's validity, whatever the threshold)."""
    linearised_left = r.get("law") == "linearised" and bool(r.get("loss_warning"))
    return linearised_left or (r["loss"] is not None and np.isfinite(r["loss"]) and r["loss"] > threshold)


def loss_warning(r, threshold):
    """The banner at the top of the page when the ball leaves the beam more than `threshold` of the time,
    or when the run warned of its loss of contact (its words quoted)."""
    if not loss_too_high(r, threshold):
        return ""
    spread = f" (± {100 * r['loss_std']:.2g} % over realisations)" if r["loss_std"] is not None else ""
    above = r["loss"] is not None and np.isfinite(r["loss"]) and r["loss"] > threshold
    said = f" The run warned: {esc(r['loss_warning'])}." if r.get("loss_warning") else ""
    return (f'<div class="warning" role="alert"><strong>Loss of contact: {100 * r["loss"]:.3g} % of the time'
            f"{esc(spread)}</strong>{f', above the {100 * threshold:.3g} % this report flags' if above else ''}."
            f"{said} The ball leaves the surface: the contact force is not the linear response to the roughness, "
            "and levels and ΔL should be read with that in mind.</div>")


def key_figures(r, cmp, threshold=LOSS_WARNING_SHARE):
    level = f"{100 * r['confidence']:.0f} %"
    cards = [card("realisations", r["realisations"], f"sensor {r['sensor_label']}")]
    if cmp is not None:
        over = f"over {cmp['count']} third-octave bands"
        cards.append(card("mean ΔL (bias), simulated − measured", f"{cmp['bias_db']:+.2f} dB", over))
        cards.append(card("rms of ΔL about the bias", f"{cmp['spread_db']:.2f} dB",
                          f"rms dB error including the bias: {cmp['rms_db_error']:.2f} dB"))
        kind = "prediction interval" if "prediction" in cmp["question"] else "interval of the simulated mean"
        cards.append(card(f"bands with the measurement inside the {level} {kind}",
                          f"{100 * cmp['inside_count'] / cmp['judged']:.0f} %" if cmp["judged"] else "—",
                          f"{cmp['inside_count']} of {cmp['judged']} bands" if cmp["judged"] else cmp["question"]))
        if cmp.get("combined_test"):  # D-26, the verdict `rollspec compare` prints
            t = cmp["combined_test"]
            cards.append(card("combined test over the bands (D-26)",
                              "—" if t["p_value"] is None else f"p = {t['p_value']:.3g}", t["verdict"],
                              bool(t["rejected"])))
    else:
        cards.append(card("mean ΔL (bias) and rms about it", "—", "no measurement given (--measurement CSV)"))
        cards.append(card(f"bands with the measurement inside the {level} interval", "—", "no measurement given"))
    if r["loss"] is not None:
        note = f"± {100 * r['loss_std']:.2g} % over realisations" if r["loss_std"] is not None else ""
        alert = loss_too_high(r, threshold)
        cards.append(card("loss-of-contact share", f"{100 * r['loss']:.3g} %",
                          (note + "; " if note else "") + f"above {100 * threshold:.3g} %" if alert else note, alert))
    else:
        cards.append(card("loss-of-contact share", "—", "no contact in this scene"))
    if r["wall_seconds"] is not None:
        threads = f"{r['threads']} threads" if r["threads"] is not None else ""
        cards.append(card("run time", f"{r['wall_seconds']:.3g} s", threads))
    else:
        cards.append(card("run time", "—", "not recorded"))
    if "reference" in r:
        n_in, n, f0, f1 = r["reference"]
        cards.append(card(f"bins holding the reference PSD ({r['reference_label']}) in their {level} interval",
                          f"{100 * n_in / n:.1f} %", f"{n_in} of {n} bins, {f0:g}–{f1:g} Hz"))
    return '<div class="cards">' + "".join(cards) + "</div>"


def rig_table(study):
    """The rig's main parameters, one row per key, grouped by study section; '' for a scene without them."""
    sections = rig_parameters(study)
    if not sections:
        return ""
    rows = "".join((f'<tr><th rowspan="{len(keys)}">{esc(section)}</th>' if i == 0 else "<tr>")
                   + f"<td>{esc(key)}</td><td>{esc(value)}</td></tr>"
                   for section, keys in sections for i, (key, value) in enumerate(keys))
    return f'<h2>Rig</h2><table class="rig">{rows}</table>'


def band_table(r, cmp):
    b, s = r["bands"], r["sensor"]
    predicted = "prediction" in cmp["question"]
    rows = []
    for i in np.flatnonzero(cmp["used"]):
        cls = "" if cmp["inside"][i] else ' class="out"'
        cells = (f"{b['nominal_frequency'][i]:g}", f"{b['level_db'][s][i]:.2f}", f"{cmp['measured_db'][i]:.2f}",
                 f"{cmp['delta_db'][i]:+.2f}", f"{b['ci_lower_db'][s][i]:.2f} … {b['ci_upper_db'][s][i]:.2f}",
                 f"{cmp['lower_db'][i]:.2f} … {cmp['upper_db'][i]:.2f}" if predicted else "",
                 ("yes" if cmp["inside"][i] else "no") if cmp["judged"] else "—")
        rows.append(f"<tr{cls}>" + "".join(f'<td class="num">{esc(c)}</td>' for c in cells) + "</tr>")
    head = "".join(f"<th>{esc(h)}</th>" for h in ("band (Hz)", "simulated (dB)", "measured (dB)", "Δ (dB)",
                                                  "interval of the mean (dB)", "prediction interval (dB)", "inside"))
    return (f'<p>Question: {esc(cmp["question"])}</p>'
            f"<table><tr>{head}</tr>{''.join(rows)}</table>")


def description(study):
    m = re.search(r"^\s*description\s*=\s*(.+)$", study, re.MULTILINE)
    return m.group(1).strip() if m else ""


def build_report(result, out, measurement=None, sensor=None, fmin=0.0, fmax=np.inf, column=None, measured_averages=None,
                 loss_threshold=LOSS_WARNING_SHARE):
    page = report_html(result, measurement, sensor, fmin, fmax, column, measured_averages,
                       loss_threshold).encode("utf-8")
    write_atomic(os.path.realpath(out), lambda fh: fh.write(page))  # a failed write leaves the old file
    return out


def report_html(result, measurement=None, sensor=None, fmin=0.0, fmax=np.inf, column=None, measured_averages=None,
                loss_threshold=LOSS_WARNING_SHARE):
    """The page as text; `HTML_MARKER` in its head lets a later run replace it without --force.
    `loss_threshold`: the loss-of-contact share above which the page opens with a warning."""
    r = read_result(result, sensor)
    sensor = r["sensor_name"]  # the name: a number would be read as the K of sensor_K
    meas = read_measurement(measurement, column) if measurement else None
    cmp = compare_bands(meas, r["bands"], sensor, fmin, fmax, measured_averages) if meas is not None else None
    if cmp is not None and cmp["count"] == 0:
        raise PostError(f"{measurement}: covers none of the result's bands inside [{fmin:g}, {fmax:g}] Hz",
                        EX_DATAERR)
    psd_uri = png_data_uri(lambda buf: plot_psd(result, buf, measurement, True, sensor, column, measured_averages,
                                                        fmin if fmin > 0 else None,
                                                        fmax if np.isfinite(fmax) else None))
    prov = dict(r["provenance"], result_file=os.path.basename(result))
    if measurement:
        prov["measurement_file"] = os.path.basename(measurement)
    scene = prov["scene"]
    at = f" at the sweep point {r['point']}" if r["point"] else ""
    parts = [f"<h1>rollspec report: {esc(scene)}{esc(at)}</h1>",
             f'<p class="sub">{esc(description(r["study"]) or os.path.basename(result))}</p>',
             loss_warning(r, loss_threshold),
             "<h2>Key figures</h2>", key_figures(r, cmp, loss_threshold), rig_table(r["study"]),
             "<h2>Acceleration PSD</h2>",
             f'<img alt="acceleration PSD of sensor {esc(r["sensor_name"])}" src="{psd_uri}">']
    if cmp is not None:
        parts += ["<h2>Third-octave bands against the measurement</h2>", band_table(r, cmp)]
    parts += ["<h2>Provenance</h2>",
              "<table>" + "".join(f"<tr><th>{esc(k)}</th><td>{esc(v)}</td></tr>" for k, v in prov.items())
              + "</table>",
              "<h2>Study (resolved, defaults included)</h2>", f"<pre>{esc(r['study'])}</pre>",
              f"<footer>made by rollspec_post {esc(__version__)} from {esc(os.path.basename(result))}</footer>"]
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">{HTML_MARKER}'
            f"<title>{esc('rollspec report: ' + str(scene))}</title><style>{STYLE}</style></head>\n"
            f"<body><main>\n" + "\n".join(parts) + "\n</main></body></html>\n")
