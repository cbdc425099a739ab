"""Generated fault suite: every rollspec command that writes a file, against every hostile target.

The commands come from `rollspec --help` and each command's own `--help` (an `--out` option), so a
new command that writes a file fails `test_every_writing_command_is_covered` until it has a recipe
here. Each (command, output) meets each target below; the suite checks the exit code, a one-line
message without "internal error", the user's data byte-identical, no temporary file left and no
hang, and the last test prints the totals: tried / refused cleanly / accepted / destroyed /
internal errors / hangs (and the known ones, marked xfail with their reason, apart).

Sweeps (`run --sweep`, a [sweep] study) meet every target too, and so does their work directory
OUT.sweep; a sweep interrupted (SIGINT) or killed (SIGKILL) and resumed writes the uninterrupted
file bit for bit. `fit` writes no --out: its temporary directory under $TMPDIR meets the targets.

Label `fault`: an 8 MiB tmpfs (root) gives the full-disk cases."""
import os
import re
import shutil
import stat
import subprocess

import pytest

from conftest import BIN, SMALL_OSCILLATOR, SOURCE

USER_DATA = b"precious user data, not written by rollspec\n"
TIMEOUT = 60
TALLY = {"tried": 0, "refused cleanly": 0, "accepted": 0, "destroyed": 0, "internal errors": 0, "hangs": 0,
         "resumed identically": 0, "known internal errors (xfail)": 0}

TEXTURE = """\
[study]
scene = texture
realisations = 1
seed = 5

[texture]
source = self-affine
hurst = 0.8
rolloff_wavelength = 100e-6
short_wavelength = 8e-6
rms = 0.3e-6

[lines]
count = 2
length = 1e-3
spacing = 2e-6

[surface]
method = spectral
nx = 32
ny = 32
spacing = 2e-6
count = 1
"""


SWEEP = "\n[sweep]\noscillator.natural_frequency = 30, 45\n"


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
OTHER_KIND = {"run": "texture", "run --sweep": "texture", "run [sweep]": "texture", "psd": "run", "texture": "run", "stiffness": "run", "stiffness --rebuild": "run",
              "init": "run"}


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


def judge(r, expected, before, after, protected, known_bug=False):
    """Counts and checks one case; `known_bug`: an xfail case, whose internal error is counted apart."""
    TALLY["tried"] += 1
    if r is None:
        TALLY["hangs"] += 1
        pytest.fail("no answer within the timeout (a hang)")
    lost = [n for n in protected if before.get(n) != after.get(n)]
    if lost:
        TALLY["destroyed"] += 1
    if "internal error" in r.stderr or r.returncode < 0:
        TALLY["known internal errors (xfail)" if known_bug else "internal errors"] += 1
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


@pytest.fixture
def small_disk(tmpfs_disk):
    return tmpfs_disk("8m")


@pytest.mark.parametrize("command", sorted(RECIPES))
def test_full_disk_keeps_the_previous_output(tmp_path, small_disk, command):
    setup_inputs(small_disk)
    old = make_output(small_disk, command, "old.out")
    keep = old.read_bytes()
    fd = os.open(small_disk / "filler", os.O_WRONLY | os.O_CREAT)
    try:  # fill the disk to the last page
        while os.write(fd, b"\0" * 4096) > 0:
            pass
    except OSError:
        pass
    finally:
        os.close(fd)
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


def test_zz_totals():
    """The suite's counts (pytest -s shows them); nothing destroyed, no internal error, no hang."""
    print("\nfault suite: " + ", ".join(f"{k} {v}" for k, v in TALLY.items()))
    assert TALLY["tried"] > 0
    assert TALLY["destroyed"] == 0 and TALLY["internal errors"] == 0 and TALLY["hangs"] == 0
