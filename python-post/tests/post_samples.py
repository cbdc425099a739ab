"""Small, valid input files for every rollspec-post subcommand (written with h5py, no engine run), their
damaged variants, and marked outputs of each kind: the material test_post_faults.py attacks with."""
import io
import os
import shutil

import h5py
import numpy as np

from rollspec_post.result_file import KNOWN_SCHEMA_MAJOR
from rollspec_post.safe_output import HTML_MARKER, marker

SENSORS = ("s0", "sensor_mean")


def _rollspec(path, filetype):
    f = h5py.File(path, "w")
    f.attrs["filetype"], f.attrs["schema_version"] = filetype, f"{KNOWN_SCHEMA_MAJOR[filetype]}.0"
    return f


def _psd(f, scale):
    freq = np.linspace(0.0, 5000.0, 501)
    mean = scale * np.vstack([1e-3 / (1 + (freq / 800.0) ** 2)] * len(SENSORS))
    f["/psd/frequency"], f["/psd/mean"] = freq, mean
    f["/psd/ci_lower"], f["/psd/ci_upper"] = 0.8 * mean, 1.25 * mean
    f["/psd/sensor"] = np.array(SENSORS, dtype=h5py.string_dtype())  # as the engine writes them: compare reads it
    f["/psd/mean"].attrs["units"] = "(m/s^2)^2/Hz"
    f["/psd"].attrs["realisations"], f["/psd"].attrs["confidence_level"] = 8, 0.95
    f["/psd"].attrs["interval_method"] = "synthetic"
    f["/reference/psd"] = mean
    nominal = np.array([100.0, 125, 160, 200, 250, 315, 400, 500, 630, 800, 1000, 1250, 1600, 2000])
    f["/bands/nominal_frequency"] = nominal
    f["/bands/lower_frequency"], f["/bands/upper_frequency"] = nominal / 2 ** (1 / 6), nominal * 2 ** (1 / 6)
    level = 10 * np.log10(np.maximum(scale * 1e-3 / (1 + (nominal / 800.0) ** 2), 1e-300))
    rows = np.vstack([level] * len(SENSORS))
    for name, v in (("level_db", rows), ("ci_lower_db", rows - 1), ("ci_upper_db", rows + 1),
                    ("std", 0.3 * 10 ** (rows / 10)), ("log_std", np.full(rows.shape, 0.3))):
        f["/bands/" + name] = v
    f["/bands/sensor"] = np.array(SENSORS, dtype=h5py.string_dtype())


def _roughness(f, scale):
    k = np.logspace(1, 5, 200)
    f["/roughness/wavenumber"] = k
    f["/roughness/psd_raw"] = scale * 1e-20 * k ** -2.0
    f["/roughness/psd_patch"] = scale * 1e-20 * k ** -2.0 / (1 + (k / 1e4) ** 2)
    f["/roughness"].attrs["contact_half_width"], f["/roughness"].attrs["filter"] = 2e-4, "patch"


def _history(f, scale):
    t = np.linspace(0.0, 1.0, 101)
    pos = np.zeros((t.size, 3, 3))
    pos[:, :, 0] = scale * t[:, None]
    pos[:, :, 2] = np.array([0.0, 0.5, 1.0])[None, :]
    f["/time_history/time"], f["/time_history/position"] = t, pos
    f["/time_history/energy/kinetic"] = scale * (1 + t)
    f["/time_history/energy/balance_error"] = 1e-9 * t


def write_result(path, scale=1.0):
    """A rollspec result with /psd, /bands, /reference, /roughness and /time_history (scale 0: all zero)."""
    with _rollspec(path, "rollspec-result") as f:
        f.attrs["scene"], f.attrs["study"] = "synthetic", "[study]\ndescription = synthetic result for the fault tests\n"
        _psd(f, scale)
        _roughness(f, scale)
        _history(f, scale)
    return path


def write_sweep(path, scale=1.0):
    """A sweep result (rollspec run with [sweep]): /psd and /bands with a leading ball_speed axis."""
    speeds = np.array([1.0, 2.0, 3.0])
    with _rollspec(path, "rollspec-result") as f:
        _psd(f, scale)
        for name in ("/psd/mean", "/bands/level_db"):
            one = f[name][()]
            del f[name]
            f[name] = np.stack([one + (i if name.endswith("_db") else 0) for i in range(speeds.size)])
        for group in ("/psd", "/bands"):
            f[group + "/ball_speed"] = speeds
            f[group + "/ball_speed"].attrs["units"] = "m/s"
            f[group + "/ball_speed"].make_scale("ball_speed")
        f["/psd/mean"].dims[0].attach_scale(f["/psd/ball_speed"])
        f["/bands/level_db"].dims[0].attach_scale(f["/bands/ball_speed"])
        f.create_group("/sweep").attrs["mode"] = "crossed"
    return path


def write_texture(path, scale=1.0):
    x = np.linspace(0.0, 0.01, 256)
    k = np.logspace(2, 5, 100)
    with _rollspec(path, "rollspec-texture") as f:
        f["/texture/lines"] = scale * 1e-6 * np.sin(np.outer(np.arange(1, 5), x * 2e3))
        f["/texture/x"], f["/texture/psd_wavenumber"], f["/texture/psd_target"] = x, k, scale * 1e-20 * k ** -2.0
    return path


def write_stiffness(path, scale=1.0):
    d = np.linspace(0.0, 2e-6, 41)
    p = scale * 4 / 3 * 115e9 * np.sqrt(0.01) * d ** 1.5
    with _rollspec(path, "rollspec-stiffness-table") as f:
        for name, v in (("approach", d), ("force_mean", p), ("force_std", 0.05 * p), ("stiffness_mean", np.gradient(p, d)),
                        ("stiffness_std", 0.05 * np.gradient(p, d))):
            f["/stiffness/" + name] = v
        f["/stiffness"].attrs["ball_radius"], f["/stiffness"].attrs["effective_modulus"] = 0.01, 115e9
    return path


def write_bench(path, scale=1.0):
    rows = [f"{m},{s},{scale * e}" for m, (s, e) in zip("aabb", ((0.1, 3.0), (0.4, 1.0), (0.2, 2.0), (0.8, 0.5)))]
    path.write_text("method,seconds,error_db\n" + "\n".join(rows) + "\n")
    return path


def write_measurement(path):
    freq = np.linspace(10.0, 5000.0, 400)
    np.savetxt(path, np.c_[freq, 1.1e-3 / (1 + (freq / 800.0) ** 2)], delimiter=",", header="frequency_hz,psd",
               comments="")
    return path


WRITERS = {"result": write_result, "texture": write_texture, "stiffness": write_stiffness, "bench": write_bench,
           "sweep": write_sweep}
# the primary input of each subcommand (a new subcommand needs an entry here: the fault test says so)
PRIMARY = {"psd": "result", "texture": "texture", "stiffness": "stiffness", "trajectory": "result",
           "roughness": "result", "bench": "bench", "panels": "result", "report": "result", "sweep": "sweep"}
SUFFIX = {"result": ".h5", "texture": ".h5", "stiffness": ".h5", "bench": ".csv", "sweep": ".h5"}
# what each subcommand's missing item is: (object, attribute or None for the whole dataset)
MISSING = {"psd": ("/psd", "realisations"), "report": ("/psd", "realisations"), "panels": ("/psd", "realisations"),
           "roughness": ("/roughness", "contact_half_width"), "trajectory": ("/time_history/time", None),
           "texture": ("/texture/x", None), "stiffness": ("/stiffness", "ball_radius"), "sweep": ("/sweep", None)}


def command_args(command, primary, measurement):
    """The arguments (without --out) of a successful run of `command` on the sample `primary`."""
    if command == "panels":
        return ["--panel", "A", f"{primary}=sim"]
    if command in ("psd", "report"):
        return [str(primary), "--measurement", str(measurement)]
    return [str(primary)]


def write_primary(command, directory, variant="valid"):
    """The primary input of `command` in `directory`: valid, all_zero, missing_item or truncated."""
    kind = PRIMARY[command]
    path = directory / f"{command}-{variant}{SUFFIX[kind]}"
    WRITERS[kind](path, 0.0 if variant == "all_zero" else 1.0)
    if variant == "missing_item" and kind == "bench":
        path.write_text("method,error_db\na,1.0\n")
    elif variant == "missing_item":
        obj, attribute = MISSING[command]
        with h5py.File(path, "a") as f:
            if attribute:
                del f[obj].attrs[attribute]
            else:
                del f[obj]
    elif variant == "truncated":
        data = path.read_bytes()
        path.write_bytes(data[: len(data) // 2])
    return path


def marked_output(kind):
    """Bytes of a rollspec-post output of `kind` (png, pdf, svg or html), as a later run may replace."""
    if kind == "html":
        return f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">{HTML_MARKER}</head></html>\n'.encode()
    from matplotlib.figure import Figure
    fig = Figure(figsize=(2, 2))
    fig.add_subplot().plot([0, 1], [1, 0])
    buf = io.BytesIO()
    fig.savefig(buf, format=kind, metadata=marker(kind))
    return buf.getvalue()


def copy(src, dst):
    shutil.copyfile(src, dst)
    return dst


def snapshot(paths):
    """{path: (file type, bytes or link target)} of what a run must leave as it was."""
    out = {}
    for p in paths:
        p = str(p)
        if os.path.islink(p):
            out[p] = ("link", os.readlink(p))
        elif os.path.isfile(p):
            with open(p, "rb") as fh:
                out[p] = ("file", fh.read())
        elif os.path.exists(p):
            out[p] = ("other", os.stat(p).st_mode, sorted(os.listdir(p)) if os.path.isdir(p) else None)
        else:
            out[p] = ("absent",)
    return out
