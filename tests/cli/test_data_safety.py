"""Issue 16, items 1-7 and 13: rollspec never replaces or deletes what the user did not ask it to.

Each case checks the refusal (sysexits code, a message naming the path or key and what is allowed)
and that the file or directory in the way is byte-identical afterwards, with no temporary file."""
import os
import shutil
import signal
import subprocess
import time

import h5py
import numpy as np
import pytest

from conftest import (BIN, EX_CANTCREAT, EX_DATAERR, EX_INTERRUPTED, EX_USAGE, SMALL_OSCILLATOR, SOURCE,
                      assert_bitwise_equal, assert_refused, run)

SENTINEL = b"precious user data\n"



def no_temps(d):
    left = [p.name for p in d.rglob("*.tmp*")]
    assert not left, f"temporary files left behind: {left}"


def study_file(tmp_path, realisations=8, chunk=4, duration=4, name="s.ini"):
    p = tmp_path / name
    p.write_text(SMALL_OSCILLATOR.format(realisations=realisations, chunk=chunk, duration=duration))
    return p


def chunks(d):
    return sorted(p.name for p in d.glob("chunk_*.bin"))


# --- item 1: --resume reuses the checkpoint's study; plain runs refuse an unfinished checkpoint --------

def interrupted_run(tmp_path, study, out, realisations):
    """Starts `run --set study.realisations=N`, sends SIGINT once a chunk is checkpointed."""
    ck = tmp_path / (out.name + ".checkpoint")
    p = subprocess.Popen([BIN, "run", study, "--out", out, "--quiet", "--set", f"study.realisations={realisations}"],
                         stderr=subprocess.PIPE, text=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
    deadline = time.time() + 30
    while time.time() < deadline and p.poll() is None and not list(ck.glob("chunk_*.bin")):
        time.sleep(0.005)
    p.send_signal(signal.SIGINT)
    err = p.communicate(timeout=30)[1]
    assert p.returncode == EX_INTERRUPTED, err
    assert "finish with --resume" in err
    return ck


def test_resume_without_set_reuses_the_checkpoint_study(tmp_path):
    study = study_file(tmp_path, realisations=8, chunk=16, duration=16)
    out = tmp_path / "r.h5"
    ck = interrupted_run(tmp_path, study, out, 3000)
    saved = chunks(ck)
    assert saved and not out.exists()

    # A different --set is refused, naming the key and both values; nothing changes.
    r = run(["run", study, "--out", out, "--resume", "--quiet", "--set", "study.realisations=500"])
    assert_refused(r, EX_DATAERR, ["[study] realisations: --set 500, the checkpoint has 3000", "--restart"])
    assert chunks(ck) == saved and not out.exists()

    # A plain run refuses to delete the unfinished work.
    r = run(["run", study, "--out", out, "--quiet"])
    assert_refused(r, EX_CANTCREAT, ["r.h5.checkpoint holds an unfinished run", "--resume", "--restart"])
    assert chunks(ck) == saved and not out.exists()

    # The README's resume line, without the --set: the checkpoint's 3000 realisations are finished.
    r = run(["run", study, "--out", out, "--resume"])
    assert r.returncode == 0, r.stderr
    assert "resuming with the checkpoint's settings: --set study.realisations=3000" in r.stderr
    assert not ck.exists()
    with h5py.File(out) as f:
        assert b"realisations = 3000" in f.attrs["study"]
    ref = tmp_path / "ref.h5"
    r = run(["run", study, "--out", ref, "--quiet", "--set", "study.realisations=3000"])
    assert r.returncode == 0, r.stderr
    assert_bitwise_equal(out, ref)
    no_temps(tmp_path)


def test_restart_discards_an_unfinished_checkpoint(tmp_path):
    study = study_file(tmp_path, realisations=8, chunk=16, duration=16)
    out = tmp_path / "r.h5"
    interrupted_run(tmp_path, study, out, 3000)
    r = run(["run", study, "--out", out, "--quiet", "--restart"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        assert b"realisations = 8" in f.attrs["study"]
    assert not (tmp_path / "r.h5.checkpoint").exists()
    assert_refused(run(["run", study, "--out", out, "--resume", "--restart"]), EX_USAGE, ["--resume and --restart"])


def test_resume_after_the_study_file_changed_is_refused(tmp_path):
    study = study_file(tmp_path, realisations=8, chunk=16, duration=16)
    out = tmp_path / "r.h5"
    ck = interrupted_run(tmp_path, study, out, 3000)
    saved = chunks(ck)
    study.write_text(study.read_text().replace("seed = 42", "seed = 43"))
    r = run(["run", study, "--out", out, "--resume", "--quiet"])
    assert_refused(r, EX_DATAERR, ["belongs to a different study", "[study] seed = 43 (checkpoint: 42)", "--restart"])
    assert chunks(ck) == saved


# --- item 13: checkpoint identity includes the code identity ------------------------------------------

def fnv1a64(data):
    h = 14695981039346656037
    for b in data:
        h = ((h ^ b) * 1099511628211) % (1 << 64)
    return h


def test_resume_refuses_a_checkpoint_of_another_build(tmp_path):
    study = study_file(tmp_path, realisations=8, chunk=16, duration=16)
    out = tmp_path / "r.h5"
    ck = interrupted_run(tmp_path, study, out, 3000)
    manifest = ck / "manifest"
    text = manifest.read_text()
    assert "identity = rollspec " in text and "; git " in text and "contact kernel" in text
    body = text[: text.rindex("checksum = ")]
    lines = body.split("\n")
    lines = [("identity = rollspec 0.1.0; git 0123456789ab; contact kernel 1" if l.startswith("identity = ") else l)
             for l in lines]
    body = "\n".join(lines)
    manifest.write_text(body + "checksum = %016x\n" % fnv1a64(body.encode()))
    saved = chunks(ck)
    r = run(["run", study, "--out", out, "--resume", "--quiet"])
    assert_refused(r, EX_DATAERR, ["written by another build (rollspec 0.1.0; git 0123456789ab; contact kernel 1)",
                            "never mixed", "--restart"])
    assert chunks(ck) == saved
    manifest.write_text(body + "checksum = 0000000000000000\n")
    assert_refused(run(["run", study, "--out", out, "--resume", "--quiet"]), EX_DATAERR, ["damaged checkpoint manifest"])


def test_version_records_the_build_git_sha():
    head = subprocess.run(["git", "-C", SOURCE, "rev-parse", "--short=12", "HEAD"], capture_output=True, text=True)
    if head.returncode != 0:
        pytest.skip("the sources are not a git checkout")
    r = run(["version"])
    assert r.returncode == 0
    sha = r.stdout.split("(git ")[1].split(")")[0]
    assert sha.split("-")[0] == head.stdout.strip(), f"binary records {sha}, HEAD is {head.stdout.strip()} (rebuild?)"


# --- item 2: only files rollspec wrote are removed ------------------------------------------------------

def test_checkpoint_directory_with_user_files_is_not_touched(tmp_path):
    study = study_file(tmp_path)
    out = tmp_path / "r.h5"
    ck = tmp_path / "r.h5.checkpoint"
    ck.mkdir()
    (ck / "notes.txt").write_bytes(SENTINEL)
    for extra in ([], ["--restart"]):
        r = run(["run", study, "--out", out, "--quiet", *extra])
        assert_refused(r, EX_CANTCREAT, ["r.h5.checkpoint holds files rollspec did not write (notes.txt)", "never removes them"])
        assert (ck / "notes.txt").read_bytes() == SENTINEL and sorted(os.listdir(ck)) == ["notes.txt"]
    shutil.rmtree(ck)
    ck.write_bytes(SENTINEL)
    assert_refused(run(["run", study, "--out", out, "--quiet"]), EX_CANTCREAT, ["r.h5.checkpoint exists and is a regular file"])
    assert ck.read_bytes() == SENTINEL
    assert not out.exists()


# --- item 3: the output is never an input ---------------------------------------------------------------

def test_output_equal_to_an_input_is_refused(tmp_path):
    study = study_file(tmp_path)
    before = study.read_bytes()
    assert_refused(run(["run", study, "--out", study, "--quiet"]), EX_USAGE, ["is also an input", "s.ini"])
    link = tmp_path / "link.h5"
    link.symlink_to(study)
    assert_refused(run(["run", study, "--out", link, "--quiet"]), EX_USAGE, ["is also an input"])
    h5study = tmp_path / "study.h5"
    h5study.write_bytes(before)
    r = run(["run", "study.h5", "--quiet"], cwd=tmp_path)  # the default output name is the study itself
    assert_refused(r, EX_USAGE, ["study.h5 is also an input"])
    assert study.read_bytes() == before and h5study.read_bytes() == before and link.is_symlink()
    sig = tmp_path / "sig.csv"
    sig.write_text("a\n" + "".join(f"{np.sin(i)}\n" for i in range(64)))
    sig_before = sig.read_bytes()
    assert_refused(run(["psd", sig, "--fs", 100, "--segment", 16, "--out", sig]), EX_USAGE, ["is also the input"])
    assert sig.read_bytes() == sig_before
    no_temps(tmp_path)


# --- item 4: only regular rollspec outputs of the same kind are replaced -----------------------------

def test_devices_fifos_and_links_to_them_are_not_replaced(tmp_path):
    study = study_file(tmp_path)
    fifo = tmp_path / "pipe.h5"
    os.mkfifo(fifo)
    link = tmp_path / "null.h5"
    link.symlink_to("/dev/null")
    for target, what in ((os.devnull, "a character device"), (fifo, "a FIFO"), (link, "a symbolic link to a character device")):
        r = run(["run", study, "--out", target, "--quiet", "--force"])
        assert_refused(r, EX_CANTCREAT, ["cannot create output file", what, "never replaces"])
    assert os.path.exists("/dev/null") and not os.path.isfile("/dev/null")
    assert fifo.is_fifo() and link.is_symlink()
    no_temps(tmp_path)


def test_a_regular_file_is_replaced_only_if_it_is_a_result_or_forced(tmp_path):
    study = study_file(tmp_path)
    out = tmp_path / "r.h5"
    out.write_bytes(SENTINEL)
    assert_refused(run(["run", study, "--out", out, "--quiet"]), EX_CANTCREAT,
            ["exists and is not a rollspec file of filetype 'rollspec-result'", "--force"])
    assert out.read_bytes() == SENTINEL
    assert run(["run", study, "--out", out, "--quiet", "--force"]).returncode == 0
    assert run(["run", study, "--out", out, "--quiet"]).returncode == 0  # a result replaces a result
    sig = tmp_path / "sig.csv"
    sig.write_text("a\n" + "".join(f"{np.sin(i)}\n" for i in range(64)))
    psd = tmp_path / "psd.csv"
    psd.write_bytes(SENTINEL)
    assert_refused(run(["psd", sig, "--fs", 100, "--segment", 16, "--out", psd]), EX_CANTCREAT, ["not a PSD written by rollspec psd"])
    assert psd.read_bytes() == SENTINEL
    assert run(["psd", sig, "--fs", 100, "--segment", 16, "--out", psd, "--force"]).returncode == 0
    assert run(["psd", sig, "--fs", 100, "--segment", 16, "--out", psd]).returncode == 0
    no_temps(tmp_path)


# --- item 5: --only has its own default name and its own time history ---------------------------------

def test_only_without_out_keeps_the_ensemble_result(tmp_path):
    study_file(tmp_path)
    assert run(["run", "s.ini", "--quiet"], cwd=tmp_path).returncode == 0
    full = (tmp_path / "s.h5").read_bytes()
    r = run(["run", "s.ini", "--quiet", "--only", 3], cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "s.h5").read_bytes() == full
    with h5py.File(tmp_path / "s-only-3.h5") as f:
        assert f["/run"].attrs["only_realisation"] == 3


def test_only_stores_its_own_time_history(tmp_path):
    rig = SOURCE / "studies" / "seed002-rig-1ms.ini"
    short = ["--quiet", "--set", "ball.end=0.1", "--set", "output.time_histories=2", "--set", "study.realisations=2"]
    both, one = tmp_path / "both.h5", tmp_path / "one.h5"
    assert run(["run", rig, "--out", both, *short]).returncode == 0
    r = run(["run", rig, "--out", one, *short, "--only", 1])
    assert r.returncode == 0, r.stderr
    with h5py.File(both) as a, h5py.File(one) as b:
        assert b["/time_history/contact_force"].shape[0] == 1
        assert b["/time_history"].attrs["realisations"] in (b"1", "1")
        assert a["/time_history/contact_force"][1].tobytes() == b["/time_history/contact_force"][0].tobytes()
        assert a["/time_history/contact_force"][0].tobytes() != b["/time_history/contact_force"][0].tobytes()


# --- item 6: --rebuild replaces only rollspec tables; table_dir never climbs out ----------------------

def hertz_study(tmp_path):
    s = tmp_path / "hertz.ini"
    s.write_text((SOURCE / "studies" / "hertz.ini").read_text())
    return s


def test_rebuild_never_overwrites_a_file_that_is_not_a_table(tmp_path):
    s = hertz_study(tmp_path)
    victim = tmp_path / "victim.txt"
    victim.write_bytes(SENTINEL)
    r = run(["stiffness", s, "--quiet", "--rebuild", "--set", "stiffness.table=victim.txt"])
    assert_refused(r, EX_CANTCREAT, ["victim.txt", "rollspec-stiffness-table", "--rebuild replaces only rollspec tables"])
    assert victim.read_bytes() == SENTINEL
    r = run(["stiffness", s, "--quiet", "--rebuild", "--set", "stiffness.table=hertz.ini"])
    assert_refused(r, EX_USAGE, ["is also an input"])
    no_temps(tmp_path)


def test_table_dir_is_not_created_outside_the_study_directory(tmp_path):
    d = tmp_path / "a"
    d.mkdir()
    s = hertz_study(d)
    r = run(["stiffness", s, "--quiet", "--set", "stiffness.table_dir=../made/by/rollspec"])
    assert_refused(r, 78, ["[stiffness] table_dir = ../made/by/rollspec", "only below the study's directory"])
    assert not (tmp_path / "made").exists()
    r = run(["stiffness", s, "--quiet", "--set", f"stiffness.table_dir={tmp_path}/abs"])
    assert_refused(r, 78, ["only below the study's directory"])
    assert not (tmp_path / "abs").exists()


# --- item 7: stale temporaries of dead processes are cleaned, live ones kept -------------------------

def test_stale_temporary_files_are_removed_live_ones_kept(tmp_path):
    study = study_file(tmp_path)
    out = tmp_path / "r.h5"
    dead = subprocess.Popen(["true"])
    dead.wait()
    stale = tmp_path / f"r.h5.tmp-{dead.pid}"
    stale.write_bytes(b"half a result")
    live = tmp_path / f"r.h5.tmp-{os.getpid()}"
    live.write_bytes(b"another run's file in progress")
    other = tmp_path / "r.h5.tmp-notes"
    other.write_bytes(SENTINEL)
    r = run(["run", study, "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    assert not stale.exists()
    assert live.exists() and other.read_bytes() == SENTINEL
