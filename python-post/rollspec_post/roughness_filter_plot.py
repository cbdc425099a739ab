"""`roughness`: the roughness PSD along the rolling path, raw and as each contact filter passes it.

Reads /roughness of a ball-on-beam result (rollspec writes it for every study but blocked_force = solver):
psd_raw is the study's [texture] line PSD G(k) (filter = none draws it up to the band limit k_B, beam B40),
psd_patch the 1D patch average over the Hertz width 2a
(kernels/beam B35a, on the line's samples), psd_iso2d G_eq, the path PSD a Hertz disc of radius a sees on
the isotropic surface (kernels/texture Eq. 38), and with filter = solver psd_solver, the strip-mean PSD of
the equivalent roughness h_eq of half-space solves at the weight (kernels/contact ER-2) the line was
synthesised from. The filter the study used is drawn thick.
"""
import numpy as np
from matplotlib.figure import Figure

from .log_ticks import label_log_axes
from .result_file import EX_DATAERR, PostError, attr, open_rollspec, read_rows, text_attr
from .safe_output import emit_figure

CURVES = (("none", "psd_raw", "raw G(k) of [texture] (none: the same up to k_B)", "k"),
          ("patch", "psd_patch", "patch: G(k) T(k)², 1D average over 2a", "C0"),
          ("iso2d", "psd_iso2d", "iso2d: G_eq(k), Hertz disc on the isotropic surface", "C3"),
          ("solver", "psd_solver", "solver: PSD of h_eq, half-space solves on rough strips", "C2"))


def read_roughness(path):
    """(wavenumber, {filter: psd}, used filter, a, speed) from a result file's /roughness group."""
    return read_roughness_and_band_limit(path)[:5]


def read_roughness_and_band_limit(path):
    """read_roughness and the band limit k_B (inf when not given)."""
    with open_rollspec(path, ("rollspec-result",)) as f:
        if "/roughness/psd_raw" not in f:
            raise PostError(f"{path}: holds no /roughness (only ball-on-beam results with a line texture do)", EX_DATAERR)
        g = f["/roughness"]
        k = read_rows(f, "/roughness/wavenumber", 1)
        curves = {name: read_rows(f, "/roughness/" + ds, 1) for name, ds, _, _ in CURVES if ds in g}
        used = str(text_attr(g, "filter", ""))
        a = attr(f, "/roughness", "contact_half_width")
        speed = attr(f, "/ball", "speed") if "/ball" in f and "speed" in f["/ball"].attrs else None
        k_b = attr(f, "/roughness", "band_limit_wavenumber") if "band_limit_wavenumber" in g.attrs else np.inf
    wrong = [name for name, g in curves.items() if g.shape != k.shape]
    if wrong or not any(np.any(g > 0) for g in curves.values()):
        raise PostError(f"{path}: /roughness PSDs must be one value per wavenumber with some positive values "
                        f"({'differs: ' + ', '.join(wrong) if wrong else 'all zero'})", EX_DATAERR)
    return k, curves, used, a, speed, k_b


def plot_roughness_filters(path, out, dpi=150, kind=None):
    k, curves, used, a, speed, k_b = read_roughness_and_band_limit(path)
    fig = Figure(figsize=(7.5, 4.8), constrained_layout=True)
    ax = fig.subplots()
    positive = []
    for name, _, label, colour in CURVES:
        if name not in curves:
            continue
        g = curves[name]
        ok = g > 0
        positive.append(g[ok])
        ax.loglog(k[ok], g[ok], color=colour, lw=2.2 if name == used else 1.0,
                  label=label + (" — used" if name == used else ""))
    if a > 0:
        ax.axvline(np.pi / a, color="0.5", ls=":", lw=0.8)
        ax.text(np.pi / a, 0.02, " ka = π", transform=ax.get_xaxis_transform(), fontsize=8, color="0.4")
    if np.isfinite(k_b) and k_b < k[-1]:
        ax.axvline(k_b, color="0.5", ls="--", lw=0.8)
        ax.text(k_b, 0.2, " k_B, band\n limit", transform=ax.get_xaxis_transform(), fontsize=8, color="0.4", va="top")  # below the curves
    positive = [v for v in positive if v.size]
    top = max(v.max() for v in positive)
    ax.set_ylim(max(min(v.min() for v in positive), top * 1e-12), top * 5)
    ax.set_xlabel("wavenumber k along the path (rad/m)")
    ax.set_ylabel("one-sided roughness PSD (m³)")
    title = f"roughness along the path, Hertz contact radius a = {a * 1e6:.3g} µm"
    ax.set_title(title, fontsize=10)
    if speed and np.isfinite(speed):  # frequency axis f = v k / 2 pi
        sec = ax.secondary_xaxis("top", functions=(lambda x: x * speed / (2 * np.pi), lambda f: f * 2 * np.pi / speed))
        sec.set_xlabel(f"frequency at v = {speed:g} m/s (Hz)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    label_log_axes(ax)
    return emit_figure(fig, out, kind, dpi)
