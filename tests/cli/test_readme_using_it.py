"""The commands a user reads run as written, in order, from a copy of the repository root: the
"## Using it" block of the documentation's tour (docs/tutorials/tour.md) and the README's
"## Quick start" block, and the first block of the documentation pages in TUTORIAL_BLOCKS.
`rollspec ...` runs with the built binary, `python3 -m rollspec_post ...` with Debian's /usr/bin/python3.
`mpirun` lines need the MPI build and are left to tests/mpi.

The temporary root holds `studies/` as a directory of symlinks to the source tree's study files and
`studies/data`, not as one symlink to the folder: `rollspec stiffness` caches its table in
`tables/` beside the study file, which through a folder symlink would be the source tree. The test
checks that the source tree's studies/ is left as it was."""
import os
import shlex
import subprocess
import sys
import time

import pytest

from conftest import BIN, SOURCE

PYTHON = "/usr/bin/python3"


def sh_block(path, heading):
    """The non-empty lines of the first ```sh block after `heading` in `path`."""
    lines = path.read_text().splitlines()
    start = lines.index(heading)
    fence = next(i for i in range(start, len(lines)) if lines[i].startswith("```sh"))
    end = next(i for i in range(fence + 1, len(lines)) if lines[i].startswith("```"))
    return [line for line in lines[fence + 1:end] if line.strip()]


def using_it_commands():
    return sh_block(SOURCE / "docs" / "tutorials" / "tour.md", "## Using it")


def studies_snapshot():
    return sorted((str(p.relative_to(SOURCE)), p.lstat().st_mtime_ns) for p in (SOURCE / "studies").rglob("*"))


def run_as_written(commands, root):
    """Runs each line in `root` (which holds studies/ as symlinks); returns after checking that the
    source tree's studies/ is unchanged."""
    (root / "studies").mkdir()
    for entry in (SOURCE / "studies").iterdir():
        if entry.name != "tables":  # a table cache of earlier runs in the source tree is not part of it
            (root / "studies" / entry.name).symlink_to(entry)
    env = dict(os.environ, PYTHONPATH=str(SOURCE / "python-post"))
    before = studies_snapshot()
    timings = []
    for line in commands:
        words = shlex.split(line, comments=True)
        if words[0] == "mpirun":
            continue
        if words[0] == "rollspec":
            argv = [BIN, *words[1:]]
        elif words[:3] == ["python3", "-m", "rollspec_post"]:
            argv = [PYTHON, *words[1:]]
        else:
            raise AssertionError(f"a documented command this test cannot run: {line}")
        start = time.monotonic()
        r = subprocess.run(argv, cwd=root, env=env, capture_output=True, text=True, timeout=900)
        timings.append((time.monotonic() - start, line))
        assert r.returncode == 0, f"{line}\nexit {r.returncode}\n{r.stderr[-3000:]}"
    for seconds, line in timings:
        print(f"{seconds:7.1f} s  {line}", file=sys.stderr)
    assert studies_snapshot() == before, "the documented commands wrote into the source tree's studies/"


def test_every_command_of_using_it_runs_as_written(tmp_path):
    commands = using_it_commands()
    assert any(c.startswith("rollspec psd") for c in commands) and any("rollspec_post" in c for c in commands)
    run_as_written(commands, tmp_path)
    assert (tmp_path / "studies" / "tables").is_dir()  # the stiffness table landed in the temporary root
    for out in ("r.h5", "one.h5", "t.h5", "psd.csv", "psd-wav.csv", "report.html"):
        assert (tmp_path / out).stat().st_size > 0, out


def test_readme_quick_start_runs_as_written(tmp_path):
    commands = sh_block(SOURCE / "README.md", "## Quick start")
    assert len(commands) == 5
    assert [c.split()[:2] for c in commands] == [["rollspec", "run"], ["python3", "-m"], ["rollspec", "psd"],
                                                 ["rollspec", "compare"], ["python3", "-m"]]
    run_as_written(commands, tmp_path)
    for out in ("r.h5", "r-psd.png", "psd.csv", "report.html"):
        assert (tmp_path / out).stat().st_size > 0, out


TUTORIAL_BLOCKS = {  # pages whose first ```sh block stands alone: (page, a file it writes)
    "measurements": ("docs/tutorials/measurements.md", "psd-wav.csv"),
    "speed": ("docs/tutorials/speed.md", "speeds.png"),
    "roughness": ("docs/howto/roughness.md", "texture.png"),
}


@pytest.mark.parametrize("page", sorted(TUTORIAL_BLOCKS))
def test_documentation_page_commands_run_as_written(tmp_path, page):
    path, written = TUTORIAL_BLOCKS[page]
    title = (SOURCE / path).read_text().splitlines()[0]
    commands = sh_block(SOURCE / path, title)
    assert commands
    run_as_written(commands, tmp_path)
    assert (tmp_path / written).stat().st_size > 0, written
