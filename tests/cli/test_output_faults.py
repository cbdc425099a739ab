"""Generated fault suite: every rollspec command that writes a file, against every hostile target.

The commands come from `rollspec --help` and each command's own `--help` (an `--out` option), so a
new command that writes a file fails `test_every_writing_command_is_covered` until it has a recipe
here. Each (command, output) meets each target below; the suite checks the exit code, a one-line
message without "internal error", the user's data byte-identical, no temporary file left and no
hang, and the last test prints the totals: tried / refused cleanly / accepted / destroyed /
internal errors / hangs.

Sweeps (`run --sweep`, a [sweep] study) meet every target too, and so does their work directory
OUT.sweep; a sweep interrupted (SIGINT) or killed (SIGKILL) and resumed writes the uninterrupted
file bit for bit. `fit` writes no --out: its temporary directory under $TMPDIR meets the targets.

Label `fault`: an 8 MiB tmpfs (root) gives the full-disk cases."""
import os
import re
import shutil
import stat
import signal
import subprocess
import time

import pytest

from conftest import BIN, SMALL_OSCILLATOR, SOURCE, assert_bitwise_equal, texture_study

USER_DATA = b"precious user data, not written by rollspec\n"
TIMEOUT = 60
TALLY = {"tried": 0, "refused cleanly": 0, "accepted": 0, "destroyed": 0, "internal errors": 0, "hangs": 0,
         "resumed identically": 0}

TEXTURE = texture_study(5, {"source": "self-affine", "hurst": 0.8, "rolloff_wavelength": "100e-6",
                            "short_wavelength": "8e-6", "rms": "0.3e-6"},
                        {"count": 2, "length": "1e-3", "spacing": "2e-6"},
                        surface={"method": "spectral", "nx": 32, "ny": 32, "spacing": "2e-6", "count": 1})


SWEEP = "\n[sweep]\noscillator.natural_frequency = 30, 45\n"


def fill_disk(d):
    """Fill the file system of directory d to its last page (a file `filler` in d)."""
    fd = os.open(d / "filler", os.O_WRONLY | os.O_CREAT)
    try:
        while os.write(fd, b"\0" * 4096) > 0:
            pass
    except OSError:
        pass
    finally:
        os.close(fd)


def setup_inputs(d):
    """The inputs every recipe reads, written into d."""
    (d / "osc.ini").write_text(SMALL_OSCILLATOR.format(realisations=4, chunk=4, duration=2))
    (d / "sweep.ini").write_text(SMALL_OSCILLATOR.format(realisations=4, chunk=4, duration=2) + SWEEP)
    (d / "tex.ini").write_text(TEXTURE)
    hertz = (SOURCE / "studies" / "hertz.ini").read_text().replace("steps = 20", "steps = 3")
    (d / "hertz.ini").write_text(hertz)
    shutil.copy(SOURCE / "studies" / "data" / "example-signal.csv", d / "signal.csv")


# command -> (output kind, arguments with OUT for the output path, the input a target may alias)
RECIPES = {
    "run": ("result", ["run", "osc.ini", "--out", "OUT", "--quiet"], "osc.ini"),
    # sweeps write OUT (stacked) and their points in the work directory OUT.sweep
    "run --sweep": ("sweep result", ["run", "osc.ini", "--out", "OUT", "--quiet", "--sweep", "oscillator.mass=1,2"],
                    "osc.ini"),
    "run [sweep]": ("sweep result", ["run", "sweep.ini", "--out", "OUT", "--quiet"], "sweep.ini"),
    "psd": ("psd csv", ["psd", "signal.csv", "--unit", "g", "--segment", "1024", "--out", "OUT"], "signal.csv"),
    "texture": ("texture", ["texture", "tex.ini", "--out", "OUT", "--quiet"], "tex.ini"),
    "stiffness": ("stiffness table", ["stiffness", "hertz.ini", "--out", "OUT", "--quiet"], "hertz.ini"),
    # stiffness reads an existing --out as its cached table first; --rebuild goes on to write it.
    "stiffness --rebuild": ("stiffness table", ["stiffness", "hertz.ini", "--out", "OUT", "--quiet", "--rebuild"],
                            "hertz.ini"),
    # init reads no input: a study of the user's (osc.ini) stands for the file it must not replace.
    "init": ("study template", ["init", "random-oscillator", "--out", "OUT"], "osc.ini"),
}
# Besides 73 (cannot create) and 64 (an input as output): stiffness refuses an --out that is not a
# table it can reuse as bad data (65), and a table path in a missing directory as a bad key (78).
EXTRA_CODES = {"stiffness": {65, 78}, "stiffness --rebuild": {78}}
# What each output kind is not: a rollspec file of another kind made by another recipe.
OTHER_KIND = {"run": "texture", "run --sweep": "texture", "run [sweep]": "texture", "psd": "run", "texture": "run",
              "stiffness": "run", "stiffness --rebuild": "run", "init": "run"}


def writing_commands():
    text = subprocess.run([BIN, "--help"], capture_output=True, text=True).stdout
    commands = re.findall(r"^  (\w+)\s{2,}", text.split("commands:")[1].split("options:")[0], re.M)
    writing = []
    for c in commands:
        h = subprocess.run([BIN, c, "--help"], capture_output=True, text=True)
        if re.search(r"--out\b", h.stdout + h.stderr):
            writing.append(c)
    return writing


def test_every_writing_command_is_covered():
    found = writing_commands()
    assert found, "no command with --out found in rollspec --help"
    missing = [c for c in found if c not in {r[1][0] for r in RECIPES.values()}]
    assert not missing, f"commands that write a file without a fault recipe: {missing}"


def execute(d, args, out):
    argv = [BIN] + [str(out) if a == "OUT" else a for a in args]
    try:
        return subprocess.run(argv, cwd=d, capture_output=True, text=True, timeout=TIMEOUT,
                              env={**os.environ, "OMP_NUM_THREADS": "1"})
    except subprocess.TimeoutExpired:
        return None


def make_output(d, command, name):
    """A genuine output of `command` at d/name."""
    r = execute(d, RECIPES[command][1], d / name)
    assert r is not None and r.returncode == 0, r and r.stderr
    return d / name


def snapshot(d):
    """Every regular file under d (links not followed) with its bytes, except checkpoints."""
    out = {}
    for root, _, files in os.walk(d):
        for f in files:
            p = os.path.join(root, f)
            if os.path.isfile(p) and not os.path.islink(p) and ".checkpoint" not in p:
                with open(p, "rb") as fh:
                    out[os.path.relpath(p, d)] = fh.read()
    return out


# target -> builds the hostile --out in d for `command`; returns (path, expected exit codes, protected names)
def t_user_file(d, command):
    (d / "notes.out").write_bytes(USER_DATA)
    return d / "notes.out", {73}, ["notes.out"]


def t_other_kind(d, command):
    p = make_output(d, OTHER_KIND[command], "other.out")
    return p, {73}, ["other.out"]


def t_link_to_user_file(d, command):
    (d / "notes.txt").write_bytes(USER_DATA)
    (d / "link.out").symlink_to("notes.txt")
    return d / "link.out", {73}, ["notes.txt"]


def t_link_to_same_kind(d, command):
    make_output(d, command, "mine.out")
    (d / "link.out").symlink_to("mine.out")
    return d / "link.out", {0}, []


def t_own_input(d, command):
    return d / RECIPES[command][2], {64, 73}, [RECIPES[command][2]]


def t_fifo(d, command):
    os.mkfifo(d / "pipe.out")
    return d / "pipe.out", {73}, []


def t_device(d, command):
    return "/dev/null", {73}, []


def t_link_to_device(d, command):
    (d / "null.out").symlink_to("/dev/null")
    return d / "null.out", {73}, []


def t_directory(d, command):
    (d / "dir.out").mkdir()
    (d / "dir.out" / "keep.txt").write_bytes(USER_DATA)
    return d / "dir.out", {73}, ["dir.out/keep.txt"]


def t_missing_directory(d, command):
    return d / "no" / "such" / "dir" / "x.out", {73}, []


def t_read_only_directory(d, command):
    if os.geteuid() == 0:
        pytest.skip("root writes into a read-only directory")
    ro = d / "ro"
    ro.mkdir()
    ro.chmod(stat.S_IRUSR | stat.S_IXUSR)
    return ro / "x.out", {73}, []


TARGETS = {f.__name__[2:]: f for f in (t_user_file, t_other_kind, t_link_to_user_file, t_link_to_same_kind, t_own_input,
                                       t_fifo, t_device, t_link_to_device, t_directory, t_missing_directory,
                                       t_read_only_directory)}


def judge(r, expected, before, after, protected):
    """Counts and checks one case."""
    TALLY["tried"] += 1
    if r is None:
        TALLY["hangs"] += 1
        pytest.fail("no answer within the timeout (a hang)")
    lost = [n for n in protected if before.get(n) != after.get(n)]
    if lost:
        TALLY["destroyed"] += 1
    if "internal error" in r.stderr or r.returncode < 0:
        TALLY["internal errors"] += 1
    if r.returncode == 0:
        TALLY["accepted"] += 1
    elif r.returncode in expected and "error:" in r.stderr:
        TALLY["refused cleanly"] += 1
    assert not lost, f"destroyed: {lost}"
    assert r.returncode in expected, f"exit {r.returncode}, expected {sorted(expected)}: {r.stderr[-1500:]}"
    assert "internal error" not in r.stderr, r.stderr
    if r.returncode:
        errors = [l for l in r.stderr.splitlines() if "error:" in l]
        assert len(errors) == 1, r.stderr


@pytest.mark.parametrize("target", sorted(TARGETS))
@pytest.mark.parametrize("command", sorted(RECIPES))
def test_hostile_output(tmp_path, command, target):
    setup_inputs(tmp_path)
    out, expected, protected = TARGETS[target](tmp_path, command)
    if expected != {0}:
        expected = expected | EXTRA_CODES.get(command, set())
    before, names = snapshot(tmp_path), set(os.listdir(tmp_path))
    r = execute(tmp_path, RECIPES[command][1], out)
    after = snapshot(tmp_path)
    judge(r, expected, before, after, protected)
    if target == "link_to_same_kind":
        assert os.path.islink(tmp_path / "link.out"), "the link was replaced by a file"
    left = [n for n in os.listdir(tmp_path) if ".tmp" in n]
    assert not left, f"temporary files left: {left}"
    work = [n for n in set(os.listdir(tmp_path)) - names if n.endswith(".sweep")]
    assert not work, f"sweep work directory left: {work}"


# run keeps its checkpoint in <out>.checkpoint/: whatever the user has there is never removed.
def user_directory(d):
    d.mkdir()
    (d / "keep.txt").write_bytes(USER_DATA)
    return d


CHECKPOINT_TARGETS = {
    "user file": lambda c: c.write_bytes(USER_DATA),
    "link to a user directory": lambda c: c.symlink_to(user_directory(c.parent / "mine")),
    "fifo": os.mkfifo,
    "directory with user files": user_directory,
}


@pytest.mark.parametrize("target", sorted(CHECKPOINT_TARGETS))
def test_hostile_checkpoint(tmp_path, target):
    setup_inputs(tmp_path)
    CHECKPOINT_TARGETS[target](tmp_path / "r.h5.checkpoint")
    before = snapshot(tmp_path)
    r = execute(tmp_path, RECIPES["run"][1], tmp_path / "r.h5")
    after = snapshot(tmp_path)
    judge(r, {73}, before, after, [n for n in before if "keep.txt" in n or n == "r.h5.checkpoint"])
    assert not (tmp_path / "r.h5").exists()


# A sweep keeps its points in OUT.sweep/: whatever is there that rollspec did not make is refused, by a
# plain run, --resume and --restart alike, and kept.
WORK_TARGETS = {
    "user file": lambda w: w.write_bytes(USER_DATA),
    "fifo": os.mkfifo,
    "link to a user directory": lambda w: w.symlink_to(user_directory(w.parent / "mine")),
    "dangling link": lambda w: w.symlink_to("nowhere"),
    "directory with user files": user_directory,
}


def lstat_kind(p):
    return stat.S_IFMT(os.lstat(p).st_mode)


@pytest.mark.parametrize("mode", ["plain", "--resume", "--restart"])
@pytest.mark.parametrize("target", sorted(WORK_TARGETS))
def test_hostile_sweep_work_directory(tmp_path, target, mode):
    setup_inputs(tmp_path)
    work = tmp_path / "r.h5.sweep"
    WORK_TARGETS[target](work)
    kind = lstat_kind(work)
    before = snapshot(tmp_path)
    r = execute(tmp_path, RECIPES["run --sweep"][1] + ([] if mode == "plain" else [mode]), tmp_path / "r.h5")
    after = snapshot(tmp_path)
    judge(r, {73}, before, after, list(before))
    assert not (tmp_path / "r.h5").exists()
    assert lstat_kind(work) == kind, "the work path was replaced"
    if target.startswith("link to"):
        assert sorted(os.listdir(tmp_path / "mine")) == ["keep.txt"], "written through the link"


@pytest.fixture
def mounted(tmp_path):
    """mount(path, size) -> path, a tmpfs there (remount(path) makes it read-only); unmounted afterwards."""
    done = []

    def mount(path, size="4m"):
        path.mkdir()
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(path)], capture_output=True,
                           text=True)
        if r.returncode != 0:
            pytest.skip(f"cannot mount a tmpfs here (needs root with mount permission): {r.stderr.strip()}")
        done.append(path)
        return path

    yield mount
    for p in reversed(done):
        subprocess.run(["umount", "-l", str(p)], capture_output=True)


def read_only(path):
    r = subprocess.run(["mount", "-o", "remount,ro", str(path)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


@pytest.mark.parametrize("mode", ["plain", "--resume", "--restart"])
def test_read_only_sweep_work_directory(tmp_path, mounted, mode):
    """A read-only OUT.sweep holding the first finished point: nothing written, that point kept."""
    setup_inputs(tmp_path)
    work = mounted(tmp_path / "r.h5.sweep")
    # the first point of the sweep, finished (the study of point 1 is osc.ini with its --set)
    r = execute(tmp_path, ["run", "osc.ini", "--out", "OUT", "--quiet", "--set", "oscillator.mass=1"],
                work / "point_0000.h5")
    assert r.returncode == 0, r.stderr
    read_only(work)
    before = snapshot(tmp_path)
    r = execute(tmp_path, RECIPES["run --sweep"][1] + ([] if mode == "plain" else [mode]), tmp_path / "r.h5")
    after = snapshot(tmp_path)
    judge(r, {73}, before, after, list(before))
    assert not (tmp_path / "r.h5").exists()


def wait_for_chunk(proc, checkpoint, timeout=120):
    deadline = time.time() + timeout
    while time.time() < deadline and proc.poll() is None:
        if list(checkpoint.glob("chunk_*.bin")):
            return
        time.sleep(0.01)


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGKILL], ids=["SIGINT", "SIGKILL"])
@pytest.mark.parametrize("point", [0, 1])
def test_interrupted_sweep_resumes_to_the_uninterrupted_file(tmp_path, sig, point):
    """Stopped in point 1 or 2 of three (after a checkpointed chunk), then --resume: the same bits."""
    for duration in (256, 1024, 4096):  # long enough that the signal lands inside the point
        study = tmp_path / f"s{duration}.ini"
        study.write_text(SMALL_OSCILLATOR.format(realisations=24, chunk=2, duration=duration) +
                         "\n[sweep]\noscillator.mass = 1, 2.5, 4\n")
        out, work = tmp_path / f"s{duration}.h5", tmp_path / f"s{duration}.h5.sweep"
        proc = subprocess.Popen([BIN, "run", str(study), "--out", str(out), "--quiet"], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
        wait_for_chunk(proc, work / f"point_{point:04d}.h5.checkpoint")
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=TIMEOUT)
        if proc.returncode != 0:
            break
    TALLY["tried"] += 1
    assert proc.returncode == (130 if sig == signal.SIGINT else -signal.SIGKILL), err
    if sig == signal.SIGINT:
        errors = [l for l in err.splitlines() if "error:" in l]
        assert len(errors) == 1 and "--resume" in errors[0], err
    assert not out.exists() and work.is_dir()
    r = execute(tmp_path, ["run", str(study), "--out", "OUT", "--quiet", "--resume"], out)
    assert r is not None and r.returncode == 0, r and r.stderr
    assert not work.exists(), "the work directory is removed after the merge"
    ref = tmp_path / "ref.h5"
    r = execute(tmp_path, ["run", str(study), "--out", "OUT", "--quiet"], ref)
    assert r.returncode == 0, r.stderr
    assert_bitwise_equal(out, ref)
    assert not [n for n in os.listdir(tmp_path) if ".tmp" in n]
    TALLY["resumed identically"] += 1


@pytest.fixture
def small_disk(tmpfs_disk):
    return tmpfs_disk("8m")


@pytest.mark.parametrize("command", sorted(RECIPES))
def test_full_disk_keeps_the_previous_output(tmp_path, small_disk, command):
    setup_inputs(small_disk)
    old = make_output(small_disk, command, "old.out")
    keep = old.read_bytes()
    fill_disk(small_disk)
    before = snapshot(small_disk)
    r = execute(small_disk, RECIPES[command][1], old)
    after = snapshot(small_disk)
    if r is not None and r.returncode == 0:  # the output fit in what was left: still a whole file
        TALLY["tried"] += 1
        TALLY["accepted"] += 1
        return
    judge(r, {73, 74} | EXTRA_CODES.get(command, set()), before, after, ["old.out"])
    assert old.read_bytes() == keep
    assert not [n for n in os.listdir(small_disk) if ".tmp" in n]
    empty = [n for n in os.listdir(small_disk) if n.endswith(".sweep") and not os.listdir(small_disk / n)]
    assert not empty, f"an empty sweep work directory left (the next run would ask for --resume): {empty}"


@pytest.mark.parametrize("args", [["keys"], ["keys", "ball-on-beam"], ["version"], ["plan", "osc.ini"],
                                  ["psd", "signal.csv", "--segment", "1024"], ["stiffness", "hertz.ini"]],
                         ids=lambda a: " ".join(a))
def test_full_standard_output(tmp_path, args):
    setup_inputs(tmp_path)
    with open("/dev/full", "w") as full:
        try:
            r = subprocess.run([BIN, *args], cwd=tmp_path, stdout=full, stderr=subprocess.PIPE, text=True, timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            r = None
    judge(r, {74}, {}, {}, [])


# `fit` writes no --out: each evaluation's result goes to a temporary directory under $TMPDIR, removed
# when the fit ends. $TMPDIR meets the targets; a usable one is left as it was found.
FIT_FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
            "spectrum.band_max=200", "study.realisations=20"]


@pytest.fixture(scope="module")
def fit_measurement(tmp_path_factory):
    from fit_experiment import measurement
    return measurement(tmp_path_factory.mktemp("fit"), 4242, {"force.level": 2.0})


def fit_argv(csv):
    return [BIN, "fit", str(SOURCE / "studies" / "random-oscillator.ini"), str(csv), "--vary",
            "force.level=0.1:10:log", "--measured-averages", "16", "--format", "json",
            *[a for kv in FIT_FAST for a in ("--set", kv)]]


def fit_in(tmpdir, csv, stdout=subprocess.PIPE):
    try:
        return subprocess.run(fit_argv(csv), stdout=stdout, stderr=subprocess.PIPE, text=True, timeout=TIMEOUT * 4,
                              env={**os.environ, "OMP_NUM_THREADS": "1", "TMPDIR": str(tmpdir)})
    except subprocess.TimeoutExpired:
        return None


def fit_temps(tmpdir):
    return [n for n in os.listdir(tmpdir) if n.startswith("rollspec-fit")] if os.path.isdir(tmpdir) else []


FIT_TARGETS = {  # name -> (builds $TMPDIR in d, expected exit codes)
    "user file": (lambda d: (d / "t").write_bytes(USER_DATA), {73}),
    "fifo": (lambda d: os.mkfifo(d / "t"), {73}),
    "missing directory": (lambda d: None, {73}),
    "dangling link": (lambda d: (d / "t").symlink_to("nowhere"), {73}),
    "link to a user directory": (lambda d: (d / "t").symlink_to(user_directory(d / "mine")), {0}),
}


@pytest.mark.parametrize("target", sorted(FIT_TARGETS))
def test_hostile_fit_temporary_directory(tmp_path, fit_measurement, target):
    build, expected = FIT_TARGETS[target]
    build(tmp_path)
    before = snapshot(tmp_path)
    r = fit_in(tmp_path / "t", fit_measurement)
    after = snapshot(tmp_path)
    judge(r, expected, before, after, list(before))
    if expected == {73}:
        assert "TMPDIR" in r.stderr, r.stderr
    assert not fit_temps(tmp_path / "t"), "temporary directory left"


def test_read_only_fit_temporary_directory(tmp_path, mounted, fit_measurement):
    t = mounted(tmp_path / "t")
    read_only(t)
    r = fit_in(t, fit_measurement)
    judge(r, {73}, {}, {}, [])
    assert "TMPDIR" in r.stderr


def test_fit_on_a_full_disk_leaves_no_temporary_directory(tmp_path, mounted, fit_measurement):
    t = mounted(tmp_path / "t", "1m")
    (t / "keep.txt").write_bytes(USER_DATA)
    fill_disk(t)
    before = snapshot(t)
    r = fit_in(t, fit_measurement)
    after = snapshot(t)
    judge(r, {73, 74}, before, after, ["keep.txt"])
    assert not fit_temps(t), "temporary directory left"


def test_fit_into_a_full_standard_output(tmp_path, fit_measurement):
    with open("/dev/full", "w") as full:
        r = fit_in(tmp_path, fit_measurement, stdout=full)
    judge(r, {74}, {}, {}, [])
    assert not fit_temps(tmp_path)


def interrupted_fit(tmp_path, csv):
    proc = subprocess.Popen(fit_argv(csv), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env={**os.environ, "OMP_NUM_THREADS": "1", "TMPDIR": str(tmp_path)})
    deadline = time.time() + TIMEOUT
    while time.time() < deadline and proc.poll() is None:  # inside an evaluation, past its first chunk
        if list(tmp_path.glob("rollspec-fit*/*.checkpoint/chunk_*.bin")):
            break
        time.sleep(0.005)
    proc.send_signal(signal.SIGINT)
    try:
        out, err = proc.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        proc.kill()
        return None, ""
    return subprocess.CompletedProcess(proc.args, proc.returncode, out, err), out


def test_interrupted_fit_exits_cleanly_without_its_temporary_directory(tmp_path, fit_measurement):
    r, out = interrupted_fit(tmp_path, fit_measurement)
    judge(r, {130}, {}, {}, [])
    assert out == "", "an interrupted fit prints no estimate"
    assert not fit_temps(tmp_path), "temporary directory left"


def test_interrupted_fit_names_no_removed_file(tmp_path, fit_measurement):
    r, _ = interrupted_fit(tmp_path, fit_measurement)
    assert r is not None and r.returncode == 130, r and r.stderr
    assert "rollspec-fit" not in r.stderr and "--resume" not in r.stderr, r.stderr


def test_zz_totals():
    """The suite's counts (pytest -s shows them); nothing destroyed, no internal error, no hang."""
    print("\nfault suite: " + ", ".join(f"{k} {v}" for k, v in TALLY.items()))
    assert TALLY["tried"] > 0
    assert TALLY["destroyed"] == 0 and TALLY["internal errors"] == 0 and TALLY["hangs"] == 0
