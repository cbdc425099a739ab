"""`stiffness`: contact force P(δ) and stiffness k(δ) of a rough ball with their ±1 std spread over
realisations (and the real contact area when tabled), against the smooth Hertz ball of the same
radius and modulus."""
import numpy as np
from matplotlib.figure import Figure

from .result_file import EX_DATAERR, PostError, attr, open_rollspec, read
from .safe_output import emit_figure

TABLE_FILETYPE = "rollspec-stiffness-table"
COLUMNS = ("approach", "force_mean", "force_std", "stiffness_mean", "stiffness_std")


def hertz(approach, radius, modulus):
    """Hertz force P = 4/3 E* sqrt(R) δ^1.5 and its derivative k = 2 E* sqrt(R δ)."""
    d = np.clip(approach, 0.0, None)
    return 4.0 / 3.0 * modulus * np.sqrt(radius) * d ** 1.5, 2.0 * modulus * np.sqrt(radius * d)


def floats(f, name):
    try:
        return np.asarray(read(f, name), dtype=float)
    except (TypeError, ValueError):
        raise PostError(f"{f.filename}: {name} is not numeric", EX_DATAERR) from None


def read_table(path):
    with open_rollspec(path, (TABLE_FILETYPE,)) as f:
        cols = {c: floats(f, "/stiffness/" + c) for c in COLUMNS}
        area = floats(f, "/stiffness/contact_area_mean") if "/stiffness/contact_area_mean" in f else None
        attrs = f["/stiffness"].attrs
        missing = [a for a in ("ball_radius", "effective_modulus") if a not in attrs]
        if missing:
            raise PostError(f"{path}: /stiffness lacks the attribute(s) {', '.join(missing)}", EX_DATAERR)
        meta = {a: attr(f, "/stiffness", a) for a in ("ball_radius", "effective_modulus")}
        meta["hardness"] = attr(f, "/stiffness", "hardness") if "hardness" in attrs else np.inf
        meta["realisations"] = attr(f, "/stiffness", "realisations", int) if "realisations" in attrs else None
    if area is not None:
        cols["contact_area_mean"] = area
    n = cols["approach"].size
    bad = [c for c in cols if cols[c].shape != (n,)]
    if bad or n < 2:
        raise PostError(f"{path}: /stiffness columns must be 1-D of one length >= 2 (differs: {', '.join(bad)})",
                        EX_DATAERR)
    return cols, meta


def plot_stiffness(path, out, kind=None):
    cols, meta = read_table(path)
    d = cols["approach"]
    p_h, k_h = hertz(d, meta["ball_radius"], meta["effective_modulus"])
    um = d * 1e6
    n = meta["realisations"]
    spread = "±1 std" + (f" over {n} realisation{'s' if n != 1 else ''}" if n else "")
    has_area = "contact_area_mean" in cols
    fig = Figure(figsize=(15 if has_area else 11, 4.5), constrained_layout=True)
    axes = fig.subplots(1, 3 if has_area else 2)
    ax_p, ax_k = axes[:2]
    # force in N, stiffness in N/µm: the numbers a bearing engineer reads off a rig
    for ax, mean, std, ref, scale, label in ((ax_p, "force_mean", "force_std", p_h, 1.0, "force P (N)"),
                                             (ax_k, "stiffness_mean", "stiffness_std", k_h, 1e-6,
                                              "stiffness k (N/µm)")):
        m, s = cols[mean] * scale, cols[std] * scale
        ax.plot(um, m, "C0", lw=1.5, label="table: mean")
        ax.fill_between(um, m - s, m + s, color="C0", alpha=0.25, lw=0, label=spread)
        ax.plot(um, ref * scale, "k--", lw=1.0, label="Hertz (smooth ball, same R, E*)")
        ax.set_xlabel("approach δ (µm)")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    ax_p.set_title("force–approach")
    ax_k.set_title("contact stiffness dP/dδ")
    if has_area:
        # Hertz area π a² with a² = R δ: the rough ball touches on a fraction of it
        axes[2].plot(um, cols["contact_area_mean"] * 1e12, "C0", lw=1.5, label="table: mean")
        axes[2].plot(um, np.pi * meta["ball_radius"] * np.clip(d, 0, None) * 1e12, "k--", lw=1.0,
                     label="Hertz π R δ")
        axes[2].set_xlabel("approach δ (µm)")
        axes[2].set_ylabel("real contact area (µm²)")
        axes[2].set_title("contact area")
        axes[2].grid(True, alpha=0.3)
        axes[2].legend(fontsize=8)
    hard = "elastic" if not np.isfinite(meta["hardness"]) else f"H = {meta['hardness'] / 1e9:.3g} GPa"
    fig.suptitle(f"R = {meta['ball_radius'] * 1e3:.4g} mm, E* = {meta['effective_modulus'] / 1e9:.4g} GPa, {hard}",
                 fontsize=10)
    return emit_figure(fig, out, kind)
