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
    except SystemExit:
        raise
    except MemoryError:
        fail("out of memory", EX_SOFTWARE)
    except ModuleNotFoundError as e:
        fail(f"needs the Python module {e.name} (run with Debian's /usr/bin/python3)", EX_UNAVAILABLE)
    except UnicodeError as e:
        fail(f"not UTF-8 text: {e}", EX_DATAERR)
    except OSError as e:
        where = f"{e.filename}: " if e.filename else ""
        if e.errno in (errno.ENOSPC, errno.EDQUOT):
            fail(f"{where}no space left on device", EX_IOERR)
        fail(f"{where}{e.strerror or e}", EX_IOERR if e.errno in (errno.EIO, errno.EPIPE) else EX_CANTCREAT)
    except Exception as e:  # a bug: still one line
        fail(f"internal error ({type(e).__name__}: {e}); please report this", EX_SOFTWARE)
    sys.exit(code or 0)
