"""python3 -m rollspec_post COMMAND ... (installed: rollspec-post COMMAND ...): plots and reports from rollspec result files.

Every failure is one line on stderr and a sysexits code (64 usage, 65 bad data, 66 missing input, 69 a
Python module missing, 73 cannot create the output, 74 I/O error, 70 a bug). Only the standard library
is imported at the top, so a Python without numpy, h5py or matplotlib is told so in one line."""
import argparse
import io
import math
import os
import sys

EX_USAGE, EX_UNAVAILABLE, EX_SOFTWARE = 64, 69, 70
# module, the Debian package that provides it
REQUIRED = (("numpy", "python3-numpy"), ("h5py", "python3-h5py"), ("matplotlib", "python3-matplotlib"))
PICTURES = (".png", ".pdf", ".svg")
MAX_DPI = 1200  # a 7.5-inch figure at 1200 dpi is 9000 pixels wide; more only exhausts memory
MAX_CSV_BYTES = 64 * 2**20  # a measured PSD of a million lines is ~40 MB
MAX_MEASUREMENT_BYTES = 2**30  # a recording: 40 million samples as text; a 5 GB file of zeros is refused first


def program_name():
    """`rollspec-post` when run as the installed command (pyproject.toml), else `python3 -m rollspec_post`."""
    name = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else ""
    return name if name == "rollspec-post" else "python3 -m rollspec_post"


class Parser(argparse.ArgumentParser):
    """argparse with one line and exit 64 for a usage error (its default is the usage text and exit 2)."""

    def error(self, message):
        self.exit(EX_USAGE, f"{self.prog.replace('python3 -m ', '')}: error: {' '.join(message.split())}\n")


def finite(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"{text!r}: allowed: a finite number")
    return v


def frequency(text):
    """A frequency in Hz: finite and >= 0."""
    v = finite(text)
    if v < 0:
        raise argparse.ArgumentTypeError(f"{text!r}: allowed: a frequency >= 0 Hz")
    return v


def upper_frequency(text):
    """--fmax of report: >= 0 Hz, or inf (its default: no upper limit)."""
    if text.strip().lower() in ("inf", "+inf", "infinity"):
        return math.inf
    return frequency(text)


def dpi(text):
    v = finite(text)
    if not 0 < v <= MAX_DPI:
        raise argparse.ArgumentTypeError(f"{text!r}: allowed: 0 < dpi <= {MAX_DPI}")
    return v


def writer(sub, name, help_text, out_types, out_help):
    """A subcommand that writes --out: `out_types` are the allowed extensions (None: any name, HTML)."""
    p = sub.add_parser(name, help=help_text)
    p.add_argument("--out", "-o", required=True, help=out_help)
    p.add_argument("--force", action="store_true",
                   help="replace an existing --out that rollspec-post did not write (never an input)")
    p.set_defaults(out_types=out_types)
    return p


def build_parser():
    parser = Parser(prog=program_name(), description="Plots and reports from rollspec result files.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = writer(sub, "psd", "acceleration PSD with confidence band, measurement and band levels", PICTURES,
               "output picture: .png, .pdf or .svg")
    p.add_argument("result", help="rollspec result file (HDF5)")
    p.add_argument("--bands", action="store_true", help="draw third-octave band levels (and ΔL with a measurement)")
    p.add_argument("--sensor", help="the row drawn and compared: a name, or K for sensor_K "
                                    "(default: sensor_mean if present, else the first)")
    p.add_argument("--sensors", choices=("one", "all"), default="one", help="all: every sensor as thin grey lines too")
    p.add_argument("--xscale", choices=("linear", "log"), default="linear", help="frequency axis (default linear)")
    p.add_argument("--dpi", type=dpi, default=150, help=f"resolution of a PNG (default 150, at most {MAX_DPI})")
    p.add_argument("--title", help="figure title (default: none)")
    p.add_argument("--label", help="legend name of the simulated mean (default: SENSOR, mean of K)")
    p.add_argument("--measurement-label", help="legend name of the measurement (default: measurement)")
    p.add_argument("--ylim", nargs=2, type=finite, metavar=("LOW", "HIGH"), help="level axis range in dB")
    p.add_argument("--style", choices=("default", "seed"), default="default",
                   help="seed: the seeds' figures, computed dotted, measured solid black, both in the legend")
    t = writer(sub, "texture", "line texture, surface image, target vs realised PSD", (".png",), "output PNG")
    t.add_argument("texture_file", help="file written by rollspec texture")
    s = writer(sub, "stiffness", "P(δ) and k(δ) with their spread over realisations, and Hertz", (".png",), "output PNG")
    s.add_argument("table", help="stiffness table (HDF5, filetype rollspec-stiffness-table)")
    j = writer(sub, "trajectory", "rolling-beam node paths, speeds and energies over time", (".png",), "output PNG")
    j.add_argument("result", help="rollspec result file with /time_history/position")
    g = writer(sub, "roughness", "roughness PSD along the path: raw and with each contact filter (ball-on-beam)",
               PICTURES, "output picture: .png, .pdf or .svg")
    g.add_argument("result", help="rollspec result file with /roughness")
    b = writer(sub, "bench", "work-precision plot: error against run time, log-log, one line per method", (".png",),
               "output PNG")
    b.add_argument("csv", help="CSV with columns method (or integrator), seconds (or time_s), error_db (or error)")
    n = writer(sub, "panels", "results side by side in the seeds' style: PSD level in dB, linear 0-5 kHz", PICTURES,
               "output picture: .png, .pdf or .svg")
    n.add_argument("--panel", nargs="+", action="append", required=True, metavar="WORD",
                   help="TITLE FILE=LABEL [FILE=LABEL ...]: one panel; FILE a result or a measured PSD CSV (rollspec psd's, "
                        "or frequency and PSD columns); the first curve solid black, the others dotted/dashed")
    n.add_argument("--sensor", help="a sensor name, or K for sensor_K "
                                    "(default: sensor_mean if present, else the first)")
    n.add_argument("--fmax", type=frequency, default=5000.0, help="highest frequency drawn (Hz; default 5000)")
    n.add_argument("--column", help="PSD column of a measured CSV that has several (default: psd, or its only one)")
    w = writer(sub, "sweep", "a sweep result: band levels against the swept value, and PSDs of points overlaid",
               PICTURES, "output picture: .png, .pdf or .svg")
    w.add_argument("result", help="rollspec result file of a sweep (HDF5 with /sweep)")
    w.add_argument("--sensor", help="sensor name or index (default: sensor_mean if present, else 0)")
    w.add_argument("--points", nargs="+", type=int, metavar="I",
                   help="indices along the first swept key whose PSDs are overlaid (default: all)")
    r = writer(sub, "report", "one self-contained HTML page: key figures, PSD, provenance, study", None, "output HTML")
    r.add_argument("result", help="rollspec result file (HDF5)")
    r.add_argument("--sensor", help="a sensor name, or K for sensor_K "
                                    "(default: sensor_mean if present, else the first)")
    r.add_argument("--fmin", type=frequency, help="lowest band edge compared (Hz; default: every band)")
    r.add_argument("--fmax", type=upper_frequency, help="highest band edge compared (Hz; default: every band)")
    r.add_argument("--loss-threshold", type=finite, default=0.05, metavar="SHARE",
                   help="loss-of-contact share (0-1) above which the page opens with a warning (default 0.05)")
    p.add_argument("--fmin", type=frequency, help="lowest frequency drawn and compared (Hz; default: the study's band "
                   "range, from 0 on a linear axis)")
    p.add_argument("--fmax", type=frequency, help="highest frequency drawn and compared (Hz; default: the study's band range)")
    for q in (p, r, n):
        q.add_argument("--point", metavar="K|KEY=VALUE",
                       help="of a sweep result: the point read, K (1-based, run order) or section.key=value[,...]")
    for q in (p, r):
        compare_arguments(q)
    return parser


def compare_arguments(q):
    """The measurement and the options of `rollspec compare` that python-post passes through to it."""
    q.add_argument("--measurement", nargs="+", metavar="FILE",
                   help="the recordings (one file per roll: CSV, WAV/FLAC, .mat) or one PSD table, compared by "
                        "`rollspec compare` (ROLLSPEC_BIN, else rollspec on PATH)")
    q.add_argument("--noise", metavar="QUIET", help="a recording of the rig at rest (or its PSD table): bands within "
                                                    "--noise-margin of it leave the test")
    q.add_argument("--noise-margin", type=finite, metavar="DB", help="compare's margin to the noise (default 10 dB)")
    q.add_argument("--keep-floor-bands", action="store_true",
                   help="keep bands that look like the logger's noise floor (no --noise) in the test")
    q.add_argument("--same-surface", action="store_true",
                   help="the measurement was taken on the very surface the model's contact table was built on")
    q.add_argument("--column", action="append", metavar="NAME",
                   help="channel(s) of the recordings, or the PSD column of a PSD table (repeatable)")
    q.add_argument("--unit", help="unit of the recordings' values (default: from the file; m/s2, g, mm/s2, ...)")
    q.add_argument("--scale", type=finite, help="physical units per file unit, or per full scale (integer PCM)")
    q.add_argument("--fs", type=finite, metavar="HZ", help="sample rate of the recordings (default: from the file)")
    q.add_argument("--time-column", metavar="NAME", help="time column of CSV recordings, or none")
    q.add_argument("--skip-rows", type=int, metavar="N", help="CSV lines before the header (default: from the data)")
    q.add_argument("--roll-per-channel", action="store_true", help="each channel of the recordings is one roll")
    q.add_argument("--measured-averages", type=finite, metavar="M",
                   help="independent rolls averaged into a PSD table (recordings: their number)")
    q.add_argument("--test-level", type=finite, metavar="A", help="level of the combined test (default 0.05)")


COMPARE_OPTIONS = ("noise", "noise_margin", "keep_floor_bands", "same_surface", "column", "unit", "scale", "fs",
                   "time_column", "skip_rows", "roll_per_channel", "measured_averages", "test_level")


def compare_options(args):
    """The CompareOptions of the command line (the sensor and band range are the caller's)."""
    from .engine_compare import CompareOptions
    return CompareOptions(columns=args.column or [], unit=args.unit, scale=args.scale, fs=args.fs,
                          time_column=args.time_column, skip_rows=args.skip_rows,
                          roll_per_channel=args.roll_per_channel, measured_averages=args.measured_averages,
                          noise=args.noise, noise_margin=args.noise_margin, keep_floor_bands=args.keep_floor_bands,
                          same_surface=args.same_surface, test_level=args.test_level)


def missing_module(name=None):
    """One line naming every module this package needs that the running Python lacks and the command
    that installs them, else None (found, not imported: a refusal must not wait for matplotlib).
    `name`: one known to be missing (found but failing to import)."""
    import importlib.util
    missing = [m for m, _ in REQUIRED if m == name or importlib.util.find_spec(m) is None]
    if not missing:
        return None
    needed = ", ".join(m for m, _ in REQUIRED)
    packages = " ".join(p for m, p in REQUIRED if m in missing)
    return (f"{program_name().replace('python3 -m rollspec_post', 'rollspec-post')} needs {needed} "
            f"(missing from {sys.executable}: {', '.join(missing)}): on Debian, apt-get install {packages}, "
            "or run it with /usr/bin/python3")


def inputs(args):
    """(path, what, size limit) of every file the command reads."""
    files = [(getattr(args, n), "a rollspec HDF5 file", None) for n in ("result", "texture_file", "table")
             if getattr(args, n, None)]
    if getattr(args, "csv", None):
        files.append((args.csv, "a benchmark CSV", MAX_CSV_BYTES))
    for path in getattr(args, "measurement", None) or []:
        files.append((path, "a measurement (a recording or a PSD table)", MAX_MEASUREMENT_BYTES))
    if getattr(args, "noise", None):
        files.append((args.noise, "a noise recording (or its PSD table)", MAX_MEASUREMENT_BYTES))
    given = [name for name in COMPARE_OPTIONS if args.command in ("psd", "report") and getattr(args, name, None)
             is not None and getattr(args, name) is not False and getattr(args, name) != []]  # 0.0 == False
    if given and not getattr(args, "measurement", None):
        from .result_file import EX_USAGE as usage, PostError
        raise PostError(f"--{given[0].replace('_', '-')}: an option of the comparison with a measurement; allowed with "
                        "--measurement FILE... only", usage)
    if args.command == "panels":
        from .panels_plot import parse_panel
        args.panels = [parse_panel(words) for words in args.panel]
        files += [(path, "a rollspec HDF5 file or a PSD CSV", None) for _, curves in args.panels
                  for path, _ in curves]
    return files


def check_ranges(args):
    from .result_file import EX_USAGE as usage, PostError
    fmin, fmax = getattr(args, "fmin", None), getattr(args, "fmax", None)
    if fmin is not None and fmax is not None and not fmin < fmax:
        raise PostError(f"--fmin {fmin:g} --fmax {fmax:g}: allowed: fmin < fmax", usage)
    if args.command == "panels" and not fmax > 0:
        raise PostError(f"--fmax {fmax:g}: allowed: a frequency > 0 Hz", usage)
    share = getattr(args, "loss_threshold", None)
    if share is not None and not 0 <= share <= 1:
        raise PostError(f"--loss-threshold {share:g}: allowed: a share from 0 to 1", usage)
    ylim = getattr(args, "ylim", None)
    if ylim is not None and not ylim[0] < ylim[1]:
        raise PostError(f"--ylim {ylim[0]:g} {ylim[1]:g}: allowed: LOW < HIGH", usage)



def render(args, kind):
    """The bytes of the output file."""
    buf = io.BytesIO()
    if args.command == "psd":
        from .psd_plot import plot_psd
        plot_psd(args.result, buf, args.measurement, args.bands, args.sensor, compare_options(args),
                 args.fmin, args.fmax, args.xscale, args.sensors == "all", args.dpi, kind=kind, title=args.title,
                 label=args.label, ylim=args.ylim, style=args.style, measurement_label=args.measurement_label)
    elif args.command == "texture":
        from .texture_plot import plot_texture
        plot_texture(args.texture_file, buf, kind)
    elif args.command == "stiffness":
        from .stiffness_plot import plot_stiffness
        plot_stiffness(args.table, buf, kind)
    elif args.command == "trajectory":
        from .trajectory_plot import plot_trajectory
        plot_trajectory(args.result, buf, kind)
    elif args.command == "roughness":
        from .roughness_filter_plot import plot_roughness_filters
        plot_roughness_filters(args.result, buf, kind=kind)
    elif args.command == "bench":
        from .bench_plot import plot_bench
        plot_bench(args.csv, buf, kind)
    elif args.command == "panels":
        from .panels_plot import plot_panels
        plot_panels(args.panels, buf, args.fmax, args.sensor, kind=kind, column=args.column)
    elif args.command == "sweep":
        from .sweep_plot import plot_sweep
        plot_sweep(args.result, buf, args.sensor, args.points, kind=kind)
    elif args.command == "report":
        from .report_page import report_html
        options = compare_options(args)
        options.sensor, options.fmin, options.fmax = args.sensor, args.fmin, args.fmax
        return report_html(args.result, args.measurement, options, args.loss_threshold).encode("utf-8")
    return buf.getvalue()


def run(args):
    """Checks every input and the output before reading any data, renders, then writes atomically."""
    from .result_file import select_point
    from .safe_output import check_input, check_output, picture_kind, refuse_inputs, write_atomic
    select_point(getattr(args, "point", None))
    files = inputs(args)
    check_ranges(args)
    refuse_inputs(args.out, [path for path, _, _ in files])  # first: the most important answer
    for path, what, limit in files:
        check_input(path, what, limit)
    kind = picture_kind(args.out, args.out_types) if args.out_types else "html"
    target = check_output(args.out, kind, [path for path, _, _ in files], args.force)
    data = render(args, kind)
    write_atomic(target, lambda fh: fh.write(data))


def interrupt_on_termination():
    """SIGTERM and SIGHUP end the run like Ctrl-C: the temporary is removed, the old output stays."""
    import signal

    def interrupt(signum, frame):
        raise KeyboardInterrupt
    for sig in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, interrupt)


def quiet():
    """Library warnings (numpy's divide by zero, matplotlib's font notes) would add lines to stderr."""
    import logging
    import warnings
    warnings.simplefilter("ignore")
    logging.getLogger("matplotlib").setLevel(logging.ERROR)


def one_line(text):
    return " ".join(str(text).split())


def raised_by_hdf5(e):
    """Whether the exception came out of h5py (a soft-link loop, undecodable text, a damaged object)."""
    tb = e.__traceback__
    while tb is not None:
        if "h5py" in tb.tb_frame.f_code.co_filename:
            return True
        tb = tb.tb_next
    return isinstance(e, UnicodeError)


def args_inputs(args):
    return ", ".join(str(getattr(args, n)) for n in ("result", "texture_file", "table", "csv", "measurement")
                     if getattr(args, n, None)) or "an input"


def checked_run(args, prefix):
    """run() with every failure as one line and an exit code."""
    from .result_file import PostError
    try:
        run(args)
    except PostError as e:
        print(f"{prefix} {one_line(e)}", file=sys.stderr)
        return e.exit_code
    except MemoryError:
        print(f"{prefix} out of memory; {args.out} not written", file=sys.stderr)
        return EX_SOFTWARE
    except ImportError:
        raise
    except Exception as e:
        if raised_by_hdf5(e):  # a damaged or unusual file h5py could not read: bad data, not a bug
            print(f"{prefix} {args_inputs(args)}: cannot be read ({type(e).__name__}: {one_line(e)}); "
                  f"{args.out} not written", file=sys.stderr)
            return 65
        # last resort: a bug, but still one line and no partial output
        print(f"{prefix} internal error ({type(e).__name__}: {one_line(e)}); {args.out} not written; "
              "please report this", file=sys.stderr)
        return EX_SOFTWARE
    say(f"wrote {args.out}")
    return 0


def say(text):
    """The success line; a closed pipe (`| head -0`) or an undecodable file name is no failure: the file is written."""
    if sys.stdout is None:
        return
    try:
        sys.stdout.reconfigure(errors="backslashreplace")
        print(text, flush=True)
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no second error at exit
    except (OSError, ValueError, AttributeError):
        pass


def main(argv=None):
    interrupt_on_termination()
    try:
        return main_checked(argv)
    except KeyboardInterrupt:  # Ctrl-C, SIGTERM, SIGHUP: the temporary is gone, the old output untouched
        print(f"{program_name().replace('python3 -m ', '')}: error: interrupted; nothing written", file=sys.stderr)
        sys.stderr.flush()
        # os._exit: CPython exits by SIGINT (-2) when an interrupt passed through an import, even if caught
        os._exit(130)


def main_checked(argv):
    args = build_parser().parse_args(argv)
    prefix = f"{program_name().replace('python3 -m ', '')} {args.command}: error:"
    missing = missing_module()
    if missing:
        print(missing, file=sys.stderr)
        return EX_UNAVAILABLE
    quiet()
    try:
        return checked_run(args, prefix)
    except ImportError as e:  # found but broken, or one of their own dependencies
        print(missing_module((e.name or "").split(".")[0]) or f"{prefix} {one_line(e)}", file=sys.stderr)
        return EX_UNAVAILABLE


if __name__ == "__main__":
    sys.exit(main())
