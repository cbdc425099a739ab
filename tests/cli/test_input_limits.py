"""Issue 16, items 10, 14 and 15: inputs refused before any work, with a message naming the key or file,
the limit and what is allowed; non-regular inputs never block; messages stay short."""
import os
import time

import pytest

from conftest import (EX_CANTCREAT, EX_CONFIG, EX_DATAERR, EX_NOINPUT, EX_USAGE, SMALL_OSCILLATOR, SOURCE,
                      assert_refused, oscillator_study, run)

RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"




# --- item 14: cross-key checks before the ensemble -------------------------------------------------

@pytest.mark.parametrize("sets,key,fragment", [
    (["spectrum.band_min=300", "spectrum.band_max=200"], "[spectrum] band_max = 200", "allowed: band_min < band_max"),
    (["spectrum.band_min=600", "spectrum.band_max=1e9"], "[spectrum] band_min = 600", "Nyquist frequency 512 Hz"),
    (["spectrum.band_min=500", "spectrum.band_max=510"], "[spectrum] band_max = 510", "no whole third-octave band"),
])
def test_band_range_is_checked_before_the_run(tmp_path, sets, key, fragment):
    out = tmp_path / "r.h5"
    args = [a for kv in sets for a in ("--set", kv)]
    r = run(["run", oscillator_study(tmp_path, realisations=4000), "--out", out, "--quiet", *args], timeout=20)
    assert_refused(r, EX_CONFIG, [key, fragment])
    assert not out.exists() and not (tmp_path / "r.h5.checkpoint").exists()


def test_too_many_beam_modes_are_refused_up_front(tmp_path):
    out = tmp_path / "r.h5"
    start = time.time()
    r = run(["run", RIG, "--out", out, "--quiet", "--set", "beam.modes=640", "--set", "study.realisations=1000"])
    assert_refused(r, EX_CONFIG, ["[beam] modes = 640", "overflows double precision", "allowed: at most 629 modes"])
    assert time.time() - start < 10 and not out.exists()


def test_description_longer_than_an_attribute_is_refused(tmp_path):
    r = run(["run", oscillator_study(tmp_path), "--out", tmp_path / "r.h5", "--quiet", "--set", "study.description=" + "x" * 70000])
    assert_refused(r, EX_CONFIG, ["[study] description = xxxx", "(70000 bytes in all)", "allowed: a study of at most 61440 bytes"])
    assert len(r.stderr) < 1000


# --- item 15: more input checks -----------------------------------------------------------------------

def test_set_with_a_line_break_is_refused(tmp_path):
    out = tmp_path / "r.h5"
    r = run(["run", oscillator_study(tmp_path), "--out", out, "--quiet", "--set", "study.description=x\n[force]\nlevel = 9"])
    assert_refused(r, EX_USAGE, ["holds a line break", "allowed: one line of text"])
    assert not out.exists()


def test_fifo_inputs_are_refused_without_blocking(tmp_path):
    fifo = tmp_path / "in.fifo"
    os.mkfifo(fifo)
    assert_refused(run(["run", fifo, "--out", tmp_path / "r.h5"], timeout=10), EX_NOINPUT, ["study file", "a FIFO", "allowed: a regular file"])
    assert_refused(run(["plan", fifo], timeout=10), EX_NOINPUT, ["a FIFO"])
    assert_refused(run(["psd", fifo, "--fs", 100], timeout=10), EX_NOINPUT, ["CSV file", "a FIFO"])
    assert_refused(run(["compare", fifo, fifo], timeout=10), EX_NOINPUT, ["a FIFO"])
    ck = tmp_path / "r.h5.checkpoint"
    ck.mkdir()
    os.mkfifo(ck / "chunk_000000000000_000000000004.bin")
    r = run(["run", oscillator_study(tmp_path), "--out", tmp_path / "r.h5", "--resume", "--quiet"], timeout=10)
    assert_refused(r, EX_CANTCREAT, ["holds files rollspec did not write (chunk_000000000000_000000000004.bin)"])


def test_a_device_as_table_is_named_as_such(tmp_path):
    s = tmp_path / "t.ini"
    s.write_text("[study]\nscene = texture\nrealisations = 1\nseed = 1\n[texture]\nsource = table\ntable = /dev/zero\n")
    r = run(["texture", s, "--out", tmp_path / "t.h5"], timeout=10)
    assert_refused(r, EX_NOINPUT, ["[texture] table = /dev/zero", "is a character device, not a regular file"])
    assert "no such file" not in r.stderr


def test_huge_keys_and_cells_are_cut_in_messages(tmp_path):
    s = tmp_path / "s.ini"
    s.write_text(SMALL_OSCILLATOR.format(realisations=4, chunk=4, duration=4) + "[force]\n" + "k" * 1_000_000 + " = 1\n")
    r = run(["plan", s])
    assert r.returncode == EX_CONFIG and "bytes in all" in r.stderr and len(r.stderr) < 2000, r.stderr[:500]
    sig = tmp_path / "sig.csv"
    sig.write_text("a\n1\n" + "9" * 5_000_000 + "x\n")
    r = run(["psd", sig, "--fs", 100])
    assert_refused(r, EX_DATAERR, ["sig.csv:3: column 'a' value '999", "bytes in all", "is not a number"])
    assert len(r.stderr) < 1000


def test_duplicate_column_check_is_linear(tmp_path):
    sig = tmp_path / "wide.csv"
    n = 300_000
    sig.write_text(",".join(f"c{i}" for i in range(n)) + ",c7\n" + ",".join("1" for _ in range(n + 1)) + "\n")
    start = time.time()
    r = run(["psd", sig, "--fs", 100], timeout=30)
    assert_refused(r, EX_DATAERR, ["column 'c7' appears twice in the header (columns 8 and 300001)"])
    assert time.time() - start < 10
