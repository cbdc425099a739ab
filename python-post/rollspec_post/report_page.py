"""`report`: one self-contained HTML page from a result file (the page a user sends to a colleague):
key figures, the PSD plot (embedded as a PNG data URI), the comparison with a measurement, provenance and
the resolved study text. No scripts and no external resources. The comparison is `rollspec compare`'s
answer (engine_compare.py), shown as it is: a headline from the tested bands (the level offset with its
interval, the combined test's verdict), the bands left out apart with the reason, compare's warnings, and
how the measurement files were read."""
import base64
import html
import io
import os
import re

import numpy as np

from .engine_compare import THEORY, WHY_LEFT_OUT, CompareOptions, left_out, plain_text, run_compare, tested
from .psd_plot import headline, plot_psd
from .rig_summary import rig_parameters
from .result_file import (EX_DATAERR, PostError, as_text, attr, open_rollspec, point_label, read, read_bands, scalar,
                          sensor_labels, sensor_row, strings, text_attr)
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
tr.left td { background: #f1f1f3; color: #6b6f7a; font-style: italic; }
p.headline { font-size: 1.1em; border-left: 4px solid #3b6fb6; padding: 6px 12px; background: #f3f6fb; }
ul.flags li { margin: 4px 0; } sup { font-size: .75em; } details { margin: 10px 0; }
.wide { overflow-x: auto; }
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
             "loss_note": text_attr(f["/contact"], "loss_of_contact_note") if "/contact" in f else None,
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
    said = f" The run warned: {esc(r['loss_warning'])}." if r.get("loss_warning") else \
        f" The run noted: {esc(r['loss_note'])}." if r.get("loss_note") else ""
    return (f'<div class="warning" role="alert"><strong>Loss of contact: {100 * r["loss"]:.3g} % of the time'
            f"{esc(spread)}</strong>{f', above the {100 * threshold:.3g} % this report flags' if above else ''}."
            f"{said} The ball leaves the surface: the contact force is not the linear response to the roughness, "
            "and levels and ΔL should be read with that in mind.</div>")


class Footnotes:
    """The theory notes' equation labels the engine's texts cite, as numbered footnotes: the page's text
    carries none of them."""

    def __init__(self):
        self.labels = []

    def text(self, value):
        """`value` without its labels, escaped, with a footnote mark for them."""
        plain, labels = plain_text(str(value))
        if not labels:
            return esc(plain)
        marks = []
        for label in labels:
            if label not in self.labels:
                self.labels.append(label)
            marks.append(str(self.labels.index(label) + 1))
        return esc(plain) + f"<sup>{','.join(marks)}</sup>"

    def html(self):
        if not self.labels:
            return ""
        items = "".join(f"<li>{esc(label)}</li>" for label in self.labels)
        return (f'<h2>Notes</h2><p>How compare decides, equation by equation: the theory notes '
                f'<code>{esc(THEORY)}</code> (Theory › Spectral in the documentation).</p><ol class="notes">{items}</ol>')


def offset_cards(answer, level):
    """The headline's figures: the level offset and the combined test over the tested bands."""
    o, t = answer.get("level_offset"), answer["combined_test"]
    if o is None:
        return [card("level offset, model − measurement", "—", "none: " + answer["question"])]
    d = np.array([b["delta_db"] for b in tested(answer)], float)
    about = float(np.sqrt(np.mean((d - o["estimate_db"]) ** 2))) if d.size else float("nan")
    cards = [card("level offset, model − measurement", f"{o['estimate_db']:+.2f} dB",
                  f"{level} interval {o['lower_db']:+.2f} … {o['upper_db']:+.2f} dB over {o['bands']} tested bands; "
                  f"rms of ΔL about it {about:.2f} dB")]
    if t["defined"]:
        cards.append(card(f"combined test over the {t['bands']} tested bands",
                          "model rejected" if t["rejected"] else "not rejected",
                          f"p = {answer['p_value']:.3g} at level {t['level']:g}", bool(t["rejected"])))
    else:
        cards.append(card("combined test over the tested bands", "—", plain_text(t["verdict"])[0]))
    return cards


def band_ranges(bands):
    """'12.5–630 Hz' style runs of consecutive band centres."""
    return ", ".join(f"{b['centre_hz']:g} Hz" for b in bands) if len(bands) <= 3 else \
        f"{len(bands)} bands, {bands[0]['centre_hz']:g} … {bands[-1]['centre_hz']:g} Hz"


def key_figures(r, answer, threshold=LOSS_WARNING_SHARE):
    level = f"{100 * r['confidence']:.0f} %"
    cards = [card("realisations", r["realisations"], f"sensor {r['sensor_label']}")]
    if answer is not None:
        cards += offset_cards(answer, level)
        predicted = answer.get("measured_averages") is not None
        kind = "prediction interval" if predicted else "interval of the simulated mean"
        cards.append(card(f"tested bands with the measurement inside the {level} {kind}",
                          f"{answer['inside']} of {answer['judged']}" if answer["judged"] else "—",
                          f"{answer['bands_compared']} bands compared, {answer['bands_tested']} tested; rms ΔL over "
                          f"them {answer['rms_db_error']:.2f} dB" if answer["rms_db_error"] is not None else ""))
        gone = left_out(answer)
        cards.append(card("bands left out of the test and the offset", f"{len(gone)} of {answer['bands_compared']}",
                          "; ".join(f"{use}: {band_ranges([b for b in gone if b['use'] == use])}"
                                    for use in dict.fromkeys(b["use"] for b in gone)) or "none"))
    else:
        cards.append(card("level offset, model − measurement", "—", "no measurement given (--measurement FILE...)"))
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


def comparison_headline(answer, notes):
    """One paragraph from the tested bands only, and what was left out and why."""
    gone = left_out(answer)
    text = f"Over the tested bands: {esc(headline(answer))}."
    if gone:
        why = "; ".join(f"{band_ranges([b for b in gone if b['use'] == use])} ({use}: {WHY_LEFT_OUT.get(use, use)})"
                        for use in dict.fromkeys(b["use"] for b in gone))
        text += f" Left out of the test and the offset: {esc(why)}."
    return f'<p class="headline">{text}</p><p>Question: {notes.text(answer["question"])}</p>'


def warnings_list(answer, notes):
    if not answer["warnings"]:
        return ""
    items = "".join(f"<li>{notes.text(w)}</li>" for w in answer["warnings"])
    return f'<h3>What compare flagged</h3><ul class="flags">{items}</ul>'


def number(value, digits=2):
    return "—" if value is None else f"{value:.{digits}f}"


def band_table(answer, notes):
    """Every compared band; the left-out ones marked, with the reason."""
    predicted = answer.get("measured_averages") is not None
    noise = any(b["noise_db"] is not None for b in answer["bands"])
    rows = []
    for b in answer["bands"]:
        kept = b["use"] == "test"
        cls = ' class="left"' if not kept else ("" if b["inside"] or b["inside"] is None else ' class="out"')
        answer_cell = ("yes" if b["inside"] else "no" if b["inside"] is not None else "—") if kept else \
            f"left out: {b['use']}"
        cells = [f"{b['centre_hz']:g}", number(b["simulated_db"]), number(b["measured_db"]), f"{b['delta_db']:+.2f}",
                 f"{number(b['ci_lower_db'])} … {number(b['ci_upper_db'])}"]
        if predicted:
            cells.append(f"{number(b['prediction_lower_db'])} … {number(b['prediction_upper_db'])}")
        if noise:
            cells.append(number(b["noise_db"]))
        cells.append(answer_cell)
        rows.append(f"<tr{cls}>" + "".join(f'<td class="num">{esc(c)}</td>' for c in cells) + "</tr>")
    head = ["band (Hz)", "simulated (dB)", "measured (dB)", "Δ (dB)", "interval of the mean (dB)"] + \
        (["prediction interval (dB)"] if predicted else []) + (["noise (dB)"] if noise else []) + ["inside"]
    legend = "; ".join(f"{use}: {WHY_LEFT_OUT.get(use, use)}" for use in dict.fromkeys(b["use"] for b in left_out(answer)))
    return (f'<div class="wide"><table><tr>{"".join(f"<th>{esc(h)}</th>" for h in head)}</tr>{"".join(rows)}</table></div>'
            + (f"<p>Grey rows are left out of the test and the level offset ({esc(legend)}).</p>" if legend else ""))


def read_notes(answer, measurements, notes):
    """How compare read the files, each line once: a note repeated for every roll names the rolls once."""
    names = [str(m) for m in measurements]
    grouped = {}
    for line in answer.get("measurement_notes", []):
        who, rest = next(((n, line[len(n) + 2:]) for n in names if line.startswith(n + ": ")), (None, line))
        grouped.setdefault(rest, []).append(who)
    items = []
    for rest, who in grouped.items():
        files = [os.path.basename(w) for w in who if w]
        prefix = "" if not files else (f"{files[0]}: " if len(files) == 1 else
                                       f"{files[0]} … {files[-1]} ({len(files)} files): ")
        items.append(f"<li>{esc(prefix)}{notes.text(rest)}</li>")
    return (f"<details><summary>How the measurement was read ({len(items)} lines)</summary><ul>{''.join(items)}</ul>"
            "</details>") if items else ""


def description(study):
    m = re.search(r"^\s*description\s*=\s*(.+)$", study, re.MULTILINE)
    return m.group(1).strip() if m else ""


def build_report(result, out, measurements=(), options=None, loss_threshold=LOSS_WARNING_SHARE, sensor=None):
    page = report_html(result, measurements, options, loss_threshold, sensor).encode("utf-8")
    write_atomic(os.path.realpath(out), lambda fh: fh.write(page))  # a failed write leaves the old file
    return out


def file_list(paths):
    names = [os.path.basename(str(p)) for p in paths]
    return ", ".join(names) if len(names) <= 3 else f"{names[0]} … {names[-1]} ({len(names)} files)"


def report_html(result, measurements=(), options=None, loss_threshold=LOSS_WARNING_SHARE, sensor=None):
    """The page as text; `HTML_MARKER` in its head lets a later run replace it without --force.
    `measurements`: recordings (one per roll) or a PSD table, compared by `rollspec compare` with `options`
    (CompareOptions). `loss_threshold`: the loss-of-contact share above which the page opens with a warning.
    `sensor` (a name, or K for sensor_K; default options.sensor, else sensor_mean if present): the row shown."""
    options = CompareOptions(**vars(options)) if options is not None else CompareOptions()
    options.sensor = sensor if sensor is not None else options.sensor
    r = read_result(result, options.sensor)
    options.sensor = r["sensor_name"]  # the name: a number would be read as the K of sensor_K
    measurements = [measurements] if isinstance(measurements, (str, os.PathLike)) else list(measurements or [])
    answer = run_compare(result, measurements, options) if measurements else None
    notes = Footnotes()
    fmin = options.fmin if options.fmin else None
    fmax = options.fmax if options.fmax is not None and np.isfinite(options.fmax) else None
    psd_uri = png_data_uri(lambda buf: plot_psd(result, buf, measurements or None, True, r["sensor_name"],
                                                fmin=fmin, fmax=fmax, answer=answer))
    prov = dict(r["provenance"], result_file=os.path.basename(result))
    if measurements:
        prov["measurement_files"] = file_list(measurements)
    if options.noise:
        prov["noise_recording"] = os.path.basename(str(options.noise))
    scene = prov["scene"]
    at = f" at the sweep point {r['point']}" if r["point"] else ""
    parts = [f"<h1>rollspec report: {esc(scene)}{esc(at)}</h1>",
             f'<p class="sub">{esc(description(r["study"]) or os.path.basename(result))}</p>',
             loss_warning(r, loss_threshold),
             "<h2>Key figures</h2>", key_figures(r, answer, loss_threshold), rig_table(r["study"]),
             "<h2>Acceleration PSD</h2>",
             f'<img alt="acceleration PSD of sensor {esc(r["sensor_name"])}" src="{psd_uri}">']
    if answer is not None:
        parts += ["<h2>Third-octave bands against the measurement</h2>", comparison_headline(answer, notes),
                  warnings_list(answer, notes), band_table(answer, notes), read_notes(answer, measurements, notes)]
    parts += [notes.html(), "<h2>Provenance</h2>",
              '<div class="wide"><table>' + "".join(f"<tr><th>{esc(k)}</th><td>{esc(v)}</td></tr>"
                                                    for k, v in prov.items()) + "</table></div>",
              "<h2>Study (resolved, defaults included)</h2>", f"<pre>{esc(r['study'])}</pre>",
              f"<footer>made by rollspec_post {esc(__version__)} from {esc(os.path.basename(result))}</footer>"]
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">{HTML_MARKER}'
            f"<title>{esc('rollspec report: ' + str(scene))}</title><style>{STYLE}</style></head>\n"
            f"<body><main>\n" + "\n".join(parts) + "\n</main></body></html>\n")
