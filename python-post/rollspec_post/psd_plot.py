"""`psd`: acceleration PSD in dB re 1 (m/s^2)^2/Hz with its confidence band, an exact reference or
a measurement overlaid, and (with --bands) the third-octave levels with a per-band difference panel."""
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .measurement import compare_bands, read_measurement
from .result_file import open_rollspec, text_attr


def db(x):
    with np.errstate(divide="ignore"):
        return 10.0 * np.log10(x)


def plot_psd(result, out, measurement=None, bands=False, sensor=None):
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
        band_data = {n: f["/bands/" + n][:] for n in ("nominal_frequency", "lower_frequency", "upper_frequency",
                                                     "level_db", "ci_lower_db", "ci_upper_db")}
    sensors = range(len(names)) if sensor is None else [sensor]
    meas = read_measurement(measurement) if measurement else None
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
        cmp = compare_bands(meas, band_data, sensors[0])
        ok = cmp["used"]
        ax2 = fig.add_subplot(2, 1, 2)
        # bars coloured by whether the measured level lies in the simulated interval
        ax2.bar(np.arange(ok.sum()), cmp["delta_db"][ok], color=np.where(cmp["inside"][ok], "C0", "C3"))
        ax2.set_xticks(np.arange(ok.sum()))
        ax2.set_xticklabels([f"{v:g}" for v in band_data["nominal_frequency"][ok]], rotation=90, fontsize=7)
        ax2.axhline(0, color="k", lw=0.8)
        ax2.set_ylabel("ΔL sim − meas (dB)")
        ax2.set_title(f"rms {cmp['rms_db_error']:.2f} dB; measured level inside the interval in "
                      f"{cmp['inside_count']}/{cmp['count']} bands (blue: inside, red: outside)"
                      if cmp["count"] else "the measurement covers none of the bands", fontsize=9)
        ax2.set_xlabel("third-octave band (Hz)")
        ax2.grid(True, axis="y", alpha=0.3)
    FigureCanvasAgg(fig).print_png(out)
    return out
