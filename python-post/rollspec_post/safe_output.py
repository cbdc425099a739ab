"""Every file rollspec_post writes goes through here, so a run never destroys what the user did not ask
it to (the rule of the engine's src/io/output_target.hpp):
  - a directory, FIFO, device or socket as the output (or a symbolic link to one) is refused;
  - an output that resolves to an input of the command (symlinks and hard links followed) is refused;
  - an existing regular file is replaced only if it carries rollspec_post's marker of the same kind
    (PNG tEXt entry, PDF /Creator, SVG dc:creator, HTML <meta name="generator">), or with --force;
  - the new file is written to a temporary in the same directory, flushed, fsync'ed and renamed onto
    the target; on any failure the temporary is removed and the old file is untouched. A symbolic link
    to a regular file stays: its target is replaced."""
import errno
import os
import stat

from .post_error import EX_CANTCREAT, EX_IOERR, EX_NOINPUT, EX_USAGE, PostError

MARKER_KEY = "rollspec-post"  # PNG tEXt keyword
KINDS = ("png", "pdf", "svg", "html")
PICTURES = (".png", ".pdf", ".svg")
HTML_MARKER = '<meta name="generator" content="rollspec-post html">'
HEAD_BYTES = 64 * 1024    # PNG tEXt, SVG metadata and the HTML head sit at the start
TAIL_BYTES = 256 * 1024   # the PDF info dictionary sits before the cross-reference table at the end


def marker(kind):
    """The metadata matplotlib's savefig writes for `kind` (png, pdf or svg)."""
    return {MARKER_KEY: "png"} if kind == "png" else {"Creator": f"rollspec-post {kind}"}


def file_kind_name(mode):
    for test, name in ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return name
    return "not a regular file"


def _png_marked(fh):
    """True if a tEXt chunk before the image data is `rollspec-post\\0png`."""
    if fh.read(8) != b"\x89PNG\r\n\x1a\n":
        return False
    for _ in range(64):  # matplotlib writes its few text chunks first
        head = fh.read(8)
        if len(head) < 8:
            return False
        size, name = int.from_bytes(head[:4], "big"), head[4:]
        if name in (b"IDAT", b"IEND") or size > HEAD_BYTES:
            return False
        body = fh.read(size)
        fh.seek(4, os.SEEK_CUR)  # CRC
        if name == b"tEXt" and body == MARKER_KEY.encode() + b"\0png":
            return True
    return False


def _tail(fh, size):
    end = fh.seek(0, os.SEEK_END)
    fh.seek(max(0, end - size))
    return fh.read(size)


def has_marker(path, kind):
    """True if the regular file `path` is a rollspec_post output of `kind` (older pictures carry the
    Creator rollspec_post that psd and panels wrote before the marker)."""
    try:
        with open(path, "rb") as fh:
            if kind == "png":
                return _png_marked(fh)
            if kind == "pdf":
                ok = fh.read(5) == b"%PDF-"
                tail = _tail(fh, TAIL_BYTES)
                return ok and (b"/Creator (rollspec-post pdf)" in tail or b"/Creator (rollspec_post)" in tail)
            head = fh.read(HEAD_BYTES)
    except OSError:
        return False
    if kind == "svg":
        return b"<svg" in head and (b"<dc:title>rollspec-post svg</dc:title>" in head
                                    or b"<dc:title>rollspec_post</dc:title>" in head)
    return kind == "html" and head.lstrip().lower().startswith(b"<!doctype html") and HTML_MARKER.encode() in head


def _same_file(a, b):
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.realpath(a) == os.path.realpath(b)


def refuse_inputs(out, inputs, option="--out"):
    """The resolved output path, unless it is one of the command's inputs (links followed)."""
    if not out:
        raise PostError(f"{option}: empty path; allowed: a file name", EX_USAGE)
    target = os.path.realpath(out)
    for i in inputs:
        if i and _same_file(target, i):
            raise PostError(f"{option} {out}: is the input {i} of this command; allowed: another file name", EX_USAGE)
    return target


def check_output(out, kind, inputs=(), force=False, option="--out"):
    """The path to write (symlinks resolved) after the checks above; PostError otherwise."""
    target = refuse_inputs(out, inputs, option)
    try:
        st = os.stat(target)
    except FileNotFoundError:
        st = None
    except OSError as e:
        raise PostError(f"{option} {out}: cannot be checked ({e.strerror})", EX_CANTCREAT) from None
    if st is not None and not stat.S_ISREG(st.st_mode):
        raise PostError(f"{option} {out}: is {file_kind_name(st.st_mode)}; allowed: a regular file", EX_CANTCREAT)
    if st is not None and not force and not has_marker(target, kind):
        raise PostError(f"{option} {out}: exists and is not a rollspec-post {kind} output; allowed: a new file, "
                        f"a {kind} written by rollspec-post, or --force to replace it", EX_CANTCREAT)
    directory = os.path.dirname(target)
    if not os.path.isdir(directory):
        raise PostError(f"{option} {out}: cannot create (no directory {directory})", EX_CANTCREAT)
    return target


def check_input(path, what="input", max_bytes=None):
    """A regular file, refused before it is opened otherwise (a FIFO would block, /dev/zero never ends)."""
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise PostError(f"{path}: no such file", EX_NOINPUT) from None
    except OSError as e:
        raise PostError(f"{path}: cannot be read ({e.strerror})", EX_NOINPUT) from None
    if not stat.S_ISREG(st.st_mode):
        raise PostError(f"{path}: is {file_kind_name(st.st_mode)}; allowed: a regular file as {what}", EX_NOINPUT)
    if max_bytes is not None and st.st_size > max_bytes:
        raise PostError(f"{path}: {st.st_size} bytes; allowed: {what} up to {max_bytes // 2**20} MiB", EX_NOINPUT)
    return path


def _new_file_mode(target):
    """The replaced file's permissions, or those a plain open() would give a new file."""
    try:
        return stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        mask = os.umask(0)
        os.umask(mask)
        return 0o666 & ~mask


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # EPERM: alive, someone else's
        pass
    return True


def remove_stale_temporaries(target):
    """Temporaries of `target` left by killed runs (`.NAME.tmp-PID-XXXX` of a dead PID)."""
    import glob
    directory, name = os.path.split(target)
    for path in glob.glob(os.path.join(glob.escape(directory), glob.escape(f".{name}.tmp-") + "*-*")):
        pid = os.path.basename(path)[len(name) + 6:].split("-")[0]
        if pid.isdigit() and not _alive(int(pid)) and os.path.isfile(path) and not os.path.islink(path):
            try:
                os.unlink(path)
            except OSError:
                pass


def _create_temporary(target):
    import tempfile
    remove_stale_temporaries(target)
    directory, name = os.path.split(target)
    try:
        return tempfile.mkstemp(prefix=f".{name}.tmp-{os.getpid()}-", dir=directory)
    except OSError as e:
        raise PostError(f"{target}: cannot create a file in {directory} ({e.strerror})", EX_CANTCREAT) from None


def write_atomic(target, write):
    """Calls write(binary file object) on a temporary next to `target`, then renames it onto `target`."""
    fd, tmp = _create_temporary(target)
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, _new_file_mode(target))
        os.replace(tmp, target)
    except BaseException as e:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(e, OSError):
            code = EX_CANTCREAT if e.errno in (errno.EACCES, errno.EPERM, errno.EROFS) else EX_IOERR
            raise PostError(f"{target}: cannot write ({e.strerror or e}); the previous file is unchanged", code) \
                from None
        raise
    _sync_directory(os.path.dirname(target))
    return target


def _sync_directory(directory):
    """The rename itself survives a crash only once the directory is on disk; best effort."""
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def picture_kind(out, allowed=PICTURES):
    """png, pdf or svg from the output name."""
    ext = os.path.splitext(os.fspath(out))[1].lower()
    if ext not in allowed:
        raise PostError(f"{out}: unknown picture type {ext or '(none)'!r}; allowed: {', '.join(allowed)}", EX_USAGE)
    return ext[1:]


def save_figure(fig, fh, kind, dpi=150):
    """Figure to an open binary file with the marker of `kind`."""
    fig.savefig(fh, format=kind, dpi=dpi, metadata=marker(kind))


def emit_figure(fig, out, kind=None, dpi=150):
    """A figure to a path or an open binary file, with the marker of `kind` (default: from the name)."""
    if not isinstance(out, (str, os.PathLike)):
        save_figure(fig, out, kind or "png", dpi)
        return out
    import io
    kind, buf = kind or picture_kind(out), io.BytesIO()
    save_figure(fig, buf, kind, dpi)  # library callers too: a failed write leaves the old file
    write_atomic(os.path.realpath(out), lambda fh: fh.write(buf.getvalue()))
    return out
