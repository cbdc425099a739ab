"""Bitwise-identical result data for any thread count, chunk size, and after interruption + --resume."""
import os
import signal
import subprocess
import time

import h5py

from conftest import BIN, EX_INTERRUPTED, assert_bitwise_equal, run


def test_one_and_two_threads_and_chunk_sizes_give_identical_bits(small_study, tmp_path):
    study = small_study(realisations=37, chunk=4)
    outs = {}
    for threads, chunk in ((1, 4), (2, 4), (2, 16), (1, 1)):
        out = tmp_path / f"r_{threads}_{chunk}.h5"
        r = run(["run", study, "--out", out, "--quiet", "--set", f"ensemble.chunk_size={chunk}"],
                env={"OMP_NUM_THREADS": str(threads)})
        assert r.returncode == 0, r.stderr
        outs[(threads, chunk)] = out
    base = outs[(1, 4)]
    for key, out in outs.items():
        assert_bitwise_equal(base, out)
    with h5py.File(base) as f:
        assert f["/psd"].attrs["realisations"] == 37
        assert not (tmp_path / "r_1_4.h5.checkpoint").exists(), "checkpoints are removed after the result is written"


def interrupt_after_chunks(cmd, checkpoint_dir, sig, min_chunks=2, timeout=60):
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + timeout
    while time.time() < deadline:
        if checkpoint_dir.is_dir() and len(list(checkpoint_dir.glob("chunk_*.bin"))) >= min_chunks:
            break
        if proc.poll() is not None:
            break
        time.sleep(0.01)
    proc.send_signal(sig)
    out, err = proc.communicate(timeout=timeout)
    return proc.returncode, err


def test_interrupted_then_resumed_equals_uninterrupted(small_study, tmp_path):
    # Long records so the run lasts long enough to be interrupted mid-way; a machine fast enough to
    # finish before the signal lands gets longer records (no bound on timing is asserted).
    for duration in (512, 2048, 8192):
        study = small_study(realisations=48, chunk=2, duration=duration)
        out = tmp_path / f"int-{duration}.h5"
        ckpt = tmp_path / f"int-{duration}.h5.checkpoint"
        code, err = interrupt_after_chunks([BIN, "run", str(study), "--out", str(out)], ckpt, signal.SIGINT)
        if code != 0:
            break
    assert code == EX_INTERRUPTED, err
    assert "--resume" in err
    assert not out.exists(), "an interrupted run must not leave a result file"
    done = len(list(ckpt.glob("chunk_*.bin")))
    assert done >= 2  # the signal came after two checkpointed chunks
    r = run(["run", study, "--out", out, "--resume"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        assert f["/run"].attrs["realisations_computed"] == 48 - 2 * done
    ref = tmp_path / "ref.h5"
    assert run(["run", study, "--out", ref, "--quiet"]).returncode == 0
    assert_bitwise_equal(ref, out)


def test_sigkill_loses_only_chunks_in_flight(small_study, tmp_path):
    study = small_study(realisations=48, chunk=2, duration=512)
    ref = tmp_path / "ref.h5"
    assert run(["run", study, "--out", ref, "--quiet"], env={"OMP_NUM_THREADS": "2"}).returncode == 0
    out = tmp_path / "killed.h5"
    ckpt = tmp_path / "killed.h5.checkpoint"
    code, _ = interrupt_after_chunks([BIN, "run", str(study), "--out", str(out), "--quiet"], ckpt, signal.SIGKILL, 3)
    assert code == -signal.SIGKILL
    assert not out.exists()
    r = run(["run", study, "--out", out, "--resume", "--quiet"], env={"OMP_NUM_THREADS": "1"})
    assert r.returncode == 0, r.stderr
    assert_bitwise_equal(ref, out)


def test_resume_refuses_checkpoints_of_another_study(small_study, tmp_path):
    study = small_study(realisations=48, chunk=2, duration=512)
    out = tmp_path / "x.h5"
    ckpt = tmp_path / "x.h5.checkpoint"
    code, _ = interrupt_after_chunks([BIN, "run", str(study), "--out", str(out)], ckpt, signal.SIGINT)
    assert code == EX_INTERRUPTED
    r = run(["run", study, "--out", out, "--resume", "--set", "oscillator.mass=3"])
    assert r.returncode == 65 and "different study" in r.stderr
