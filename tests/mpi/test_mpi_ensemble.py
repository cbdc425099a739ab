"""MPI ensembles: 2 ranks give the bits of 1 process (and of the non-MPI build), and a run
interrupted in one layout resumes in another with the same bits."""
import os
import pathlib
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "cli"))
from conftest import SMALL_OSCILLATOR, assert_bitwise_equal  # noqa: E402

BIN = os.environ["ROLLSPEC_BIN"]
MPIRUN = os.environ.get("MPIRUN", "mpirun")
REFERENCE = os.environ.get("ROLLSPEC_REFERENCE_BIN", "")


def run(cmd, **kw):
    env = dict(os.environ, OMP_NUM_THREADS=kw.pop("threads", "1"))
    return subprocess.run([str(c) for c in cmd], capture_output=True, text=True, env=env, **kw)


def mpi(n, *args, **kw):
    return run([MPIRUN, "-np", str(n), "--oversubscribe", BIN, *args], **kw)


def study(tmp_path, realisations=37, chunk=4, duration=16):
    p = tmp_path / "s.ini"
    p.write_text(SMALL_OSCILLATOR.format(realisations=realisations, chunk=chunk, duration=duration))
    return p


def test_two_ranks_equal_one_process_bitwise(tmp_path):
    s = study(tmp_path)
    one = tmp_path / "one.h5"
    two = tmp_path / "two.h5"
    r = run([BIN, "run", s, "--out", one, "--quiet"], threads="2")
    assert r.returncode == 0, r.stderr
    r = mpi(2, "run", s, "--out", two)
    assert r.returncode == 0, r.stderr
    assert "[rank 1/2]" in r.stderr and "[rank 0/2]" in r.stderr, "logs carry the rank"
    assert_bitwise_equal(one, two)
    # The non-MPI build must give the same bits: never skipped silently.
    assert REFERENCE and pathlib.Path(REFERENCE).exists(), \
        f"no non-MPI reference binary at ROLLSPEC_REFERENCE_BIN={REFERENCE!r} (configure with -DROLLSPEC_REFERENCE_BIN=...)"
    ref = tmp_path / "ref.h5"
    assert run([REFERENCE, "run", s, "--out", ref, "--quiet"]).returncode == 0
    assert_bitwise_equal(ref, two)


def test_interrupted_single_process_resumes_on_two_ranks(tmp_path):
    s = study(tmp_path, realisations=48, chunk=2, duration=512)
    ref = tmp_path / "ref.h5"
    assert run([BIN, "run", s, "--out", ref, "--quiet"]).returncode == 0
    out = tmp_path / "x.h5"
    ckpt = tmp_path / "x.h5.checkpoint"
    proc = subprocess.Popen([BIN, "run", str(s), "--out", str(out), "--quiet"], stderr=subprocess.PIPE, text=True,
                            env=dict(os.environ, OMP_NUM_THREADS="1"))
    deadline = time.time() + 60
    while time.time() < deadline and not (ckpt.is_dir() and len(list(ckpt.glob("chunk_*.bin"))) >= 3):
        time.sleep(0.01)
    proc.send_signal(signal.SIGINT)
    proc.communicate(timeout=60)
    assert proc.returncode == 130 and not out.exists()
    r = mpi(2, "run", s, "--out", out, "--resume", "--quiet")
    assert r.returncode == 0, r.stderr
    assert_bitwise_equal(ref, out)


def test_bad_study_fails_on_every_rank_without_hanging(tmp_path):
    s = study(tmp_path)
    r = mpi(2, "run", s, "--out", tmp_path / "r.h5", "--set", "oscillator.mass=-1", timeout=60)
    assert r.returncode != 0 and "mass = -1" in r.stderr
    assert not (tmp_path / "r.h5").exists()


def test_stiffness_table_realisations_over_two_ranks_are_bitwise_equal(tmp_path):
    import h5py
    study = pathlib.Path(os.environ.get("ROLLSPEC_SOURCE", ".")) / "studies" / "seed002-table.ini"
    small = ["--quiet", "--set", "surface.nx=64", "--set", "surface.ny=64", "--set", "stiffness.realisations=5",
             "--set", "stiffness.steps=6"]
    one, two = tmp_path / "one.h5", tmp_path / "two.h5"
    r = run([BIN, "stiffness", study, "--out", one, *small], threads="2")
    assert r.returncode == 0, r.stderr
    r = mpi(2, "stiffness", study, "--out", two, *small)
    assert r.returncode == 0, r.stderr
    assert r.stdout.count("at the ball's weight") == 1, "only rank 0 reports"
    with h5py.File(one) as a, h5py.File(two) as b:
        for name in ("force_mean", "force_std", "stiffness_mean", "stiffness_std", "contact_area_mean"):
            assert a["/stiffness/" + name][:].tobytes() == b["/stiffness/" + name][:].tobytes()


def test_single_run_is_computed_and_written_once(tmp_path):
    """A deterministic single run (scene rolling-beam) has no ensemble to share: rank 0 alone
    computes and writes it; the other ranks validate the study and stop."""
    study = pathlib.Path(os.environ.get("ROLLSPEC_SOURCE", ".")) / "studies" / "seed000-disc.ini"
    one, two = tmp_path / "one.h5", tmp_path / "two.h5"
    r = run([BIN, "run", study, "--out", one])
    assert r.returncode == 0, r.stderr
    r = mpi(2, "run", study, "--out", two, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stderr.count("rolling-beam:") == 1, f"computed on more than one rank:\n{r.stderr}"
    assert r.stdout.count("wrote ") == 1, f"written by more than one rank:\n{r.stdout}"
    assert_bitwise_equal(one, two)


def test_two_rank_sweep_equals_one_process_bitwise(tmp_path):
    """A sweep's points each run on every rank; rank 0 alone stacks them and removes the work directory."""
    s = study(tmp_path, realisations=13, chunk=2, duration=4)
    sweep = ["--sweep", "oscillator.mass=1,2.5", "--sweep", "oscillator.natural_frequency=30,45"]
    one, two = tmp_path / "one.h5", tmp_path / "two.h5"
    r = run([BIN, "run", s, "--out", one, "--quiet", *sweep], threads="2")
    assert r.returncode == 0, r.stderr
    r = mpi(2, "run", s, "--out", two, *sweep, timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.count(f"wrote {two} (sweep") == 1, f"written by more than one rank:\n{r.stdout}"
    assert r.stdout.count("sweep point 1 of 4") == 1, f"the points are announced once:\n{r.stdout}"
    assert not (tmp_path / "two.h5.sweep").exists(), "the work directory is removed after the merge"
    assert_bitwise_equal(one, two)


def test_table_jackknife_over_two_ranks_equals_one_process_bitwise(tmp_path):
    # [stiffness] table_error = jackknife (kernels/spectral D-30): the sub-tables' combined ensemble and its
    # paired noise (D-30c) are summed on rank 0 from every rank's chunks, the same bits as one process.
    study = pathlib.Path(os.environ.get("ROLLSPEC_SOURCE", ".")) / "studies" / "seed001-beam-r.ini"
    small = [a for s in ("stiffness.realisations=3", "surface.nx=128", "surface.ny=128", "study.realisations=12",
                         "ensemble.chunk_size=2", "stiffness.table_error=jackknife",
                         f"stiffness.table_dir={tmp_path / 'tables'}") for a in ("--set", s)]
    (tmp_path / "tables").mkdir()
    one, two = tmp_path / "one.h5", tmp_path / "two.h5"
    r = run([BIN, "run", study, "--out", one, "--quiet", *small], threads="2")
    assert r.returncode == 0, r.stderr
    r = mpi(2, "run", study, "--out", two, "--quiet", *small)
    assert r.returncode == 0, r.stderr
    assert_bitwise_equal(one, two)
