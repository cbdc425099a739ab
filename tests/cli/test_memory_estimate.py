"""Issue "never lose a user's data, part II": a memory estimate that holds. Every term that grows with
a study's keys is in `rollspec plan`'s estimate and stops `run` before any work; the ensemble keeps
no state that grows with the number of chunks (nor does --resume); --resume may drop an optional
output the checkpointed chunks do not depend on."""
import os
import re
import resource
import shutil
import signal
import subprocess
import time

import h5py

from conftest import (BIN, EX_CONFIG, EX_DATAERR, EX_INTERRUPTED, SMALL_OSCILLATOR, SOURCE, assert_bitwise_equal,
                      assert_refused, run)

UNITS = {"B": 1, "KiB": 1 << 10, "MiB": 1 << 20, "GiB": 1 << 30, "TiB": 1 << 40, "PiB": 1 << 50}
RIG = "seed002-rig-3ms.ini"


def copied(tmp_path, name):
    study = tmp_path / name
    shutil.copy(SOURCE / "studies" / name, study)
    return study


def estimate(study, *sets):
    """plan's estimated peak (bytes) and its line."""
    r = run(["plan", study, *[a for s in sets for a in ("--set", s)]])
    assert r.returncode == 0, r.stderr
    line = next(l for l in r.stdout.splitlines() if l.startswith("memory: estimated peak"))
    m = re.match(r"memory: estimated peak ([0-9.e+]+) (\w+)", line)
    return float(m.group(1)) * UNITS[m.group(2)], line


def sensors(n):
    return "sensors.positions=" + ",".join(f"{0.02 + 0.3 * i / n:.4f}" for i in range(n))


def test_linearised_reference_grows_with_sensor_pairs_and_can_be_dropped(tmp_path):
    study = copied(tmp_path, RIG)
    e10, _ = estimate(study, sensors(10))
    e80, line = estimate(study, sensors(80))
    off, _ = estimate(study, sensors(80), "output.reference=false")
    # 80 sensors: 3240 pairs against 55; the per-sensor records grow only 8-fold.
    assert e80 - off > 30 * (e10 - estimate(study, sensors(10), "output.reference=false")[0]) > 0
    assert "linearised reference" in line and "[output] reference = false skips it" in line, line


def limited(gib):
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (gib << 30, gib << 30))
    return limit


def test_a_reference_that_cannot_fit_is_refused_before_the_ensemble(tmp_path):
    study = copied(tmp_path, RIG)
    out = tmp_path / "r.h5"
    start = time.monotonic()
    r = subprocess.run([BIN, "run", study, "--out", out, "--quiet", "--set", sensors(400)], capture_output=True,
                       text=True, preexec_fn=limited(2), timeout=120)
    assert_refused(r, EX_CONFIG, ["needs an estimated", "linearised reference", "[sensors] positions", "--force"])
    assert time.monotonic() - start < 20 and not out.exists() and not (tmp_path / "r.h5.checkpoint").exists()


def test_path_table_grows_with_approaches_times_positions(tmp_path):
    study = copied(tmp_path, "seed002-rig-1ms.ini")
    # B45's positions (a/4): twice the cubic rule's, over a million table cells at 64 approaches.
    path = ["contact.law=path", "surface.spacing=4e-6", "texture.short_wavelength=8e-6", "path_table.interpolation=linear"]
    e8, _ = estimate(study, *path, "path_table.approaches=8")
    e64, line = estimate(study, *path, "path_table.approaches=64")
    m = re.search(r"path table, 64 approaches x (\d+) positions", line)
    assert m, line
    cells = 64 * int(m.group(1))
    # At least the force table itself, 8 bytes per cell, comes on top for the 56 extra approaches.
    assert e64 - e8 >= 8 * 56 * int(m.group(1)) and cells > 1_000_000, (e8, e64, line)


def test_rolling_beam_history_and_elements_are_estimated_and_refused_up_front(tmp_path):
    puck = copied(tmp_path, "seed000-puck.ini")
    small, _ = estimate(puck)
    fine, line = estimate(puck, "analysis.dt=1e-7", "analysis.record_every=1")
    assert fine > 2 * (1 << 30) and fine > 100 * small and "time history" in line, line
    beam = copied(tmp_path, "seed000-cantilever.ini")
    e20, _ = estimate(beam, "beam.elements=20")
    e1e5, line = estimate(beam, "beam.elements=100000")
    assert e1e5 > 5 * (1 << 30) and e1e5 > 50 * e20, line
    for study, sets, key in ((puck, ["analysis.dt=1e-7", "analysis.record_every=1"], "[analysis] dt = 1e-07"),
                             (beam, ["beam.elements=100000"], "[beam] elements = 100000")):
        start = time.monotonic()
        out = tmp_path / "rb.h5"
        r = subprocess.run([BIN, "run", study, "--out", out, "--quiet", *[a for s in sets for a in ("--set", s)]],
                           capture_output=True, text=True, preexec_fn=limited(2), timeout=120)
        assert_refused(r, EX_CONFIG, ["needs an estimated", key, "is available"])
        assert time.monotonic() - start < 5 and not out.exists()


def peak_rss_of_run(args, env=None):
    """Peak resident memory (bytes) of one rollspec child, and its result."""
    full = dict(os.environ, OMP_NUM_THREADS="2", **(env or {}))
    p = subprocess.Popen([BIN, *map(str, args)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=full)
    _, status, usage = os.wait4(p.pid, 0)
    err = p.stderr.read().decode()
    return os.waitstatus_to_exitcode(status), usage.ru_maxrss * 1024, err


def interrupt_at_chunks(args, checkpoint, chunks, poll):
    """`rollspec ARGS` interrupted (SIGINT) once its checkpoint directory holds CHUNKS chunks (or it has ended,
    or 120 s have passed, polled every POLL s); it must exit EX_INTERRUPTED."""
    proc = subprocess.Popen([BIN, *map(str, args)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while time.time() < deadline and proc.poll() is None:
        if checkpoint.is_dir() and len(list(checkpoint.glob("chunk_*.bin"))) >= chunks:
            break
        time.sleep(poll)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == EX_INTERRUPTED, err


def big_values_study(tmp_path, realisations, name):
    # 16384-sample segments: about 33,000 values per realisation, 0.26 MB of sums per chunk of 1.
    p = tmp_path / name
    text = SMALL_OSCILLATOR.format(realisations=realisations, chunk=1, duration=16).replace("segment = 1024",
                                                                                            "segment = 16384")
    p.write_text(text)
    return p


def test_memory_stays_flat_with_the_number_of_chunks_and_on_resume(tmp_path):
    few = big_values_study(tmp_path, 32, "few.ini")
    code, rss_few, err = peak_rss_of_run(["run", few, "--out", tmp_path / "few.h5", "--quiet"])
    assert code == 0, err
    many = big_values_study(tmp_path, 1024, "many.ini")
    code, rss_many, err = peak_rss_of_run(["run", many, "--out", tmp_path / "many.h5", "--quiet"])
    assert code == 0, err
    # Keeping every chunk's sums would add 1024 x 0.26 MB = 270 MB.
    assert rss_many < rss_few + (40 << 20), (rss_few, rss_many)
    # The plan's estimate holds within a factor 2.
    est, _ = estimate(many)
    assert 0.5 < est / rss_many < 2, (est, rss_many)
    # --resume over ~800 checkpointed chunks reads them one at a time, and gives the same bits.
    out = tmp_path / "resumed.h5"
    interrupt_at_chunks(["run", many, "--out", out, "--quiet"], tmp_path / "resumed.h5.checkpoint", 800, poll=0.02)
    code, rss_resume, err = peak_rss_of_run(["run", many, "--out", out, "--resume", "--quiet"])
    assert code == 0, err
    assert rss_resume < rss_few + (40 << 20), (rss_few, rss_resume)
    with h5py.File(out) as a:
        assert a["/run"].attrs["realisations_computed"] < 1024 - 700
    assert_bitwise_equal(tmp_path / "many.h5", out)


def interrupted_rig(tmp_path, *sets):
    study = copied(tmp_path, RIG)
    out = tmp_path / "rig.h5"
    args = [a for s in ("study.realisations=400", "ensemble.chunk_size=2", *sets) for a in ("--set", s)]
    interrupt_at_chunks(["run", study, "--out", out, "--quiet", *args], tmp_path / "rig.h5.checkpoint", 3, poll=0.01)
    return study, out


def test_resume_may_drop_the_reference_but_not_change_what_the_chunks_hold(tmp_path):
    study, out = interrupted_rig(tmp_path)
    r = run(["run", study, "--out", out, "--resume", "--quiet", "--set", "spectrum.segment=512"])
    assert_refused(r, EX_DATAERR, ["[spectrum] segment", "the checkpointed chunks were computed with these values",
                                   "[output] reference"])
    r = run(["run", study, "--out", out, "--resume", "--quiet", "--set", "output.reference=false"])
    assert r.returncode == 0, r.stderr
    ref = tmp_path / "ref.h5"
    r = run(["run", study, "--out", ref, "--quiet", "--set", "study.realisations=400", "--set", "ensemble.chunk_size=2",
             "--set", "output.reference=false"])
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as a:
        assert "reference" not in a
        assert a["/run"].attrs["realisations_computed"] < 400
    assert_bitwise_equal(ref, out)


def test_table_jackknife_holds_its_sub_tables_scenes_and_the_estimate_says_so(tmp_path):
    # [stiffness] table_error = jackknife runs the N sub-tables' scenes in one ensemble (kernels/spectral D-30c):
    # N more scenes' time records and chunk sums alive at once. A small table (6 surfaces of 128^2) keeps it quick.
    study = SOURCE / "studies" / "seed001-beam-r.ini"
    small = ["stiffness.realisations=6", "surface.nx=128", "surface.ny=128", "study.realisations=8",
             f"stiffness.table_dir={tmp_path}"]
    plain, _ = estimate(study, *small)
    jack, line = estimate(study, *small, "stiffness.table_error=jackknife")
    assert "the sub-tables' scenes" in line and "[stiffness] table_error = jackknife" in line, line
    assert jack > 1.5 * plain, (plain, jack)
    sets = [a for s in small for a in ("--set", s)]
    code, rss, err = peak_rss_of_run(["run", study, "--out", tmp_path / "jk.h5", "--quiet", *sets,
                                      "--set", "stiffness.table_error=jackknife"])
    assert code == 0, err
    assert 0.5 < jack / rss < 2, (jack, rss)
