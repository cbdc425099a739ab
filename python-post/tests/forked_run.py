"""`python3 -m rollspec_post ARGS` run in a fork of the test process instead of a new interpreter.

A new interpreter spends about 1.5 s of CPU importing numpy, h5py and matplotlib before the
command starts; the fault suite runs hundreds of commands. The fork has them imported already and
is otherwise the command as a user runs it: its own stdin (/dev/null), stdout and stderr (pipes),
sys.argv, exit status (SystemExit as Python maps it; an uncaught exception prints its traceback and
exits 1, as the interpreter does), signal handlers and working directory. What only a new interpreter
can show (a Python without a module, a changed environment, `-S`) stays with subprocess.run, and
ROLLSPEC_POST_TESTS_SUBPROCESS=1 runs every case that way."""
import io
import os
import selectors
import signal
import subprocess
import sys
import time
import traceback

PACKAGE = "rollspec_post"
MODULES = ("numpy", "h5py", "matplotlib.figure", "matplotlib.backends.backend_agg",
           "matplotlib.backends.backend_pdf", "matplotlib.backends.backend_svg")


def preload():
    """Imports what every command imports, once, in the test process."""
    import importlib
    for m in MODULES:
        importlib.import_module(m)


def forking():
    return os.environ.get("ROLLSPEC_POST_TESTS_SUBPROCESS", "") != "1"


def _child(args, out_w, err_w):
    """In the fork: the command's stdio, argv and exit status; never returns."""
    code = 1
    try:
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        os.dup2(out_w, 1)
        os.dup2(err_w, 2)
        sys.stdin = io.TextIOWrapper(io.FileIO(0, "r", closefd=False))
        sys.stdout = io.TextIOWrapper(io.FileIO(1, "w", closefd=False), write_through=True)
        sys.stderr = io.TextIOWrapper(io.FileIO(2, "w", closefd=False), errors="backslashreplace",
                                      write_through=True)
        for sig in (signal.SIGTERM, signal.SIGHUP, signal.SIGPIPE):
            signal.signal(sig, signal.SIG_DFL if sig != signal.SIGPIPE else signal.SIG_IGN)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        import runpy
        sys.argv = [os.path.join(os.path.dirname(__import__(PACKAGE).__file__), "__main__.py"), *args]
        try:
            runpy.run_module(PACKAGE, run_name="__main__", alter_sys=True)
            code = 0
        except SystemExit as e:
            if e.code is None:
                code = 0
            elif isinstance(e.code, int):
                code = e.code
            else:
                print(e.code, file=sys.stderr)
                code = 1
        except KeyboardInterrupt:
            code = 130
        except BaseException:  # as the interpreter: the traceback on stderr, exit 1
            traceback.print_exc()
            code = 1
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except Exception:
                pass
    finally:
        os._exit(code & 0xFF)


def run(args, timeout):
    """subprocess.CompletedProcess of the command; subprocess.TimeoutExpired after `timeout` s (killed)."""
    args = [str(a) for a in args]
    out_r, out_w = os.pipe()
    err_r, err_w = os.pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        os.close(out_r)
        os.close(err_r)
        _child(args, out_w, err_w)
    os.close(out_w)
    os.close(err_w)
    chunks = {out_r: [], err_r: []}
    deadline = time.monotonic() + timeout
    with selectors.DefaultSelector() as sel:
        for fd in chunks:
            sel.register(fd, selectors.EVENT_READ)
        while sel.get_map():
            left = deadline - time.monotonic()
            if left <= 0:
                break
            for key, _ in sel.select(left):
                data = os.read(key.fd, 65536)
                if data:
                    chunks[key.fd].append(data)
                else:
                    sel.unregister(key.fd)
        timed_out = bool(sel.get_map())
    if timed_out:
        os.kill(pid, signal.SIGKILL)
    _, status = os.waitpid(pid, 0)
    for fd in chunks:
        os.close(fd)
    out, err = (b"".join(chunks[fd]).decode(errors="replace") for fd in (out_r, err_r))
    command = [sys.executable, "-m", PACKAGE, *args]
    if timed_out:
        raise subprocess.TimeoutExpired(command, timeout, output=out, stderr=err)
    return subprocess.CompletedProcess(command, os.waitstatus_to_exitcode(status), out, err)
