"""`psd`: acceleration PSD in dB re 1 (m/s^2)^2/Hz with its confidence band, an exact reference or
a measurement overlaid, and (with --bands) the third-octave levels with a per-band difference panel."""
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .measurement import compare_bands, read_bands, read_measurement, sensor_row
from .result_file import open_rollspec, text_attr


def db(x):
    with np.errstate(divide="ignore"):
        return 10.0 * np.log10(x)


def plot_psd(result, out, measurement=None, bands=False, sensor=None, column=None, measured_averages=None,
             fmin=0.0, fmax=np.inf):
    """`sensor` (name or index) limits the plot to one row; the ΔL panel uses the row `rollspec
    compare` would (that one, else sensor_mean if present, else the first) and says which."""
    with open_rollspec(result) as f:
        freq = f["/psd/frequency"][:]
        mean, lo, hi = f["/psd/mean"][:], f["/psd/ci_lower"][:], f["/psd/ci_upper"][:]
        names = [n.decode() if isinstance(n, bytes) else n for n in f["/psd/sensor"][:]]
        ref = f["/reference/psd"][:] if "/reference/psd" in f else None
        ref_label = text_attr(f["/reference/psd"], "label", "reference") if ref is not None else None
        units = text_attr(f["/psd/mean"], "units")
        k = int(f["/psd"].attrs["realisations"])
        level = float(f["/psd"].attrs["confidence_level"])
        scene = text_attr(f, "scene", "")
        band_data = read_bands(f)
    sensors = range(len(names)) if sensor is None else [sensor_row(names, sensor)]
    meas = read_measurement(measurement, column) if measurement else None
    fig = Figure(figsize=(9, 7 if (bands and meas is not None) else 5.5), constrained_layout=True)
    rows = 2 if (bands and meas is not None) else 1
    ax = fig.add_subplot(rows, 1, 1)
    sel = freq > 0
    for s in sensors:
        line, = ax.semilogx(freq[sel], db(mean[s, sel]), lw=1.0, label=f"{names[s]}: mean of {k}")
        ax.fill_between(freq[sel], db(lo[s, sel]), db(hi[s, sel]), color=line.get_color(), alpha=0.25, lw=0,
                        label=f"{100 * level:.0f} % interval")
        if ref is not None:
            ax.semilogx(freq[sel], db(ref[s, sel]), "k--", lw=0.8, label=ref_label)
        if bands:
            ax.hlines(band_data["level_db"][s], band_data["lower_frequency"], band_data["upper_frequency"],
                      color=line.get_color(), lw=2.5, alpha=0.8, label="third-octave bands")
    if meas is not None:
        ax.semilogx(meas[0], db(meas[1]), color="C3", lw=1.0, label="measurement")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("PSD (dB re 1 " + str(units) + ")")
    ax.set_title(f"{scene}: acceleration PSD" if scene else "acceleration PSD")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    if rows == 2:
        cmp = compare_bands(meas, band_data, sensor, fmin, fmax, measured_averages)
        ok = cmp["used"]
        ax2 = fig.add_subplot(2, 1, 2)
        # ΔL bars coloured by the answer to compare's question; grey: the ΔL the interval allows
        x = np.arange(ok.sum())
        level = band_data["level_db"][cmp["row"]][ok]
        if cmp["judged"]:
            ax2.bar(x, cmp["upper_db"][ok] - cmp["lower_db"][ok], bottom=level - cmp["upper_db"][ok],
                    width=0.8, color="0.85", label="ΔL the interval allows")
        ax2.bar(x, cmp["delta_db"][ok], width=0.4, color=np.where(cmp["inside"][ok], "C0", "C3"))
        ax2.set_xticks(x)
        ax2.set_xticklabels([f"{v:g}" for v in band_data["nominal_frequency"][ok]], rotation=90, fontsize=7)
        ax2.axhline(0, color="k", lw=0.8)
        ax2.set_ylabel("ΔL sim − meas (dB)")
        ax2.set_title(f"{cmp['sensor']}: rms {cmp['rms_db_error']:.2f} dB; inside {cmp['inside_count']}/"
                      f"{cmp['judged']} bands (blue: inside, red: outside)\n{cmp['question']}"
                      if cmp["count"] else "the measurement covers none of the bands", fontsize=9)
        ax2.set_xlabel("third-octave band (Hz)")
        ax2.grid(True, axis="y", alpha=0.3)
    FigureCanvasAgg(fig).print_png(out)
    return cmp if rows == 2 else None
