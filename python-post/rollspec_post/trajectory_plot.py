"""`trajectory`: node paths of a rolling beam in the plane where they move most, their speeds and
angular speeds, and the energies over time with the balance error on its own scale."""
import numpy as np
from matplotlib.figure import Figure

from .result_file import EX_DATAERR, PostError, is_dimension_scale, open_rollspec, read_rows
from .safe_output import emit_figure

AXIS_NAMES = "xyz"


def plane_axes(position):
    """The two coordinates with the largest range over all times and nodes, in x, y, z order."""
    span = np.ptp(position.reshape(-1, 3), axis=0)
    return tuple(sorted(np.argsort(span)[-2:]))


def read_history(path):
    with open_rollspec(path) as f:
        if "/time_history/position" not in f:
            raise PostError(f"{path}: has no /time_history/position (not a rolling-beam result)", EX_DATAERR)
        t = read_rows(f, "/time_history/time", 1)
        pos = read_rows(f, "/time_history/position", 3)
        omega = read_rows(f, "/time_history/angular_velocity", 3) if "/time_history/angular_velocity" in f else None
        group = f["/time_history/energy"] if "/time_history/energy" in f else {}
        if not hasattr(group, "keys"):
            raise PostError(f"{path}: /time_history/energy is not a group of energies", EX_DATAERR)
        # only the series: the engine labels each with a dimension scale `<name>_index` in the same group
        energy = {n: read_rows(f, f"/time_history/energy/{n}", 1) for n in group.keys()
                  if not is_dimension_scale(group[n])}
    if pos.ndim != 3 or pos.shape[0] != t.size or pos.shape[2] != 3 or t.size < 2:
        raise PostError(f"{path}: /time_history/position is {pos.shape}, expected time ({t.size}) x node x 3",
                        EX_DATAERR)
    if omega is not None and omega.shape != pos.shape:
        raise PostError(f"{path}: /time_history/angular_velocity is {omega.shape}, expected {pos.shape}", EX_DATAERR)
    bad = [n for n, e in energy.items() if e.shape != t.shape]
    if bad:
        raise PostError(f"{path}: /time_history/energy/{bad[0]} is not one value per time", EX_DATAERR)
    return t, pos, omega, energy


def plot_trajectory(path, out, kind=None):
    t, pos, omega, energy = read_history(path)
    balance = energy.pop("balance_error", None)
    a, b = plane_axes(pos)
    nodes = pos.shape[1]
    fig = Figure(figsize=(12, 8), constrained_layout=True)
    ax_path, ax_speed, ax_e, ax_bal = fig.subplots(2, 2).ravel()

    colours = [f"C{i % 10}" for i in range(nodes)]
    marks = np.linspace(0, t.size - 1, 11).astype(int)  # equal time steps: spacing shows the speed
    for n in range(nodes):
        ax_path.plot(pos[:, n, a], pos[:, n, b], color=colours[n], lw=1.0,
                     label=f"node {n}" if nodes <= 8 or n in (0, nodes - 1) else None)
        ax_path.plot(pos[marks, n, a], pos[marks, n, b], "o", color=colours[n], ms=3)
    ax_path.set_xlabel(f"{AXIS_NAMES[a]} (m)")
    ax_path.set_ylabel(f"{AXIS_NAMES[b]} (m)")
    ax_path.set_title(f"node paths ({AXIS_NAMES[a]}–{AXIS_NAMES[b]}; dots every {t[marks[1]] - t[0]:.3g} s)")
    ax_path.grid(True, alpha=0.3)
    ax_path.legend(fontsize=8)

    # mean over nodes: for a rigidly rolling beam every node has the same speed
    speed = np.linalg.norm(np.gradient(pos, t, axis=0), axis=2).mean(axis=1)
    ax_speed.plot(t, speed, "C0", lw=1.2, label="|v| (mean over nodes)")
    ax_speed.set_xlabel("time (s)")
    ax_speed.set_ylabel("speed (m/s)", color="C0")
    ax_speed.grid(True, alpha=0.3)
    ax_speed.set_title("speed and angular speed")
    if omega is not None:
        ax_w = ax_speed.twinx()
        ax_w.plot(t, np.linalg.norm(omega, axis=2).mean(axis=1), "C1", lw=1.2, label="|ω| (mean over nodes)")
        ax_w.set_ylabel("angular speed (rad/s)", color="C1")
        lines = ax_speed.get_lines() + ax_w.get_lines()
        ax_speed.legend(lines, [line.get_label() for line in lines], fontsize=8, loc="center right")

    for name, e in energy.items():
        ax_e.plot(t, e, lw=1.2, label=name.replace("_", " "))
    ax_e.set_xlabel("time (s)")
    ax_e.set_ylabel("energy (J)")
    ax_e.set_title("energies")
    ax_e.grid(True, alpha=0.3)
    if energy:  # below the axes: eight energies over the curves would hide them
        ax_e.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=min(4, len(energy)),
                    frameon=False)

    if balance is not None:
        ax_bal.plot(t, balance, "C3", lw=1.0)
        scale = max(abs(e).max() for e in energy.values()) if energy else 0.0
        rel = f" (max {np.abs(balance).max() / scale:.2e} of the largest energy)" if scale > 0 else ""
        ax_bal.set_title("energy balance error" + rel, fontsize=10)
        ax_bal.set_ylabel("balance error (J)")
    else:
        ax_bal.text(0.5, 0.5, "no /time_history/energy/balance_error in the file", ha="center", va="center",
                    transform=ax_bal.transAxes)
    ax_bal.set_xlabel("time (s)")
    ax_bal.grid(True, alpha=0.3)
    return emit_figure(fig, out, kind)
