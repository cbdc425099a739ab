#!/usr/bin/env bash
# Regenerates every picture the README shows, from the current Release build, so none can go stale:
#   cmake --build --preset release && bash python-post/docs/make_readme_pictures.sh
# About 10 minutes on 2 cores (seed 002 with the contact-solver F0 and seed 001's stiffness tables are most of it). Needs /usr/bin/chromium for
# the report screenshot (.ci/setup installs it).
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=build/release/rollspec
docs=python-post/docs
fail() { echo "make_readme_pictures.sh: error: $2" >&2; exit "$1"; }
[ -x "$bin" ] || fail 66 "no $bin; build it first: cmake --preset release && cmake --build --preset release"
# --force below replaces the README's pictures whatever they hold: only regular files of this folder, never
# a link that would carry the write elsewhere.
for f in "$docs"/*.png; do
  if [ -L "$f" ] || { [ -e "$f" ] && [ ! -f "$f" ]; }; then fail 73 "$f is not a picture this script wrote (a link, or not a regular file); move it away"; fi
done
# --force: the committed pictures predate the rollspec-post marker that lets a run replace its own output
post() { PYTHONPATH=python-post /usr/bin/python3 -m rollspec_post "$@" --force; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Random-oscillator verification study: mean of 200, 95 % interval, exact answer, bands.
"$bin" run studies/random-oscillator.ini --out "$work/ro.h5" --quiet
post psd "$work/ro.h5" --bands --xscale log --out "$docs/random-oscillator-psd.png"

# Seed 002 rig at 1 m/s: the mean of the 5 sensors beside the frequency-domain solution.
"$bin" run studies/seed002-rig-1ms.ini --out "$work/rig.h5" --quiet
post psd "$work/rig.h5" --bands --sensor sensor_mean --out "$docs/seed002-rig-psd.png"

# Seed 002 in its own style (linear 0-5 kHz, dB): both speeds, the spring F0 the study ships against the
# contact-solver F0 on its derived grid (issue 15 part 3).
"$bin" run studies/seed002-rig-3ms.ini --out "$work/rig3.h5" --quiet
"$bin" run studies/seed002-rig-1ms.ini --out "$work/rig-solver.h5" --quiet --set contact.blocked_force=solver
"$bin" run studies/seed002-rig-3ms.ini --out "$work/rig3-solver.h5" --quiet --set contact.blocked_force=solver
post panels --panel "1 m/s" "$work/rig.h5=spring F0, as shipped" "$work/rig-solver.h5=contact-solver F0" \
  --panel "3 m/s" "$work/rig3.h5=spring F0, as shipped" "$work/rig3-solver.h5=contact-solver F0" \
  --out "$docs/seed002-seed-style.png"

# Seed 001 in its own style (Fig. 8): beams S and R, the seed's chain (profiles -> stiffness table)
# against the Hertz law with a parametric PSD.
for beam in s r; do
  "$bin" run studies/seed001-beam-$beam.ini --out "$work/seed001-$beam.h5" --quiet
  "$bin" run studies/seed001-beam-$beam-hertz.ini --out "$work/seed001-$beam-hertz.h5" --quiet
done
post panels --panel "Beam S (ground, Ra 0.29 µm)" "$work/seed001-s.h5=stiffness table from profiles" \
  "$work/seed001-s-hertz.h5=Hertz, parametric PSD" \
  --panel "Beam R (milled, Ra 2.25 µm)" "$work/seed001-r.h5=stiffness table from profiles" \
  "$work/seed001-r-hertz.h5=Hertz, parametric PSD" --out "$docs/seed001-seed-style.png"

# Report of the rig against a "measurement": the sensor mean of 25 other rolls of the same model,
# judged by the prediction interval for a 25-roll measurement.
"$bin" run studies/seed002-rig-1ms.ini --out "$work/rig-measured.h5" --quiet --set study.seed=2026
/usr/bin/python3 - "$work/rig-measured.h5" "$work/measured.csv" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1]) as f:
    freq, psd = f["/psd/frequency"][1:], f["/psd/mean"][-1, 1:]
np.savetxt(sys.argv[2], np.c_[freq, psd], delimiter=",", header="frequency_hz,psd", comments="", fmt="%.17g")
PY
post report "$work/rig.h5" --measurement "$work/measured.csv" --measured-averages 25 --fmin 100 --fmax 5000 \
  --out "$work/report.html"
/usr/bin/chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$work/profile" --hide-scrollbars \
  --screenshot="$docs/report-screenshot.png" --window-size=1200,2000 "file://$work/report.html" 2>/dev/null

# Seed 000 example 4.4, the flying beam.
"$bin" run studies/seed000-flying-beam.ini --out "$work/flying.h5" --quiet
post trajectory "$work/flying.h5" --out "$docs/flying-beam-trajectory.png"

# The rolling-pipe study, 32 realisations.
"$bin" run studies/rolling-pipe.ini --out "$work/pipe.h5" --quiet
post psd "$work/pipe.h5" --bands --sensors all --xscale log --out "$docs/rolling-pipe-psd.png"

# Line textures and surfaces of the texture demo.
"$bin" texture studies/texture-demo.ini --out "$work/texture.h5"
post texture "$work/texture.h5" --out "$docs/texture-demo.png"

# Seed 001 beam S: the roughness PSD along the path, raw and under each contact filter (/roughness).
"$bin" run studies/seed001-beam-s-hertz.ini --out "$work/beam-s.h5" --quiet --set study.realisations=1 --set contact.filter=iso2d
post roughness "$work/beam-s.h5" --out "$docs/seed001-contact-filter.png"

# Work-precision of the ball-on-beam integrators, from the table bench/beam/bench_beam wrote.
post bench "$docs/work-precision.csv" --out "$docs/work-precision.png"
