"""Isotropic surfaces from a PSD estimated from measured profiles keep the profiles' rms: the estimate
is band-averaged before the 2D conversion (kernels/texture/README.md Eq. 33-35), and seed-method
surfaces take the profiles' sigma (seed 001 Eq. 10) unless [surface] sigma is given."""
import h5py
import numpy as np
import pytest

from conftest import run, texture_study

SOURCE_STUDY = texture_study(515, {"source": "self-affine", "hurst": 0.8, "rolloff_wavelength": "20e-6",
                                   "short_wavelength": "2e-6", "rms": "0.4e-6"},
                              {"count": 50, "length": "4.0965e-3", "spacing": "1e-6"})


def profile_study(files, method, extra=""):
    """Surfaces from the profiles `files` by `method`; `extra`, more [surface] lines."""
    return texture_study(7, {"source": "profiles", "profiles": ", ".join(files), "table_extension": "zero"},
                         {"count": 0, "length": "1e-3", "spacing": "1e-6"},
                         {"method": method, "nx": 128, "ny": 128, "spacing": "1e-6", "count": 4}) + extra


@pytest.fixture(scope="module")
def profiles(tmp_path_factory):
    d = tmp_path_factory.mktemp("profiles")
    (d / "source.ini").write_text(SOURCE_STUDY)
    r = run(["texture", d / "source.ini", "--out", d / "source.h5", "-q"])
    assert r.returncode == 0, r.stderr
    with h5py.File(d / "source.h5") as f:
        x, lines = f["/texture/x"][()], f["/texture/lines"][()]
    names = []
    for i, z in enumerate(lines):
        np.savetxt(d / f"p{i}.csv", np.c_[x, z], delimiter=",", header="position_m,height_m", comments="")
        names.append(f"p{i}.csv")
    return d, names, lines


def detrended_std(z):
    i = np.arange(len(z))
    return np.std(z - np.polyval(np.polyfit(i, z, 1), i))


def surface_rms(d, names, method, extra=""):
    s = d / f"{method}-{len(names)}.ini"
    s.write_text(profile_study(names, method, extra))
    r = run(["texture", s, "--out", d / f"{method}-{len(names)}.h5", "-q"])
    assert r.returncode == 0, r.stderr
    with h5py.File(d / f"{method}-{len(names)}.h5") as f:
        h = f["/surface/heights"][()]
    return np.mean([np.std(x) for x in h])


@pytest.mark.parametrize("count", [5, 15, 50])
def test_surfaces_keep_the_profiles_rms(profiles, count):
    d, names, lines = profiles
    sigma = np.mean([detrended_std(z) for z in lines[:count]])
    spectral = surface_rms(d, names[:count], "spectral") / sigma
    assert abs(spectral - 1) < 0.1, spectral
    seed = surface_rms(d, names[:count], "seed") / sigma
    assert abs(seed - 1) < 1e-6, seed  # Eq. 10: exactly the profiles' sigma


def test_a_given_sigma_still_sets_seed_surfaces(profiles):
    d, names, _ = profiles
    assert surface_rms(d, names[:5], "seed", "sigma = 2e-7\n") == pytest.approx(2e-7, rel=1e-9)


def one_over_e_length(z, dx):
    z = z - z.mean()
    r = np.fft.irfft(np.abs(np.fft.rfft(z, 2 * len(z))) ** 2)[:len(z)]
    r /= r[0]
    k = int(np.argmax(r < np.exp(-1)))
    return dx * (k - 1 + (r[k - 1] - np.exp(-1)) / (r[k - 1] - r[k]))


def test_seed_surfaces_take_the_profiles_correlation_length(profiles):
    # Seed 001 §3.1: the box lengths n, m come from the measured profiles' correlation length.
    d, names, lines = profiles
    i = np.arange(lines.shape[1])
    measured = np.mean([one_over_e_length(z - np.polyval(np.polyfit(i, z, 1), i), 1e-6) for z in lines[:15]])
    s = d / "corr.ini"
    s.write_text(profile_study(names[:15], "seed").replace("count = 4", "count = 8"))
    r = run(["texture", s, "--out", d / "corr.h5"])
    assert r.returncode == 0, r.stderr
    row = next(l.split() for l in r.stdout.splitlines() if l.startswith("surf_mean"))
    for got in (float(row[5]), float(row[6])):  # corr_len_x_m, corr_len_y_m
        assert got == pytest.approx(measured, rel=0.15), (got, measured)
    print(f"profiles 1/e {measured:.4g} m, seed surfaces {row[5]} x, {row[6]} y")
