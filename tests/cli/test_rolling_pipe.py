"""Monte-Carlo rolling pipe: a tube of beam elements rolling with friction over random
rough surfaces. Ensemble bits independent of thread count and chunking; the ensemble mean stays
inside its own chi-square interval when the realisation count doubles; bad studies refused."""
import h5py
import numpy as np
import pytest

from conftest import EX_CONFIG, SMALL_PIPE, SOURCE, assert_bitwise_equal, run

def small_pipe(tmp_path, realisations, chunk=4, kind="isotropic", name="pipe.ini"):
    p = tmp_path / name
    p.write_text(SMALL_PIPE.format(realisations=realisations, chunk=chunk, kind=kind))
    return p


def test_one_and_two_threads_give_identical_bits(tmp_path):
    study = small_pipe(tmp_path, 4, chunk=2)
    a, b = tmp_path / "t1.h5", tmp_path / "t2.h5"
    r1 = run(["run", study, "--out", a, "--quiet"], env={"OMP_NUM_THREADS": "1"})
    assert r1.returncode == 0, r1.stderr
    r2 = run(["run", study, "--out", b, "--quiet", "--set", "ensemble.chunk_size=4"], env={"OMP_NUM_THREADS": "2"})
    assert r2.returncode == 0, r2.stderr
    assert_bitwise_equal(a, b)
    with h5py.File(a) as f:
        assert f["/psd/mean"].shape[0] == 4  # three sensors and their mean
        assert np.all(f["/psd/mean"][:, 1:] > 0)
        # rolling without slip at the start, and the floor barely slows the tube
        assert abs(f["/roll/speed_ratio"][0] - 1) < 0.01
        # r kappa_max < 1 under every node sphere: single-point contact
        assert f["/contact/two_point_realisations"][0] == 0
        assert f["/contact/curvature_ratio"][0] < 1


@pytest.mark.long  # minutes under the sanitizers: their pass skips it (tests/cli/CMakeLists.txt)
def test_an_independent_larger_ensemble_falls_inside_the_interval(tmp_path):
    # Two ensembles with different seeds share no realisation. The K = 32 mean differs from the
    # K = 16 mean by a scatter of variance s^2/16 + s^2/32 = 1.5 s^2/16, so it falls inside the
    # K = 16 interval of the mean (half-width ~1.96 s/4) for a share P(|Z| < 1.96/sqrt(1.5)) = 0.89
    # of the bins if that interval is right (measured here: 0.98-1.0, the union of laws errs wide);
    # a too narrow one gives far less.
    study = small_pipe(tmp_path, 32)
    half, full = tmp_path / "k16.h5", tmp_path / "k32.h5"
    r = run(["run", study, "--out", half, "--quiet", "--set", "study.realisations=16", "--set", "study.seed=11"])
    assert r.returncode == 0, r.stderr
    r = run(["run", study, "--out", full, "--quiet", "--set", "study.seed=12"])
    assert r.returncode == 0, r.stderr
    with h5py.File(half) as a, h5py.File(full) as b:
        f = a["/psd/frequency"][:]
        band = (f >= 40) & (f <= 4000)
        lo, hi = a["/psd/ci_lower"][:, band], a["/psd/ci_upper"][:, band]
        m32 = b["/psd/mean"][:, band]
        share = ((m32 >= lo) & (m32 <= hi)).mean(axis=1)
        print("share of bins of the K = 32 mean inside the K = 16 interval, per sensor row:", share)
        assert np.all(share >= 0.8), share
        # the interval narrows as K doubles
        assert np.all(np.median(b["/psd/ci_upper"][:, band] / b["/psd/ci_lower"][:, band], axis=1)
                      < np.median(hi / lo, axis=1))


def test_coarse_step_and_sharp_roughness_are_refused(tmp_path):
    study = small_pipe(tmp_path, 2)
    r = run(["run", study, "--out", tmp_path / "x.h5", "--set", "analysis.dt=5e-4"])
    assert r.returncode == EX_CONFIG
    assert "[analysis] dt" in r.stderr and "T_c/20" in r.stderr
    assert not (tmp_path / "x.h5").exists()
    r = run(["run", study, "--out", tmp_path / "x.h5", "--set", "texture.short_wavelength=1e-4",
             "--set", "roughness.kind=line", "--set", "roughness.spacing=5e-5"])
    assert r.returncode == EX_CONFIG
    assert "[roughness] spacing" in r.stderr and "two points" in r.stderr


def test_default_study_plans():
    r = run(["plan", SOURCE / "studies" / "rolling-pipe.ini"])
    assert r.returncode == 0, r.stderr
    assert "surface" in r.stdout and "dynamics" in r.stdout
