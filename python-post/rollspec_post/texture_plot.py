"""`texture`: a line texture, a surface image, and the target PSD against the realised one."""
import numpy as np
from matplotlib.figure import Figure

from .log_ticks import label_log_axes
from .result_file import PostError, EX_DATAERR, open_rollspec, read_rows
from .safe_output import emit_figure


def read_texture(path):
    """Lines (the first two), x, target and realised PSD, and the first surface, checked for shape."""
    with open_rollspec(path, ("rollspec-texture",)) as f:
        has_lines = "/texture/lines" in f
        has_surface = "/surface/heights" in f
        if not (has_lines or has_surface):
            raise PostError(f"{path}: holds neither /texture/lines nor /surface/heights", EX_DATAERR)
        d = {}
        if has_lines:
            all_lines = read_rows(f, "/texture/lines", 2)
            d.update(lines=all_lines[:2], count=all_lines.shape[0], x=read_rows(f, "/texture/x", 1),
                     k=read_rows(f, "/texture/psd_wavenumber", 1), target=read_rows(f, "/texture/psd_target", 1))
            if "/texture/psd_realised" in f:
                d["realised"] = (read_rows(f, "/texture/psd_realised_wavenumber", 1),
                                 read_rows(f, "/texture/psd_realised", 1))
        if has_surface:
            d.update(surface=read_rows(f, "/surface/heights", 3)[0] if f["/surface/heights"].shape[0] else None,
                     sx=read_rows(f, "/surface/x", 1), sy=read_rows(f, "/surface/y", 1))
    check_texture(path, d)
    return has_lines, has_surface, d


def check_texture(path, d):
    """Shapes that fit together and a target PSD with something to draw on a log axis."""
    bad = None
    if "lines" in d and (d["lines"].shape[1:] != d["x"].shape or d["k"].shape != d["target"].shape
                         or not np.any(d["target"] > 0) or d["x"].size < 2):
        bad = "/texture/lines, x, psd_wavenumber and psd_target do not fit together (or the target PSD is all zero)"
    if "realised" in d and d["realised"][0].shape != d["realised"][1].shape:
        bad = "/texture/psd_realised and psd_realised_wavenumber differ in length"
    if "sx" in d and (d["surface"] is None or d["surface"].shape != (d["sy"].size, d["sx"].size) or d["sx"].size < 2
                      or d["sy"].size < 2):
        bad = "/surface/heights is not realisation x y x x over /surface/y and /surface/x"
    if bad:
        raise PostError(f"{path}: {bad}", EX_DATAERR)


def plot_texture(path, out, kind=None):
    has_lines, has_surface, d = read_texture(path)
    lines, x, k, target, count = (d.get(n) for n in ("lines", "x", "k", "target", "count"))
    realised, surface, sx, sy = (d.get(n) for n in ("realised", "surface", "sx", "sy"))
    fig = Figure(figsize=(12, 4), layout="constrained")
    # room between panels: the colour bar's label sits right beside the next panel's y label otherwise
    fig.get_layout_engine().set(wspace=0.08)
    axes = fig.subplots(1, 3)
    if has_lines:
        for i, h in enumerate(lines):
            axes[0].plot(x * 1e3, h * 1e6, lw=0.6, label=f"realisation {i}")
        axes[0].set_xlabel("x (mm)")
        axes[0].set_ylabel("height (µm)")
        axes[0].set_title("line textures")
        axes[0].legend(fontsize=8)
        sel = target > 0
        axes[2].loglog(k[sel], target[sel], "k-", lw=1.2, label="target G(k)")
        if realised is not None:
            kr, gr = realised
            ok = (kr > 0) & (gr > 0)
            axes[2].loglog(kr[ok], gr[ok], "C1", lw=0.8, alpha=0.8, label=f"realised (mean of {count})")
        axes[2].set_ylim(target[sel].min() / 30, target[sel].max() * 30)
        axes[2].set_xlabel("wavenumber k (rad/m)")
        axes[2].set_ylabel("one-sided PSD (m³)")
        axes[2].set_title("PSD: target vs realised")
        axes[2].grid(True, which="both", alpha=0.3)
        axes[2].legend(fontsize=8)
        label_log_axes(axes[2])
    if has_surface:
        im = axes[1].imshow(surface * 1e6, origin="lower", cmap="viridis",
                            extent=[sx[0] * 1e6, sx[-1] * 1e6, sy[0] * 1e6, sy[-1] * 1e6])
        fig.colorbar(im, ax=axes[1], label="height (µm)")
        axes[1].set_xlabel("x (µm)")
        axes[1].set_ylabel("y (µm)")
        axes[1].set_title("isotropic surface")
    return emit_figure(fig, out, kind)
