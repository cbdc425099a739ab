#!/usr/bin/python3
"""The accuracy and contact-filter pages' cheap checks, through the command and the kernels' doctests.

usage: /usr/bin/python3 bench/engine/accuracy_checks.py [--bin build/werror/rollspec] [--checks accuracy]
           [--record bench/records/validation/accuracy-checks.json]
       /usr/bin/python3 bench/engine/accuracy_checks.py --checks contact-filter
           [--record bench/records/validation/contact-filter-checks.json]

--checks accuracy (the accuracy page):

  - `rollspec psd` against scipy.signal.welch (Hann, half overlap, density) on a sine plus white noise
    (2^16 samples at 25.6 kHz, segment 4096; numpy's Philox generator, key 5): the largest relative
    difference over the bins;
  - studies/random-oscillator.ini with 200 realisations: the share of bins from 10 to 250 Hz whose 95 %
    interval holds the exact PSD (/reference/psd), and the mean of 10 log10(mean / exact) over them;
  - `rollspec stiffness studies/hertz.ini`: the table's k at the ball's weight against smooth Hertz;
  - the default ball-on-beam integrator against Dormand–Prince (signal.integrator = dopri5, rtol 1e-9)
    on the seed 002 rig in its near-linear regime (Hertz law, 0.05 µm, 4 realisations): the largest
    band-level difference, as tests/cli/test_ball_on_beam.py runs it;
  - the linearised ball-on-beam model against its frequency-domain solution (/reference) where the
    quasi-stationary approximation holds (0.05 m/s, loss factor 0.05, K = 100, as the same test file):
    the share of bins 100 Hz–5 kHz whose 95 % interval holds the ensemble mean;
  - the kernels' own checks, read from what their doctests print (the doctest executables of the
    build next to --bin: tests/kernels/*/test_*): the line texture's periodogram, spectral surfaces,
    Hertz on the half-space grid, DC-FFT, clamped–clamped modes, static deflection, the moving force
    against Frýba's series (undamped) and the damped closed form, the rolling tube and disc, the rolling
    model's tangent.

--checks contact-filter (the contact-filter page; its kernels' doctests alone, about 5 minutes on 2
shared cores, most of it the isotropic equivalent-roughness test): the equivalent roughness
(kernels/contact ER-1…ER-7) against its cold whole-strip reference, against sin(ka)/(ka) on a uniform
corrugation and against G_eq on isotropic surfaces; the path table (kernels/beam B41–B46) against
Hertz and against direct solves; a narrow spectral strip's variance against a square surface's
(kernels/texture Eq. 26a).

Runs in a scratch directory; --record writes the table as a record that the documentation's page
renders (bench/bench_record.py). --checks accuracy: about 3 minutes on 2 shared cores (most of it the
linearised model's 100 slow rolls and the Hertz stiffness doctest).
"""
import pathlib
import re
import time
import subprocess
import sys
import tempfile

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "python-post"))
import bench_record  # noqa: E402
from rollspec_post.script_main import fail, script_main  # noqa: E402  (one line per failure, no traceback)

COMPONENTS = ["engine", "beam", "contact", "integrators", "rolling", "spectral", "texture"]


def rollspec(binary, *args, cwd=None):
    r = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    if r.returncode:
        fail(f"rollspec {args[0]}: exit {r.returncode}: {(r.stderr.strip().splitlines() or [''])[-1]}", 70)
    return r.stdout


def welch_against_scipy(binary, work):
    import scipy.signal
    fs, n, segment = 25600.0, 2**16, 4096
    rng = np.random.Generator(np.random.Philox(5))
    t = np.arange(n) / fs
    x = 2.0 * np.sin(2 * np.pi * 1234.5 * t) + 0.5 * rng.standard_normal(n)
    signal = work / "signal.csv"
    signal.write_text("time_s,acc\n" + "\n".join(f"{ti:.17g},{xi:.17g}" for ti, xi in zip(t, x)) + "\n")
    out = work / "psd.csv"
    rollspec(binary, "psd", signal, "--segment", segment, "--out", out, "--quiet", cwd=work)
    ours = np.genfromtxt(out, delimiter=",", names=True)
    _, theirs = scipy.signal.welch(x, fs=fs, window="hann", nperseg=segment, noverlap=segment // 2)
    col = ours.dtype.names[1]
    rel = np.abs(ours[col] - theirs) / np.maximum(np.abs(theirs), np.finfo(float).tiny)
    return [f"`rollspec psd` against `scipy.signal.welch` (sine plus white noise, {n} samples, segment {segment})",
            f"largest relative difference {rel.max():.2g}"]


def oscillator_coverage(binary, work):
    import h5py
    out = work / "oscillator.h5"
    rollspec(binary, "run", ROOT / "studies" / "random-oscillator.ini", "--out", out, "--quiet",
             "--set", "study.realisations=200", cwd=work)
    with h5py.File(out) as f:
        freq = f["/psd/frequency"][:]
        sel = (freq >= 10.0) & (freq <= 250.0)
        lo, hi, mean = (f[f"/psd/{d}"][0, sel] for d in ("ci_lower", "ci_upper", "mean"))
        exact = f["/reference/psd"][0, sel]
    inside = np.mean((lo <= exact) & (exact <= hi))
    return ["random oscillator (`random-oscillator.ini`), 200 realisations: bins 10–250 Hz whose 95 % interval "
            "holds the exact PSD", f"{100 * inside:.1f} % of {sel.sum()} bins; mean 10 log10(mean / exact) "
            f"{np.mean(10 * np.log10(mean / exact)):+.3f} dB"]


def hertz_stiffness(binary, work):
    text = rollspec(binary, "stiffness", ROOT / "studies" / "hertz.ini", "--out", work / "hertz.h5", cwd=work)
    m = re.search(r"k = ([0-9.eE+-]+) N/m \(smooth Hertz: approach [0-9.eE+-]+ m, k = ([0-9.eE+-]+) N/m\)", text)
    if not m:
        fail("rollspec stiffness studies/hertz.ini: no line 'at the ball's weight ... k = ... (smooth Hertz: ...)'", 70)
    k, hertz = float(m.group(1)), float(m.group(2))
    return ["Hertz table through `rollspec stiffness studies/hertz.ini`: k at the ball's weight against smooth Hertz",
            f"{k:.6g} against {hertz:.6g} N/m ({k / hertz - 1:+.1e} relative)"]


def band_levels(path):
    import h5py
    with h5py.File(path) as f:
        return f["/bands/nominal_frequency"][:], f["/bands/level_db"][-1]


def integrator_against_dopri5(binary, work):
    rig = ROOT / "studies" / "seed002-rig-1ms.ini"
    common = ["--quiet", "--set", "study.realisations=4", "--set", "contact.law=hertz", "--set", "texture.rms=0.05e-6",
              "--set", "ball.end=0.2", "--set", "spectrum.segment=1024"]
    rollspec(binary, "run", rig, "--out", work / "fast.h5", *common, cwd=work)
    rollspec(binary, "run", rig, "--out", work / "dopri5.h5", *common, "--set", "signal.integrator=dopri5",
             "--set", "signal.rtol=1e-9", cwd=work)
    nominal, a = band_levels(work / "fast.h5")
    _, b = band_levels(work / "dopri5.h5")
    worst = np.abs(a - b).max()
    return ["default ball-on-beam integrator against Dormand–Prince 5(4) (rtol 1e-9), seed 002 rig, Hertz law, "
            f"rms 0.05 µm, 4 realisations: sensor-mean band levels {nominal[0]:g} Hz–{nominal[-1] / 1000:g} kHz",
            f"largest difference {worst:.3f} dB over {len(nominal)} bands"]


def linearised_against_frequency_domain(binary, work):
    import h5py
    out = work / "linearised.h5"
    rollspec(binary, "run", ROOT / "studies" / "seed002-rig-1ms.ini", "--out", out, "--quiet",
             "--set", "study.realisations=100", "--set", "texture.rms=0.01e-6", "--set", "ball.speed=0.05",
             "--set", "ball.start=0.1", "--set", "ball.end=0.3", "--set", "beam.loss_factor=0.05",
             "--set", "spectrum.skip_start=0.15", "--set", "spectrum.segment=1024", cwd=work)
    with h5py.File(out) as f:
        freq = f["/psd/frequency"][:]
        sel = (freq >= 100) & (freq <= 5000)
        mean, ref = f["/psd/mean"][:, sel], f["/reference/psd"][:, sel]
        lower, upper = f["/reference/mean_lower"][:, sel], f["/reference/mean_upper"][:, sel]
    inside = ((mean >= lower) & (mean <= upper)).mean(axis=1)
    median = np.median(10 * np.log10(mean[-1] / ref[-1]))
    return ["linearised ball-on-beam (seed 002 rig at 0.05 m/s, loss factor 0.05, K = 100: quasi-stationary), "
            "bins 100 Hz–5 kHz whose 95 % interval holds the frequency-domain solution (kernels/beam B34a–c, B35a)",
            f"{100 * inside[-1]:.0f} % sensor mean, {100 * inside[:-1].min():.0f}–{100 * inside[:-1].max():.0f} % "
            f"per sensor; median deviation {median:+.3f} dB"]


# (row text, doctest executable under build/<preset>/tests/kernels, test case (a doctest filter), the
# printed figures: a regular expression whose groups are read as numbers, and the row's result from them)
def _worst(values):
    return max(abs(v) for v in values)


ACCURACY_DOCTESTS = [
    ("deterministic line texture: periodogram of one realisation against the target", "texture/test_texture",
     "deterministic amplitudes: the periodogram*", r"max relative periodogram error over (\d+) harmonics: (\S+)",
     lambda m: f"{_worst(float(x[1]) for x in m):.1e} relative, over {m[0][0]} harmonics"),
    ("spectral surfaces: radial 2D PSD of 50 Rayleigh surfaces against C_iso", "texture/test_texture",
     "spectral surfaces: 50 Rayleigh surfaces*", r"radial 2D PSD: (\d+) bands, worst \|dL\| = (\S+) dB",
     lambda m: f"worst band {_worst(float(x[1]) for x in m):.2f} dB over {m[0][0]} bands"),
    ("Hertz on the half-space grid, 32 cells per contact radius: force / max pressure / contact radius",
     "contact/test_contact", "Hertz sphere at 32 cells per contact radius",
     r"Hertz 32 cells/a: force (\S+), p_max (\S+), radius (\S+),",
     lambda m: " / ".join(f"{abs(float(v)):.1e}" for v in m[0]) + " relative"),
    ("Hertz, k against 2E*a over 11 approaches in [0.95, 1.05] w0 (sub-cell contact edge, kernels/contact Eq. 13–15)",
     "contact/test_contact", "Hertz stiffness k = 2 E* a with the sub-cell*",
     r"Hertz k vs 2E\*a, (\d+) cells/a, 11 approaches: frozen set mean \S+, rms \S+, worst (\S+); with sub-cell "
     r"edge mean (\S+), rms \S+, worst (\S+)",
     lambda m: "; ".join(f"{c} cells: worst {float(w):.1e}, mean {float(me):.1e} (frozen set alone: worst "
                         f"{float(fw):.1e})" for c, fw, me, w in m if c in ("32", "64"))),
    ("DC-FFT product against the direct sum", "contact/test_contact", "DC-FFT product equals*",
     r"DC-FFT vs direct, \S+: max rel diff (\S+)", lambda m: f"{_worst(float(x) for x in m):.1e} relative"),
    ("clamped–clamped eigenvalues, modes 1–200, against 400-digit roots", "beam/test_beam_modes",
     "clamped-clamped eigenvalues*", r"400-digit roots (\S+)",
     lambda m: (f"{_worst(float(x) for x in m):.1e} relative" if _worst(float(x) for x in m) else
                "0: every root the double nearest the 400-digit one")),
    ("clamped–clamped eigenfunctions, modes 1–200: orthogonality |∫φ_m φ_n / l − δ_mn|",
     "beam/test_beam_modes",
     "eigenfunctions of modes 1-200 are finite*", r"CC max \|int phi_m phi_n / l - delta_mn\|, 200 modes: (\S+)",
     lambda m: f"{_worst(float(x) for x in m):.1e}"),
    ("static deflection under the ball, 16 modes + static correction, against P a³b³/(3EIL³) (a = 0.1, 0.3, 0.5 l)",
     "beam/test_beam_dynamics", "static deflection under the ball*",
     r"with correction, a = \S+ l: max rel. error (\S+)", lambda m: f"{_worst(float(x) for x in m):.1e} relative"),
    ("moving constant force on a simply supported beam (30 modes, undamped) against Frýba's series "
     "(kernels/beam B29–B30), speed parameters 0.1, 0.5, 1.3", "beam/test_beam_dynamics",
     "moving constant force on a simply supported beam*", r"max \|w - w_Fryba\| / max \|w_Fryba\| = (\S+),",
     lambda m: f"{_worst(float(x) for x in m):.1e} of the peak"),
    ("the same on a damped beam (loss factor 0.01) against the damped modal closed form; in brackets, how far "
     "the damped beam is from Frýba's undamped series", "beam/test_beam_dynamics",
     "moving constant force on a damped*",
     r"max \|w - w_damped\| / peak = (\S+), max \|w - w_Fryba,undamped\| / peak = (\S+)",
     lambda m: f"{_worst(float(x[0]) for x in m):.1e} of the peak (undamped series: "
               f"{min(float(x[1]) for x in m):.1e}–{max(float(x[1]) for x in m):.1e})"),
    ("tube rolling with friction over a sinusoidal floor (120 / 450 / 1500 Hz) against the frequency-domain "
     "solution of its own M, C, K", "rolling/test_rolling", "rolling pipe over a sinusoidal floor*",
     r"f0 = \s*(\S+) Hz, \S+ node: .*? \(discrete frequency domain\) (\S+); continuous frequency domain \S+ \((\S+)\)",
     lambda m: f"{_worst(float(x[1]) for x in m):.1e} (trapezoidal rule, exact); "
               f"{_worst(float(x[2]) for x in m if float(x[0]) < 1000):.1e} against the continuous solution "
               "below 1 kHz"),
    ("disc rolling with friction over a bump (R-63): centre against the offset curve, r|ω|/|v| − 1, slip steps",
     "rolling/test_rolling", "rolling friction on a height field (R-63): a disc*",
     r"centre vs offset curve \S+ m \((\S+) of H\), max \|r w/v - 1\| (\S+), slip steps (\d+)",
     lambda m: f"{float(m[0][0]):.1e} H, {float(m[0][1]):.1e}, {m[0][2]}"),
    ("rolling model's tangent (beam, inertia, load, contact) against central differences of the residual",
     "rolling/test_rolling", "beam + inertia + load + contact tangent*", r"tangent rel. error (\S+)",
     lambda m: f"{_worst(float(x) for x in m):.1e} relative"),
]

CONTACT_FILTER_DOCTESTS = [
    ("equivalent roughness on the blocked-force moving window with warm starts against cold whole-strip solves "
     "(rough strip)", "contact/test_contact", "equivalent roughness: moving window*",
     r"fast − reference up to (\S+) δ_H|k_eq fast / reference - 1 up to (\S+)",
     lambda m: f"h_eq within {_worst(float(x[0]) for x in m if x[0]):.1e} δ_H, k_eq within "
               f"{_worst(float(x[1]) for x in m if x[1]):.1e} relative"),
    ("equivalent roughness of a corrugation uniform across the path (amplitude 10⁻³ δ_H, 32 cells per radius, "
     "ball on a cell centre): h_eq/h against sin(ka)/(ka)", "contact/test_contact",
     "equivalent roughness: uniform corrugation*",
     r"ka = (\S+): h_eq/h = \S+, sin\(ka\)/\(ka\) = \S+, relative error (\S+)",
     lambda m: f"within {100 * _worst(float(x[1]) for x in m):.2g} % for ka = {m[0][0]}–{m[-1][0]} "
               f"({100 * abs(float(m[-1][1])):.2g} % at ka = {m[-1][0]})"),
    ("equivalent roughness of isotropic surfaces (8 surfaces × 3 paths): PSD of h_eq against G_eq (Eq. 38), "
     "third-octave bands", "contact/test_equivalent_roughness_psd", "*",
     r"ka = (\S+) \(\S+ bins x \d+ paths\): PSD\(h_eq\) / G_eq = (\S+) dB",
     lambda m: f"{min(float(x[1]) for x in m):+.2f} … {max(float(x[1]) for x in m):+.2f} dB over ka "
               f"{float(m[0][0]):.2f}–{float(m[-1][0]):.2f}"),
    ("path table on a smooth strip: P(δ, ξ) and its interpolation against the Hertz force (kernels/beam B41–B45)",
     "beam/test_beam_dynamics", "path table on a smooth strip*", r"worst \|P/P_Hertz - 1\| over the table = (\S+)",
     lambda m: f"{_worst(float(x) for x in m):.1e} relative"),
    ("path table on a rough strip: values mid-way between nodes against direct solves", "beam/test_beam_dynamics",
     "path table on a rough strip*", r"worst \|P_interp - P_direct\| / W: in delta (\S+), in xi (\S+)",
     lambda m: f"{100 * float(m[0][0]):.2g} % of W in δ, {100 * float(m[0][1]):.2g} % in ξ"),
    ("`law = path` on an exact Hertz table against `law = hertz` in the ball-on-beam integrator (B46)",
     "beam/test_beam_dynamics", "law = path on an exact Hertz*", r"acceleration (\S+) of its peak",
     lambda m: f"acceleration within {_worst(float(x) for x in m):.1e} of its peak"),
    ("a narrow spectral strip against a square surface of the same PSD (each mode its cell's mean, "
     "kernels/texture Eq. 26a): variance ratio", "texture/test_texture", "a narrow strip holds*",
     r"strip / square variance = (\S+)", lambda m: f"{float(m[0]):.4f}"),
]
GROUPS = {"accuracy": ("Checks through the command and the kernels' doctests", ACCURACY_DOCTESTS),
          "contact-filter": ("The contact filters' checks in the kernels' doctests", CONTACT_FILTER_DOCTESTS)}


def doctest_rows(binary, doctests):
    """The kernels' checks from what their doctests print: each test case run alone, its figures read."""
    build = pathlib.Path(binary).parent / "tests" / "kernels"
    rows = []
    for text, exe, case, pattern, result in doctests:
        path = build / exe
        if not path.is_file():
            fail(f"{path}: no doctest executable next to --bin {binary}; allowed: a build's rollspec (its "
                 "tests built with it)", 66)
        r = subprocess.run([str(path), f"--test-case={case}", "--no-version"], capture_output=True, text=True)
        found = re.findall(pattern, r.stdout)
        if r.returncode or not found:
            fail(f"{exe} --test-case='{case}': " + (f"exit {r.returncode}" if r.returncode else
                                                    "printed no figures this script reads"), 70)
        rows.append([f"{text} (`{exe.split('/')[-1]}`)", result(found)])
    return rows


def main():
    p = bench_record.record_script_parser(__doc__.split("\n")[0], ROOT / "build" / "werror" / "rollspec")
    p.add_argument("--checks", choices=sorted(GROUPS), default="accuracy", help="which page's checks")
    a, binary = bench_record.record_script_arguments(p)
    title, doctests = GROUPS[a.checks]
    with tempfile.TemporaryDirectory(prefix="accuracy-") as tmp:
        work = pathlib.Path(tmp)
        start = time.monotonic()
        rows = []
        if a.checks == "accuracy":
            rows = [welch_against_scipy(binary, work), oscillator_coverage(binary, work),
                    hertz_stiffness(binary, work), integrator_against_dopri5(binary, work),
                    linearised_against_frequency_domain(binary, work)]
        rows += doctest_rows(binary, doctests)
        wall = time.monotonic() - start
    for row in rows:
        print(" | ".join(row), flush=True)
    if a.record:
        bench_record.write_measured(
            a.record, binary, title=title, argv=sys.argv,
            settings=f"each command and doctest once, in a scratch directory; {wall:.0f} s wall",
            columns=["check", "result"], rows=rows, components=COMPONENTS)


if __name__ == "__main__":
    script_main(main)
