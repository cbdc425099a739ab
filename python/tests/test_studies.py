"""rollspec.studies.run against `rollspec run` on the same study: the result data are the command's bit for
bit, on 1 and 2 threads; a bad key or a missing file raises the command's one-line message; Ctrl-C stops the
ensemble with KeyboardInterrupt, keeps the completed chunks, and resume=True finishes them with the bits of
an uninterrupted run."""
import os
import shutil
import subprocess

import h5py
import pytest

from rollspec import studies
from sigint_when import SigintWhen, has_chunk

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
# The random oscillator, short records: 2000 realisations take a fraction of a second.
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "ensemble.chunk_size=16"]
DATA = ["/psd/mean", "/psd/frequency", "/bands/level_db", "/bands/ci_lower_db", "/bands/ci_upper_db", "/bands/std"]


@pytest.fixture
def study(tmp_path):
    path = tmp_path / "oscillator.ini"
    shutil.copy(os.path.join(SOURCE, "studies", "random-oscillator.ini"), path)
    return path


def command(study, out, *sets):
    r = subprocess.run([ROLLSPEC, "run", str(study), "--out", str(out), "--quiet",
                        *[a for s in sets for a in ("--set", s)]], capture_output=True, text=True)
    return r


def same_data(a, b):
    with h5py.File(a) as fa, h5py.File(b) as fb:
        for name in DATA:
            x, y = fa[name][...], fb[name][...]
            assert x.shape == y.shape and x.tobytes() == y.tobytes(), name


def test_a_run_in_process_holds_the_commands_bits_on_any_thread_count(study, tmp_path):
    sets = FAST + ["study.realisations=200"]
    assert command(study, tmp_path / "command.h5", *sets).returncode == 0
    for threads in (1, 2):
        out = studies.run(study, tmp_path / f"module-{threads}.h5", set=sets, threads=threads)
        assert out == str(tmp_path / f"module-{threads}.h5")
        same_data(tmp_path / "command.h5", out)


def test_the_default_output_is_the_commands(study, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert studies.run(study, set=FAST + ["study.realisations=8"]) == "oscillator.h5"
    assert (tmp_path / "oscillator.h5").is_file()


def test_errors_are_the_commands_line(study, tmp_path):
    bad = FAST + ["oscillator.mass=-1"]
    r = command(study, tmp_path / "c.h5", *bad)
    prefix = "rollspec run: error: "
    assert r.returncode == 78 and r.stderr.startswith(prefix), r.stderr
    with pytest.raises(ValueError) as e:
        studies.run(study, tmp_path / "m.h5", set=bad)
    assert str(e.value) == r.stderr.strip().splitlines()[-1][len(prefix):]
    with pytest.raises(OSError, match="no-such.ini"):
        studies.run(tmp_path / "no-such.ini", tmp_path / "m.h5")
    with pytest.raises(ValueError, match="threads = 0: fewer than one"):
        studies.run(study, tmp_path / "m.h5", threads=0)
    assert not (tmp_path / "m.h5").exists()


def test_ctrl_c_keeps_the_chunks_and_resume_gives_the_same_bits(study, tmp_path):
    sets = FAST + ["study.realisations=20000"]
    out = tmp_path / "m.h5"
    checkpoint = tmp_path / "m.h5.checkpoint"

    watcher = SigintWhen(lambda: has_chunk(checkpoint))
    with pytest.raises(KeyboardInterrupt, match="resume=True"):
        studies.run(study, out, set=sets, threads=2)
    watcher.join()
    assert not out.exists() and checkpoint.is_dir()
    assert studies.run(study, out, set=sets, resume=True, threads=1) == str(out)
    assert not checkpoint.exists()
    assert command(study, tmp_path / "whole.h5", *sets).returncode == 0
    same_data(tmp_path / "whole.h5", out)
    # The process stays usable: the next run is not stopped by the interrupt before it.
    studies.run(study, tmp_path / "next.h5", set=FAST + ["study.realisations=8"])
