"""rollspec_post: plots and reports from rollspec result files (run with Debian's /usr/bin/python3)."""

__version__ = "0.1.0"
__all__ = ["open_result", "run"]


def __getattr__(name):
    """The package API, imported on first use: `python3 -m rollspec_post` must start without h5py or
    xarray so that it can say in one line which module is missing."""
    if name in __all__:
        from . import notebook
        return getattr(notebook, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
