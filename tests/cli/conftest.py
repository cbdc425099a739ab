"""Shared helpers for the command-line tests: the rollspec binary, small studies, HDF5 comparison."""
import json
import os
import pathlib
import re
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


def study_head(scene, realisations, seed):
    """The [study] section of a study's text, a blank line after it."""
    return f"[study]\nscene = {scene}\nrealisations = {realisations}\nseed = {seed}\n\n"


def ensemble_head(scene, seed):
    """[study] and [ensemble] of the small studies below, with the format fields {realisations} and {chunk}."""
    return study_head(scene, "{realisations}", seed) + "[ensemble]\nchunk_size = {chunk}\n\n"


SMALL_OSCILLATOR = ensemble_head("random-oscillator", 42) + """\
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
SMALL_PIPE = ensemble_head("rolling-pipe", 77) + """\
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


def texture_study(seed, texture, lines, surface=None):
    """The text of a one-realisation `scene = texture` study: [texture], [lines] and (if given) [surface] from
    {key: value} dicts, each value written as given."""
    sections = {"texture": texture, "lines": lines, **({"surface": surface} if surface else {})}
    return study_head("texture", 1, seed) + "\n".join(
        f"[{name}]\n" + "".join(f"{k} = {v}\n" for k, v in keys.items()) for name, keys in sections.items())


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


def set_args(sets):
    """--set KEY=VALUE for each of sets."""
    return [a for kv in sets for a in ("--set", kv)]


def study_result(study, directory, name, *sets, command="run"):
    """`rollspec run STUDY --set SETS` (or another COMMAND that writes --out) into directory/NAME.h5 (asserted to
    succeed)."""
    out = directory / f"{name}.h5"
    r = run([command, study, "--out", out, "--quiet", *set_args(sets)])
    assert r.returncode == 0, r.stderr
    return out


def measurement_from(path, csv, row=-1):
    """The mean PSD of one row of a result (default: the last, the sensor mean), written as a measured
    PSD (frequency_hz,psd)."""
    with h5py.File(path) as f:
        freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][row, 1:]
    np.savetxt(csv, np.c_[freq, psd], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
    return csv


def lorentzian_comparison(tmp_path):
    """A 6-realisation oscillator result r.h5 and a measured PSD m.csv (a Lorentzian at 40 Hz, 2049 bins to
    512 Hz, plain CSV) compared with `--format csv` (asserted to succeed): (result, frequencies, PSD,
    the comparison)."""
    res = tmp_path / "r.h5"
    assert run(["run", oscillator_study(tmp_path, realisations=6), "--out", res, "--quiet"]).returncode == 0
    f = np.linspace(0, 512, 2049)
    p = 1e-4 / (1 + ((f - 40) / 4) ** 2)
    plain = tmp_path / "m.csv"
    plain.write_text("frequency_hz,psd\n" + "".join(f"{a:.17g},{b:.17g}\n" for a, b in zip(f, p)))
    want = run(["compare", res, plain, "--format", "csv"])
    assert want.returncode == 0, want.stderr
    return res, f, p, want


def run_copied_study(name, tmp_path, *sets, out="r.h5", command="run"):
    """studies/NAME copied to tmp_path (its tables are written beside it, not in the source tree) and
    run (returns (result, out path)) or planned (returns (result, None)) with --set SETS."""
    study = tmp_path / name
    if not study.exists():
        shutil.copy(SOURCE / "studies" / name, study)
    args = set_args(sets)
    if command == "plan":
        return run(["plan", study, *args]), None
    path = tmp_path / out
    return run(["run", study, "--out", path, *args]), path


def rig_1ms(tmp_path, *sets, name="r.h5", command="run"):
    """studies/seed002-rig-1ms.ini copied, run (or planned) with --set SETS: run_copied_study's (result, out path)."""
    return run_copied_study("seed002-rig-1ms.ini", tmp_path, *sets, out=name, command=command)


def band_levels(path):
    """A result's band levels (dB) and its first row's loss-of-contact share."""
    with h5py.File(path) as f:
        return f["/bands/level_db"][:], f["/contact/loss_of_contact_share"][0]


def coarse_rig(tmp_path, name, base, *sets, command="run"):
    """studies/seed002-rig-1ms.ini run (or planned) copied with the sets `base` and `sets`, and the table's error
    only where `sets` asks for it ([stiffness] table_error's default, auto, estimates it); it must succeed."""
    own = [] if any(s.startswith("stiffness.table_error=") for s in sets) else ["stiffness.table_error=none"]
    r, out = rig_1ms(tmp_path, *base, *own, *sets, name=name, command=command)
    assert r.returncode == 0, r.stderr
    return r, out


def attr_text(attrs, name):
    """A string attribute as str (a fixed-length one reads as bytes)."""
    v = attrs[name]
    return v.decode() if isinstance(v, bytes) else v


def assert_intervals_name_the_table(plain, jackknife, table, over):
    """Open results of a run without and with `[stiffness] table_error = jackknife` on the TABLE table: the same
    band levels, bit for bit; the first's intervals conditional on the table, the second's including it."""
    assert plain["bands/level_db"][()].tobytes() == jackknife["bands/level_db"][()].tobytes()
    assert attr_text(plain["bands"].attrs, "interval_includes") == \
        f"realisations only (conditional on the {table} table)"
    assert attr_text(jackknife["bands"].attrs, "interval_includes") == \
        f"realisations, {table} table (jackknife over {over})"


def measure_and_fit(study, directory, seed, key, truth, rng, *, short, bands, records, realisations):
    """A synthetic measurement, M = RECORDS realisations of STUDY (with the sets SHORT) at KEY = TRUTH and study
    seed SEED, fitted for KEY over RNG ('lo:hi[:log]') with K = REALISATIONS and a model seed of its own
    (50000 + SEED) in the bands BANDS (--fmin/--fmax); both asserted to succeed: the fit's JSON."""
    out = directory / f"m{seed}.h5"
    r = run(["run", study, "--out", out, "--quiet",
             *set_args(short + [f"{key}={truth}", f"study.realisations={records}", f"study.seed={seed}"])])
    assert r.returncode == 0, r.stderr
    csv = measurement_from(out, directory / f"m{seed}.csv")
    r = run(["fit", study, csv, "--measured-averages", records, "--format", "json", "--vary", f"{key}={rng}", *bands,
             *set_args(short + [f"study.realisations={realisations}", f"study.seed={50000 + seed}"])])
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def scene_keys(scene):
    """`rollspec keys SCENE` as [(section, key, default, [the lines that describe the key])]."""
    out = subprocess.run([BIN, "keys", scene], capture_output=True, text=True, check=True).stdout
    keys, section = [], None
    for line in out.splitlines():
        m = re.match(r"^\[(\w+)\]", line)
        if m:
            section = m.group(1)
            continue
        m = re.match(r"^  (\w+) = ?(.*)$", line)
        if m:
            keys.append((section, m.group(1), m.group(2), []))
        elif keys:
            keys[-1][3].append(line)
    return keys


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
