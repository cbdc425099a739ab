"""The command's rule for every script of the repository (docs/, bench/, studies/): a failure is one line
on stderr, `NAME: error: ...`, and a sysexits code; no traceback, no hang. Standard library only, so a
script can say in one line that a module is missing.

    from rollspec_post.script_main import fail, script_main
    ...
    if __name__ == "__main__":
        script_main(main)
"""
import errno
import os
import signal
import subprocess
import sys

EX_USAGE, EX_DATAERR, EX_NOINPUT, EX_UNAVAILABLE, EX_SOFTWARE, EX_CANTCREAT, EX_IOERR = 64, 65, 66, 69, 70, 73, 74
EX_INTERRUPTED = 130


def script_name():
    name = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else "script"
    return name[:-3] if name.endswith(".py") else name


def one_line(text):
    return " ".join(str(text).split())


def fail(message, code):
    """Ends the script: `NAME: error: MESSAGE` on stderr, exit `code`."""
    print(f"{script_name()}: error: {one_line(message)}", file=sys.stderr)
    sys.stderr.flush()
    _quiet_stdout()
    sys.exit(code)


def _quiet_stdout():
    """Points stdout at /dev/null: whatever could not be written is not reported twice at exit."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def flush_stdout():
    """Standard output flushed now, so that a full disk or a closed pipe is one line and exit 74."""
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        _quiet_stdout()  # `script | head`: the reader chose to stop; no failure
    except OSError as e:
        _quiet_stdout()
        fail(f"cannot write standard output: {e.strerror or e}", EX_IOERR)


def _interrupt(signum, frame):
    raise KeyboardInterrupt


def _one_line_for(e):
    """(message, exit code) of an exception that ends a script."""
    code = getattr(e, "exit_code", None)
    if isinstance(code, int) and code > 0:
        return str(e), code
    if isinstance(e, MemoryError):
        return "out of memory", EX_SOFTWARE
    if isinstance(e, ModuleNotFoundError) and (e.name or "").split(".")[0] == "rollspec":
        return (f"needs the Python module {e.name}: install it (cmake --install BUILD --component python --prefix "
                "~/.local, as the README's first command does) or put BUILD/python on PYTHONPATH"), EX_UNAVAILABLE
    if isinstance(e, ModuleNotFoundError):
        return f"needs the Python module {e.name} (run with Debian's /usr/bin/python3)", EX_UNAVAILABLE
    if isinstance(e, UnicodeError):
        return f"not UTF-8 text: {e}", EX_DATAERR
    if isinstance(e, OSError):
        where = f"{e.filename}: " if e.filename else ""
        if e.errno in (errno.ENOSPC, errno.EDQUOT):
            return f"{where}no space left on device", EX_IOERR
        if e.errno == errno.ENOENT:
            return f"{where}{e.strerror}", EX_NOINPUT
        return f"{where}{e.strerror or e}", EX_IOERR if e.errno in (errno.EIO, errno.EPIPE) else EX_CANTCREAT
    return f"internal error ({type(e).__name__}: {e}); please report this", EX_SOFTWARE


def one_line_errors():
    """For a script that runs at module level (a gallery example): when it is the program (python3 FILE),
    an exception that ends it is one line and an exit code, not a traceback. Run inside another program
    (sphinx-gallery, which gives the script no __file__), nothing changes."""
    file = sys._getframe(1).f_globals.get("__file__")
    if not file or not sys.argv or os.path.abspath(sys.argv[0]) != os.path.abspath(file):
        return
    def hook(kind, e, tb):
        if isinstance(e, KeyboardInterrupt):
            message, code = "interrupted", EX_INTERRUPTED
        else:
            message, code = _one_line_for(e)
        print(f"{script_name()}: error: {one_line(message)}", file=sys.stderr)
        sys.stderr.flush()
        os._exit(code)
    sys.excepthook = hook
    for sig in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, _interrupt)


def require_program(path, what):
    """A program the script runs (a rollspec build, a bench binary), checked before any work: an executable
    regular file, else one line and exit 66."""
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        fail(f"{what} {path}: no executable program there; allowed: the path of a build's binary", EX_NOINPUT)
    return path


def run_or_exit(cmd, failed="{command}: exit {code}\n{stderr}"):
    """Runs the program `cmd` (its output captured as text) and returns the finished run; a failure ends the
    script as sys.exit(message) does, the message `failed` filled in with the command, its exit code and stderr."""
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode:
        sys.exit(failed.format(command=" ".join(map(str, cmd)), code=r.returncode, stderr=r.stderr))
    return r


def check_output_file(path, what, own=lambda target: False):
    """The file `path` would replace (a symbolic link followed), before any work: refused (exit 73, one
    line) if it is a directory, FIFO, device or socket, if its folder is missing, or if it exists and
    own(target) does not recognise it as this script's. Returns the target."""
    target = os.path.realpath(path)
    if os.path.exists(target) and not os.path.isfile(target):
        fail(f"{what} {path}: is not a regular file; allowed: a new file or one this script wrote", EX_CANTCREAT)
    if os.path.exists(target) and not own(target):
        fail(f"{what} {path}: exists and was not written by this script; allowed: a new file or one it wrote "
             "(move it away or choose another path)", EX_CANTCREAT)
    if not os.path.isdir(os.path.dirname(target)):
        fail(f"{what} {path}: no folder {os.path.dirname(target)}", EX_CANTCREAT)
    return target


def starts_with(prefix):
    """own() of check_output_file: a regular file whose first bytes are `prefix` (bytes)."""
    def own(target):
        try:
            with open(target, "rb") as fh:
                return fh.read(len(prefix)) == prefix
        except OSError:
            return False
    return own


def write_output_file(target, data):
    """`data` (bytes) written to a temporary beside `target` and renamed onto it: the old file stays
    whole if the write fails."""
    from .safe_output import write_atomic
    from .result_file import PostError
    try:
        write_atomic(target, lambda fh: fh.write(data))
    except PostError as e:
        fail(e, e.exit_code)


def own_folder(path, name):
    """A folder for the script's files (--work, --keep): made if missing; an existing one must be empty
    or one this script made before (it holds .NAME), else refused (exit 73) and left as it is."""
    marker = os.path.join(path, f".{name}")
    if os.path.islink(path):
        fail(f"{path}: is a symbolic link; allowed: a new folder, or one {name} made", EX_CANTCREAT)
    if os.path.exists(path):
        if not os.path.isdir(path):
            fail(f"{path}: exists and is not a folder; allowed: a new folder, or one {name} made", EX_CANTCREAT)
        if os.listdir(path) and not os.path.isfile(marker):
            fail(f"{path}: holds files {name} did not make; allowed: a new or empty folder, or one it made "
                 f"(it holds .{name})", EX_CANTCREAT)
    try:
        os.makedirs(path, exist_ok=True)
        open(marker, "a").close()
    except OSError as e:
        fail(f"{path}: cannot make it ({e.strerror})", EX_CANTCREAT)
    return path


def script_main(main):
    """Runs main() (its return value is the exit code) under the rule: every failure is one line."""
    for sig in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, _interrupt)
    try:
        code = main()
        flush_stdout()
    except KeyboardInterrupt:
        print(f"{script_name()}: error: interrupted", file=sys.stderr)
        sys.stderr.flush()
        os._exit(EX_INTERRUPTED)
    except SystemExit as e:  # argparse's --help and usage errors, sys.exit("message"): output flushed first
        flush_stdout()
        if isinstance(e.code, str):  # sys.exit("name: message"): one line, "name: error: message"
            text = e.code
            for prefix in (script_name() + ": ", "error: "):
                text = text[len(prefix):] if text.startswith(prefix) else text
            fail(text, 1)
        raise
    except Exception as e:  # a damaged input, a full disk, a bug: still one line
        fail(*_one_line_for(e))
    sys.exit(code or 0)
