"""Seed 001 as the paper ran it (issue 15 part 1; CTest label `studies`, about 2 min): the shipped
studies seed001-beam-s.ini and seed001-beam-r.ini run the seed's chain from the stand-in profiles
(studies/data/seed001-profiles/) through isotropic surfaces and an elastic-plastic stiffness table to
the table law, 25 realisations each, and reproduce the seed's finding (§4, conclusions): "frequent
loss of contact" on the rough beam R, rarely on the ground beam S."""
import shutil

import h5py
import numpy as np
import pytest

from conftest import SOURCE, run


@pytest.fixture(scope="module")
def beams(tmp_path_factory):
    d = tmp_path_factory.mktemp("seed001")
    studies = d / "studies"
    shutil.copytree(SOURCE / "studies", studies, ignore=shutil.ignore_patterns("tables"))
    out = {}
    for beam in ("s", "r"):
        study = studies / f"seed001-beam-{beam}.ini"
        plan = run(["plan", study])
        assert plan.returncode == 0, plan.stderr
        stages = {row.split()[0]: row.split()[1] for row in plan.stdout.splitlines() if len(row.split()) >= 2}
        assert stages.get("stiffness_table") == "run", plan.stdout  # the table is built from the profiles
        h5 = d / f"beam-{beam}.h5"
        # The seed ran no table jackknife, and nothing here reads an interval: the table's own error
        # (6 or 10 sub-tables and their ensembles, about half this test's time) is tested in
        # test_table_jackknife*.py.
        r = run(["run", study, "--out", h5, "--set", "stiffness.table_error=none", "--quiet"], timeout=900)
        assert r.returncode == 0, r.stderr
        with h5py.File(h5) as f:
            law = f["/contact"].attrs["law"]
            out[beam] = {"law": law.decode() if isinstance(law, bytes) else law,
                         "loss": float(f["/contact/loss_of_contact_share"][0]),
                         "bands": f["/bands/level_db"][-1], "centre": f["/bands/centre_frequency"][:]}
    return out


def test_both_beams_run_the_table_law_from_the_profiles(beams):
    assert beams["s"]["law"] == "table" and beams["r"]["law"] == "table"


def test_beam_r_loses_contact_frequently_and_beam_s_rarely(beams):
    # The share depends on the stiffness table (6 surfaces for S, 10 for R; its sampling error, kernels/spectral
    # D-28). Measured, 25 realisations each: S 5.1 % with the default [stiffness] table_seed 1, 3.3-3.5 % with
    # table seeds 2-4 (2.2-4.0 % when the study seed drew the table); R 45-58 % over table seeds 1-5
    # (K = 800), 51 % with table seed 1. The bounds hold the finding for any of these tables.
    s, r = beams["s"]["loss"], beams["r"]["loss"]
    assert s < 0.08, s
    assert r > 0.3, r
    assert r > 5 * s, (s, r)


def test_the_rougher_beam_is_louder_where_the_roughness_drives_it(beams):
    # Ra 2.25 um against 0.29 um (7.8x): beam R's acceleration is higher in every band 100 Hz-5 kHz
    # even with contact lost half of the time (measured: by 3.4 dB at least, at 1.6 kHz; 3.6 dB before the
    # measured-profile PSD kept its periodogram level, kernels/texture Eq. 43).
    # The seed gives no band levels in its text, so this is a consistency check, not a published figure.
    centre = beams["s"]["centre"]
    band = (centre >= 100) & (centre <= 5000)
    assert np.all(beams["r"]["bands"][band] > beams["s"]["bands"][band])
