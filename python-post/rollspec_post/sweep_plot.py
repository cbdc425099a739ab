"""`sweep`: a parameter sweep's result (rollspec run with [sweep]): the third-octave band levels of one
sensor against the swept value, one line per band, and the PSDs of chosen points overlaid. A crossed
sweep of several keys is drawn along its first key, the other keys at their first value (named in
the title)."""
import matplotlib
import numpy as np
from matplotlib.figure import Figure

from .measurement import sensor_row
from .result_file import EX_DATAERR, EX_USAGE, PostError, open_rollspec, read_rows, strings, text_attr
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
    colours = matplotlib.colormaps["viridis"](np.linspace(0, 0.95, levels.shape[1]))
    for b in range(levels.shape[1]):
        if np.any(np.isfinite(levels[:, b])):
            left.plot(values, levels[:, b], marker="o", ms=3, lw=1, color=colours[b], label=f"{d['nominal'][b]:g} Hz")
    left.set_xlabel(axis_label(name, units))
    left.set_ylabel("band level (dB)")
    left.set_xticks(values)
    left.grid(True, alpha=0.3)
    left.legend(fontsize=6, ncol=2, title="band", title_fontsize=7)
    for p in chosen:
        right.plot(d["frequency"], db(psd[p]), lw=0.9, label=f"{name} = {values[p]:g}")
    right.set_xlabel("frequency (Hz)")
    right.set_ylabel("PSD level (dB)")
    right.grid(True, alpha=0.3)
    right.legend(fontsize=8)
    fixed = ", ".join(f"{n} = {v[0]:g}" if v.dtype.kind in "fiu" else f"{n} = {v[0]}" for n, v, _ in rest)
    fig.suptitle(f"sweep of {name}, sensor {d['sensor']}" + (f" ({fixed})" if fixed else ""), fontsize=10)
    return emit_figure(fig, out, kind)
