"""Result files made by the engine in the test run, for the plotting tests."""
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("ROLLSPEC_SOURCE", pathlib.Path(__file__).resolve().parents[2]))
BIN = os.environ.get("ROLLSPEC_BIN", str(SOURCE / "build" / "release" / "rollspec"))


def post(*args):
    env = dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"))
    return subprocess.run([sys.executable, "-m", "rollspec_post", *map(str, args)], capture_output=True, text=True,
                          env=env)


@pytest.fixture(scope="session")
def oscillator_result(tmp_path_factory):
    out = tmp_path_factory.mktemp("results") / "ro.h5"
    r = subprocess.run([BIN, "run", SOURCE / "studies" / "random-oscillator.ini", "--out", out, "--quiet",
                        "--set", "study.realisations=16"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return out


def is_png_with_content(path):
    """PNG magic, a real image size and not one flat colour."""
    import matplotlib.image
    img = matplotlib.image.imread(path)
    return path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and img.shape[0] > 100 and img[..., :3].std() > 0.05


def rollspec_ok(*args):
    """`rollspec ARGS` (the engine under test), which must succeed."""
    r = subprocess.run([BIN, *args], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def assert_plots(command, path, out):
    """`python3 -m rollspec_post COMMAND PATH --out OUT` succeeds and OUT is a PNG with content."""
    r = post(command, path, "--out", out)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)


def write_measurement(result, path, scale=1.0):
    """`path`: a measurement CSV (frequency_hz,psd) of a result's reference PSD of its first sensor times
    `scale`, without 0 Hz."""
    import h5py
    import numpy as np
    with h5py.File(result) as f:
        freq, ref = f["/psd/frequency"][1:], f["/reference/psd"][0, 1:]
    np.savetxt(path, np.c_[freq, ref * scale], delimiter=",", header="frequency_hz,psd", comments="")
    return path


def hdf5_with_attributes(path, **attributes):
    """`path`: an HDF5 file that holds only these root attributes (a file of another kind or version)."""
    import h5py
    with h5py.File(path, "w") as f:
        for name, value in attributes.items():
            f.attrs[name] = value
    return path


def write_rollspec(path, filetype="rollspec-result"):
    import h5py
    f = h5py.File(path, "w")
    from rollspec_post.result_file import KNOWN_SCHEMA_MAJOR
    f.attrs["filetype"], f.attrs["schema_version"] = filetype, f"{KNOWN_SCHEMA_MAJOR[filetype]}.0"
    return f


@pytest.fixture
def stiffness_table(tmp_path):
    """The stiffness-table layout with a rough ball softer than Hertz at small approach."""
    import numpy as np
    radius, modulus = 0.01, 115e9
    d = np.linspace(0, 2e-6, 41)
    p = 4 / 3 * modulus * np.sqrt(radius) * d ** 1.5 * (1 - np.exp(-d / 3e-7))
    k = np.gradient(p, d)
    path = tmp_path / "stiffness.h5"
    with write_rollspec(path, "rollspec-stiffness-table") as f:
        g = f.create_group("stiffness")
        for name, v in (("approach", d), ("force_mean", p), ("force_std", 0.05 * p), ("stiffness_mean", k),
                        ("stiffness_std", 0.08 * k), ("contact_area_mean", 0.3 * np.pi * radius * d)):
            g[name] = v
        g.attrs["ball_radius"], g.attrs["effective_modulus"], g.attrs["hardness"] = radius, modulus, np.inf
    return path


@pytest.fixture
def rolling_disc_result(tmp_path):
    """A disc (seed 000 example 4.1 values) sliding, then rolling: v = V0 + mu g t, w = w0 - 2 mu g t / R until
    v = R w; beam nodes on the axis (z), motion along x, energies with a zero balance error."""
    import numpy as np
    r, w0, v0, mu, g, m = 0.2, 127.03, 2.355, 0.25, 9.81, 1e3
    inertia = m * r * r / 2
    t = np.linspace(0, 5, 501)
    t_roll = (r * w0 - v0) / (3 * mu * g)
    ts = np.minimum(t, t_roll)
    v = v0 + mu * g * ts
    w = w0 - 2 * mu * g * ts / r
    x = v0 * ts + mu * g * ts ** 2 / 2 + v[-1] * (t - ts)
    nodes = np.array([0.0, 0.5, 1.0])
    pos = np.zeros((t.size, nodes.size, 3))
    pos[:, :, 0], pos[:, :, 1], pos[:, :, 2] = x[:, None], r, nodes[None, :]
    omega = np.zeros_like(pos)
    omega[:, :, 2] = -w[:, None]
    kinetic = m * v ** 2 / 2 + inertia * w ** 2 / 2
    dissipation = kinetic[0] - kinetic
    path = tmp_path / "disc.h5"
    with write_rollspec(path) as f:
        f["/time_history/time"], f["/time_history/position"] = t, pos
        f["/time_history/angular_velocity"] = omega
        f["/time_history/energy/kinetic"] = kinetic
        f["/time_history/energy/friction_dissipation"] = dissipation
        f["/time_history/energy/balance_error"] = kinetic + dissipation - kinetic[0]
    return path
