"""Never lose a user's data III, sweeps: a sweep is checked as a whole before any work. Its point count
is capped (--max-points overrides), a 10^6-point sweep is refused at once with a line saying so, every
point's memory is checked before the first runs, values are strict (no empty item, no hex, no value
twice, no key both swept and --set), and an interrupted sweep resumes with `run --resume --out X.h5`
alone, bit for bit, even after its study file is gone. Each test fails on the build before this work."""
import os
import signal
import subprocess
import time

import pytest

from conftest import (BIN, EX_CONFIG, EX_USAGE, SMALL_OSCILLATOR, SOURCE, assert_bitwise_equal, assert_refused,
                      oscillator_study, run)

RIG = SOURCE / "studies" / "seed002-rig-1ms.ini"


def values(n, start=1):
    return ",".join(str(start + i) for i in range(n))


def test_a_million_points_are_refused_at_once_naming_the_cap_and_its_override(tmp_path):
    study = oscillator_study(tmp_path)
    out = tmp_path / "big.h5"
    start = time.monotonic()
    r = run(["run", study, "--out", out, "--sweep", f"oscillator.mass={values(1000)}",
             "--sweep", f"oscillator.natural_frequency={values(1000, 10)}"], timeout=60)
    seconds = time.monotonic() - start
    assert_refused(r, EX_CONFIG, ["has 1e+06 points (crossed: 1000 oscillator.mass x 1000 oscillator.natural_frequency)",
                                  "more than 1000", "--max-points N"])
    assert seconds < 10, f"took {seconds:.1f} s to refuse"  # generous: the build before took over an hour
    assert not out.exists() and not (tmp_path / "big.h5.sweep").exists()


def test_a_large_sweep_says_what_it_will_do_before_its_checks(tmp_path):
    """With --max-points the first line comes before any point is checked (the build before was silent)."""
    study = oscillator_study(tmp_path)
    p = subprocess.Popen([BIN, "run", study, "--out", tmp_path / "s.h5", "--max-points", "2000000",
                          "--sweep", f"oscillator.mass={values(1000)}",
                          "--sweep", f"oscillator.natural_frequency={values(1000, 10)}"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        line = p.stdout.readline()
    finally:
        p.kill()
        p.communicate()
    assert line.startswith("sweep of ") and "1000000 points (crossed), each one run of the study" in line, line
    assert "before the first point runs" in line


def test_every_point_memory_is_checked_before_the_first_point_runs(tmp_path):
    out = tmp_path / "rig.h5"
    r = run(["run", RIG, "--out", out, "--quiet", "--sweep", "ball.speed=1,0.0001"], timeout=120)
    assert_refused(r, EX_CONFIG, ["sweep point 2 of 2 (ball.speed=0.0001)", "of memory"])
    assert not out.exists() and not (tmp_path / "rig.h5.sweep").exists(), "point 1 was computed first"


@pytest.mark.parametrize("sweep,fragment", [
    ("oscillator.mass=1,,3", "item 2 is empty"),
    ("oscillator.mass=1,2,", "item 3 is empty"),
    ("oscillator.mass=,1", "item 1 is empty"),
    ("oscillator.mass=0x10,2", "a hexadecimal number"),
    ("oscillator.mass=1,2,1.0", "the value 1.0 is given twice (first as 1)"),
    ("oscillator.mass=2,2e0", "the value 2e0 is given twice"),
])
def test_sweep_values_are_strict(tmp_path, sweep, fragment):
    r = run(["plan", oscillator_study(tmp_path), "--sweep", sweep])
    assert_refused(r, EX_CONFIG, [fragment])


def test_a_swept_key_cannot_also_be_set(tmp_path):
    r = run(["plan", oscillator_study(tmp_path), "--sweep", "oscillator.mass=1,2", "--set", "oscillator.mass=3"])
    assert_refused(r, EX_USAGE, ["oscillator.mass is also given by --set oscillator.mass=3", "one of the two"])


def test_hex_is_refused_in_a_study_and_a_seed_above_9e18_exactly(tmp_path):
    study = oscillator_study(tmp_path)
    assert_refused(run(["plan", study, "--set", "oscillator.mass=0x2"]), EX_CONFIG, ["a hexadecimal number"])
    # 9000000000000000001 rounds to 9e18 as a double: the bound is compared exactly
    r = run(["run", study, "--out", tmp_path / "r.h5", "--set", "study.seed=9000000000000000001"])
    assert_refused(r, EX_CONFIG, ["[study] seed = 9000000000000000001: out of range", "[0, 9e+18]"])
    assert run(["plan", study, "--set", "study.seed=9000000000000000000"]).returncode == 0


def interrupted_sweep(tmp_path, name="s.ini"):
    """A 3-point sweep stopped (SIGINT) inside point 2 after a checkpointed chunk."""
    study = tmp_path / name
    out = tmp_path / "s.h5"
    for duration in (64, 256, 1024):
        study.write_text(SMALL_OSCILLATOR.format(realisations=32, chunk=2, duration=duration) +
                         "\n[sweep]\noscillator.mass = 1, 2.5, 4\n")
        proc = subprocess.Popen([BIN, "run", study, "--out", out, "--quiet"], stderr=subprocess.PIPE, text=True,
                                env={**os.environ, "OMP_NUM_THREADS": "1"})
        deadline = time.time() + 60
        while time.time() < deadline and proc.poll() is None:
            if list((tmp_path / "s.h5.sweep" / "point_0001.h5.checkpoint").glob("chunk_*.bin")):
                break
            time.sleep(0.01)
        proc.send_signal(signal.SIGINT)
        proc.communicate(timeout=60)
        if proc.returncode == 130:
            return study, out
        for p in tmp_path.glob("s.h5*"):
            subprocess.run(["rm", "-rf", str(p)])
    pytest.fail("the sweep finished before the signal")


@pytest.mark.parametrize("how", ["--resume --out alone", "the study file deleted"])
def test_an_interrupted_sweep_resumes_from_its_out_alone(tmp_path, how):
    study, out = interrupted_sweep(tmp_path)
    kept = tmp_path / "kept.ini"
    kept.write_text(study.read_text())
    study.unlink()
    args = ["run", "--resume", "--out", out] if how == "--resume --out alone" else ["run", study, "--resume", "--out", out]
    r = run(args, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "finished before: kept" in r.stdout and "wrote" in r.stdout
    assert not (tmp_path / "s.h5.sweep").exists()
    ref = tmp_path / "ref.h5"
    assert run(["run", kept, "--out", ref, "--quiet"]).returncode == 0
    assert_bitwise_equal(out, ref)


def test_resume_out_alone_without_an_interrupted_run_says_so(tmp_path):
    r = run(["run", "--resume", "--out", tmp_path / "none.h5"])
    assert_refused(r, 66, ["holds no checkpoint to resume"])
