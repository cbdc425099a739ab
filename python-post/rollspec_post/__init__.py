"""rollspec_post: plots and reports from rollspec result files (run with Debian's /usr/bin/python3)."""

__version__ = "0.1.0"

from .notebook import open_result, run  # noqa: E402,F401  (the package API)

__all__ = ["open_result", "run"]
