"""python3 -m rollspec_post COMMAND ...: plots from rollspec result files."""
import argparse
import sys

from .result_file import PostError


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m rollspec_post",
                                     description="Plots and reports from rollspec result files.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("psd", help="acceleration PSD with confidence band, measurement and band levels")
    p.add_argument("result", help="rollspec result file (HDF5)")
    p.add_argument("--measurement", help="measured PSD, CSV frequency_hz,psd")
    p.add_argument("--bands", action="store_true", help="draw third-octave band levels (and ΔL with a measurement)")
    p.add_argument("--sensor", type=int, help="plot only this sensor index")
    p.add_argument("--out", "-o", required=True, help="output PNG")
    t = sub.add_parser("texture", help="line texture, surface image, target vs realised PSD")
    t.add_argument("texture_file", help="file written by rollspec texture")
    t.add_argument("--out", "-o", required=True, help="output PNG")
    args = parser.parse_args(argv)
    try:
        if args.command == "psd":
            from .psd_plot import plot_psd
            plot_psd(args.result, args.out, args.measurement, args.bands, args.sensor)
            print(f"wrote {args.out}")
        elif args.command == "texture":
            from .texture_plot import plot_texture
            plot_texture(args.texture_file, args.out)
            print(f"wrote {args.out}")
    except PostError as e:
        print(f"rollspec_post {args.command}: error: {e}", file=sys.stderr)
        return e.exit_code
    return 0


if __name__ == "__main__":
    sys.exit(main())
