"""The comparison with a measurement is `rollspec compare`'s, run as a command: its JSON answer (the bands and
how each was used, the level offset, the combined test, the warnings, how the files were read, the spectra
compared) is what the report and the ΔL panel show. Nothing of the comparison is computed here, so the
page and the command cannot disagree."""
import json
import os
import pathlib
import re
import shutil
import subprocess
from dataclasses import dataclass, field

from .result_file import EX_DATAERR, EX_UNAVAILABLE, PostError

WHY_LEFT_OUT = {"noise floor": "within the margin of the noise recording's level",
                "flat floor": "flat at the measurement's lowest level while the model falls (the logger's floor)"}
THEORY = "kernels/spectral/README.md"  # the theory notes the engine's messages cite by equation


def engine_binary():
    """$ROLLSPEC_BIN, else `rollspec` on PATH, else this checkout's build/release/rollspec."""
    if os.environ.get("ROLLSPEC_BIN"):
        return os.environ["ROLLSPEC_BIN"]
    found = shutil.which("rollspec")
    if found:
        return found
    local = pathlib.Path(__file__).resolve().parents[2] / "build" / "release" / "rollspec"
    if local.exists():
        return str(local)
    raise PostError("no rollspec binary: set ROLLSPEC_BIN=/path/to/rollspec, or put rollspec on PATH", EX_UNAVAILABLE)


@dataclass
class CompareOptions:
    """The options of `rollspec compare` the report passes through (None/False: compare's default)."""
    sensor: str = None
    columns: list = field(default_factory=list)
    unit: str = None
    scale: float = None
    fs: float = None
    time_column: str = None
    skip_rows: int = None
    roll_per_channel: bool = False
    measured_averages: float = None
    noise: str = None
    noise_margin: float = None
    keep_floor_bands: bool = False
    same_surface: bool = False
    fmin: float = None
    fmax: float = None
    test_level: float = None

    def arguments(self):
        args = []
        for name in ("sensor", "unit", "scale", "fs", "time_column", "skip_rows", "measured_averages", "noise",
                     "noise_margin", "fmin", "fmax", "test_level"):
            value = getattr(self, name)
            if value is not None and not (name == "fmax" and value == float("inf")):
                args += [f"--{name.replace('_', '-')}", f"{value:.17g}" if isinstance(value, float) else str(value)]
        for column in self.columns or []:
            args += ["--column", column]
        for flag in ("roll_per_channel", "keep_floor_bands", "same_surface"):
            if getattr(self, flag):
                args.append(f"--{flag.replace('_', '-')}")
        return args


def error_line(stderr):
    """compare's own error line (its notes come first); else its last line."""
    lines = [ln.strip() for ln in stderr.splitlines() if ln.strip()]
    errors = [ln for ln in lines if "error:" in ln]
    return (errors or lines or ["no message"])[-1]


def run_compare(result, measurements, options=None):
    """`rollspec compare RESULT MEASUREMENT... --format json` with `options`; its answer as a dict. A refusal
    is a PostError with compare's message and exit code."""
    options = options or CompareOptions()
    binary = engine_binary()
    argv = [binary, "compare", str(result), *map(str, measurements), "--format", "json", *options.arguments()]
    try:
        r = subprocess.run(argv, capture_output=True, text=True, errors="backslashreplace")
    except OSError as e:
        raise PostError(f"cannot run {binary} ({e.strerror}): set ROLLSPEC_BIN=/path/to/rollspec, or put rollspec "
                        "on PATH", EX_UNAVAILABLE) from None
    if r.returncode != 0:
        raise PostError(error_line(r.stderr), r.returncode if 0 < r.returncode < 128 else EX_DATAERR)
    try:
        answer = json.loads(r.stdout)
    except ValueError:
        raise PostError(f"{binary} compare: its answer is no JSON (an older rollspec? it needs --format json)",
                        EX_DATAERR) from None
    if "bands" not in answer or "measured_psd" not in answer:
        raise PostError(f"{binary} compare: its JSON lacks bands or measured_psd (a rollspec older than this "
                        "rollspec_post); point ROLLSPEC_BIN at the matching binary", EX_DATAERR)
    return answer


_REF = r"(?:kernels/spectral(?:/README\.md)?,? )?(D-[0-9]+[a-z]?)"
_WHOLE = re.compile(r"\s*\(" + _REF + r"\)")  # "(kernels/spectral D-26)", "(D-16)"
_TAIL = re.compile(r";\s*" + _REF + r"(?=\))")  # "(--noise-margin DB sets the margin; kernels/spectral D-33a)"


def plain_text(text):
    """(the text without the theory notes' equation labels, [the labels]): the page cites them in footnotes."""
    labels = _WHOLE.findall(text) + _TAIL.findall(text)
    return _TAIL.sub("", _WHOLE.sub("", text)), labels


def tested(answer):
    return [b for b in answer["bands"] if b["use"] == "test"]


def left_out(answer):
    return [b for b in answer["bands"] if b["use"] != "test"]
