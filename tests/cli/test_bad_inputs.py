"""Malformed inputs beyond study keys (issue 9, part 3): measurement, signal, PSD-table and profile
CSV files, result files, checkpoints, study/path edge cases and unwritable outputs.

Every case asserts the sysexits code, a message naming the file (and line / column / key where
there is one) and what is allowed, no internal error, and that an output file that already
existed is left byte-identical with no temporary file (`*.tmp*`) beside it. `rollspec compare`
writes no file: there the check is that nothing at all reaches stdout (no partial table)."""
import os
import shutil
import signal
import subprocess
import time

import h5py
import numpy as np
import pytest

from conftest import BIN, EX_CANTCREAT, EX_DATAERR, EX_NOINPUT, SMALL_OSCILLATOR, assert_refused, run

SENTINEL = b"precious output that a refused run must not touch\n"



def put_sentinel(path):
    path.write_bytes(SENTINEL)
    return path


def assert_untouched(out):
    assert out.read_bytes() == SENTINEL, f"{out} was changed"
    leftovers = [p.name for p in out.parent.rglob("*.tmp*")]
    assert not leftovers, f"temporary files left behind: {leftovers}"


# --- a small, valid result file, made once ----------------------------------------------------

@pytest.fixture(scope="module")
def good_result(tmp_path_factory):
    d = tmp_path_factory.mktemp("good")
    study = d / "study.ini"
    study.write_text(SMALL_OSCILLATOR.format(realisations=4, chunk=4, duration=4))
    out = d / "result.h5"
    r = run(["run", study, "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    return out


GOOD_MEASUREMENT = "frequency_hz,psd\n1,1e-3\n300,2e-3\n500,1e-3\n"


def test_good_inputs_are_accepted(tmp_path, good_result):
    """The baseline the bad cases deviate from, plus a UTF-8 byte-order mark (spreadsheet export)."""
    m = tmp_path / "m.csv"
    m.write_text(GOOD_MEASUREMENT)
    r = run(["compare", good_result, m])
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1].startswith("rms_db_error:")
    m.write_bytes(b"\xef\xbb\xbf" + GOOD_MEASUREMENT.encode())
    r = run(["compare", good_result, m])
    assert r.returncode == 0, r.stderr


# --- measurement CSV for `rollspec compare` -------------------------------------------------------

GARBAGE = bytes(range(256)) * 3

MEASUREMENTS = [
    # name, file bytes, exit code, fragments besides the file name
    ("empty", b"", EX_DATAERR, ["m.csv: empty file", "expected a header line"]),
    ("header only", b"frequency_hz,psd\n", EX_DATAERR, ["m.csv: header but no data rows", "expected at least one row of numbers"]),
    ("wrong header", b"f,psd\n10,1\n20,1\n", EX_DATAERR,
     ["m.csv:1: no column 'frequency_hz'", "columns found: f, psd"]),
    ("wrong units header", b"frequency_hz,psd_db\n10,1\n20,1\n", EX_DATAERR,
     ["m.csv:1: no column 'psd'", "columns found: frequency_hz, psd_db"]),
    ("non-increasing frequency", b"frequency_hz,psd\n10,1\n30,1\n20,1\n", EX_DATAERR,
     ["m.csv:4: column 'frequency_hz' value 20 does not increase", "strictly increasing"]),
    ("negative psd", b"frequency_hz,psd\n1,1\n300,-2e-20\n500,1\n", EX_DATAERR,
     ["m.csv:3: psd value -2e-20 is negative", "allowed: >= 0"]),
    ("negative frequency", b"frequency_hz,psd\n-10,1\n300,1\n500,1\n", EX_DATAERR,
     ["m.csv:2: frequency_hz value -10 is negative", "allowed: >= 0"]),
    ("nan", b"frequency_hz,psd\n10,1\n20,nan\n", EX_DATAERR, ["m.csv:3: column 'psd' value 'nan' is not finite"]),
    ("binary garbage", GARBAGE, EX_DATAERR, ["m.csv:1: binary data", "expected CSV text"]),
    ("huge number 1e999", b"frequency_hz,psd\n10,1\n20,1e999\n", EX_DATAERR,
     ["m.csv:3: column 'psd' value '1e999' is not finite", "allowed: finite numbers"]),
    ("too many columns", b"frequency_hz,psd\n10,1\n20,1,3\n", EX_DATAERR,
     ["m.csv:3: 3 values, but the header names 2 columns", "allowed: one value per column"]),
    ("empty cell", b"frequency_hz,psd\n10,1\n20,\n", EX_DATAERR, ["m.csv:3: column 'psd' value '' is not a number", "allowed: a decimal number"]),
    ("duplicated column", b"frequency_hz,psd,psd\n10,1,2\n20,1,2\n", EX_DATAERR,
     ["m.csv:1: column 'psd' appears twice", "each column name may appear once"]),
    ("band average overflows", b"frequency_hz,psd\n1,1.5e308\n5000,1.5e308\n", EX_DATAERR,
     ["m.csv: the measured PSD averaged over the band", "not finite"]),
    ("covers no band", b"frequency_hz,psd\n1,1\n2,1\n", EX_DATAERR, ["m.csv: covers none of the result's bands"]),
]


@pytest.mark.parametrize("name,data,code,fragments", MEASUREMENTS, ids=[c[0] for c in MEASUREMENTS])
def test_bad_measurement(tmp_path, good_result, name, data, code, fragments):
    m = tmp_path / "m.csv"
    m.write_bytes(data)
    before = good_result.read_bytes()
    r = run(["compare", good_result, m])
    assert_refused(r, code, fragments)
    assert r.stdout == "", "a refused comparison prints no partial table"
    assert good_result.read_bytes() == before


def test_measurement_is_a_directory_or_missing(tmp_path, good_result):
    d = tmp_path / "m.csv"
    d.mkdir()
    r = run(["compare", good_result, d])
    assert_refused(r, EX_NOINPUT, ["m.csv", "is a directory", "expected a recording", "or a PSD table"])
    r = run(["compare", good_result, tmp_path / "absent.csv"])
    assert_refused(r, EX_NOINPUT, ["cannot open", "absent.csv"])


# --- signal CSV for `rollspec psd` -------------------------------------------------------------------

def signal_text(n=64, overrides=None, header="a,b"):
    rows = [f"{np.sin(0.3 * i):.6f},{np.cos(0.7 * i):.6f}" for i in range(n)]
    for i, row in (overrides or {}).items():
        rows[i] = row
    return (header + "\n" + "\n".join(rows) + "\n").encode()


SIGNALS = [
    ("empty", b"", EX_DATAERR, ["s.csv: empty file"]),
    ("header only", b"a,b\n", EX_DATAERR, ["s.csv: header but no data rows", "expected at least one row"]),
    ("fewer samples than a segment", signal_text(8), EX_DATAERR,
     ["s.csv: 8 samples, fewer than one segment (--segment 16)"]),
    ("number as header", signal_text(64, header="0.5,1.5"), EX_DATAERR,
     ["s.csv:1: the first line must be a header", "'0.5'"]),
    ("nan sample", signal_text(64, {9: "0.1,nan"}), EX_DATAERR, ["s.csv:11: column 'b' value 'nan' is not finite"]),
    ("huge number 1e999", signal_text(64, {3: "1e999,0"}), EX_DATAERR, ["s.csv:5: column 'a' value '1e999' is not finite"]),
    ("too many columns", signal_text(64, {20: "1,2,3"}), EX_DATAERR, ["s.csv:22: 3 values, but the header names 2 columns", "allowed: one value per column"]),
    ("text in a cell", signal_text(64, {5: "0.1,volts"}), EX_DATAERR, ["s.csv:7: column 'b' value 'volts' is not a number", "allowed: a decimal number"]),
    ("binary garbage", b"a,b\n0.1,0.2\n\x00\x01\x02\x03\xff\xfe\n", EX_DATAERR, ["s.csv:3: binary data"]),
    ("duplicated channel names", signal_text(64, header="a,a"), EX_DATAERR, ["s.csv:1: column 'a' appears twice"]),
    ("samples whose PSD overflows", signal_text(64, {30: "1e300,0"}), EX_DATAERR,
     ["s.csv: column 'a': the PSD overflows", "largest |value| 1e+300", "allowed:"]),
]


@pytest.mark.parametrize("name,data,code,fragments", SIGNALS, ids=[c[0] for c in SIGNALS])
def test_bad_signal(tmp_path, name, data, code, fragments):
    sig = tmp_path / "s.csv"
    sig.write_bytes(data)
    out = put_sentinel(tmp_path / "psd.csv")
    r = run(["psd", sig, "--fs", 100, "--segment", 16, "--out", out])
    assert_refused(r, code, fragments)
    assert_untouched(out)


def test_signal_is_a_directory_or_missing(tmp_path):
    out = put_sentinel(tmp_path / "psd.csv")
    d = tmp_path / "s.csv"
    d.mkdir()
    assert_refused(run(["psd", d, "--fs", 100, "--out", out]), EX_NOINPUT, ["s.csv", "is a directory"])
    assert_refused(run(["psd", tmp_path / "absent.csv", "--fs", 100, "--out", out]), EX_NOINPUT, ["absent.csv"])
    assert_untouched(out)


# --- outputs that cannot be created ------------------------------------------------------------------

def test_psd_out_into_missing_directory(tmp_path):
    sig = tmp_path / "s.csv"
    sig.write_bytes(signal_text())
    r = run(["psd", sig, "--fs", 100, "--segment", 16, "--out", tmp_path / "nodir" / "psd.csv"])
    assert_refused(r, EX_CANTCREAT, ["cannot create output file", "nodir/psd.csv"])
    assert not (tmp_path / "nodir").exists()
    assert not list(tmp_path.rglob("*.tmp*"))


def test_psd_out_onto_a_directory_leaves_no_temporary_file(tmp_path):
    sig = tmp_path / "s.csv"
    sig.write_bytes(signal_text())
    d = tmp_path / "psd.csv"
    d.mkdir()
    put_sentinel(d / "inside.txt")
    r = run(["psd", sig, "--fs", 100, "--segment", 16, "--out", d])
    assert_refused(r, EX_CANTCREAT, ["cannot create output file", "psd.csv"])
    assert_untouched(d / "inside.txt")
    assert not list(tmp_path.glob("psd.csv.tmp*"))


def test_run_out_into_missing_directory(tmp_path, small_study):
    r = run(["run", small_study(realisations=2, duration=4), "--out", tmp_path / "nodir" / "r.h5"])
    assert_refused(r, EX_CANTCREAT, ["output directory", "nodir", "does not exist"])
    assert not (tmp_path / "nodir").exists()


@pytest.fixture
def read_only_dir(tmp_path):
    """A directory nobody may write, root included (as CI runs): a tmpfs remounted read-only when
    running as root, permissions otherwise. Yields (directory, make_read_only)."""
    ro = tmp_path / "ro"
    ro.mkdir()
    if os.geteuid() != 0:
        yield ro, lambda: ro.chmod(0o555)
        ro.chmod(0o755)
        return
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(ro)], capture_output=True, text=True)
    if r.returncode != 0:
        pytest.skip(f"root ignores permissions, and no read-only mount can be made here: {r.stderr.strip()}")

    def make_read_only():
        subprocess.run(["mount", "-o", "remount,ro", str(ro)], check=True, capture_output=True)

    yield ro, make_read_only
    subprocess.run(["umount", str(ro)], check=False)


def test_read_only_output_directory(tmp_path, small_study, read_only_dir):
    ro, make_read_only = read_only_dir
    out = put_sentinel(ro / "r.h5")
    psd_out = put_sentinel(ro / "psd.csv")
    sig = tmp_path / "s.csv"
    sig.write_bytes(signal_text())
    make_read_only()
    r = run(["run", small_study(realisations=2, duration=4), "--out", out, "--quiet"])
    assert_refused(r, EX_CANTCREAT, ["r.h5"])
    r = run(["psd", sig, "--fs", 100, "--segment", 16, "--out", psd_out])
    assert_refused(r, EX_CANTCREAT, ["psd.csv"])
    assert_untouched(out)
    assert_untouched(psd_out)


# --- PSD tables and profiles for `rollspec texture` -----------------------------------------------

TEXTURE_STUDY = """[study]
scene = texture
realisations = 1
seed = 1
[texture]
{texture}
table_extension = zero
[lines]
count = 2
length = 1e-4
spacing = 1e-6
"""


def texture_study(tmp_path, texture_lines):
    s = tmp_path / "s.ini"
    s.write_text(TEXTURE_STUDY.format(texture=texture_lines))
    return s


def run_texture(tmp_path, study):
    out = put_sentinel(tmp_path / "t.h5")
    r = run(["texture", study, "--out", out])
    return r, out


TABLE_HEAD = b"wavenumber_rad_per_m,psd_m3\n"
TABLES = [
    # Existing cases (test_texture_command.py) cover a negative psd, a repeated wavenumber, nan, missing
    # units, text and an empty file; these are the others.
    ("duplicated row", TABLE_HEAD + b"1e3,1e-18\n1e5,1e-20\n1e5,1e-20\n1e6,1e-23\n", EX_DATAERR,
     ["psd.csv:4: column 'wavenumber_rad_per_m' value 100000 does not increase", "strictly increasing"]),
    ("decreasing wavenumbers", TABLE_HEAD + b"1e6,1e-23\n1e5,1e-20\n1e3,1e-18\n", EX_DATAERR,
     ["psd.csv:3: column 'wavenumber_rad_per_m'", "does not increase"]),
    ("one row", TABLE_HEAD + b"1e3,1e-18\n", EX_DATAERR, ["psd.csv: a PSD table needs at least 2 rows"]),
    ("header only", TABLE_HEAD, EX_DATAERR, ["psd.csv: header but no data rows", "expected at least one row"]),
    ("three columns", b"wavenumber_rad_per_m,psd_m3,weight\n1e3,1e-18,1\n1e6,1e-23,1\n", EX_DATAERR,
     ["psd.csv:1: a PSD table has 2 columns (abscissa, psd), found 3"]),
    ("one column", b"wavenumber_rad_per_m\n1e3\n1e6\n", EX_DATAERR, ["psd.csv:1: a PSD table has 2 columns", "found 1"]),
    ("zero wavenumber", TABLE_HEAD + b"0,1e-18\n1e6,1e-23\n", EX_DATAERR,
     ["psd.csv:2: wavenumber_rad_per_m value", "must be > 0"]),
    ("huge number 1e999", TABLE_HEAD + b"1e3,1e-18\n1e6,1e999\n", EX_DATAERR,
     ["psd.csv:3: column 'psd_m3' value '1e999' is not finite"]),
    ("binary garbage", GARBAGE, EX_DATAERR, ["psd.csv:1: binary data"]),
    ("heights overflow double precision", TABLE_HEAD + b"1e3,1e300\n1e6,1e300\n", EX_DATAERR,
     ["psd.csv", "[texture] source = table", "non-finite heights or statistics", "allowed:"]),
]


@pytest.mark.parametrize("name,data,code,fragments", TABLES, ids=[c[0] for c in TABLES])
def test_bad_psd_table(tmp_path, name, data, code, fragments):
    (tmp_path / "psd.csv").write_bytes(data)
    r, out = run_texture(tmp_path, texture_study(tmp_path, "source = table\ntable = psd.csv"))
    assert_refused(r, code, fragments)
    assert_untouched(out)


def profile_bytes(n=64, header="position_m,height_m", x=None, z=None):
    x = np.arange(n) * 1e-6 if x is None else x
    z = np.sin(np.arange(n) * 0.9) * 1e-7 if z is None else z
    rows = "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(x, z))
    return (header + "\n" + rows).encode()


def nonuniform_x(n=64):
    x = np.arange(n) * 1e-6
    x[40:] += 0.4e-6
    return x


def swapped_x(n=64):
    x = np.arange(n) * 1e-6
    x[[10, 11]] = x[[11, 10]]
    return x


PROFILES = [
    ("non-uniform spacing", profile_bytes(x=nonuniform_x()), EX_DATAERR,
     ["s.ini:7: [texture] profiles = good.csv, bad.csv", "bad.csv:18: column 'position_m' value 16 um is -0.1",
      "steps off the uniform grid x_0 + i*dx", "dx = 1.00635 um", "the spacing is not constant"]),
    ("one column", b"position_m\n" + b"".join(f"{i * 1e-6!r}\n".encode() for i in range(64)), EX_DATAERR,
     ["bad.csv:1: a profile has the columns position_m,height_m"]),
    ("wrong unit header", profile_bytes(header="position_mm,height_m"), EX_DATAERR,
     ["bad.csv:1: a profile has the columns position_m,height_m (or position_m,height_um)"]),
    ("positions not sorted", profile_bytes(x=swapped_x()), EX_DATAERR,
     ["bad.csv:13: column 'position_m'", "does not increase"]),
    ("nan height", profile_bytes(z=np.where(np.arange(64) == 5, np.nan, 1e-7)), EX_DATAERR,
     ["bad.csv:7: column 'height_m' value 'nan' is not finite"]),
    ("binary garbage", GARBAGE, EX_DATAERR, ["bad.csv:1: binary data"]),
    ("too few samples", profile_bytes(n=5), EX_DATAERR, ["bad.csv: 5 samples; a profile needs at least 8"]),
    ("heights overflow", profile_bytes(z=np.full(64, 1e200) * np.sin(np.arange(64))), EX_DATAERR,
     ["s.ini:7: [texture] profiles = good.csv, bad.csv", "inf"]),
]


@pytest.mark.parametrize("name,data,code,fragments", PROFILES, ids=[c[0] for c in PROFILES])
def test_bad_profile(tmp_path, name, data, code, fragments):
    (tmp_path / "good.csv").write_bytes(profile_bytes())
    (tmp_path / "bad.csv").write_bytes(data)
    r, out = run_texture(tmp_path, texture_study(tmp_path, "source = profiles\nprofiles = good.csv, bad.csv"))
    assert_refused(r, code, fragments)
    assert_untouched(out)


def test_good_profiles_are_accepted(tmp_path):
    """The baseline of the profile cases: two good profiles work, and so does a BOM-prefixed file."""
    (tmp_path / "good.csv").write_bytes(profile_bytes())
    (tmp_path / "bad.csv").write_bytes(b"\xef\xbb\xbf" + profile_bytes(z=np.cos(np.arange(64)) * 1e-7))
    study = texture_study(tmp_path, "source = profiles\nprofiles = good.csv, bad.csv")
    r = run(["texture", study, "--out", tmp_path / "ok.h5"])
    assert r.returncode == 0, r.stderr


# --- study files: referenced files and the study itself ------------------------------------------

def test_texture_table_points_at_a_missing_file(tmp_path):
    r, out = run_texture(tmp_path, texture_study(tmp_path, "source = table\ntable = absent.csv"))
    assert_refused(r, EX_NOINPUT, ["s.ini:7: [texture] table = absent.csv", "no such file",
                                   "allowed: the path of an existing file"])
    assert_untouched(out)


def test_path_key_points_at_a_directory(tmp_path):
    (tmp_path / "tables").mkdir()
    r, out = run_texture(tmp_path, texture_study(tmp_path, "source = table\ntable = tables"))
    assert_refused(r, EX_NOINPUT, ["s.ini:7: [texture] table = tables", "is a directory, not a file",
                                   "allowed: the path of an existing file"])
    assert_untouched(out)


def test_profile_list_names_a_directory(tmp_path):
    (tmp_path / "good.csv").write_bytes(profile_bytes())
    (tmp_path / "bad.csv").mkdir()
    r, out = run_texture(tmp_path, texture_study(tmp_path, "source = profiles\nprofiles = good.csv, bad.csv"))
    assert_refused(r, EX_NOINPUT, ["s.ini:7: [texture] profiles", "bad.csv"])
    assert_untouched(out)


def test_study_file_is_a_directory(tmp_path):
    d = tmp_path / "study.ini"
    d.mkdir()
    out = put_sentinel(tmp_path / "r.h5")
    for cmd in (["run", d, "--out", out], ["plan", d], ["texture", d, "--out", out]):
        assert_refused(run(cmd), EX_NOINPUT, ["study.ini", "is a directory", "expected an INI file"])
    assert_untouched(out)


def test_study_with_byte_order_mark_is_read(tmp_path):
    s = tmp_path / "s.ini"
    s.write_bytes(b"\xef\xbb\xbf" + SMALL_OSCILLATOR.format(realisations=2, chunk=2, duration=4).encode())
    r = run(["plan", s])
    assert r.returncode == 0, r.stderr


def test_texture_out_onto_a_directory_leaves_no_temporary_file(tmp_path):
    (tmp_path / "psd.csv").write_bytes(TABLE_HEAD + b"1e3,1e-18\n1e6,1e-23\n")
    study = texture_study(tmp_path, "source = table\ntable = psd.csv")
    d = tmp_path / "t.h5"
    d.mkdir()
    put_sentinel(d / "inside.txt")
    r = run(["texture", study, "--out", d])
    assert_refused(r, EX_CANTCREAT, ["t.h5"])
    assert_untouched(d / "inside.txt")
    assert not list(tmp_path.glob("t.h5.tmp*"))
    r = run(["texture", study, "--out", tmp_path / "nodir" / "t.h5"])
    assert_refused(r, EX_CANTCREAT, ["cannot create output file", "nodir/t.h5"])


# --- result files for `rollspec compare` --------------------------------------------------------------

def edited_copy(good, dst, edit):
    shutil.copyfile(good, dst)
    with h5py.File(dst, "r+") as f:
        edit(f)
    return dst


def replace_dataset(name, value):
    def edit(f):
        del f[name]
        f[name] = value
    return edit


def set_attr(name, value):
    def edit(f):
        f.attrs[name] = value
    return edit


def truncate_half(good, dst):
    data = good.read_bytes()
    dst.write_bytes(data[: len(data) // 2])
    return dst


def texture_file(good, dst):
    (dst.parent / "psd.csv").write_bytes(TABLE_HEAD + b"1e3,1e-18\n1e6,1e-23\n")
    study = texture_study(dst.parent, "source = table\ntable = psd.csv")
    assert run(["texture", study, "--out", dst]).returncode == 0
    return dst


def level_db(f):
    return f["/bands/level_db"][()]


RESULTS = [
    # name, how to make the file from a good result, exit code, fragments besides the file name
    ("truncated HDF5", truncate_half, EX_DATAERR, ["truncated"]),
    ("zero bytes", lambda g, d: (d.write_bytes(b""), d)[1], EX_DATAERR, ["not an HDF5 file", "expected an HDF5 file written by rollspec"]),
    ("random bytes", lambda g, d: (d.write_bytes(np.random.default_rng(9).bytes(4096)), d)[1], EX_DATAERR,
     ["not an HDF5 file"]),
    ("a CSV file", lambda g, d: (d.write_text(GOOD_MEASUREMENT), d)[1], EX_DATAERR, ["not an HDF5 file"]),
    ("texture file instead of a result", texture_file, EX_DATAERR,
     ["filetype is 'rollspec-texture'; expected 'rollspec-result'"]),
    ("filetype of another kind (h5py string)", lambda g, d: edited_copy(g, d, set_attr("filetype", "netcdf4")),
     EX_DATAERR, ["filetype is 'netcdf4'; expected 'rollspec-result'"]),
    ("filetype is a number", lambda g, d: edited_copy(g, d, set_attr("filetype", 3)), EX_DATAERR,
     ["attribute /@filetype is not text"]),
    ("filetype is a list of strings", lambda g, d: edited_copy(g, d, set_attr("filetype", np.array([b"a", b"b"]))),
     EX_DATAERR, ["attribute /@filetype holds 2 strings; expected one"]),
    ("no filetype", lambda g, d: edited_copy(g, d, lambda f: f.attrs.__delitem__("filetype")), EX_DATAERR,
     ["not a rollspec file (no filetype attribute)"]),
    ("schema_version 9.0 (fixed-length)", lambda g, d: edited_copy(g, d, set_attr("schema_version", np.bytes_(b"9.0"))),
     EX_DATAERR, ["schema_version '9.0' is not readable", "allowed: 2.x"]),
    ("schema_version 9.0 (h5py string)", lambda g, d: edited_copy(g, d, set_attr("schema_version", "9.0")),
     EX_DATAERR, ["schema_version '9.0' is not readable", "allowed: 2.x"]),
    ("no /bands/level_db", lambda g, d: edited_copy(g, d, lambda f: f.__delitem__("/bands/level_db")), EX_DATAERR,
     ["no dataset /bands/level_db", "expected it in a complete rollspec file"]),
    ("integer /bands/level_db", lambda g, d: edited_copy(g, d, lambda f: replace_dataset(
        "/bands/level_db", level_db(f).astype(np.int32))(f)), EX_DATAERR, ["dataset /bands/level_db is not floating point"]),
    ("band edges shorter than the levels", lambda g, d: edited_copy(g, d, lambda f: replace_dataset(
        "/bands/upper_frequency", f["/bands/upper_frequency"][:2])(f)), EX_DATAERR,
     ["/bands/upper_frequency has 2 values; expected"]),
    ("CI shape differs from the levels", lambda g, d: edited_copy(g, d, lambda f: replace_dataset(
        "/bands/ci_lower_db", f["/bands/ci_lower_db"][:, :3])(f)), EX_DATAERR,
     ["/bands/ci_lower_db does not have the shape of /bands/level_db"]),
    ("no sensors", lambda g, d: edited_copy(g, d, lambda f: [replace_dataset(n, np.zeros((0, level_db(f).shape[1])))(f)
                                                              for n in ("/bands/ci_lower_db", "/bands/ci_upper_db",
                                                                        "/bands/level_db")]), EX_DATAERR,
     ["/bands/level_db is empty (0 sensors"]),
    ("nan level", lambda g, d: edited_copy(g, d, lambda f: f["/bands/level_db"].__setitem__((0, 3), np.nan)), EX_DATAERR,
     ["/bands/level_db[0, 3] is NaN"]),
]


@pytest.mark.parametrize("name,make,code,fragments", RESULTS, ids=[c[0] for c in RESULTS])
def test_bad_result_file(tmp_path, good_result, name, make, code, fragments):
    bad = make(good_result, tmp_path / "bad.h5")
    m = tmp_path / "m.csv"
    m.write_text(GOOD_MEASUREMENT)
    before = bad.read_bytes()
    r = run(["compare", bad, m])
    assert_refused(r, code, ["bad.h5", *fragments])
    assert r.stdout == "", "a refused comparison prints no partial table"
    assert bad.read_bytes() == before, "compare must not modify its input"


def test_result_is_a_directory(tmp_path):
    d = tmp_path / "bad.h5"
    d.mkdir()
    m = tmp_path / "m.csv"
    m.write_text(GOOD_MEASUREMENT)
    assert_refused(run(["compare", d, m]), EX_NOINPUT, ["bad.h5", "is a directory", "expected an HDF5 file"])


# --- checkpoints of `rollspec run --resume` ----------------------------------------------------------

def test_checkpoint_of_another_study_and_damaged_checkpoint(tmp_path, good_result):
    """An interrupted run keeps its checkpoints; resuming a different study on them is refused
    (naming the differing key), and so is a truncated checkpoint; the result in place is untouched."""
    study_a = small_study_text(tmp_path / "a.ini", realisations=3000, chunk=16, duration=16)
    out = tmp_path / "r.h5"
    shutil.copyfile(good_result, out)
    before = out.read_bytes()
    ck = tmp_path / "r.h5.checkpoint"
    p = subprocess.Popen([BIN, "run", study_a, "--out", out, "--quiet"], stderr=subprocess.PIPE, text=True,
                         env={**os.environ, "OMP_NUM_THREADS": "1"})
    deadline = time.time() + 30
    while time.time() < deadline and p.poll() is None and not list(ck.glob("chunk_*.bin")):
        time.sleep(0.005)
    p.send_signal(signal.SIGINT)
    assert p.wait(timeout=30) == 130, p.stderr.read()
    chunks = sorted(ck.glob("chunk_*.bin"))
    assert chunks, "the completed chunks stay checkpointed"
    assert not list(tmp_path.glob("r.h5.tmp*"))

    study_b = tmp_path / "b.ini"
    study_b.write_text(study_a.read_text().replace("seed = 42", "seed = 43"))
    r = run(["run", study_b, "--out", out, "--resume", "--quiet"])
    assert_refused(r, EX_DATAERR, ["r.h5.checkpoint", "belongs to a different study", "[study] seed = 43 (checkpoint: 42)",
                                   "--restart"])
    assert out.read_bytes() == before

    chunks[0].write_bytes(chunks[0].read_bytes()[:-5])
    r = run(["run", study_a, "--out", out, "--resume", "--quiet"])
    assert_refused(r, EX_DATAERR, [chunks[0].name, "damaged checkpoint"])
    assert out.read_bytes() == before
    assert not list(tmp_path.rglob("*.tmp*"))


def small_study_text(path, realisations, chunk, duration):
    path.write_text(SMALL_OSCILLATOR.format(realisations=realisations, chunk=chunk, duration=duration))
    return path
