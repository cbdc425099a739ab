"""Never lose a user's data III: the scripts and smaller paths held to the command's rule. docs/build.sh
builds only into a folder of its own (never `rm -rf` of a user's DIR/src) and finds the README's
build/release binary; a non-UTF-8 bench record stops it in one line; bench/record_csv.py fails in one
line; `init --out ''`, `compare` on a spread of 1e300, an explicit filter = patch under law = path, and
a resume that read every chunk twice. Each test fails on the build before this work."""
import os
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np
import pytest

from conftest import BIN, EX_USAGE, SMALL_OSCILLATOR, SOURCE, assert_refused, run

BUILD = SOURCE / "docs" / "build.sh"
USER = b"int main(void) { return 0; }\n"


def build_docs(out, env=None, script=BUILD):
    e = {k: v for k, v in os.environ.items() if k != "ROLLSPEC_BIN"}
    e.update({"ROLLSPEC_BIN": BIN} if env is None else env)
    return subprocess.run(["bash", str(script), str(out)], capture_output=True, text=True, timeout=120, env=e)


def snapshot(d):
    return {str(p.relative_to(d)): p.read_bytes() for p in sorted(d.rglob("*")) if p.is_file() and not p.is_symlink()}


def test_build_sh_never_deletes_a_users_folder(tmp_path):
    project = tmp_path / "myproject"
    (project / "src").mkdir(parents=True)
    (project / "src" / "main.c").write_bytes(USER)
    before = snapshot(project)
    r = build_docs(project)
    assert r.returncode == 73 and "holds files docs/build.sh did not write" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    assert snapshot(project) == before and sorted(os.listdir(project)) == ["src"]


@pytest.mark.parametrize("where", ["the repository", "docs", "src"])
def test_build_sh_refuses_the_sources(where):
    target = {"the repository": SOURCE, "docs": SOURCE / "docs", "src": SOURCE / "src"}[where]
    before = sorted(os.listdir(SOURCE / "src"))
    r = build_docs(target)
    assert r.returncode == 73 and "is the repository or inside its sources" in r.stderr, r.stderr
    assert sorted(os.listdir(SOURCE / "src")) == before


@pytest.mark.parametrize("kind", ["file", "fifo", "device", "symlink"])
def test_build_sh_refuses_what_is_no_folder_of_its_own(tmp_path, kind):
    out = {"file": tmp_path / "notes", "fifo": tmp_path / "pipe", "device": "/dev/null", "symlink": tmp_path / "link"}[kind]
    if kind == "file":
        out.write_bytes(USER)
    elif kind == "fifo":
        os.mkfifo(out)
    elif kind == "symlink":
        (tmp_path / "mine").mkdir()
        out.symlink_to(tmp_path / "mine")
    r = build_docs(out)
    assert r.returncode == 73 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    if kind == "file":
        assert out.read_bytes() == USER


def stub_repository(tmp_path, binary_in):
    """A checkout with docs/build.sh, a rollspec in build/BINARY_IN, and a generate_reference.py that
    records the binary it was given and stops the build there (exit 3)."""
    repo = tmp_path / "repo"
    (repo / "docs").mkdir(parents=True)
    shutil.copy(BUILD, repo / "docs" / "build.sh")
    (repo / "docs" / "generate_reference.py").write_text(
        "import sys, pathlib\n"
        "pathlib.Path(sys.argv[sys.argv.index('--out') + 1], 'bin.txt').write_text(sys.argv[sys.argv.index('--bin') + 1])\n"
        "sys.exit(3)\n")
    if binary_in:
        (repo / "build" / binary_in).mkdir(parents=True)
        shutil.copy(BIN, repo / "build" / binary_in / "rollspec")
    return repo


@pytest.mark.parametrize("binary_in", ["release", "werror"])
def test_build_sh_finds_the_readme_build(tmp_path, binary_in):
    repo = stub_repository(tmp_path, binary_in)
    out = tmp_path / "site"
    r = build_docs(out, env={}, script=repo / "docs" / "build.sh")
    assert r.returncode == 3, r.stderr  # past the binary lookup, stopped by the stub
    assert (out / "src" / "bin.txt").read_text() == str(repo / "build" / binary_in / "rollspec")
    assert (out / ".rollspec-docs").exists()
    # Built before: the folder is its own, so it builds into it again and replaces only src/.
    (out / "html").mkdir()
    (out / "html" / "index.html").write_text("old page")
    assert build_docs(out, env={}, script=repo / "docs" / "build.sh").returncode == 3


def test_build_sh_without_a_binary_says_which_to_build(tmp_path):
    repo = stub_repository(tmp_path, None)
    r = build_docs(tmp_path / "site", env={}, script=repo / "docs" / "build.sh")
    assert r.returncode == 66 and "cmake --preset release && cmake --build --preset release" in r.stderr, r.stderr
    assert not (tmp_path / "site").exists()


def test_a_non_utf8_bench_record_stops_the_docs_build_in_one_line(tmp_path):
    records = tmp_path / "records"
    records.mkdir()
    (records / "bad.json").write_bytes(b'{"title": "\xff\xfe"}')
    r = build_docs(tmp_path / "site", env={"ROLLSPEC_BIN": BIN, "ROLLSPEC_BENCH_RECORDS": str(records)})
    assert r.returncode == 65, r.stderr
    assert r.stderr.strip() == "generate_reference: benchmark record bad.json: not UTF-8 text (byte 11)"


def record_csv(tmp_path, *args, stdout=subprocess.PIPE):
    return subprocess.run([sys.executable, str(SOURCE / "bench" / "record_csv.py"), "--record", str(tmp_path / "r.json"),
                           "--title", "t", "--describe", "d", *args], stdout=stdout, stderr=subprocess.PIPE,
                          text=True, timeout=60)


@pytest.mark.parametrize("case,args,code,fragment", [
    ("missing command", ["--", "no-such-command-here"], 66, "cannot run no-such-command-here"),
    ("--env NOEQUALS", ["--env", "NOEQUALS", "--", "echo", "a,b"], 64, "--env 'NOEQUALS': allowed: NAME=VALUE"),
    ("non-UTF-8 output", ["--", "printf", "a,b\\n\\377,2\\n"], 0, ""),
])
def test_record_csv_fails_in_one_line(tmp_path, case, args, code, fragment):
    r = record_csv(tmp_path, *args)
    assert r.returncode == code and "Traceback" not in r.stderr, r.stderr
    assert fragment in r.stderr and len(r.stderr.strip().splitlines()) == (1 if code else 0), r.stderr


def test_record_csv_on_a_full_standard_output(tmp_path):
    with open("/dev/full", "w") as full:
        r = record_csv(tmp_path, "--", "printf", "a,b\\n1,2\\n", stdout=full)
    assert r.returncode == 74 and "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr


def test_init_out_empty_is_a_usage_error():
    r = run(["init", "random-oscillator", "--out", ""])
    assert_refused(r, EX_USAGE, ["--out is empty"])
    assert r.stdout == ""


def test_compare_on_a_spread_of_1e300_gives_an_unbounded_interval(tmp_path):
    study = tmp_path / "s.ini"
    study.write_text(SMALL_OSCILLATOR.format(realisations=8, chunk=4, duration=4))
    out = tmp_path / "r.h5"
    assert run(["run", study, "--out", out, "--quiet"]).returncode == 0
    with h5py.File(out, "a") as f:
        f["/bands/std"][...] = np.full(f["/bands/std"].shape, 1e300)
    r = run(["compare", out, SOURCE / "studies" / "data" / "measured-psd.csv", "--measured-averages", "5"])
    assert r.returncode == 0 and "internal error" not in r.stderr, r.stderr
    assert "-inf..inf" in r.stdout


def test_an_explicit_patch_filter_the_path_law_does_not_apply_is_said(tmp_path):
    r = run(["plan", SOURCE / "studies" / "seed002-rig-1ms.ini", "--set", "contact.law=path"])
    assert "[contact] filter = patch: not applied: law = path resolves the contact on its strip" in r.stderr, r.stderr


def test_resume_reads_each_checkpointed_chunk_once(tmp_path):
    """Bytes read by the resume (/proc/PID/io rchar) against the chunk files' bytes: the build before read
    every chunk whole twice (once to check it, once to reduce it) and its header a few more times."""
    study = tmp_path / "s.ini"
    study.write_text(SMALL_OSCILLATOR.format(realisations=3000, chunk=1, duration=1))
    env = {**os.environ, "OMP_NUM_THREADS": "1"}
    out, ck = tmp_path / "r.h5", tmp_path / "r.h5.checkpoint"
    p = subprocess.Popen([BIN, "run", study, "--out", out, "--quiet"], stderr=subprocess.PIPE, text=True, env=env)
    while p.poll() is None and len(list(ck.glob("chunk_*.bin"))) < 1500:
        time.sleep(0.02)
    p.send_signal(signal.SIGINT)
    p.communicate(timeout=60)
    assert p.returncode == 130
    chunk_bytes = sum(f.stat().st_size for f in ck.glob("chunk_*.bin"))
    p = subprocess.Popen([BIN, "run", study, "--out", out, "--quiet", "--resume"], stderr=subprocess.PIPE, text=True,
                         env=env)
    read = 0
    while p.poll() is None:
        try:
            read = max(read, int(open(f"/proc/{p.pid}/io").read().split("rchar:")[1].split()[0]))
        except (OSError, IndexError, ValueError):
            pass
        time.sleep(0.002)
    assert p.wait() == 0
    assert read < 1.5 * chunk_bytes, f"read {read / chunk_bytes:.2f} times the chunks' bytes"


def test_resume_after_the_study_file_is_deleted(tmp_path):
    """`run STUDY --resume --out X` with STUDY gone since the interrupted run: the checkpoint's own study."""
    from conftest import assert_bitwise_equal
    study, kept = tmp_path / "s.ini", tmp_path / "kept.ini"
    study.write_text(SMALL_OSCILLATOR.format(realisations=400, chunk=2, duration=8))
    kept.write_text(study.read_text())
    out, ck = tmp_path / "r.h5", tmp_path / "r.h5.checkpoint"
    p = subprocess.Popen([BIN, "run", study, "--out", out, "--quiet"], stderr=subprocess.PIPE, text=True,
                         env={**os.environ, "OMP_NUM_THREADS": "1"})
    while p.poll() is None and not list(ck.glob("chunk_*.bin")):
        time.sleep(0.01)
    p.send_signal(signal.SIGINT)
    p.communicate(timeout=60)
    assert p.returncode == 130
    study.unlink()
    r = run(["run", study, "--resume", "--out", out], timeout=300)
    assert r.returncode == 0, r.stderr
    assert "s.ini no longer exists; resuming the study" in r.stderr
    ref = tmp_path / "ref.h5"
    assert run(["run", kept, "--out", ref, "--quiet"]).returncode == 0
    assert_bitwise_equal(out, ref)
