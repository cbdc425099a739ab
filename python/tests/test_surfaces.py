"""rollspec.surfaces.line and .isotropic against `rollspec texture` (the same bits for a seed and an index);
lines: the requested PSD exactly (deterministic amplitudes) and within its sampling error (Rayleigh);
surfaces: Parseval, isotropy and the anisotropic stretch (spectral), rms and correlation lengths (seed)."""
import os
import subprocess

import h5py
import numpy as np
import pytest

from rollspec import surfaces

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
K = np.array([1e3, 1e5, 1e6])  # rad/m
G = np.array([1e-18, 1e-20, 1e-23])  # m^3


def table_psd(k):
    """The table's log-log interpolation (a power law between nodes), zero outside."""
    inside = (k >= K[0]) & (k <= K[-1])
    out = np.zeros_like(k)
    out[inside] = np.exp(np.interp(np.log(k[inside]), np.log(K), np.log(G)))
    return out


def test_lines_equal_the_texture_command_bit_for_bit(tmp_path):
    with open(tmp_path / "psd.csv", "w") as f:
        f.write("wavenumber_rad_per_m,psd_m3\n")
        f.writelines("%.17g,%.17g\n" % kg for kg in zip(K, G))
    (tmp_path / "s.ini").write_text(
        "[study]\nscene = texture\nrealisations = 1\nseed = 77\n[texture]\nsource = table\ntable = psd.csv\n"
        "table_extension = zero\n[lines]\ncount = 2\nlength = 1.5e-3\nspacing = 1e-6\n")
    subprocess.run([ROLLSPEC, "texture", str(tmp_path / "s.ini"), "--out", str(tmp_path / "t.h5"), "--quiet"],
                   check=True, capture_output=True)
    with h5py.File(tmp_path / "t.h5") as f:
        lines = f["/texture/lines"][:]
        target = f["/texture/psd_target"][:]
    for index in (0, 1):
        r = surfaces.line(K, G, 1e-6, lines.shape[1], seed=77, index=index, extension="zero")
        assert r["heights"].tobytes() == lines[index].tobytes()
        assert np.array_equal(r["target_psd"], target)


def test_deterministic_amplitudes_give_the_requested_psd():
    n, dx = 1024, 1e-6  # n is its own synthesis period: every harmonic is one DFT bin
    r = surfaces.line(K, G, dx, n, seed=1, amplitudes="deterministic", extension="zero")
    assert r["period"] == n
    dk = 2 * np.pi / (n * dx)
    assert np.allclose(r["wavenumber"], dk * np.arange(n // 2 + 1), rtol=1e-15, atol=0)
    want = table_psd(r["wavenumber"])
    assert np.allclose(r["target_psd"][1:-1], want[1:-1], rtol=1e-12, atol=0)
    # h = sum A_j cos(k_j x + phi_j) has DFT (n/2) A_j e^{i phi_j} at bin j, and A_j^2 = 2 G_j dk.
    realised = 2 * np.abs(np.fft.rfft(r["heights"])) ** 2 / (n * n * dk)
    j = np.arange(1, n // 2)
    assert np.allclose(realised[j], want[j], rtol=1e-9, atol=1e-12 * want.max())
    assert r["target_rms"] == pytest.approx(np.sqrt(np.sum(want[j]) * dk), rel=1e-12)


def test_rayleigh_lines_average_to_the_requested_psd():
    n, dx, count = 1024, 1e-6, 200
    dk = 2 * np.pi / (n * dx)
    mean = np.zeros(n // 2 + 1)
    for index in range(count):
        h = surfaces.line(K, G, dx, n, seed=5, index=index, extension="zero")["heights"]
        mean += 2 * np.abs(np.fft.rfft(h)) ** 2 / (n * n * dk) / count
    want = table_psd(dk * np.arange(n // 2 + 1))
    # Each bin's periodogram is exponential (mean G, relative std 1); 16 bins of 200 lines: relative std
    # 1/sqrt(3200) = 1.8 %. Four of them.
    for start in range(1, 160, 16):
        band = slice(start, start + 16)
        assert abs(mean[band].sum() / want[band].sum() - 1) < 4 / np.sqrt(16 * count), start


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"extension": "cubic"}, "extension = 'cubic': unknown; allowed: error, constant, power_law, zero"),
        ({"amplitudes": "flat"}, "amplitudes = 'flat': unknown; allowed: rayleigh, deterministic"),
        ({"samples": 4}, "samples = 4: out of range; allowed: a whole number in [8, 2^26]"),
        ({"spacing": 0.0}, "spacing = 0: not a spacing; allowed: a finite number > 0 (m)"),
        ({"psd": G[:2]}, "psd = 2 values: not one per wavenumber (3); allowed: as many values as wavenumbers"),
        ({"psd": -G}, "wavenumber, psd: "),
        ({"spacing": 1e-5}, "wavenumber, psd: "),  # pi / dx below the table's last wavenumber
    ],
)
def test_bad_input_is_a_value_error_naming_it(kwargs, message):
    assert_value_error(surfaces.line, "samples", 64, kwargs, message)


def assert_value_error(make, count_name, count, kwargs, message):
    """make(wavenumber, psd, spacing, count, **rest) with `kwargs` over good arguments raises a ValueError whose
    one-line message holds `message`."""
    args = {"wavenumber": K, "psd": G, "spacing": 1e-6, count_name: count, "seed": 1, "extension": "zero"}
    args.update(kwargs)
    with pytest.raises(ValueError) as e:
        make(args.pop("wavenumber"), args.pop("psd"), args.pop("spacing"), args.pop(count_name), **args)
    assert message in str(e.value)
    assert "\n" not in str(e.value)


# --- isotropic surfaces ------------------------------------------------------------------------------

def texture_surfaces(tmp_path, surface_keys, seed=77, count=2):
    """/surface/heights of `rollspec texture` on the table K, G with the [surface] keys given."""
    with open(tmp_path / "psd.csv", "w") as f:
        f.write("wavenumber_rad_per_m,psd_m3\n")
        f.writelines("%.17g,%.17g\n" % kg for kg in zip(K, G))
    keys = "".join("%s = %s\n" % kv for kv in surface_keys.items())
    (tmp_path / "s.ini").write_text(
        f"[study]\nscene = texture\nrealisations = 1\nseed = {seed}\n[texture]\nsource = table\ntable = psd.csv\n"
        f"table_extension = zero\n[lines]\ncount = 0\nlength = 1e-4\nspacing = 1e-6\n[surface]\ncount = {count}\n{keys}")
    subprocess.run([ROLLSPEC, "texture", str(tmp_path / "s.ini"), "--out", str(tmp_path / "t.h5"), "--quiet"],
                   check=True, capture_output=True)
    with h5py.File(tmp_path / "t.h5") as f:
        return f["/surface/heights"][:]


@pytest.mark.parametrize("keys", [
    {"method": "spectral", "nx": 32, "ny": 48, "spacing": 1e-6, "anisotropy": 2},
    {"method": "seed", "nx": 40, "ny": 32, "spacing": 1e-6, "sigma": 2e-7, "correlation_x": 8e-6,
     "correlation_y": 5e-6},
])
def test_surfaces_equal_the_texture_command_bit_for_bit(tmp_path, keys):
    heights = texture_surfaces(tmp_path, keys)
    options = {k: v for k, v in keys.items() if k not in ("nx", "ny", "spacing")}
    for index in (0, 1):
        r = surfaces.isotropic(K, G, keys["spacing"], keys["nx"], keys["ny"], seed=77, index=index,
                               extension="zero", **options)
        assert r["heights"].shape == (keys["ny"], keys["nx"])
        assert r["heights"].tobytes() == heights[index].tobytes()


def test_deterministic_spectral_surfaces_hold_their_target_power_and_are_isotropic():
    n, dx = 64, 1e-6
    r = surfaces.isotropic(K, G, dx, n, seed=1, amplitudes="deterministic", extension="zero")
    z = r["heights"]
    # Parseval: every mode carries its |Z_q|^2, the mean square of the grid is their sum (DC none).
    assert abs(z.mean()) < 1e-12 * r["target_rms"]
    assert np.mean(z**2) == pytest.approx(r["target_rms"] ** 2, rel=1e-12)
    # C(q) depends on |q| only: on a square grid, mode (ix, iy) carries the power of mode (iy, ix).
    power = np.abs(np.fft.fft2(z)) ** 2
    assert np.allclose(power, power.T, rtol=1e-9, atol=1e-12 * power.max())
    # Anisotropy a^2 stretches the spectrum, C(qx, qy) = C_iso(|(a qx, qy / a)|): a^2 = 4 is a^2 = 1/4
    # transposed, mode by mode. Along a line the PSD becomes a G(a k) (x) and G(k / a) / a (y): in the
    # table's k^-3 range (this grid's modes 3 to 5) their ratio y / x is a^4 = 16 (1 without the stretch,
    # 1/16 the wrong way round).
    wide, tall = (surfaces.isotropic(K, G, dx, n, seed=1, amplitudes="deterministic", extension="zero",
                                     anisotropy=a)["heights"] for a in (4.0, 0.25))
    p_wide, p_tall = np.abs(np.fft.fft2(wide)) ** 2, np.abs(np.fft.fft2(tall)) ** 2
    assert np.allclose(p_wide, p_tall.T, rtol=1e-9, atol=1e-12 * p_wide.max())
    along_x = (np.abs(np.fft.rfft(wide, axis=1)) ** 2).mean(axis=0)
    along_y = (np.abs(np.fft.rfft(wide, axis=0)) ** 2).mean(axis=1)
    assert np.all(along_y[3:6] > 4 * along_x[3:6])


def test_seed_surfaces_have_the_requested_rms_and_correlation_lengths():
    dx = 1e-6
    for index in range(3):
        r = surfaces.isotropic(K, G, dx, 128, 96, seed=9, index=index, method="seed", sigma=2.5e-7,
                               correlation_x=3e-5, correlation_y=1.5e-5, extension="zero")
        z = r["heights"]
        assert abs(z.mean()) < 1e-12 * 2.5e-7
        assert np.sqrt(np.mean(z**2)) == pytest.approx(2.5e-7, rel=1e-12)  # Eq. 30: rms sigma exactly
    # Eq. 31-32: integer box lengths whose expected 1/e lengths are the nearest to those asked for, each
    # box sample moving them by less than dx here.
    n, m = r["box"]
    assert n > m > 1
    assert abs(r["expected_correlation"][0] - 3e-5) < dx and abs(r["expected_correlation"][1] - 1.5e-5) < dx


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"nx": 33}, "nx = 33: odd; allowed: an even number of grid points ([surface] nx)"),
        ({"nx": 2}, "nx ([surface] nx) = 2: out of range"),
        ({"method": "fourier"}, "method = 'fourier': unknown; allowed: spectral, seed"),
        ({"anisotropy": 0.0}, "anisotropy ([surface] anisotropy) = 0: out of range"),
        ({"spacing": -1e-6}, "spacing ([surface] spacing) = -1e-06: out of range"),
        ({"psd": G[:2]}, "psd = 2 values: not one per wavenumber (3)"),
        ({"spacing": 1e-5}, "wavenumber, psd: "),  # pi / dx below the table's last wavenumber
        ({"wavenumber": np.array([[1e3, 1e5, 1e6]])}, "wavenumber: 2 dimension(s); allowed"),
    ],
)
def test_bad_surface_input_is_a_value_error_naming_it(kwargs, message):
    assert_value_error(surfaces.isotropic, "nx", 32, kwargs, message)
