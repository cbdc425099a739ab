"""The progress bar on a real terminal (tmux): fitted to 50 and 200 columns without wrapping, no
stale characters, a final "took" line, and Ctrl-C's message on a line of its own."""
import os
import re
import shutil
import subprocess
import time

import pytest

from conftest import BIN, SOURCE

pytestmark = pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux absent (.ci/setup installs it)")
STUDY = SOURCE / "studies" / "seed001-beam-s-hertz.ini"


class Terminal:
    """A tmux server of its own (a socket per test, so one test's shutdown never meets the next)."""

    def __init__(self, name):
        self.name = name

    def tmux(self, *args):
        return subprocess.run(["tmux", "-L", self.name, *args], capture_output=True, text=True, timeout=30)

    def start(self, tmp_path, columns, realisations):
        out = tmp_path / "r.h5"
        cmd = f"{BIN} run {STUDY} --out {out} --set study.realisations={realisations} --set ensemble.chunk_size=4; sleep 60"
        r = self.tmux("new-session", "-d", "-s", "t", "-x", str(columns), "-y", "30", cmd)
        assert r.returncode == 0, r.stderr

    def screen(self):
        return self.tmux("capture-pane", "-p", "-t", "t").stdout.splitlines()

    def wait_for(self, pattern, seconds=60):
        end = time.time() + seconds
        while time.time() < end:
            lines = self.screen()
            if any(re.search(pattern, line) for line in lines):
                return lines
            time.sleep(0.2)
        raise AssertionError(f"{pattern!r} never appeared:\n" + "\n".join(self.screen()))


@pytest.fixture
def terminal(request):
    t = Terminal(f"rollspec-test-{os.getpid()}-{request.node.name}".replace("[", "-").replace("]", ""))
    yield t
    t.tmux("kill-server")


@pytest.mark.parametrize("columns", [50, 200])
def test_bar_fits_and_ends_with_took(tmp_path, terminal, columns):
    terminal.start(tmp_path, columns, 160)
    during = terminal.wait_for(r"^realisations .*ETA")
    bar = next(line for line in during if line.startswith("realisations"))
    assert len(bar) < columns and "ETA" in bar
    assert not any(line.startswith(("ETA", "s", "/s")) for line in during), "the bar wrapped"
    lines = terminal.wait_for(r"^wrote ")
    took = [line for line in lines if line.startswith("realisations")]
    assert len(took) == 1, lines
    assert re.fullmatch(r"realisations( \[#+\])? 160/160  [0-9.]+/s  took [0-9]+s", took[0]), took[0]
    assert ("[" in took[0]) == (columns >= 80)


def test_interrupt_message_starts_its_own_line(tmp_path, terminal):
    terminal.start(tmp_path, 120, 100000)
    terminal.wait_for(r"^realisations .*ETA")
    terminal.tmux("send-keys", "-t", "t", "C-c")
    lines = terminal.wait_for(r"error: interrupted")
    assert any(line.startswith("rollspec run: error: interrupted") for line in lines), lines


def test_every_slow_phase_reports_progress_once_in_a_log(tmp_path):
    """Not a terminal (a log): the ensemble's one final line, and the post-ensemble linearised
    reference of seed 002 (seconds of work whatever K is) shows its own progress when it is slow."""
    study = SOURCE / "studies" / "seed002-rig-1ms.ini"
    start = time.monotonic()
    r = subprocess.run([str(BIN), "run", str(study), "--out", str(tmp_path / "r.h5"), "--set", "study.realisations=1"],
                       capture_output=True, text=True, timeout=600)
    elapsed = time.monotonic() - start
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("wrote ") and "(1 realisation, 1 computed in" in r.stdout and "1 rank x" in r.stdout
    finals = [line for line in r.stderr.splitlines() if line.startswith("realisations: 1/1")]
    assert len(finals) == 1 and "took" in finals[0], r.stderr
    reference = [line for line in r.stderr.splitlines() if line.startswith("linearised reference:")]
    if elapsed > 3.0:  # the reference (run after the ensemble's one realisation) took over a second
        assert reference and "took" in reference[-1] and re.search(r"(\d+)/\1 ", reference[-1]), r.stderr
    quiet = subprocess.run([str(BIN), "run", str(study), "--out", str(tmp_path / "q.h5"), "--set", "study.realisations=1",
                            "-q"], capture_output=True, text=True, timeout=600)
    assert quiet.returncode == 0 and quiet.stdout == "" and "linearised reference" not in quiet.stderr
