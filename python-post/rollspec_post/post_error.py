"""The one error rollspec_post raises, PostError, and the exit codes (sysexits.h) it carries: the bottom of
the package, imported by the modules that read (result_file) and write (safe_output) files alike."""

# sysexits.h
EX_USAGE, EX_DATAERR, EX_NOINPUT, EX_UNAVAILABLE, EX_SOFTWARE, EX_CANTCREAT, EX_IOERR = 64, 65, 66, 69, 70, 73, 74


class PostError(Exception):
    """A user-facing error with the exit code the command returns."""

    def __init__(self, message, exit_code):
        super().__init__(message)
        self.exit_code = exit_code
