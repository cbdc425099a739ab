"""`texture`: a line texture, a surface image, and the target PSD against the realised one."""
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .result_file import PostError, EX_DATAERR, open_rollspec


def plot_texture(path, out):
    with open_rollspec(path, ("rollspec-texture",)) as f:
        has_lines = "/texture/lines" in f
        has_surface = "/surface/heights" in f
        if not (has_lines or has_surface):
            raise PostError(f"{path}: holds neither /texture/lines nor /surface/heights", EX_DATAERR)
        lines = f["/texture/lines"][:2] if has_lines else None
        x = f["/texture/x"][:] if has_lines else None
        k, target = (f["/texture/psd_wavenumber"][:], f["/texture/psd_target"][:]) if has_lines else (None, None)
        realised = ((f["/texture/psd_realised_wavenumber"][:], f["/texture/psd_realised"][:])
                    if "/texture/psd_realised" in f else None)
        count = f["/texture/lines"].shape[0] if has_lines else 0
        surface = f["/surface/heights"][0] if has_surface else None
        sx, sy = (f["/surface/x"][:], f["/surface/y"][:]) if has_surface else (None, None)
    fig = Figure(figsize=(12, 4), constrained_layout=True)
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
    if has_surface:
        im = axes[1].imshow(surface * 1e6, origin="lower", cmap="viridis",
                            extent=[sx[0] * 1e6, sx[-1] * 1e6, sy[0] * 1e6, sy[-1] * 1e6])
        fig.colorbar(im, ax=axes[1], label="height (µm)")
        axes[1].set_xlabel("x (µm)")
        axes[1].set_ylabel("y (µm)")
        axes[1].set_title("isotropic surface")
    FigureCanvasAgg(fig).print_png(out)
    return out
