"""Shared helpers for the command-line tests: the rollspec binary, small studies, HDF5 comparison."""
import os
import pathlib
import shutil
import subprocess

import h5py
import numpy as np
import pytest

BIN = os.environ.get("ROLLSPEC_BIN", "rollspec")


def pytest_configure(config):
    # A file with tests marked long gets two CTest entries, `-m "not long"` and `-m long` (tests/cli/CMakeLists.txt);
    # the sanitizer pass skips the second. An unknown marker would only warn, so the name is registered here.
    config.addinivalue_line("markers", "long: minutes under the sanitizers (a long simulation or ensemble)")
SOURCE = pathlib.Path(os.environ.get("ROLLSPEC_SOURCE", pathlib.Path(__file__).resolve().parents[2]))

# Exit codes from <sysexits.h>.
EX_USAGE, EX_DATAERR, EX_NOINPUT, EX_CANTCREAT, EX_CONFIG, EX_INTERRUPTED = 64, 65, 66, 73, 78, 130

SMALL_OSCILLATOR = """\
[study]
scene = random-oscillator
realisations = {realisations}
seed = 42

[ensemble]
chunk_size = {chunk}

[oscillator]
mass = 1.5
natural_frequency = 40
damping_ratio = 0.05

[force]
level = 2.0

[signal]
sample_rate = 1024
duration = {duration}

[spectrum]
segment = 1024
band_min = 8
band_max = 400
"""


# Half-metre tube, 2 elements (5 node spheres), 0.1 m rolled at 0.5 m/s on an isotropic floor.
SMALL_PIPE = """\
[study]
scene = rolling-pipe
realisations = {realisations}
seed = 77

[ensemble]
chunk_size = {chunk}

[pipe]
length = 0.5
elements = 2

[roll]
speed = 0.5
distance = 0.1

[roughness]
kind = {kind}
spacing = 2e-3

[texture]
source = self-affine
hurst = 0.8
rolloff_wavelength = 0.05
short_wavelength = 0.008
rms = 20e-6

[surface]
method = spectral
nx = 96
ny = 288
spacing = 2e-3

[contact]
penalty_normal = 2e6
penalty_tangential = 4e5

[analysis]
dt = 1e-4

[spectrum]
segment = 256
skip_start = 0.02
band_min = 40
band_max = 4000
"""


def assert_refused(r, code, fragments):
    """A clean refusal: the exit code, no internal error, and every fragment in the message."""
    assert r.returncode == code, f"exit {r.returncode}, expected {code}: {r.stderr[:2000]}"
    assert "internal error" not in r.stderr and "Traceback" not in r.stderr, r.stderr[:2000]
    for frag in fragments:
        assert frag in r.stderr, f"{frag!r} not in {r.stderr[:2000]!r}"


def oscillator_study(tmp_path, realisations=4):
    """SMALL_OSCILLATOR with 4 s records, chunks of 4, as s.ini in tmp_path."""
    p = tmp_path / "s.ini"
    p.write_text(SMALL_OSCILLATOR.format(realisations=realisations, chunk=4, duration=4))
    return p


def run(args, env=None, **kw):
    full_env = dict(os.environ)
    if env:
        full_env.update(env)
    return subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, env=full_env, **kw)


def study_result(study, directory, name, *sets):
    """`rollspec run STUDY --set SETS` into directory/NAME.h5 (asserted to succeed)."""
    out = directory / f"{name}.h5"
    args = ["run", study, "--out", out, "--quiet"]
    for s in sets:
        args += ["--set", s]
    r = run(args)
    assert r.returncode == 0, r.stderr
    return out


def measurement_from(path, csv, row=-1):
    """The mean PSD of one row of a result (default: the last, the sensor mean), written as a measured
    PSD (frequency_hz,psd)."""
    with h5py.File(path) as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][row, 1:]
    np.savetxt(csv, np.c_[freq, psd], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
    return csv


def run_copied_study(name, tmp_path, *sets, out="r.h5", command="run"):
    """studies/NAME copied to tmp_path (its tables are written beside it, not in the source tree) and
    run (returns (result, out path)) or planned (returns (result, None)) with --set SETS."""
    study = tmp_path / name
    if not study.exists():
        shutil.copy(SOURCE / "studies" / name, study)
    args = [a for kv in sets for a in ("--set", kv)]
    if command == "plan":
        return run(["plan", study, *args]), None
    path = tmp_path / out
    return run(["run", study, "--out", path, *args]), path


def coarse_rig(tmp_path, name, base, *sets, command="run"):
    """studies/seed002-rig-1ms.ini run (or planned) copied with the sets `base` and `sets`, and the table's error
    only where `sets` asks for it ([stiffness] table_error's default, auto, estimates it); it must succeed."""
    own = [] if any(s.startswith("stiffness.table_error=") for s in sets) else ["stiffness.table_error=none"]
    r, out = run_copied_study("seed002-rig-1ms.ini", tmp_path, *base, *own, *sets, out=name, command=command)
    assert r.returncode == 0, r.stderr
    return r, out


@pytest.fixture
def small_study(tmp_path):
    def make(realisations=24, chunk=4, duration=16, name="study.ini"):
        p = tmp_path / name
        p.write_text(SMALL_OSCILLATOR.format(realisations=realisations, chunk=chunk, duration=duration))
        return p
    return make


def result_datasets(path):
    """Every dataset of a result file except the run's own timing, as {name: array}."""
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and not name.startswith("run"):
                out[name] = obj[()]
        f.visititems(visit)
    return out


def assert_bitwise_equal(a, b):
    da, db = result_datasets(a), result_datasets(b)
    assert sorted(da) == sorted(db)
    for k in da:
        x, y = np.asarray(da[k]), np.asarray(db[k])
        if x.dtype.kind == "f":
            assert x.tobytes() == y.tobytes(), f"{k} differs"
        else:
            assert np.array_equal(x, y), f"{k} differs"


def hertz_radius(radius=0.02, density=7850.0, e=210e9, nu=0.3, g=9.81):
    """Hertz contact radius a (m) of a steel ball on steel under its own weight."""
    weight = 4 / 3 * np.pi * radius ** 3 * density * g
    e_star = 1 / (2 * (1 - nu ** 2) / e)
    delta = (3 * weight / (4 * e_star * np.sqrt(radius))) ** (2 / 3)
    return np.sqrt(radius * delta)


@pytest.fixture
def tmpfs_disk(tmp_path):
    """mount(size) -> tmp_path/disk, a tmpfs of that size (e.g. "1m"), unmounted after the test;
    skips where mounting is not allowed (needs root with mount permission)."""
    mounted = []

    def mount(size):
        d = tmp_path / "disk"
        d.mkdir()
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(d)], capture_output=True, text=True)
        if r.returncode != 0:
            pytest.skip(f"cannot mount a {size} tmpfs here (needs root with mount permission): {r.stderr.strip()}")
        mounted.append(d)
        return d

    yield mount
    for d in mounted:
        subprocess.run(["umount", "-l", str(d)], capture_output=True)
