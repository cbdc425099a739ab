"""Never lose a user's data, part II: names, links and locks, damaged inputs, standard output.

Each test is one reported case: it fails on the build before these fixes and passes after. Every
refusal is checked for its exit code, a message that names the file and what is allowed, and the
file in the way left byte-identical."""
import os
import struct
import subprocess
import time
import zlib

import numpy as np
import pytest
import scipy.io

from conftest import (BIN, EX_CANTCREAT, EX_DATAERR, EX_USAGE, SMALL_OSCILLATOR, SOURCE, assert_bitwise_equal,
                      assert_refused, run)
from sound_files import write_pcm16

EX_IOERR = 74
SENTINEL = b"precious user data\n"


def no_temps(d):
    left = [p.name for p in d.rglob("*.tmp*")]
    assert not left, f"temporary files left behind: {left}"


def oscillator(tmp_path, name="s.ini", realisations=8):
    p = tmp_path / name
    p.write_text(SMALL_OSCILLATOR.format(realisations=realisations, chunk=4, duration=4))
    return p


def hertz(tmp_path):
    s = tmp_path / "hertz.ini"
    s.write_text((SOURCE / "studies" / "hertz.ini").read_text())
    return s


# --- 1: psd --out never replaces a measurement ------------------------------------------------------

def test_psd_out_refuses_a_measured_psd_and_replaces_its_own(tmp_path):
    m = tmp_path / "m.csv"
    m.write_bytes((SOURCE / "studies" / "data" / "measured-psd.csv").read_bytes())
    before = m.read_bytes()
    args = ["psd", SOURCE / "studies" / "data" / "example-signal.csv", "--unit", "g"]
    r = run([*args, "--segment", "2048", "--out", m])
    assert_refused(r, EX_CANTCREAT, ["m.csv", "not a PSD written by rollspec psd", "--force"])
    assert m.read_bytes() == before and not (tmp_path / "m.csv-metadata.json").exists()
    own = tmp_path / "p.csv"
    assert run([*args, "--segment", "2048", "--out", own]).returncode == 0
    assert own.read_text().startswith("frequency_hz,")  # no marker line: its sidecar says whose it is
    assert (tmp_path / "p.csv-metadata.json").is_file()
    r = run([*args, "--segment", "1024", "--out", own])
    assert r.returncode == 0, r.stderr
    no_temps(tmp_path)


# --- 2: --rebuild never writes over or through a user's file at the automatic table name ---------------

def automatic_table(tmp_path):
    s = hertz(tmp_path)
    r = run(["stiffness", s, "--quiet"])
    assert r.returncode == 0, r.stderr
    (table,) = (tmp_path / "tables").glob("stiffness-*.h5")
    return s, table


@pytest.mark.parametrize("how", ["symlink", "regular file"])
def test_rebuild_keeps_a_user_file_at_the_automatic_name(tmp_path, how):
    s, table = automatic_table(tmp_path)
    notes = tmp_path / "notes.txt"
    notes.write_bytes(SENTINEL)
    table.unlink()
    if how == "symlink":
        table.symlink_to(os.path.relpath(notes, table.parent))
    else:
        table.write_bytes(SENTINEL)
    r = run(["stiffness", s, "--quiet", "--rebuild"])
    assert_refused(r, EX_CANTCREAT, [table.name, "rollspec-stiffness-table"])
    assert notes.read_bytes() == SENTINEL
    if how == "regular file":
        assert table.read_bytes() == SENTINEL
    no_temps(tmp_path)


def test_rebuild_replaces_a_damaged_table(tmp_path):
    s, table = automatic_table(tmp_path)
    table.write_bytes(table.read_bytes()[:100])  # HDF5 signature, nothing readable after it
    r = run(["stiffness", s, "--quiet", "--rebuild"])
    assert r.returncode == 0, r.stderr
    assert table.stat().st_size > 1000


# --- 4: the lock belongs to the file written; --only takes it and keeps finished ensembles -----------

def test_a_second_run_through_a_symlink_to_the_same_result_is_refused(tmp_path):
    study = oscillator(tmp_path)
    out, link = tmp_path / "r.h5", tmp_path / "a.h5"
    assert run(["run", study, "--out", out, "--quiet"]).returncode == 0
    link.symlink_to("r.h5")
    slow = subprocess.Popen([BIN, "run", study, "--out", out, "--quiet", "--set", "study.realisations=40000"],
                            stderr=subprocess.PIPE, text=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
    try:
        deadline = time.time() + 30
        while time.time() < deadline and not (tmp_path / "r.h5.checkpoint" / "lock").exists():
            time.sleep(0.01)
        for extra in ([], ["--only", "3", "--force"]):
            r = run(["run", study, "--out", link, "--quiet", *extra])
            assert_refused(r, EX_CANTCREAT, ["another rollspec run", "r.h5.checkpoint"])
    finally:
        slow.terminate()
        slow.communicate(timeout=30)


def test_only_never_replaces_a_finished_ensemble(tmp_path):
    study = oscillator(tmp_path)
    out = tmp_path / "r.h5"
    assert run(["run", study, "--out", out, "--quiet"]).returncode == 0
    before = out.read_bytes()
    r = run(["run", study, "--out", out, "--quiet", "--only", "3"])
    assert_refused(r, EX_CANTCREAT, ["r.h5", "finished ensemble result", "--only", "--force"])
    assert out.read_bytes() == before
    one = tmp_path / "one.h5"
    assert run(["run", study, "--out", one, "--quiet", "--only", "3"]).returncode == 0
    assert run(["run", study, "--out", one, "--quiet", "--only", "4"]).returncode == 0
    assert not (tmp_path / "one.h5.checkpoint").exists()


# --- 5: table_dir stays below the study's directory, links and '..' resolved -------------------------

@pytest.mark.parametrize("how", ["symlinked directory", "existing ../dir"])
def test_table_dir_cannot_leave_the_study_directory(tmp_path, how):
    outside = tmp_path / "outside"
    outside.mkdir()
    d = tmp_path / "study"
    d.mkdir()
    s = hertz(d)
    if how == "symlinked directory":
        (d / "link").symlink_to(outside)
        value = "link/new"
    else:
        value = "../outside"
    r = run(["stiffness", s, "--quiet", "--set", f"stiffness.table_dir={value}"])
    assert_refused(r, 78, [f"[stiffness] table_dir = {value}", "outside the study's directory", "allowed"])
    assert list(outside.iterdir()) == []


# --- 6: damaged sound files are refused, not read short -----------------------------------------------

def write_sound(path, major, frames=32768, rate=8000):
    """16-bit mono sound file through libsndfile."""
    x = (np.sin(np.arange(frames) * 0.05) * 12000 + np.random.default_rng(1).normal(0, 500, frames)).astype("<i2")
    write_pcm16(path, x, rate, major)


@pytest.mark.parametrize("suffix, major", [(".wav", 0x010000), (".aiff", 0x020000), (".flac", 0x170000)])
@pytest.mark.parametrize("damage", ["cut in half", "flipped bytes"])
def test_damaged_sound_files_are_refused(tmp_path, suffix, major, damage):
    good = tmp_path / ("good" + suffix)
    write_sound(good, major)
    psd = ["psd", "--scale", "10", "--unit", "g", "--segment", "1024"]
    assert run([*psd, good]).returncode == 0
    data = bytearray(good.read_bytes())
    bad = tmp_path / ("bad" + suffix)
    if damage == "cut in half":
        bad.write_bytes(bytes(data[:len(data) // 2]))
    else:
        if suffix != ".flac":
            pytest.skip("flipped PCM bytes are valid samples in WAV and AIFF: no format can tell")
        for k in range(len(data) // 2, len(data) // 2 + 64):
            data[k] ^= 0xFF
        bad.write_bytes(bytes(data))
    r = run([*psd, bad])
    assert_refused(r, EX_DATAERR, [bad.name, "damaged", "allowed: an undamaged sound file"])


# --- 7: MAT v5 dimensions must match the stored data ----------------------------------------------------

def compressed(mat):
    """The same MAT v5 file with each top-level variable in a zlib miCOMPRESSED element."""
    out, at = bytearray(mat[:128]), 128
    while at < len(mat):
        _, n = struct.unpack("<II", mat[at:at + 8])
        z = zlib.compress(bytes(mat[at:at + 8 + n]))
        out += struct.pack("<II", 15, len(z)) + z
        at += 8 + n + (-n) % 8
    return bytes(out)


@pytest.mark.parametrize("declared", [8192, 2048])
@pytest.mark.parametrize("packing", ["plain", "compressed"])
def test_mat_dimensions_that_differ_from_the_data_are_refused(tmp_path, declared, packing):
    good = tmp_path / "good.mat"
    scipy.io.savemat(good, {"acc": np.sin(np.arange(4096) * 0.1), "fs": 8000.0})
    raw = bytearray(good.read_bytes())
    at = raw.find(struct.pack("<ii", 1, 4096))
    raw[at:at + 8] = struct.pack("<ii", 1, declared)
    bad = tmp_path / "bad.mat"
    bad.write_bytes(compressed(raw) if packing == "compressed" else bytes(raw))
    ok = tmp_path / "ok.mat"
    ok.write_bytes(compressed(good.read_bytes()) if packing == "compressed" else good.read_bytes())
    assert run(["psd", ok, "--segment", "256"]).returncode == 0
    r = run(["psd", bad, "--segment", "256"])
    assert_refused(r, EX_DATAERR, ["bad.mat", "'acc'", f"1x{declared}", "stores 4096", "allowed"])


# --- 8: standard output is checked -----------------------------------------------------------------------

def test_commands_that_print_fail_on_a_full_standard_output(tmp_path):
    study = oscillator(tmp_path)
    result = tmp_path / "r.h5"
    assert run(["run", study, "--out", result, "--quiet"]).returncode == 0
    psd = tmp_path / "p.csv"
    assert run(["psd", SOURCE / "studies" / "data" / "example-signal.csv", "--unit", "g", "--segment", "2048",
                "--out", psd]).returncode == 0
    commands = [["psd", SOURCE / "studies" / "data" / "example-signal.csv", "--unit", "g", "--segment", "2048"],
                ["compare", result, psd, "--column", "sensor_1"],
                ["compare", result, psd, "--column", "sensor_1", "--format", "json"],
                ["keys"], ["keys", "ball-on-beam"], ["plan", study], ["stiffness", hertz(tmp_path)]]
    for args in commands:
        with open("/dev/full", "w") as full:
            r = subprocess.run([BIN, *map(str, args)], stdout=full, stderr=subprocess.PIPE, text=True)
        assert r.returncode == EX_IOERR, f"{args[0]}: exit {r.returncode}: {r.stderr}"
        assert "cannot write standard output" in r.stderr


# --- 10: compare refuses tampered results with a message, never an internal error -------------------------

TAMPER = [("/psd", "confidence_level", 1.5), ("/psd", "confidence_level", float("nan")), ("/psd", "confidence_level", 0.0),
          ("/psd", "realisations", float("nan")), ("/psd", "realisations", -3.0), ("/psd", "realisations", 2.5),
          ("/bands/std", None, float("inf")), ("/bands/level_db", None, 1e308), ("/bands/ci_lower_db", None, 1e3),
          ("/bands/sensor", None, b"\xff\xfe bad")]


@pytest.fixture(scope="module")
def compare_inputs(tmp_path_factory):
    d = tmp_path_factory.mktemp("compare")
    study = oscillator(d, realisations=8)
    result = d / "r.h5"
    assert run(["run", study, "--out", result, "--quiet"]).returncode == 0
    psd = d / "p.csv"
    assert run(["psd", SOURCE / "studies" / "data" / "example-signal.csv", "--unit", "g", "--segment", "2048",
                "--out", psd]).returncode == 0
    return result, psd


@pytest.mark.parametrize("where, attr, value", TAMPER)
def test_compare_refuses_a_tampered_result(tmp_path, compare_inputs, where, attr, value):
    import h5py
    result, psd = compare_inputs
    bad = tmp_path / "bad.h5"
    bad.write_bytes(result.read_bytes())
    with h5py.File(bad, "r+") as f:
        if attr:
            f[where].attrs[attr] = value
        elif where == "/bands/sensor":
            names = list(f[where][()])
            del f[where]
            f.create_dataset(where, data=np.array([value] * len(names), dtype=object), dtype=h5py.string_dtype("ascii"))
        else:
            data = f[where][()]
            data[0, 0] = value
            f[where][...] = data
    for fmt in ("table", "json"):
        r = run(["compare", bad, psd, "--column", "sensor_1", "--format", fmt])
        assert_refused(r, EX_DATAERR, ["bad.h5", "allowed"])


# --- smaller cases --------------------------------------------------------------------------------------

def test_texture_with_no_power_on_the_surface_grid_is_refused_before_work(tmp_path):
    sets = ["surface.method=seed", "surface.correlation_x=6e-5", "surface.correlation_y=5e-5", "surface.nx=42",
            "surface.ny=124", "surface.spacing=1.8e-7", "texture.source=iso8608", "texture.table_extension=zero"]
    r = run(["texture", SOURCE / "studies" / "texture-demo.ini", "--out", tmp_path / "t.h5",
             *[a for kv in sets for a in ("--set", kv)]])
    assert_refused(r, 78, ["[surface] spacing", "zero at every wavenumber", "allowed"])
    assert not (tmp_path / "t.h5").exists()


def test_a_huge_study_file_is_refused_before_it_is_read(tmp_path):
    big = tmp_path / "big.ini"
    with open(big, "wb") as f:
        f.truncate(5 << 30)  # sparse: 5 GiB without using the disk
    t0 = time.time()
    r = run(["plan", big])
    assert_refused(r, 78, ["big.ini", "bytes", "allowed: at most"])
    assert time.time() - t0 < 10


def test_ten_thousand_sets_are_recorded_in_full(tmp_path):
    import h5py
    study = oscillator(tmp_path, realisations=4)
    out = tmp_path / "r.h5"
    sets = [a for _ in range(10000) for a in ("--set", "oscillator.mass=1.5")]
    r = run(["run", study, "--out", out, "--quiet", *sets])
    assert r.returncode == 0, r.stderr[-2000:]
    with h5py.File(out) as f:
        line = f.attrs["command_line"]
        line = line.decode() if isinstance(line, bytes) else line
        assert line.count("oscillator.mass=1.5") == 10000


def test_a_column_named_T_is_not_a_time_column(tmp_path):
    fs, n = 1000.0, 4096
    x = np.sin(2 * np.pi * 50 * np.arange(n) / fs)
    csv = tmp_path / "temp.csv"
    temperature = 20 + 0.2 * np.sin(np.arange(n) / 300)  # a logged temperature: not increasing
    csv.write_text("T,acc\n" + "".join(f"{t:.4f},{v:.6f}\n" for t, v in zip(temperature, x)))
    r = run(["psd", csv, "--fs", str(fs), "--column", "acc", "--segment", "1024"])
    assert r.returncode == 0, r.stderr
    assert "time column" not in r.stderr


def test_resume_needs_no_study_file(tmp_path):
    """The checkpoint holds the resolved study: a moved or deleted study file does not strand the run."""
    d = tmp_path / "work"
    d.mkdir()
    study = oscillator(d, realisations=8)
    out = tmp_path / "r.h5"
    p = subprocess.Popen([BIN, "run", study, "--out", out, "--quiet", "--set", "study.realisations=4000"],
                         stderr=subprocess.PIPE, text=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
    deadline = time.time() + 30
    while time.time() < deadline and not list((tmp_path / "r.h5.checkpoint").glob("chunk_*.bin")):
        time.sleep(0.005)
    p.send_signal(2)
    assert p.communicate(timeout=30)[1] is not None and p.returncode == 130
    reference = tmp_path / "ref.h5"
    assert run(["run", study, "--out", reference, "--quiet", "--set", "study.realisations=4000"]).returncode == 0
    study.unlink()
    r = run(["run", "--out", out, "--quiet"])
    assert_refused(r, EX_USAGE, ["study file is missing", "--resume --out"])
    r = run(["run", "--resume", "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    assert_bitwise_equal(out, reference)
    r = run(["run", "--resume", "--out", tmp_path / "none.h5", "--quiet"])
    assert_refused(r, 66, ["holds no checkpoint to resume", "allowed"])
