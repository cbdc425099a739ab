"""rollspec_post.run runs a study in this process through rollspec.studies.run when the module imports (and
ROLLSPEC_BIN names no binary), else through the command: both write the same file bits, and a refused study
or output is the same PostError (message and exit code) either way, and no user's file changes."""
import os
import subprocess

import h5py
import pytest

from rollspec_post import notebook
from rollspec_post.post_error import PostError

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
STUDY = os.path.join(os.path.dirname(__file__), "..", "..", "studies", "random-oscillator.ini")
SETS = {"signal.duration": 4, "signal.sample_rate": 1024, "spectrum.segment": 2048, "study.realisations": 24}
DATA = ["/psd/mean", "/psd/frequency", "/bands/level_db", "/bands/ci_lower_db", "/bands/ci_upper_db", "/bands/std"]


def no_command(*args, **kwargs):
    raise AssertionError(f"the command ran: {args}")


def test_in_process_and_command_give_the_same_bits_and_errors(tmp_path, monkeypatch):
    monkeypatch.setenv("ROLLSPEC_BIN", ROLLSPEC)
    assert notebook.in_process() is None
    by_command = notebook.run(STUDY, tmp_path / "command.h5", set=SETS)
    with pytest.raises(PostError) as command_error:
        notebook.run(STUDY, tmp_path / "bad.h5", set={**SETS, "oscillator.mass": -1})
    monkeypatch.delenv("ROLLSPEC_BIN")
    assert notebook.in_process() is not None
    monkeypatch.setattr(subprocess, "run", no_command)
    in_process = notebook.run(STUDY, tmp_path / "module.h5", set=SETS)
    with pytest.raises(PostError) as module_error:
        notebook.run(STUDY, tmp_path / "bad.h5", set={**SETS, "oscillator.mass": -1})
    assert (str(module_error.value), module_error.value.exit_code) == \
        (str(command_error.value), command_error.value.exit_code)
    assert command_error.value.exit_code == 78 and "mass" in str(command_error.value)
    assert sorted(in_process) == sorted(by_command)
    with h5py.File(tmp_path / "command.h5") as a, h5py.File(tmp_path / "module.h5") as b:
        for name in DATA:
            assert a[name][()].tobytes() == b[name][()].tobytes(), name
    assert in_process["psd"]["mean"].values.tobytes() == by_command["psd"]["mean"].values.tobytes()


@pytest.mark.parametrize("target", ["fifo", "directory", "the study", "a user's file", "symlink loop", "device",
                                    "missing directory"])
def test_a_refused_output_is_the_commands_post_error_in_process(tmp_path, monkeypatch, target):
    study = tmp_path / "s.ini"
    study.write_bytes(open(STUDY, "rb").read())
    user = tmp_path / "user.txt"
    user.write_text("a user's notes\n")
    out = {"fifo": tmp_path / "fifo", "directory": tmp_path / "dir", "the study": study, "a user's file": user,
           "symlink loop": tmp_path / "loop", "device": "/dev/null",
           "missing directory": tmp_path / "no-such" / "r.h5"}[target]
    if target == "fifo":
        os.mkfifo(out)
    elif target == "directory":
        out.mkdir()
    elif target == "symlink loop":
        out.symlink_to(out)
    errors = []
    for binary in (ROLLSPEC, None):
        if binary:
            monkeypatch.setenv("ROLLSPEC_BIN", binary)
        else:
            monkeypatch.delenv("ROLLSPEC_BIN")
            monkeypatch.setattr(subprocess, "run", no_command)
        with pytest.raises(PostError) as e:
            notebook.run(study, out, set=SETS)
        errors.append((str(e.value), e.value.exit_code))
    assert errors[0] == errors[1] and errors[0][1] in (64, 73), errors
    assert user.read_text() == "a user's notes\n" and study.read_bytes() == open(STUDY, "rb").read()
