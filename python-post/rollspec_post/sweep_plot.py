"""`sweep`: a parameter sweep's result (rollspec run with [sweep]): the third-octave band levels of one
sensor against the swept value, one line per band, and the PSDs of chosen points overlaid. A crossed
sweep of several keys is drawn along its first key, the other keys at their first value (named in
the title). Thirty bands or points would make a legend that covers the data: the bands are told apart by
a colour bar of their centre frequency, the points by a legend above the axes up to LEGEND_POINTS of them
and by a colour bar of the swept value beyond."""
import matplotlib
import numpy as np
from matplotlib.colors import LogNorm, Normalize
from matplotlib.figure import Figure

from .result_file import EX_DATAERR, EX_USAGE, PostError, open_rollspec, read_rows, sensor_row, strings, text_attr
from .safe_output import emit_figure


def db(x):
    with np.errstate(divide="ignore", invalid="ignore"):
        return 10.0 * np.log10(x)


def read_sweep(result, sensor=None):
    """{axes: [(name, values, units)], levels, nominal, frequency, psd, sensor name} of a sweep result;
    levels and psd keep one leading dimension per sweep axis."""
    with open_rollspec(result) as f:
        if "/sweep" not in f:
            raise PostError(f"{result}: not a sweep result (no /sweep group); rollspec run of a study with "
                            "[sweep] (or --sweep) writes one", EX_DATAERR)
        mean = f["/bands/level_db"] if "/bands/level_db" in f else None
        if mean is None:
            raise PostError(f"{result}: has no /bands/level_db", EX_DATAERR)
        axes = []
        for i in range(max(mean.ndim - 2, 0)):
            if len(mean.dims[i]) == 0:
                raise PostError(f"{result}: axis {i} of /bands/level_db has no dimension scale (a sweep axis names "
                                "its key)", EX_DATAERR)
            scale = mean.dims[i][0]
            values = np.asarray(scale[()])
            if values.shape != (mean.shape[i],):
                raise PostError(f"{result}: the sweep axis {scale.name} has {values.size} values for "
                                f"{mean.shape[i]} points", EX_DATAERR)
            axes.append((scale.name.split("/")[-1], values, text_attr(scale, "units", "")))
        if not axes:
            raise PostError(f"{result}: /bands/level_db has no sweep axis (sensors x bands only)", EX_DATAERR)
        names = strings(f, "/bands/sensor")
        row = sensor_row(names, sensor)
        levels = np.asarray(mean[()], float)[..., row, :]
        nominal = read_rows(f, "/bands/nominal_frequency", 1)
        frequency = read_rows(f, "/psd/frequency", 1)
        psd = np.asarray(f["/psd/mean"][()], float)
        psd = psd[..., row, :] if psd.ndim == len(axes) + 2 else np.broadcast_to(psd[row], levels.shape[:-1] +
                                                                                    frequency.shape)
    return {"axes": axes, "levels": levels, "nominal": nominal, "frequency": frequency, "psd": psd,
            "sensor": names[row]}


LEGEND_POINTS = 6  # more PSDs than this get a colour bar instead of legend entries


def axis_label(name, units):
    return f"{name} ({units})" if units not in ("", "1", "-") else name


def plot_sweep(result, out, sensor=None, points=None, kind=None):
    d = read_sweep(result, sensor)
    (name, values, units), rest = d["axes"][0], d["axes"][1:]
    first = (slice(None),) + (0,) * len(rest)
    levels, psd = d["levels"][first], d["psd"][first]  # points x bands, points x frequencies
    if values.dtype.kind not in "fiu":
        raise PostError(f"{result}: the sweep axis {name} holds text values; the band-level plot needs numbers",
                        EX_DATAERR)
    chosen = list(range(len(values))) if points is None else points
    bad = [p for p in chosen if not 0 <= p < len(values)]
    if bad:
        raise PostError(f"--points {bad[0]}: the sweep has points 0 to {len(values) - 1} along {name}", EX_USAGE)
    fig = Figure(figsize=(11, 4.8), constrained_layout=True)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    drawn = [b for b in range(levels.shape[1]) if np.any(np.isfinite(levels[:, b]))]
    centres = d["nominal"][drawn] if drawn else np.array([1.0])
    band_norm = LogNorm(centres.min(), max(centres.max(), centres.min() * 1.01))
    bands = matplotlib.colormaps["viridis"]
    for b in drawn:
        left.plot(values, levels[:, b], marker="o", ms=3, lw=1, color=bands(band_norm(d["nominal"][b])),
                  label=f"{d['nominal'][b]:g} Hz")
    left.set_xlabel(axis_label(name, units))
    left.set_ylabel("band level (dB)")
    left.set_xticks(values)
    left.grid(True, alpha=0.3)
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=band_norm, cmap=bands), ax=left, pad=0.01)
    bar.set_label("third-octave band centre (Hz)", fontsize=8)
    points_norm = Normalize(values[chosen].min(), values[chosen].max() if values[chosen].max() > values[chosen].min()
                            else values[chosen].min() + 1.0)
    cmap = matplotlib.colormaps["plasma"]
    for i, p in enumerate(chosen):
        colour = cmap(0.9 * points_norm(values[p])) if len(chosen) > LEGEND_POINTS else f"C{i}"
        right.plot(d["frequency"], db(psd[p]), lw=0.9, color=colour, label=f"{name} = {values[p]:g}")
    right.set_xlabel("frequency (Hz)")
    right.set_ylabel("PSD level (dB)")
    right.grid(True, alpha=0.3)
    if len(chosen) > LEGEND_POINTS:
        bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=points_norm, cmap=matplotlib.colors.ListedColormap(
            cmap(np.linspace(0, 0.9, 256)))), ax=right, pad=0.01)
        bar.set_label(axis_label(name, units), fontsize=8)
    else:  # above the axes, where it covers nothing
        right.legend(loc="lower left", bbox_to_anchor=(0.0, 1.01), ncol=3, fontsize=8, frameon=False,
                     borderaxespad=0.0)
    fixed = ", ".join(f"{n} = {v[0]:g}" if v.dtype.kind in "fiu" else f"{n} = {v[0]}" for n, v, _ in rest)
    fig.suptitle(f"sweep of {name}, sensor {d['sensor']}" + (f" ({fixed})" if fixed else ""), fontsize=10)
    return emit_figure(fig, out, kind)
