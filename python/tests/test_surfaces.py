"""rollspec.surfaces.line against `rollspec texture` (the same bits for a seed and an index), the
requested PSD exactly (deterministic amplitudes) and within its sampling error (Rayleigh)."""
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
    args = {"wavenumber": K, "psd": G, "spacing": 1e-6, "samples": 64, "seed": 1, "extension": "zero"}
    args.update(kwargs)
    with pytest.raises(ValueError) as e:
        surfaces.line(args.pop("wavenumber"), args.pop("psd"), args.pop("spacing"), args.pop("samples"), **args)
    assert message in str(e.value)
    assert "\n" not in str(e.value)
