"""rollspec.surfaces.read_profiles, .profile_psd and ProfilePsd against `rollspec texture` on the same
measured profiles ([texture] source = profiles): the /profiles record, lines and surfaces bit for bit;
the periodogram against Eq. 15-17 written out in numpy; bad profiles and keys refused with the
command's messages."""
import os
import subprocess

import h5py
import numpy as np
import pytest

from rollspec import surfaces

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
PROFILES = os.path.join(os.path.dirname(__file__), "..", "..", "studies", "data", "seed001-profiles")
FILES = [os.path.abspath(os.path.join(PROFILES, "beam-r-%02d.csv" % i)) for i in (1, 2, 3)]
SEED = 91


def texture(tmp_path, name, *sets):
    """`rollspec texture` on a study of FILES: 2 lines of 3 mm at 1 um, 2 surfaces of 64 x 64 cells of 2 um."""
    study = tmp_path / "s.ini"
    study.write_text(
        "[study]\nscene = texture\nrealisations = 1\nseed = %d\n[texture]\nsource = profiles\nprofiles = %s\n"
        "table_extension = zero\n[lines]\ncount = 2\nlength = 3e-3\nspacing = 1e-6\n"
        "[surface]\nmethod = spectral\nnx = 64\nny = 64\nspacing = 2e-6\ncount = 2\n" % (SEED, ", ".join(FILES)))
    out = tmp_path / name
    args = [a for kv in sets for a in ("--set", kv)]
    subprocess.run([ROLLSPEC, "texture", str(study), "--out", str(out), "--quiet", *args], check=True,
                   capture_output=True)
    return h5py.File(out, "r")


def test_the_profile_record_lines_and_surfaces_equal_the_texture_command_bit_for_bit(tmp_path):
    p = surfaces.read_profiles(FILES, extension="zero")
    with texture(tmp_path, "t.h5") as f:
        g = f["/profiles"]
        assert p.wavenumber.tobytes() == g["wavenumber"][:].tobytes()
        assert p.periodogram.tobytes() == g["periodogram"][:].tobytes()
        a = g.attrs
        assert (p.scans, p.samples) == (a["scans"], a["samples"]) == (3, 7501)
        for name in ("spacing", "variance", "resolved_variance", "unresolved_variance", "resolved_wavenumber",
                     "short_wavelength_cut"):
            assert getattr(p, name) == a[name], name
        assert p.description == f.attrs["psd"].decode()
        lines = f["/texture/lines"][:]
        for index in (0, 1):
            r = p.line(1e-6, lines.shape[1], seed=SEED, index=index)
            assert r["heights"].tobytes() == lines[index].tobytes()
        assert np.array_equal(r["target_psd"], f["/texture/psd_target"][:])
        heights = f["/surface/heights"][:]
        for index in (0, 1):
            s = p.isotropic(2e-6, 64, seed=SEED, index=index)
            assert s["heights"].tobytes() == heights[index].tobytes()


def test_a_short_wavelength_cut_and_seed_surfaces_from_the_profiles_values(tmp_path):
    # Seed surfaces take sigma and the correlation lengths from the profiles (seed 001 Eq. 10).
    p = surfaces.read_profiles(FILES, extension="zero", short_wavelength=2e-5)
    with texture(tmp_path, "t.h5", "surface.method=seed", "texture.short_wavelength=2e-5") as f:
        assert p.short_wavelength_cut == f["/profiles"].attrs["short_wavelength_cut"] == 2e-5
        assert p.description == f.attrs["psd"].decode()
        lines = f["/texture/lines"][:]
        assert p.line(1e-6, lines.shape[1], seed=SEED, index=1)["heights"].tobytes() == lines[1].tobytes()
        s = p.isotropic(2e-6, 64, seed=SEED, index=1, method="seed")
        assert s["heights"].tobytes() == f["/surface/heights"][1].tobytes()
        assert s["sigma"] == p.sigma and s["correlation"] == (p.correlation_length, p.correlation_length)
    # The cut removes the PSD above 2 pi / 2e-5 m.
    assert p(np.array([2 * np.pi / 2e-5 * 1.01]))[0] == 0.0
    assert surfaces.read_profiles(FILES, extension="zero")(np.array([2 * np.pi / 2e-5 * 1.01]))[0] > 0.0


def test_arrays_give_the_files_estimate_and_eq_15_to_17():
    read = [surfaces.read_profile(f) for f in FILES]
    heights = np.array([r["heights"] for r in read])
    dx = read[0]["spacing"]
    assert dx == 2e-6 and np.array_equal(read[0]["x"], dx * np.arange(7501))
    p = surfaces.profile_psd(heights, dx)
    q = surfaces.read_profiles(FILES)
    assert p.periodogram.tobytes() == q.periodogram.tobytes() and p.variance == q.variance
    # Eq. 15-17: linear trend removed, periodic Hann window, density scaling, one-sided, mean over profiles.
    n = heights.shape[1]
    i = np.arange(n)
    w = 0.5 - 0.5 * np.cos(2 * np.pi * i / n)
    want = np.zeros(n // 2 + 1)
    for z in heights:
        z = z - np.polyval(np.polyfit(i, z, 1), i)
        g = dx * np.abs(np.fft.rfft(w * z)) ** 2 / (2 * np.pi * np.sum(w * w))
        g[1:-1 if n % 2 == 0 else None] *= 2
        want += g / len(heights)
    assert np.allclose(p.periodogram[1:], want[1:], rtol=1e-9, atol=0)
    assert np.allclose(p.wavenumber, 2 * np.pi * i[: n // 2 + 1] / (n * dx), rtol=1e-14, atol=0)
    # Another layout is read as C-contiguous float64: the same bits.
    assert surfaces.profile_psd(np.asfortranarray(heights), dx).periodogram.tobytes() == p.periodogram.tobytes()
    # One profile as a 1-D array is one row.
    one = surfaces.profile_psd(heights[0], dx)
    assert one.scans == 1 and one.periodogram.tobytes() == surfaces.read_profiles(FILES[:1]).periodogram.tobytes()


@pytest.mark.parametrize("heights, kwargs, message", [
    (np.zeros((2, 5)), {}, "heights: profile 0 has 5 samples"),
    (np.full(16, np.nan), {}, "heights: 16 values NaN or infinite"),
    (np.zeros((2, 2, 8)), {}, "heights: 3 dimension(s)"),
    (np.zeros(0), {}, "heights: shape (0,), a side under 1"),
    (np.zeros((0, 8)), {}, "heights: shape (0, 8), a side under 1"),
    (np.array(["a"] * 8), {}, "heights: an array of dtype <U1"),
    (np.zeros(16), {"spacing": -1.0}, "spacing = -1: not a spacing"),
    (np.zeros(16), {"extension": "linear"}, "extension = 'linear': unknown; allowed: error, constant, power_law"),
])
def test_bad_arrays_and_keys_are_value_errors_naming_them(heights, kwargs, message):
    args = {"spacing": 1e-6, **kwargs}
    with pytest.raises(ValueError, match="^" + message.replace("(", r"\(").replace(")", r"\)")):
        surfaces.profile_psd(heights, args.pop("spacing"), **args)


def test_bad_files_and_cuts_are_the_commands_errors(tmp_path):
    with pytest.raises(OSError, match="no-such.csv"):
        surfaces.read_profiles([str(tmp_path / "no-such.csv")])
    bad = tmp_path / "bad.csv"
    bad.write_text("x,height_m\n" + "".join("%d,0\n" % i for i in range(10)))
    with pytest.raises(ValueError, match=r"bad.csv:1: a profile has the columns position_m,height_m"):
        surfaces.read_profile(str(bad))
    with pytest.raises(ValueError, match=r"^short_wavelength = 1 um: cuts the measured PSD .* allowed: between 4 um"):
        surfaces.read_profiles(FILES, short_wavelength=1e-6)
    # The PSD ends at the profiles' Nyquist wavenumber: a finer line needs an extension, as in a study.
    with pytest.raises(ValueError, match=r"^spacing = 1e-06: PSD table covers k = "):
        surfaces.read_profiles(FILES).line(1e-6, 1000, seed=1)
