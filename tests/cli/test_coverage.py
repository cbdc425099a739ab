"""Coverage of the ensemble intervals, by experiment (kernels/spectral D-21; CTest label `statistics`).

For each scene, M independent ensembles of K realisations (different study seeds) are compared
with a large-K ensemble of the same study (another seed): a nominal 95 % interval must hold the
large-K mean in 90-98 % of the (ensemble, row, bin) and (ensemble, row, band) cases from 100 Hz
to 5 kHz (clipped to the study's bands). The large-K mean has its own scatter, K / K_ref of the
small ensembles' variance, which lowers the expected coverage by ~0.5 point at the ratios used.

Measured when this was written, with this file's seeds (K_ref = 1000 unless said):
  scene                                          bins before/after   bands before/after
  random oscillator (K = 25)                     0.947 / 0.955       0.933 / 0.950
  seed001-beam-s-hertz (K = 25, 34 % loss)      0.859 / 0.960       0.618 / 0.946
  seed002-rig-1ms (K = 25, issue 13's case)      0.865 / 0.964       0.632 / 0.965   (not run here; "after"
                                                 re-measured with the issue 15 roughness, 74 s)
  small pipe (K = 16, K_ref = 480)               0.800 / 0.922       0.798 / 0.947
  seed001-beam-r, 4-surface table (K = 25)       -     / 0.958       -     / 0.951
  seed002-rig-1ms, blocked force = solver        -     / 0.962       -     / 0.953   (0.7 % loss of contact)
  coarse rig, blocked-force table jackknife      0.422 / 0.923       0.414 / 0.924   (12 tables against 4 others:
                                                 "before" is without the term, below)
"Before" is the Welch / bin-count dof (Satterthwaite-capped for the pipe) this replaced. All runs
are Philox-keyed, so each figure is reproducible bit for bit."""
import h5py
import numpy as np
import pytest

from conftest import SMALL_PIPE, SOURCE, run


def ensemble(tmp_path, study, seed, realisations, sets, name):
    out = tmp_path / f"{name}.h5"
    if study == "small-pipe":
        study = tmp_path / "small-pipe.ini"
        study.write_text(SMALL_PIPE.format(realisations=realisations, chunk=4, kind="isotropic"))
    args = ["run", SOURCE / "studies" / study, "--out", out, "--quiet",
            "--set", f"study.realisations={realisations}", "--set", f"study.seed={seed}"]
    for s in sets:
        args += ["--set", s]
    r = run(args)
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        return {k: f[k][()] for k in ("/psd/frequency", "/psd/mean", "/psd/ci_lower", "/psd/ci_upper",
                                      "/bands/centre_frequency", "/bands/level_db", "/bands/ci_lower_db",
                                      "/bands/ci_upper_db")} | (
            {"loss": float(f["/contact/loss_of_contact_share"][0])} if "/contact/loss_of_contact_share" in f else {})


def coverage(tmp_path, study, K, M, K_ref, sets=()):
    ref = ensemble(tmp_path, study, 900001, K_ref, sets, "reference")
    bins = (ref["/psd/frequency"] >= 100) & (ref["/psd/frequency"] <= 5000)
    bands = (ref["/bands/centre_frequency"] >= 100) & (ref["/bands/centre_frequency"] <= 5000)
    assert bins.sum() >= 30 and bands.sum() >= 5
    held_bins, held_bands = [], []
    for m in range(M):
        e = ensemble(tmp_path, study, 1000 + m, K, sets, f"e{m}")
        held_bins.append(((e["/psd/ci_lower"] <= ref["/psd/mean"]) & (ref["/psd/mean"] <= e["/psd/ci_upper"]))[:, bins])
        held_bands.append(((e["/bands/ci_lower_db"] <= ref["/bands/level_db"])
                           & (ref["/bands/level_db"] <= e["/bands/ci_upper_db"]))[:, bands])
    return float(np.mean(held_bins)), float(np.mean(held_bands)), ref


@pytest.mark.parametrize("study,K,M,K_ref,sets", [
    ("random-oscillator.ini", 25, 20, 1000, []),
    # Hertz contact with loss of contact in about a third of the time (asserted below).
    ("seed001-beam-s-hertz.ini", 25, 20, 1000, []),
    # The command-line tests' half-metre rolling pipe (conftest.SMALL_PIPE), rolled 0.03 m: the node
    # spheres touch the floor intermittently (about half the node-time open), so a realisation's
    # PSD varies over orders of magnitude (ln-spread 1.0-1.6, lognormal-like).
    ("small-pipe", 16, 20, 480, ["roll.distance=0.03", "spectrum.skip_start=0.01", "spectrum.segment=128",
                                  "spectrum.band_min=100", "spectrum.band_max=2000"]),
    # Seed 001 beam R, law = table, about half the time out of contact, with a 4-surface table (fast
    # to build). Every study seed shares the table ([stiffness] table_seed): the intervals are
    # conditional on it (table_error = none), and so is this check (its own sampling error: D-28, D-30).
    ("seed001-beam-r.ini", 25, 20, 1000, ["stiffness.realisations=4", "stiffness.table_dir={tmp}/tables",
                                          "stiffness.table_error=none"]),
    # The seed 002 rig on its own route: the linearised law's blocked force from the contact solver
    # along strips of the texture (a solver table, built once, about 35 s CPU), shared by every study
    # seed as above (conditional on it: table_error = none).
    ("seed002-rig-1ms.ini", 25, 20, 1000, ["contact.blocked_force=solver", "stiffness.table_dir={tmp}/tables",
                                           "stiffness.table_error=none"]),
], ids=["random-oscillator", "ball-on-beam-loss-of-contact", "rolling-pipe", "table-law-loss-of-contact",
        "solver-table"])
def test_nominal_95_percent_intervals_hold_the_large_k_mean_in_90_to_98_percent(request, tmp_path, study, K, M, K_ref,
                                                                                sets):
    (tmp_path / "tables").mkdir()  # a table study's cache, outside the source tree
    sets = [s.format(tmp=tmp_path) for s in sets]
    held_bins, held_bands, ref = coverage(tmp_path, study, K, M, K_ref, sets)
    print(f"{study}: K = {K}, M = {M}, K_ref = {K_ref}: bins {held_bins:.3f}, bands {held_bands:.3f}")
    if "loss-of-contact" in request.node.callspec.id:
        assert ref["loss"] > 0.2, "the ball-on-beam case must lose contact"
    assert 0.90 <= held_bins <= 0.98
    assert 0.90 <= held_bands <= 0.98


# The blocked-force table's own error (kernels/spectral D-30d): a coarse seed 002 rig on its own route
# (12 um cells, a 6.6 mm strip, 15 Welch segments of F0; under a second per table), whose every study
# seed shares the table. Each of M test tables (table seeds 11-22) runs K realisations with
# [stiffness] table_error = jackknife; the reference is the mean level over 4 other tables (table
# seeds 31-34) at K_ref and another study seed. Measured when written: bins 0.923, bands 0.924 with
# the term; 0.422 / 0.414 without it (the intervals conditional on the table).
BLOCKED_FORCE = ["contact.blocked_force=solver", "surface.spacing=12e-6", "texture.short_wavelength=24e-6",
                 "blocked_force.segment=64", "blocked_force.strip_length=6.6e-3", "ball.start=0.1", "ball.end=0.2",
                 "spectrum.segment=128", "spectrum.band_min=400", "spectrum.band_max=5000"]


def levels_db(e):
    """Bins (dB) and bands of an ensemble from 400 Hz to 5 kHz, with their intervals, as (level, lower, upper)."""
    f = (e["/psd/frequency"] >= 400) & (e["/psd/frequency"] <= 5000)
    return (tuple(10 * np.log10(e[d][:, f]) for d in ("/psd/mean", "/psd/ci_lower", "/psd/ci_upper")),
            (e["/bands/level_db"], e["/bands/ci_lower_db"], e["/bands/ci_upper_db"]))


def test_a_blocked_force_table_jackknife_holds_other_tables_mean_in_90_to_98_percent(tmp_path):
    (tmp_path / "tables").mkdir()
    sets = [*BLOCKED_FORCE, f"stiffness.table_dir={tmp_path}/tables"]
    refs = [levels_db(ensemble(tmp_path, "seed002-rig-1ms.ini", 555, 400,
                               sets + [f"stiffness.table_seed={t}", "stiffness.table_error=none"], f"ref{t}"))
            for t in (31, 32, 33, 34)]
    ref = [np.mean([r[k][0] for r in refs], axis=0) for k in (0, 1)]
    held = {True: ([], []), False: ([], [])}
    for t in range(11, 23):
        for term in (True, False):
            e = levels_db(ensemble(tmp_path, "seed002-rig-1ms.ini", 999, 25,
                                   sets + [f"stiffness.table_seed={t}",
                                           f"stiffness.table_error={'jackknife' if term else 'none'}"],
                                   f"t{t}-{term}"))
            for k in (0, 1):
                held[term][k].append((e[k][1] <= ref[k]) & (ref[k] <= e[k][2]))
    with_term = [float(np.mean(h)) for h in held[True]]
    without = [float(np.mean(h)) for h in held[False]]
    print(f"blocked-force table jackknife: bins / bands {with_term[0]:.3f} / {with_term[1]:.3f} with the term, "
          f"{without[0]:.3f} / {without[1]:.3f} without")
    assert all(0.90 <= c <= 0.98 for c in with_term), with_term
    assert all(c < 0.8 for c in without), without  # the tables differ by more than the realisations' intervals
