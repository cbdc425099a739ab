"""Generated fault suite, every entry point: the rollspec commands (each writing one meets every hostile
target in test_output_faults.py; here the others meet a full standard output), rollspec-post's subcommands
(python-post/tests/test_post_faults.py), every script under docs/, bench/, python-post/, studies/ and the
tests' runnable helpers, and the notebook API. The suite lists the programs itself (a script with a main,
a shell script, a gallery example): one without a recipe in program_recipes.py fails
test_every_program_has_a_recipe, so a new script is covered or the suite fails.

Each script x its outputs (a file, a folder, or fixed files of its own in a copy of the repository) x a
symbolic link to a user's file, a user's file, a FIFO, a device, a user's folder and its own input; its
inputs x a FIFO, a device and the wrong kind; its standard output x /dev/full; its rollspec x a missing
one. Each case: no user file changed, no traceback, one line on failure, no hang (timeout). `pytest -s`
prints the totals (test_zz_totals). Label `fault`."""
import collections
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

import pytest

from conftest import BIN, SOURCE
from program_recipes import RECIPES

PY = "/usr/bin/python3"
USER = b"precious user data, not written by any script\n"
TIMEOUT = 30
TOTALS = collections.Counter()


def listed_programs():
    """Every program a user can run, by path: scripts with a main, shell scripts, gallery examples."""
    found = []
    for top in ("docs", "bench", "python", "python-post", "studies", "tests"):
        for p in sorted((SOURCE / top).rglob("*")):
            rel = str(p.relative_to(SOURCE))
            if "__pycache__" in rel or p.name.startswith("test_") or p.name == "conftest.py" or not p.is_file():
                continue
            if p.suffix == ".sh" or (p.suffix == ".py" and (re.search(r'^if __name__ == "__main__":', p.read_text(),
                                                                       re.M) or rel.startswith("docs/examples/plot_"))):
                found.append(rel)
    return found


def test_every_program_has_a_recipe():
    listed = listed_programs()
    assert len(listed) >= 30, listed
    missing = [p for p in listed if p not in RECIPES]
    stale = [p for p in RECIPES if p not in listed]
    assert not missing, f"programs the fault suite does not run (add a recipe to program_recipes.py): {missing}"
    assert not stale, f"recipes of programs that are gone: {stale}"


def user_folder(path):
    path.mkdir(parents=True, exist_ok=True)
    (path / "keep.txt").write_bytes(USER)
    return path


def user_file(path):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(USER)
    return path


def link(path, to):
    path.symlink_to(to)
    return path


def fifo(path):
    os.mkfifo(path)
    return path


# target -> builds the hostile path at `p` (a path in the case's folder); returns (path, files to keep)
FILE_TARGETS = {
    "symlink to a user's file": lambda p: (link(p, user_file(p.parent / "user-linked.txt")), [p.parent / "user-linked.txt"]),
    "a user's file": lambda p: (user_file(p), [p]),
    "FIFO": lambda p: (fifo(p), []),
    "device": lambda p: ("/dev/null", []),
    "symlink to a device": lambda p: (link(p, "/dev/null"), []),
    "a user's folder": lambda p: (user_folder(p), [p / "keep.txt"]),
}
FOLDER_TARGETS = {
    "a user's folder": lambda p: (user_folder(p), [p / "keep.txt"]),
    "symlink to a user's folder": lambda p: (link(p, user_folder(p.parent / "mine")), [p.parent / "mine" / "keep.txt"]),
    "a user's file": lambda p: (user_file(p), [p]),
    "FIFO": lambda p: (fifo(p), []),
    "device": lambda p: ("/dev/null", []),
}
INPUT_TARGETS = {"FIFO": lambda p: (fifo(p), []), "device": lambda p: ("/dev/zero", []), "the wrong kind": None}


def cases():
    out = []
    for script, r in sorted(RECIPES.items()):
        if "delegated" in r:
            continue
        if r.get("out"):
            targets = FILE_TARGETS if r["out"] == "file" else FOLDER_TARGETS
            out += [(script, "output", t) for t in targets]
            if r.get("in") == "file":
                out.append((script, "output", "its own input"))
        if r.get("in"):
            out += [(script, "input", t) for t in INPUT_TARGETS]
        for fixed in r.get("fixed", []):
            out += [(script, f"fixed {fixed}", t) for t in FILE_TARGETS if t != "device"]
        if r.get("help"):
            out.append((script, "standard output", "/dev/full"))
        if r.get("binary"):
            out.append((script, "binary", "missing"))
    return out


def tree(tmp, r, script):
    """A copy of the parts of the repository the script needs (it writes its fixed outputs there)."""
    root = tmp / "tree"
    for part in r.get("tree", []) + [script]:
        src, dst = SOURCE / part, root / part
        dst.parent.mkdir(parents=True, exist_ok=True)
        if src.is_dir():
            shutil.copytree(src, dst, dirs_exist_ok=True, ignore=shutil.ignore_patterns("__pycache__"))
        else:
            shutil.copy(src, dst)
    if r.get("binary") == "tree":
        (root / "build" / "release").mkdir(parents=True, exist_ok=True)
        shutil.copy(BIN, root / "build" / "release" / "rollspec")
    return root


def argv_of(r, tmp, script, out=None, inp=None, binary=BIN, argv=None):
    """The recipe's argv and environment with its tokens replaced."""
    (tmp / "empty").mkdir(exist_ok=True)
    default_in = tmp / "empty" if r.get("in") == "folder" else tmp / "input.txt"
    if not default_in.exists():
        default_in.write_bytes(b"{}\n")
    words = {"PY": PY, "S": str(script), "BIN": str(binary), "BINDIR": str(os.path.dirname(binary)),
             "STUDY": str(SOURCE / "studies" / "random-oscillator.ini"), "EMPTY": str(tmp / "empty"),
             "SRCDIR": str(tmp / "empty"), "OUT": str(out or tmp / "new-output"), "IN": str(inp or default_in)}
    env = dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"), MPLBACKEND="Agg", OMP_NUM_THREADS="1")
    env.update({k: words.get(v, v) for k, v in r.get("env", {}).items()})
    return [words.get(a, a) for a in (argv or r["argv"])], env


def snapshot(paths):
    return {str(p): (p.read_bytes() if os.path.isfile(p) else None) for p in paths}


def run_case(tmp, script, where, target):
    """Runs one case; returns a fault (text) or None, and counts it."""
    r = RECIPES[script]
    path = SOURCE / script
    keep, stdout = [], subprocess.DEVNULL
    (tmp / "user.txt").write_bytes(USER)
    keep.append(tmp / "user.txt")
    argv_args = {}
    if where == "output":
        if target == "its own input":
            inp = tmp / "input.h5"
            inp.write_bytes(USER)
            argv_args, keep = {"out": inp, "inp": inp}, keep + [inp]
        else:
            out, kept = (FILE_TARGETS if r["out"] == "file" else FOLDER_TARGETS)[target](tmp / "target")
            argv_args, keep = {"out": out}, keep + kept
    elif where == "input":
        if target == "the wrong kind":
            inp = user_folder(tmp / "in") if r["in"] == "file" else tmp / "user.txt"
        else:
            inp, _ = INPUT_TARGETS[target](tmp / "in")
        argv_args = {"inp": inp, "argv": r.get("in_argv")}
    elif where.startswith("fixed "):
        root = tree(tmp, r, script)
        path = root / script
        fixed = root / where[len("fixed "):]
        if fixed.exists() or fixed.is_symlink():
            fixed.unlink()
        fixed.parent.mkdir(parents=True, exist_ok=True)
        _, kept = FILE_TARGETS[target](fixed)
        keep += kept
    elif where == "binary":
        argv_args = {"binary": "/nonexistent/rollspec"}
        if r["binary"] == "tree":
            path = tree(tmp, {**r, "binary": None}, script) / script
    if where == "standard output":
        argv, env = argv_of(r, tmp, path, argv=r["argv"][:2] + r["help"])
        stdout = open("/dev/full", "w")
    else:
        argv, env = argv_of(r, tmp, path, **argv_args)
    before = snapshot(keep)
    try:
        p = subprocess.run(argv, stdout=stdout, stderr=subprocess.PIPE, text=True, errors="replace", env=env,
                           timeout=TIMEOUT, cwd=tmp, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        TOTALS["hangs"] += 1
        return f"no answer within {TIMEOUT} s"
    finally:
        if stdout is not subprocess.DEVNULL:
            stdout.close()
    TOTALS["tried"] += 1
    lines = [line for line in p.stderr.splitlines() if line.strip()]
    destroyed = [k for k, v in snapshot(keep).items() if v != before[k]]
    traceback = "Traceback" in p.stderr or "Exception ignored" in p.stderr
    TOTALS["destroyed"] += bool(destroyed)
    TOTALS["tracebacks"] += traceback
    if destroyed:
        return f"changed {destroyed}: {p.stderr[-300:]}"
    if traceback:
        return f"a traceback: {p.stderr[-600:]}"
    if p.returncode == 0:
        TOTALS["accepted"] += 1
        return f"accepted (exit 0): {p.stderr[-300:]}"
    if where == "standard output" and p.returncode != 74:
        return f"exit {p.returncode} on a full standard output, expected 74: {p.stderr[-300:]}"
    if len(lines) != 1:
        return f"{len(lines)} lines on stderr, expected one: {p.stderr[-600:]}"
    TOTALS["refused cleanly"] += 1
    return None


CASES = cases()


def test_the_suite_covers_every_program_and_target():
    scripts = {c[0] for c in CASES}
    assert scripts == {s for s, r in RECIPES.items() if "delegated" not in r}
    assert len(CASES) >= 150, len(CASES)


@pytest.mark.parametrize("script", sorted({c[0] for c in CASES}))
def test_script_against_hostile_targets(tmp_path, script):
    mine = [c for c in CASES if c[0] == script]

    def one(i_case):
        i, (_, where, target) = i_case
        d = tmp_path / f"case{i}"
        d.mkdir()
        return where, target, run_case(d, script, where, target)
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        faults = [f"{where} = {target}: {why}" for where, target, why in pool.map(one, enumerate(mine)) if why]
    assert not faults, f"{script}:\n" + "\n".join(faults)


@pytest.mark.parametrize("args", [["compare", "R", SOURCE / "studies" / "data" / "measured-psd.csv"],
                                  ["modes", SOURCE / "studies" / "seed002-rig-1ms.ini"]], ids=["compare", "modes"])
def test_commands_that_print_on_a_full_standard_output(tmp_path, args):
    """The commands test_output_faults.py does not send to /dev/full (they write no --out)."""
    result = tmp_path / "r.h5"
    study = SOURCE / "studies" / "random-oscillator.ini"
    assert subprocess.run([BIN, "run", study, "--out", result, "--quiet", "--set", "study.realisations=4"]).returncode == 0
    with open("/dev/full", "w") as full:
        p = subprocess.run([BIN, *[result if a == "R" else a for a in args]], stdout=full, stderr=subprocess.PIPE,
                           text=True, timeout=TIMEOUT)
    TOTALS["tried"] += 1
    assert p.returncode == 74 and len(p.stderr.strip().splitlines()) == 1, p.stderr
    TOTALS["refused cleanly"] += 1


NOTEBOOK = """
import os, sys
from rollspec_post import open_result, run
from rollspec_post.result_file import PostError
try:
    {call}
    print("accepted")
except PostError as e:
    print("PostError", e.exit_code)
except BaseException as e:
    print("LEAKED", type(e).__name__, e)
"""


def notebook_cases():
    """(function, target): each notebook API function (rollspec_post.__all__) against each hostile path."""
    sys.path.insert(0, str(SOURCE / "python-post"))
    import rollspec_post
    calls = {"open_result": ["FIFO", "device", "a user's folder", "a user's file", "symlink loop", "missing"],
             "run": list(FILE_TARGETS) + ["its own input", "missing binary"]}
    assert sorted(calls) == sorted(rollspec_post.__all__), "a notebook API function without fault cases"
    return [(f, t) for f in sorted(calls) for t in calls[f]]


@pytest.mark.parametrize("function,target", notebook_cases())
def test_notebook_api_raises_one_exception_type(tmp_path, function, target):
    study = tmp_path / "s.ini"
    shutil.copy(SOURCE / "studies" / "random-oscillator.ini", study)
    (tmp_path / "user.txt").write_bytes(USER)
    keep, env = [tmp_path / "user.txt", study], dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"),
                                                     ROLLSPEC_BIN=BIN)
    p = tmp_path / "target"
    if target == "its own input":
        p = study
    elif target == "symlink loop":
        p.symlink_to(p)
    elif target == "missing":
        p = tmp_path / "no-such.h5"
    elif target == "missing binary":
        env["ROLLSPEC_BIN"] = "/nonexistent/rollspec"
    elif target in FILE_TARGETS:
        p, kept = FILE_TARGETS[target](p)
        keep += kept
    call = f"open_result({str(p)!r})" if function == "open_result" else \
        f"run({str(study)!r}, {str(p)!r}, set={{'study.realisations': 2, 'signal.duration': 4}})"
    before = snapshot(keep)
    r = subprocess.run([PY, "-c", NOTEBOOK.format(call=call)], capture_output=True, text=True, env=env,
                       timeout=TIMEOUT, cwd=tmp_path)
    TOTALS["tried"] += 1
    assert snapshot(keep) == before, "a user's file changed"
    assert r.stdout.startswith("PostError"), r.stdout + r.stderr
    assert "Traceback" not in r.stderr, r.stderr
    TOTALS["refused cleanly"] += 1


def test_zz_totals():
    """Last: the suite's counts (pytest -s shows them); nothing destroyed, no traceback, no hang."""
    print("\nprogram fault suite: " + ", ".join(f"{k} {v}" for k, v in sorted(TOTALS.items())))
    assert TOTALS["tried"] > 0
    assert TOTALS["destroyed"] == TOTALS["tracebacks"] == TOTALS["hangs"] == 0
