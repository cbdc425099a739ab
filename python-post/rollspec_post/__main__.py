"""python3 -m rollspec_post COMMAND ... (installed: rollspec-post COMMAND ...): plots and reports from rollspec result files."""
import argparse
import os
import sys

from .result_file import EX_CANTCREAT, PostError


def program_name():
    """`rollspec-post` when run as the installed command (pyproject.toml), else `python3 -m rollspec_post`."""
    name = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else ""
    return name if name == "rollspec-post" else "python3 -m rollspec_post"


def build_parser():
    parser = argparse.ArgumentParser(prog=program_name(),
                                     description="Plots and reports from rollspec result files.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("psd", help="acceleration PSD with confidence band, measurement and band levels")
    p.add_argument("result", help="rollspec result file (HDF5)")
    p.add_argument("--measurement", help="measured PSD, CSV with frequency_hz and a PSD column")
    p.add_argument("--bands", action="store_true", help="draw third-octave band levels (and ΔL with a measurement)")
    p.add_argument("--sensor", help="the row drawn and compared: name or index (default: sensor_mean if present, else 0)")
    p.add_argument("--sensors", choices=("one", "all"), default="one", help="all: every sensor as thin grey lines too")
    p.add_argument("--xscale", choices=("linear", "log"), default="linear", help="frequency axis (default linear)")
    p.add_argument("--dpi", type=float, default=150, help="resolution of a PNG (default 150)")
    p.add_argument("--out", "-o", required=True, help="output picture: .png, .pdf or .svg")
    t = sub.add_parser("texture", help="line texture, surface image, target vs realised PSD")
    t.add_argument("texture_file", help="file written by rollspec texture")
    t.add_argument("--out", "-o", required=True, help="output PNG")
    s = sub.add_parser("stiffness", help="P(δ) and k(δ) with their spread over realisations, and Hertz")
    s.add_argument("table", help="stiffness table (HDF5, filetype rollspec-stiffness-table)")
    s.add_argument("--out", "-o", required=True, help="output PNG")
    j = sub.add_parser("trajectory", help="rolling-beam node paths, speeds and energies over time")
    j.add_argument("result", help="rollspec result file with /time_history/position")
    j.add_argument("--out", "-o", required=True, help="output PNG")
    g = sub.add_parser("roughness", help="roughness PSD along the path: raw and with each contact filter (ball-on-beam)")
    g.add_argument("result", help="rollspec result file with /roughness")
    g.add_argument("--out", "-o", required=True, help="output picture: .png, .pdf or .svg")
    b = sub.add_parser("bench", help="work-precision plot: error against run time, log-log, one line per method")
    b.add_argument("csv", help="CSV with columns method (or integrator), seconds (or time_s), error_db (or error)")
    b.add_argument("--out", "-o", required=True, help="output PNG")
    n = sub.add_parser("panels", help="results side by side in the seeds' style: PSD level in dB, linear 0-5 kHz")
    n.add_argument("--panel", nargs="+", action="append", required=True, metavar="WORD",
                   help="TITLE FILE=LABEL [FILE=LABEL ...]: one panel; the first curve solid black, the others dotted/dashed")
    n.add_argument("--sensor", help="sensor name or index (default: sensor_mean if present, else 0)")
    n.add_argument("--fmax", type=float, default=5000.0, help="highest frequency drawn (Hz; default 5000)")
    n.add_argument("--out", "-o", required=True, help="output picture: .png, .pdf or .svg")
    r = sub.add_parser("report", help="one self-contained HTML page: key figures, PSD, provenance, study")
    r.add_argument("result", help="rollspec result file (HDF5)")
    r.add_argument("--measurement", help="measured PSD, CSV with frequency_hz and a PSD column (rule of `rollspec compare`)")
    r.add_argument("--sensor", help="sensor name or index (default: sensor_mean if present, else 0)")
    r.add_argument("--fmin", type=float, default=0.0, help="lowest band edge compared (Hz)")
    r.add_argument("--fmax", type=float, default=float("inf"), help="highest band edge compared (Hz)")
    r.add_argument("--out", "-o", required=True, help="output HTML")
    p.add_argument("--fmin", type=float, help="lowest frequency drawn and compared (Hz; default: the study's band range, "
                   "from 0 on a linear axis)")
    p.add_argument("--fmax", type=float, help="highest frequency drawn and compared (Hz; default: the study's band range)")
    for q in (p, r):
        q.add_argument("--column", help="PSD column of the measurement CSV (default: psd)")
        q.add_argument("--measured-averages", type=float, metavar="M",
                       help="independent records averaged into the measurement: judge it by its prediction interval")
    return parser


def run(args):
    out_dir = os.path.dirname(os.path.abspath(args.out))
    if not os.path.isdir(out_dir):
        raise PostError(f"{args.out}: cannot create (no directory {out_dir})", EX_CANTCREAT)
    if args.command == "psd":
        from .psd_plot import plot_psd
        plot_psd(args.result, args.out, args.measurement, args.bands, args.sensor, args.column, args.measured_averages,
                 args.fmin, args.fmax, args.xscale, args.sensors == "all", args.dpi)
    elif args.command == "texture":
        from .texture_plot import plot_texture
        plot_texture(args.texture_file, args.out)
    elif args.command == "stiffness":
        from .stiffness_plot import plot_stiffness
        plot_stiffness(args.table, args.out)
    elif args.command == "trajectory":
        from .trajectory_plot import plot_trajectory
        plot_trajectory(args.result, args.out)
    elif args.command == "roughness":
        from .roughness_filter_plot import plot_roughness_filters
        plot_roughness_filters(args.result, args.out)
    elif args.command == "bench":
        from .bench_plot import plot_bench
        plot_bench(args.csv, args.out)
    elif args.command == "panels":
        from .panels_plot import parse_panel, plot_panels
        plot_panels([parse_panel(words) for words in args.panel], args.out, args.fmax, args.sensor)
    elif args.command == "report":
        from .report_page import build_report
        build_report(args.result, args.out, args.measurement, args.sensor, args.fmin, args.fmax, args.column,
                     args.measured_averages)


def main(argv=None):
    args = build_parser().parse_args(argv)
    try:
        run(args)
    except PostError as e:
        print(f"rollspec_post {args.command}: error: {e}", file=sys.stderr)
        return e.exit_code
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
