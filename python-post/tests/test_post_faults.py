"""Generated fault suite ("Never lose a user's data, part II"): every rollspec-post subcommand that
writes a file (enumerated from build_parser, so a new one is covered) x each output kind it writes x each
hostile --out target; then hostile inputs, arguments, a Python without a module, and a full disk.
Each case: the exit code, exactly one stderr line on failure and no traceback, user data byte-identical,
no temporary left, no hang (timeout). `pytest -s` prints the totals (test_totals, last in the file)."""
import argparse
import collections
import glob
import os
import subprocess
import sys

import numpy as np
import pytest

import forked_run
from conftest import SOURCE
from post_samples import (PRIMARY, command_args, copy, marked_output, snapshot, write_measurement, write_primary,
                          write_result)
from rollspec_post.__main__ import REQUIRED, build_parser
from rollspec_post.safe_output import has_marker

TIMEOUT = 60
ROOT = os.geteuid() == 0
TOTALS = collections.Counter()


def writers():
    """(command, [kinds]) of every subcommand with --out, from the parser itself."""
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    for name, p in sub.choices.items():
        if any("--out" in a.option_strings for a in p._actions):
            types = p.get_default("out_types")
            yield name, [t[1:] for t in types] if types else ["html"]


WRITERS = list(writers())
forked_run.preload()


def reads_measurement(command):
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    return any("--measurement" in a.option_strings for a in sub.choices[command]._actions)


# target -> exit codes allowed (a function of the command where it depends on it)
TARGETS = {
    "user_data": {73}, "user_data_force": {0}, "rollspec_result_file": {73}, "post_output_other_kind": {73},
    "symlink_to_user_data": {73}, "same_kind": {0}, "symlink_to_same_kind": {0}, "own_input": {64},
    "symlink_to_own_input": {64}, "hardlink_to_own_input": {64}, "own_input_force": {64},
    "symlink_loop": {73}, "dangling_symlink": {0},  # a link to a file still to be made: made, the link kept
    "measurement_file": lambda c: {64} if reads_measurement(c) else {73},
    "fifo": {73}, "symlink_to_dev_null": {73}, "dev_null": {64, 73},  # /dev/null has no picture extension: 64
    "directory": {73}, "no_such_directory": {73}, "read_only_directory": {0} if ROOT else {73},
}
CASES = [(c, k, t) for c, kinds in WRITERS for k in kinds for t in TARGETS]


def run_post(args, timeout=TIMEOUT, env=None, python=()):
    """rollspec-post as a command (in a fork of this process with its modules imported, forked_run.py, or,
    for another environment or interpreter option, a new interpreter); a hang fails the test (and is counted)."""
    try:
        if env is None and not python and forked_run.forking():
            return forked_run.run(args, timeout)
        env = env or dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"))
        return subprocess.run([sys.executable, *python, "-m", "rollspec_post", *map(str, args)], capture_output=True,
                              text=True,
                              env=env, timeout=timeout, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        TOTALS["tried"] += 1
        TOTALS["hangs"] += 1
        pytest.fail(f"rollspec-post {' '.join(map(str, args))}: no answer within {timeout} s")


def temporaries(directory):
    return glob.glob(os.path.join(glob.escape(str(directory)), "**", ".*.tmp-*"), recursive=True)


def record(r, allowed, before, after, leftovers):
    """Counts the case, then asserts on it: the counts hold even when an assertion fails."""
    TOTALS["tried"] += 1
    traceback = "Traceback" in r.stderr
    destroyed = before != after
    lines = r.stderr.strip().splitlines()
    TOTALS["tracebacks"] += traceback
    TOTALS["last-resort messages"] += "internal error" in r.stderr
    TOTALS["destroyed"] += destroyed
    if r.returncode == 0:
        TOTALS["accepted"] += 1
    elif len(lines) == 1 and not traceback and not destroyed and not leftovers:
        TOTALS["refused cleanly"] += 1
    else:
        TOTALS["refused, not cleanly"] += 1
    assert not traceback, r.stderr
    assert "internal error" not in r.stderr, r.stderr  # a hostile case deserves its own message
    assert not destroyed, f"changed: {[p for p in before if before[p] != after.get(p)]}"
    assert not leftovers, leftovers
    assert r.returncode in allowed, (r.returncode, r.stderr)
    assert len(lines) == (0 if r.returncode == 0 else 1), r.stderr


@pytest.fixture(scope="module")
def samples(tmp_path_factory):
    """Valid inputs of every subcommand, a measurement, a result file of another kind, a marked output per kind."""
    d = tmp_path_factory.mktemp("samples")
    s = {c: write_primary(c, d) for c in PRIMARY}
    s["measurement"] = write_measurement(d / "measurement.csv")
    s["result"] = write_result(d / "other-result.h5")
    s["marked"] = {k: marked_output(k) for k in ("png", "pdf", "svg", "html")}
    return s


def other_kind(kind):
    return "html" if kind != "html" else "png"


def make_target(name, d, kind, inputs, samples):
    """(out, files that must stay as they are, extra arguments) for one hostile target."""
    user = d / "user" / "notes.txt"
    user.parent.mkdir()
    user.write_text("precious user data\n")
    out, keep, extra = d / f"out.{kind}", [user], []
    if name in ("user_data", "user_data_force"):
        copy(user, out)
        keep, extra = ([user] if name == "user_data_force" else [user, out]), (["--force"] if "force" in name else [])
    elif name == "rollspec_result_file":
        keep.append(copy(samples["result"], out))
    elif name == "post_output_other_kind":
        out.write_bytes(samples["marked"][other_kind(kind)])
        keep.append(out)
    elif name == "symlink_to_user_data":
        out.symlink_to(user)
        keep.append(out)
    elif name == "same_kind":
        out.write_bytes(samples["marked"][kind])
    elif name == "symlink_to_same_kind":
        (d / "user" / f"fig.{kind}").write_bytes(samples["marked"][kind])
        out.symlink_to(d / "user" / f"fig.{kind}")
        keep = [user, out]  # the link itself stays; its target is replaced
    elif name in ("own_input", "own_input_force"):
        out, extra = inputs[0], (["--force"] if "force" in name else [])
    elif name == "symlink_to_own_input":
        out.symlink_to(inputs[0])
        keep.append(out)
    elif name == "hardlink_to_own_input":
        os.link(inputs[0], out)
        keep.append(out)
    elif name == "symlink_loop":
        out.symlink_to(out)
        keep.append(out)
    elif name == "dangling_symlink":
        out.symlink_to(d / "user" / f"new.{kind}")
        keep.append(out)
    elif name == "measurement_file":
        out = copy(samples["measurement"], d / f"measurement.{kind}") if len(inputs) < 2 else inputs[1]
        keep.append(out)
    elif name == "fifo":
        os.mkfifo(out)
        keep.append(out)
    elif name == "symlink_to_dev_null":
        out.symlink_to("/dev/null")
        keep.append(out)
    elif name == "dev_null":
        out = "/dev/null"
    elif name == "directory":
        out.mkdir()
        (out / "inside.txt").write_text("kept\n")
        keep += [out, out / "inside.txt"]
    elif name == "no_such_directory":
        out = d / "missing" / f"out.{kind}"
        keep.append(d / "missing")
    elif name == "read_only_directory":
        (d / "ro").mkdir()
        out = d / "ro" / f"out.{kind}"
        os.chmod(d / "ro", 0o555)
    return out, keep + list(inputs), extra


def inputs_for(command, d, samples, kind):
    """Copies of the inputs, named like the output (input.png): --out = input must meet the input check."""
    primary = copy(samples[command], d / f"input.{kind}")
    if reads_measurement(command):
        return [primary, copy(samples["measurement"], d / f"measurement.{kind}")]
    return [primary]


@pytest.mark.parametrize("command,kind,target", CASES, ids=[f"{c}-{k}-{t}" for c, k, t in CASES])
def test_hostile_output(command, kind, target, samples, tmp_path):
    inputs = inputs_for(command, tmp_path, samples, kind)
    out, keep, extra = make_target(target, tmp_path, kind, inputs, samples)
    args = [command, *command_args(command, inputs[0], inputs[-1]), "--out", out, *extra]
    before = snapshot(keep)
    r = run_post(args)
    after = snapshot(keep)
    allowed = TARGETS[target](command) if callable(TARGETS[target]) else TARGETS[target]
    try:
        record(r, allowed, before, after, temporaries(tmp_path))
        if r.returncode == 0:  # the output (or a link's target) was replaced by a marked file of the kind
            assert has_marker(os.path.realpath(out), kind), r.stdout
        if allowed == {64}:
            assert "input" in r.stderr, r.stderr
    finally:
        if target == "read_only_directory":
            os.chmod(tmp_path / "ro", 0o755)


def test_stale_temporary_of_a_killed_run_is_removed(samples, tmp_path):
    dead = subprocess.Popen(["true"])  # its PID is free once it is reaped
    dead.wait()
    stale = tmp_path / f".out.png.tmp-{dead.pid}-abcd1234"
    stale.write_bytes(b"half a picture")
    r = run_post(["psd", samples["psd"], "--out", tmp_path / "out.png"])
    record(r, {0}, {}, {}, [])
    assert not stale.exists() and has_marker(tmp_path / "out.png", "png")


def test_terminated_run_leaves_the_old_output(samples, tmp_path):
    """SIGTERM while drawing: exit 130 with one line (or 0 if it was done), old output or new, no temporary."""
    import signal
    import time
    out = tmp_path / "out.png"
    out.write_bytes(samples["marked"]["png"])
    env = dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"))
    p = subprocess.Popen([sys.executable, "-m", "rollspec_post", "psd", str(samples["psd"]), "--bands", "--out", str(out)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    time.sleep(1.0)
    p.send_signal(signal.SIGTERM)
    stdout, stderr = p.communicate(timeout=TIMEOUT)
    assert has_marker(out, "png") and not temporaries(tmp_path)
    if p.returncode == -signal.SIGTERM:  # a loaded machine: still starting Python, before main(); nothing written
        return
    record(subprocess.CompletedProcess(p.args, p.returncode, stdout, stderr), {0, 130}, {}, {}, temporaries(tmp_path))


def test_closed_stdout_is_no_failure(samples, tmp_path):
    """`rollspec-post ... | head -0`: the file is written, exit 0, no BrokenPipeError."""
    env = dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"))
    cmd = f"{sys.executable} -m rollspec_post psd {samples['psd']} --out {tmp_path / 'out.png'} | true; exit ${{PIPESTATUS[0]}}"
    r = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, env=env, timeout=TIMEOUT)
    record(r, {0}, {}, {}, temporaries(tmp_path))
    assert has_marker(tmp_path / "out.png", "png")


def test_every_writer_has_samples_and_kinds():
    """A new subcommand with --out must say what it writes and have a sample input here."""
    assert WRITERS and all(kinds for _, kinds in WRITERS)
    assert sorted(c for c, _ in WRITERS) == sorted(PRIMARY)


INPUT_VARIANTS = ("fifo", "dev_zero", "directory", "empty", "truncated", "missing_item", "all_zero", "absent")
INPUT_CASES = [(c, v) for c, _ in WRITERS for v in INPUT_VARIANTS]


def hostile_input(command, variant, d):
    if variant in ("valid", "truncated", "missing_item", "all_zero"):
        return write_primary(command, d, variant)
    path = d / f"in-{variant}.h5"
    if variant == "fifo":
        os.mkfifo(path)
    elif variant == "dev_zero":
        return "/dev/zero"
    elif variant == "directory":
        path.mkdir()
    elif variant == "empty":
        path.write_bytes(b"")
    return path


@pytest.mark.parametrize("command,variant", INPUT_CASES, ids=[f"{c}-{v}" for c, v in INPUT_CASES])
def test_hostile_input(command, variant, samples, tmp_path):
    bad = hostile_input(command, variant, tmp_path)
    meas = copy(samples["measurement"], tmp_path / "measurement.csv")
    out = tmp_path / f"out.{dict(WRITERS)[command][0]}"
    keep = [bad, meas] if variant != "dev_zero" else [meas]
    before = snapshot(keep)
    r = run_post([command, *command_args(command, bad, meas), "--out", out])
    # all zero may draw; a truncated CSV may still be a valid shorter one
    csv = PRIMARY[command] == "bench"
    allowed = {0, 65} if variant == "all_zero" else {0, 65, 66} if (variant == "truncated" and csv) else {65, 66}
    record(r, allowed, before, snapshot(keep), temporaries(tmp_path))
    assert os.path.exists(out) == (r.returncode == 0)


def _replace(name, value):
    def edit(f):
        del f[name]
        f[name] = value(f) if callable(value) else value
    return edit


DEGENERATE = {  # edits of a valid result: each must give a clear error or a valid picture
    "nan_psd": _replace("/psd/mean", lambda f: np.full((2, 501), np.nan)),
    "negative_psd": _replace("/psd/mean", lambda f: -np.ones((2, 501))),
    "one_dimensional_psd": _replace("/psd/mean", lambda f: np.ones(501)),
    "no_sensors": _replace("/psd/sensor", lambda f: np.array([], dtype="S")),
    "empty_bands": _replace("/bands/nominal_frequency", lambda f: np.zeros(0)),
    "text_realisations": lambda f: f["/psd"].attrs.__setitem__("realisations", "many"),
    "group_for_a_dataset": lambda f: (f.__delitem__("/psd/mean"), f.create_group("/psd/mean")),
}


@pytest.mark.parametrize("command", ["psd", "report", "panels"])
@pytest.mark.parametrize("variant", sorted(DEGENERATE))
def test_degenerate_result(command, variant, samples, tmp_path):
    import h5py
    bad = copy(samples[command], tmp_path / "bad.h5")
    with h5py.File(bad, "a") as f:
        DEGENERATE[variant](f)
    out = tmp_path / ("out.html" if command == "report" else "out.png")
    r = run_post([command, *command_args(command, bad, samples["measurement"]), "--out", out])
    record(r, {0, 65}, {}, {}, temporaries(tmp_path))
    assert os.path.exists(out) == (r.returncode == 0)


def _soft_link_loop(f):
    del f["/psd/mean"]
    f["/psd/mean"] = h5py_module().SoftLink("/psd/mean_again")
    f["/psd/mean_again"] = h5py_module().SoftLink("/psd/mean")


def _bad_utf8(f):
    h5py = h5py_module()
    for obj, name in ((f["/psd/mean"], "units"), (f, "study")):
        if name in obj.attrs:
            del obj.attrs[name]
        obj.attrs.create(name, np.array(b"\xff\xfe", dtype=h5py.string_dtype("utf-8", 2)))


def h5py_module():
    import h5py
    return h5py


@pytest.mark.parametrize("command", ["psd", "report"])
@pytest.mark.parametrize("variant", ["soft link loop", "non-UTF-8 attributes"])
def test_damaged_hdf5_content_is_one_line(command, variant, samples, tmp_path):
    """A soft link that loops and attributes that are not UTF-8 were internal errors (exit 70)."""
    bad = copy(samples[command], tmp_path / "bad.h5")
    with h5py_module().File(bad, "a") as f:
        (_soft_link_loop if variant == "soft link loop" else _bad_utf8)(f)
    out = tmp_path / ("out.html" if command == "report" else "out.png")
    r = run_post([command, *command_args(command, bad, samples["measurement"]), "--out", out])
    record(r, {0, 65}, {}, {}, temporaries(tmp_path))
    assert os.path.exists(out) == (r.returncode == 0)


MEASUREMENT_VARIANTS = ("fifo", "dev_zero", "directory", "empty", "binary", "huge")


@pytest.mark.parametrize("command", [c for c, _ in WRITERS if reads_measurement(c)])
@pytest.mark.parametrize("variant", MEASUREMENT_VARIANTS)
def test_hostile_measurement(command, variant, samples, tmp_path):
    meas = tmp_path / "m.csv"
    if variant == "fifo":
        os.mkfifo(meas)
    elif variant == "dev_zero":
        meas = "/dev/zero"
    elif variant == "directory":
        meas.mkdir()
    elif variant == "empty":
        meas.write_bytes(b"")
    elif variant == "binary":
        meas.write_bytes(bytes(range(256)) * 16)
    elif variant == "huge":  # sparse: no disk used, but 5 GB to a reader that does not look first
        with open(meas, "wb") as fh:
            fh.truncate(5 * 2**30)
    out = tmp_path / f"out.{dict(WRITERS)[command][0]}"
    r = run_post([command, samples[command], "--measurement", meas, "--out", out])
    record(r, {65, 66}, {}, {}, temporaries(tmp_path))
    assert not os.path.exists(out)


O = ["--out", "OUT"]
BAD_ARGUMENTS = (["psd", "R", "--dpi", "0", *O], ["psd", "R", "--dpi", "nan", *O], ["psd", "R", "--dpi", "1e9", *O],
                 ["psd", "R", "--fmin", "500", "--fmax", "100", *O], ["psd", "R", "--fmax", "inf", *O],
                 ["psd", "R", "--fmin", "-1", *O], ["report", "R", "--fmax", "nan", *O], ["report", "R", "--fmin", "inf", *O],
                 ["report", "R", "--measured-averages", "0", *O], ["psd", "R", "--measured-averages", "nan", *O],
                 ["panels", "--panel", "A", "R=x", "--fmax", "0", *O], ["panels", "--panel", "A", *O],
                 ["panels", "--panel", "A", "noequals", *O], ["psd", "R", "--out", "OUT.jpg"], ["psd", "R", "--frobnicate", *O],
                 ["texture", "R", "--out", "OUT.pdf"], ["psd", "R"], ["psd", "R", "--out", ""], [], ["nosuchcommand"])


@pytest.mark.parametrize("argv", BAD_ARGUMENTS, ids=[" ".join(a) or "(none)" for a in BAD_ARGUMENTS])
def test_bad_arguments(argv, samples, tmp_path):
    subst = {"R": str(samples["psd"]), "R=x": f"{samples['psd']}=x", "OUT": str(tmp_path / "x.png"),
             "OUT.jpg": str(tmp_path / "x.jpg"), "OUT.pdf": str(tmp_path / "x.pdf")}
    r = run_post([subst.get(a, a) for a in argv])
    record(r, {64}, {}, {}, temporaries(tmp_path))
    assert not os.listdir(tmp_path)


def test_python_without_its_modules(samples, tmp_path):
    """python3 -S: no site-packages, so no numpy: one line naming it and the Debian package, exit 69."""
    r = run_post(["psd", samples["psd"], "--out", tmp_path / "x.png"], python=["-S"])
    record(r, {69}, {}, {}, [])
    assert "numpy" in r.stderr and "apt-get install python3-numpy" in r.stderr


@pytest.mark.parametrize("module,package", REQUIRED)
def test_missing_python_module(module, package, samples, tmp_path):
    """A module that fails to import: one line naming it and the Debian package, exit 69."""
    (tmp_path / f"{module}.py").write_text("raise ModuleNotFoundError(%r, name=%r)\n" % (f"No module named {module}", module))
    env = dict(os.environ, PYTHONPATH=f"{tmp_path}{os.pathsep}{SOURCE / 'python-post'}")
    r = run_post(["psd", samples["psd"], "--out", tmp_path / "x.png"], env=env)
    record(r, {69}, {}, {}, [])
    assert module in r.stderr and f"apt-get install {package}" in r.stderr
    assert not (tmp_path / "x.png").exists()


@pytest.fixture
def tiny_disk(tmp_path):
    """A 1 MiB tmpfs (root only); skipped where it cannot be mounted."""
    d = tmp_path / "disk"
    d.mkdir()
    if not ROOT or subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(d)],
                                  capture_output=True).returncode != 0:
        pytest.skip("cannot mount a tmpfs here (needs root)")
    yield d
    subprocess.run(["umount", str(d)], capture_output=True)


def test_full_disk_keeps_the_old_output(samples, tiny_disk):
    out = tiny_disk / "psd.png"
    r = run_post(["psd", samples["psd"], "--out", out])
    assert r.returncode == 0, r.stderr
    with open(tiny_disk / "filler", "wb", buffering=0) as fh:  # fill the disk to the last block
        try:
            while True:
                fh.write(b"\0" * 4096)
        except OSError:
            pass
    before = snapshot([out])
    r = run_post(["psd", samples["psd"], "--bands", "--out", out])
    record(r, {73, 74}, before, snapshot([out]), temporaries(tiny_disk))
    assert has_marker(out, "png")


FILETYPE_GROUPS = {"rollspec-result": "psd", "rollspec-texture": "texture", "rollspec-stiffness-table": "stiffness",
                   "rollspec-blocked-force": "blocked_force", "rollspec-path-table": "path_table",
                   "rollspec-equivalent-roughness": "equivalent_roughness"}


@pytest.mark.parametrize("filetype", sorted(FILETYPE_GROUPS))
def test_open_result_opens_every_engine_filetype(filetype, tmp_path):
    """Every filetype the engine writes (src: grep '"rollspec-'); the cached tables are schema 1.0."""
    import h5py
    import numpy as np
    from rollspec_post import open_result
    from rollspec_post.result_file import KNOWN_SCHEMA_MAJOR
    path = tmp_path / "f.h5"
    with h5py.File(path, "w") as f:
        f.attrs["filetype"], f.attrs["schema_version"] = filetype, f"{KNOWN_SCHEMA_MAJOR[filetype]}.0"
        f[f"/{FILETYPE_GROUPS[filetype]}/values"] = np.arange(4.0)
    ds = open_result(path)
    assert float(ds[FILETYPE_GROUPS[filetype]]["values"].sum()) == 6.0


def test_totals():
    """Last in the file: the counts of every case above (`pytest -s` shows them)."""
    t = TOTALS
    print(f"\nrollspec-post fault suite: tried {t['tried']}, refused cleanly {t['refused cleanly']}, accepted "
          f"{t['accepted']}, refused not cleanly {t['refused, not cleanly']}, destroyed {t['destroyed']}, "
          f"tracebacks {t['tracebacks']}, hangs {t['hangs']}, last-resort messages {t['last-resort messages']}")
    assert t["destroyed"] == t["tracebacks"] == t["hangs"] == t["refused, not cleanly"] == 0
    assert t["last-resort messages"] == 0
