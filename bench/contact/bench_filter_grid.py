#!/usr/bin/python3
"""What the equivalent-roughness table of `[contact] filter = solver` can drop and keep its band levels (issue 51):
fewer positions, and a coarser cell, each against the exhaustive table's own discretisation error.

  /usr/bin/python3 bench/contact/bench_filter_grid.py [--bin build/werror/rollspec] [--positions 256] \
      [--textures rig,rougher,untested] [--record bench/records/validation/filter-grid.json]

On the seed 002 rig (studies/seed002-rig-1ms.ini, contact.law = hertz, contact.filter = solver) and the textures
of the path benches (the rig's, a rougher one and one no test uses), third-octave band levels of h_eq's PSD over
the run's bands at the ball's speed (contact README ER-1, ER-2):
  - positions: the exhaustive table as `rollspec run` builds it (`answer_tolerance = 0`, its 2 strips x 1024
    positions, the derived step), read at every 2nd and every 3rd position and put back on every position by a
    cubic spline through them (interpolation the contact's band limit allows), against the table itself;
  - cell: one strip per texture of the rig's isotropic texture (kernels/texture Eq. 6, rollspec.surfaces.isotropic)
    drawn at half the table's cell, and the same surface at the table's cell and at twice it (2 x 2 cell means, the
    grid's own representation of a surface, kernels/texture Eq. 26a); h_eq at the same positions on each grid by
    load-controlled solves (rollspec.contact.solve, elastic, cold at every position, the ball at the window's
    centre), the window the table's in metres. Twice the cell against the table's cell is what a coarse grid
    would cost at the answer; the table's cell against half of it is the exhaustive table's own error.
The table's cell, window, step and contact radius come from `rollspec plan`; the load from the table the run built.
"""
import configparser
import os
import pathlib
import re
import subprocess
import sys
import time

import h5py
import numpy as np
from scipy.interpolate import CubicSpline
from scipy.signal import welch

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "bench" / "contact"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from bench_path_ladder import TEXTURES  # noqa: E402  (the path benches' textures: --set texture.key=value lists)
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

STUDY = ROOT / "studies" / "seed002-rig-1ms.ini"
COMMON = ["contact.law=hertz", "contact.filter=solver", "study.realisations=2",
          "equivalent_roughness.answer_tolerance=0"]
THINNING = (2, 3)
HERTZ_LINE = re.compile(r"Hertz a = ([\d.]+) um")
PLAN_LINE = re.compile(r"cell ([\d.]+) um \(a/[\d.]+\).*?window (\d+) cells, (\d+) positions per strip \(step (\d+) "
                       r"cells = [\d.]+ um\), Welch segment (\d+); contact radius a = ([\d.]+) um")
TITLE = ("The filter's table (filter = solver): fewer positions and a coarser cell, against the exhaustive table's "
         "own discretisation error")
SETTINGS = ("studies/seed002-rig-1ms.ini with contact.law = hertz, contact.filter = solver. Positions: the exhaustive "
            "table (answer_tolerance = 0, 2 strips x {positions_engine} positions {step_um:.1f} um apart) read at "
            "every "
            "2nd / 3rd position, a cubic spline through them back to every position. Cell: one strip per texture "
            "drawn at half the table's cell ({cell_um:.3f} um), {positions} positions {grid_step_um:.1f} um apart "
            "(every 2nd of the table's), window {window_um:.0f} um, h_eq by cold load-controlled solves on cells of "
            "a/{a_half:.0f}, a/{a_cell:.0f} (the table's) and a/{a_double:.0f} of the same surface. Band levels of "
            "h_eq's PSD (Welch, Hann, segments {segment_um:.2f} mm with half overlap, each segment's mean removed) "
            "over the run's third octaves {band_lo:.0f} Hz - {band_hi:.0f} Hz at {speed:g} m/s.")
NOTES = ("Each figure is the largest |difference| over the bands with a Welch bin, and the band it is at. The grid "
         "columns are one strip per texture, the thinning columns the table's two strips. Cold solve CPU: "
         "rollspec.contact.solve on one thread, the whole strip's solves on each grid, the table's cell over twice "
         "it; the table's own warm-started solves cost less, so this is what a coarse grid saves per cold solve, "
         "not per table.")


def study_keys():
    """The study's [texture] keys as floats (the keys this bench varies and the cut-offs) and its ball radius."""
    parser = configparser.ConfigParser(inline_comment_prefixes=("#",))
    parser.read(STUDY)
    t = parser["texture"]
    if t.get("source") != "self-affine":
        fail(f"{STUDY}: [texture] source = {t.get('source')}; this bench draws the self-affine texture only", 1)
    return ({k: float(t[k]) for k in ("hurst", "rolloff_wavelength", "short_wavelength", "rms")},
            float(parser["ball"]["radius"]))


def plan_geometry(binary):
    r = subprocess.run([str(binary), "plan", str(STUDY), *[a for kv in COMMON for a in ("--set", kv)]],
                       capture_output=True, text=True)
    m, hertz = PLAN_LINE.search(r.stdout + r.stderr), HERTZ_LINE.search(r.stdout + r.stderr)
    if r.returncode != 0 or not m or not hertz:
        fail(f"{binary} plan {STUDY.name}: no equivalent-roughness geometry in its output", 1)
    return {"hertz_radius": float(hertz.group(1)) * 1e-6, "cell": float(m.group(1)) * 1e-6, "window": int(m.group(2)),
            "positions": int(m.group(3)),
            "step": int(m.group(4)), "segment": int(m.group(5)), "radius": float(m.group(6)) * 1e-6}


def band_levels(h, spacing, segment, speed, lower, upper):
    """Band levels (dB re 1 m^2) of the mean Welch PSD of the rows of h (positions `spacing` apart) over the
    frequency bands [lower, upper) at `speed` (NaN where a band holds no bin)."""
    f, p = welch(h, fs=speed / spacing, nperseg=segment, noverlap=segment // 2, window="hann", detrend="constant",
                 axis=-1)
    p = np.atleast_2d(p).mean(axis=0)
    out = np.full(len(lower), np.nan)
    for b, (lo, hi) in enumerate(zip(lower, upper)):
        sel = (f >= lo) & (f < hi)
        if sel.any():
            out[b] = 10 * np.log10(p[sel].sum())
    return out


def thinned(height, m):
    """Every m-th position of each strip, put back on the positions up to the last of them by a cubic spline:
    (thinned rows, the exhaustive rows over the same positions)."""
    n = height.shape[1]
    kept = np.arange(0, n, m)
    span = np.arange(kept[-1] + 1)
    return np.array([CubicSpline(kept, row[kept])(span) for row in height]), height[:, :span.size]


def self_affine(texture, k_max):
    """Eq. 6 with k_l = 0 on a log grid, scaled to the rms, cut at k_max (the grid's Nyquist)."""
    kr, ks = 2 * np.pi / texture["rolloff_wavelength"], 2 * np.pi / texture["short_wavelength"]
    k = np.concatenate([np.linspace(kr / 200, kr, 200, endpoint=False), np.geomspace(kr, ks, 800)])
    g = np.where(k < kr, 1.0, (k / kr) ** -(1 + 2 * texture["hurst"]))
    g *= texture["rms"] ** 2 / np.trapz(g, k)
    keep = k <= k_max
    return k[keep], g[keep]


def heq_on_grid(rollspec, z, cell, window, step, positions, radius, e_star, load):
    """h_eq = delta_smooth - delta_eq (ER-2) at each position by cold load-controlled solves; CPU seconds."""
    ball = np.asarray(rollspec.contact.ball_gap(radius, cell, window, window))
    y0 = z.shape[0] // 2 - window // 2
    t0 = time.process_time()
    smooth = rollspec.contact.solve(ball, cell, e_star=e_star, force=load, stiffness=False)["approach"]
    h = [smooth - rollspec.contact.solve(np.ascontiguousarray(ball - z[y0:y0 + window, j * step:j * step + window]),
                                         cell, e_star=e_star, force=load, stiffness=False)["approach"]
         for j in range(positions)]
    return np.array(h), time.process_time() - t0


def worst(diff, centre):
    ok = ~np.isnan(diff)
    b = int(np.argmax(np.abs(np.where(ok, diff, 0.0))))
    return f"{abs(diff[b]):.3f} at {centre[b]:.0f} Hz"


def main():
    parser = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    parser.add_argument("--positions", type=int, default=256,
                        help="positions per grid strip (at least the table's Welch segment, 256 on the rig)")
    parser.add_argument("--textures", default=",".join(TEXTURES), help=f"comma-separated, of {', '.join(TEXTURES)}")
    a, binary = bench_record.record_script_arguments(parser)
    textures = [t for t in a.textures.split(",") if t]
    for t in textures:
        if t not in TEXTURES:
            fail(f"--textures: {t!r} is not one of {', '.join(TEXTURES)}", 64)
    module = pathlib.Path(binary).parent / "python"
    if not (module / "rollspec").is_dir():
        fail(f"--bin {a.bin}: no Python module beside it ({module}/rollspec); allowed: a build tree's rollspec", 66)
    sys.path.insert(0, str(module))
    os.environ["OMP_NUM_THREADS"] = "1"  # one thread for the solves' CPU ratio (read when the module loads)
    import rollspec  # the module of the build measured
    geo = plan_geometry(binary)
    if a.positions < geo["segment"]:  # three half-overlapping Welch segments of the table's length at least
        fail(f"--positions: {a.positions} is too few; allowed: {geo['segment']} or more (three Welch segments)", 64)
    base, ball_radius = study_keys()
    busy, own, t0 = bench_record.busy_seconds(), bench_record.own_cpu(), time.perf_counter()
    rows, data = [], {}
    for name in textures:
        texture = dict(base, **{kv.split("=")[0].removeprefix("texture."): float(kv.split("=")[1])
                                for kv in TEXTURES[name]})
        settings = COMMON + TEXTURES[name]
        with bench_record.study_run(binary, STUDY, settings, 1, "bench-filter-grid-") as (path, _, _, _):
            with h5py.File(path) as f:
                speed = float(np.ravel(f["/ball"].attrs["speed"])[0])
                lower, upper = f["/bands/lower_frequency"][:], f["/bands/upper_frequency"][:]
                centre = f["/bands/nominal_frequency"][:]
            table = next(path.parent.glob("tables/equivalent-roughness-*.h5"), None)
            if table is None:
                fail(f"{binary} run: no equivalent-roughness table in {path.parent / 'tables'}", 1)
            with h5py.File(table) as f:
                height = f["/equivalent_roughness/height"][:]
                load = float(np.ravel(f["/equivalent_roughness"].attrs["load"])[0])
        spacing = geo["step"] * geo["cell"]
        entry = {"centre_frequency": centre.tolist(), "load": load}
        for m in THINNING:
            th, ex = thinned(height, m)
            entry[f"every_{m}_db"] = (band_levels(th, spacing, geo["segment"], speed, lower, upper)
                                      - band_levels(ex, spacing, geo["segment"], speed, lower, upper)).tolist()
        # Cell: one surface at half the table's cell, its 2 x 2 means on the table's cell and on twice it.
        half = geo["cell"] / 2
        window2, step2 = 2 * geo["window"], 4 * geo["step"]  # on the half cell: every 2nd table position
        e_star = 3 * load * ball_radius / (4 * geo["hertz_radius"] ** 3)  # Hertz: a = (3 W R / 4 E*)^(1/3)
        nx = window2 + step2 * a.positions
        k, g = self_affine(texture, np.pi / half * 0.999)
        z2 = np.asarray(rollspec.surfaces.isotropic(k, g, half, nx, window2, seed=1, index=0)["heights"])
        z1 = z2.reshape(window2 // 2, 2, nx // 2, 2).mean(axis=(1, 3))
        z0 = z1.reshape(window2 // 4, 2, nx // 4, 2).mean(axis=(1, 3))
        grids = {}
        for label, z, cell, window, step in (("double", z0, 4 * half, window2 // 4, step2 // 4),
                                             ("table", z1, 2 * half, window2 // 2, step2 // 2),
                                             ("half", z2, half, window2, step2)):
            grids[label] = heq_on_grid(rollspec, z, cell, window, step, a.positions, ball_radius, e_star, load)
        segment = geo["segment"] // 2  # positions twice the table's step apart: the table's segment in metres
        lv = {label: band_levels(h, 2 * spacing, segment, speed, lower, upper) for label, (h, _) in grids.items()}
        entry.update({"double_minus_table_db": (lv["double"] - lv["table"]).tolist(),
                      "table_minus_half_db": (lv["table"] - lv["half"]).tolist(),
                      "cpu_seconds": {label: cpu for label, (_, cpu) in grids.items()},
                      "heq_rms_m": float(grids["table"][0].std())})
        data[name] = entry
        rows.append([name, worst(np.array(entry["every_2_db"]), centre), worst(np.array(entry["every_3_db"]), centre),
                     worst(np.array(entry["table_minus_half_db"]), centre),
                     worst(np.array(entry["double_minus_table_db"]), centre),
                     f"{grids['table'][1] / grids['double'][1]:.1f}"])
        print(" | ".join(rows[-1]), flush=True)
    others = bench_record.other_work(busy, bench_record.own_cpu() - own, time.perf_counter() - t0)
    columns = ["texture", "every 2nd position (dB)", "every 3rd position (dB)",
               "table's cell against half of it (dB)", "twice the cell against the table's (dB)",
               "cold solve CPU, table's cell over twice it"]
    a_cell = geo["radius"] / geo["cell"]
    settings = SETTINGS.format(positions_engine=geo["positions"], step_um=geo["step"] * geo["cell"] * 1e6,
                               cell_um=half * 1e6, positions=a.positions, grid_step_um=2 * spacing * 1e6,
                               window_um=geo["window"] * geo["cell"] * 1e6, a_half=2 * a_cell, a_cell=a_cell,
                               a_double=a_cell / 2, segment_um=geo["segment"] * spacing * 1e3, band_lo=lower[0],
                               band_hi=upper[-1], speed=speed)
    if a.record:
        bench_record.write_measured(a.record, binary, title=TITLE, argv=sys.argv, settings=settings, columns=columns,
                                    rows=rows, other_cores=others, components=["contact", "texture", "engine"],
                                    notes=NOTES, data={"textures": data, "geometry": geo})
        print(f"wrote {a.record}")


if __name__ == "__main__":
    script_main(main)
