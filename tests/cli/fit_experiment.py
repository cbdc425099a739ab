"""Synthetic measurements for `rollspec fit` tests: the random oscillator at known key values, another
seed and M realisations, its sensor-mean PSD written as CSV (as conftest.measurement_from does)."""
import json

from conftest import SOURCE, measurement_from, run

STUDY = SOURCE / "studies" / "random-oscillator.ini"
# A fast scene: 4 s records at 1024 Hz, 0.5 Hz bins, the nine bands 22 .. 178 Hz around the 50 Hz resonance.
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
        "spectrum.band_max=200"]
RECORDS = 16       # M
REALISATIONS = 40  # K of every fit evaluation


def sets(pairs):
    return [a for kv in pairs for a in ("--set", kv)]


def measurement(directory, seed, truth):
    """A measured PSD of M records of the study with the keys at `truth` ({key: value})."""
    out = directory / f"m{seed}.h5"
    r = run(["run", STUDY, "--out", out, "--quiet",
             *sets(FAST + [f"{k}={v}" for k, v in truth.items()] + [f"study.realisations={RECORDS}",
                                                                     f"study.seed={seed}"])])
    assert r.returncode == 0, r.stderr
    return measurement_from(out, directory / f"m{seed}.csv")


def fit(csv, vary, *extra):
    """`rollspec fit` of the fast study with --vary VARY ({key: 'lo:hi[:log]'}), its JSON (or the process)."""
    r = run(["fit", STUDY, csv, "--measured-averages", RECORDS, "--format", "json",
             *[a for k, rng in vary.items() for a in ("--vary", f"{k}={rng}")],
             *sets(FAST + [f"study.realisations={REALISATIONS}"]), *extra])
    return (json.loads(r.stdout), r) if r.returncode == 0 else (None, r)
