"""`[texture] source = profiles` as a user meets it: positions as printed, readable messages, every
[texture] key acting or refused, the short-wavelength cut (kernels/texture Eq. 46), the unresolved
variance said by texture, plan and run and recorded in /profiles, and a warning with the share of
variance a spectral surface smaller than the scans keeps."""
import re

import h5py
import numpy as np
import pytest

from conftest import EX_CONFIG, EX_DATAERR, SOURCE, assert_refused, run

DATA = SOURCE / "studies" / "data" / "measured-profiles"
ROWS = sorted((DATA / "top-1-rows").glob("row-*.csv"))
ROW_SPACING = 600e-9 / 256


def texture_study(tmp_path, texture, lines="count = 2\nlength = 5e-7\nspacing = 2.34375e-09", surface=""):
    p = tmp_path / "s.ini"
    p.write_text(f"[study]\nscene = texture\nrealisations = 1\nseed = 3\n\n[texture]\n{texture}\n\n[lines]\n{lines}\n"
                 + (f"\n[surface]\n{surface}\n" if surface else ""))
    return p


def rows_texture(extra=""):
    return "source = profiles\nprofiles = " + ", ".join(str(r) for r in ROWS) + "\ntable_extension = zero\n" + extra


def stylus_export(path, x_text, n=2000):
    """A profile whose positions are the given texts (a stylus export), heights a rough sine mix."""
    z = 1e-7 * (np.sin(np.arange(n) * 0.37) + 0.5 * np.sin(np.arange(n) * 0.011))
    path.write_text("position_m,height_m\n" + "".join(f"{a},{b!r}\n" for a, b in zip(x_text, z)))


def test_positions_rounded_to_their_printed_digits_are_accepted_and_messages_print_lengths_readably(tmp_path):
    n, step = 2000, 0.15625e-6  # a Dektak's 0.156 um steps, printed to 0.1 um as its export does
    stylus_export(tmp_path / "scan.csv", [f"{round(i * step * 1e7) / 1e7:.7f}" for i in range(n)], n)
    study = texture_study(tmp_path, "source = profiles\nprofiles = scan.csv\ntable_extension = zero",
                          "count = 1\nlength = 3e-4\nspacing = 1.5625e-7")
    r = run(["texture", study, "--out", tmp_path / "t.h5"])
    assert r.returncode == 0, r.stderr
    with h5py.File(tmp_path / "t.h5") as f:
        assert f["/profiles"].attrs["spacing"][0] == 1.5625e-7  # the step the positions were printed from
    # A gap of 0.2 um (more than the rounding explains): refused at its line, lengths in nm and um.
    x = [f"{round((i * step + (0.2e-6 if i >= 700 else 0.0)) * 1e7) / 1e7:.7f}" for i in range(n)]
    stylus_export(tmp_path / "scan.csv", x, n)
    r = run(["texture", study, "--out", tmp_path / "t2.h5"])
    assert_refused(r, EX_DATAERR, [f"s.ini:8: [texture] profiles = scan.csv: {tmp_path / 'scan.csv'}:702: column "
                                   "'position_m' steps by 400 nm (from 109.2 um to 109.6 um)", "steps of the profile "
                                   "(dx = 156.", " nm from the first and last positions): a missing, repeated or "
                                   "shifted sample", "within the rounding of its printed digits"])
    assert "0.000000 m" not in r.stderr


@pytest.mark.parametrize("key, value", [("table", "psd.csv"), ("hurst", "0.5"), ("long_wavelength", "0.001"),
                                        ("rolloff_wavelength", "1e-04"), ("rms_kind", "slope"), ("rms", "1e-07"),
                                        ("road_class", "B")])
def test_texture_keys_that_cannot_act_on_profiles_are_refused(tmp_path, key, value):
    (tmp_path / "psd.csv").write_text("wavenumber_rad_per_m,psd_m3\n1e3,1e-18\n1e6,1e-23\n")
    r = run(["texture", texture_study(tmp_path, rows_texture(f"{key} = {value}")), "--out", tmp_path / "t.h5"])
    assert_refused(r, EX_CONFIG, [f"s.ini:10: [texture] {key} = {value}: does not act on measured profiles",
                                  "allowed with profiles: profiles, median_filter, table_extension, short_wavelength"])


def test_short_wavelength_cuts_the_measured_psd(tmp_path):
    cut = 20e-9  # within the rows' resolved band (4.7 nm .. 171 nm)
    lines = f"count = 4\nlength = {256.5 * ROW_SPACING!r}\nspacing = {ROW_SPACING!r}"
    r = run(["texture", texture_study(tmp_path, rows_texture(), lines), "--out", tmp_path / "a.h5"])
    assert r.returncode == 0, r.stderr
    r = run(["texture", texture_study(tmp_path, rows_texture(f"short_wavelength = {cut!r}"), lines), "--out",
             tmp_path / "b.h5"])
    assert r.returncode == 0, r.stderr
    assert "cut at [texture] short_wavelength = 20 nm (Eq. 46)" in r.stderr
    with h5py.File(tmp_path / "a.h5") as a, h5py.File(tmp_path / "b.h5") as b:
        k, whole, cut_psd = a["/texture/psd_wavenumber"][:], a["/texture/psd_target"][:], b["/texture/psd_target"][:]
        assert b["/profiles"].attrs["short_wavelength_cut"][0] == cut
    dk, kc = k[1] - k[0], 2 * np.pi / cut
    assert np.all(cut_psd[k > kc + dk] == 0.0) and np.any(whole[k > kc + dk] > 0.0)
    below = k < kc - dk
    assert np.array_equal(cut_psd[below], whole[below])
    for bad, allowed in [(2e-9, "between 4.6875 nm (twice the scans' spacing"), (500e-9, "and 171.")]:
        r = run(["texture", texture_study(tmp_path, rows_texture(f"short_wavelength = {bad!r}")), "--out",
                 tmp_path / "c.h5"])
        assert_refused(r, EX_CONFIG, [f"s.ini:10: [texture] short_wavelength = {bad:g}", "resolved band",
                                      allowed, "(the longest wavelength the scans resolve)"])


def test_a_spectral_surface_smaller_than_the_scans_warns_with_the_share_it_keeps(tmp_path):
    surface = f"count = 6\nnx = 64\nny = 64\nspacing = {ROW_SPACING!r}"
    study = texture_study(tmp_path, rows_texture(), "count = 0\nlength = 5e-7\nspacing = 2.34375e-09", surface)
    r = run(["texture", study, "--out", tmp_path / "t.h5"])
    assert r.returncode == 0, r.stderr
    m = re.search(r"s\.ini:\d+: \[surface\] nx = 64: the spectral surfaces of 64 x 64 cells of 2\.34375 nm hold "
                  r"([0-9.]+) % of the measured profiles' variance", r.stderr)
    assert m, r.stderr
    assert "[surface] nx and ny at least 256 at this spacing" in r.stderr
    with h5py.File(tmp_path / "t.h5") as f:
        kept = f["/surface/heights"][:].var(axis=(1, 2)).mean() / f["/profiles"].attrs["variance"][0]
    print(f"64 x 64 surfaces: the warning says {m.group(1)} %, 6 surfaces hold {100 * kept:.1f} %")
    assert float(m.group(1)) < 95 and abs(float(m.group(1)) / 100 / kept - 1) < 0.25
    big = texture_study(tmp_path, rows_texture(), "count = 0\nlength = 5e-7\nspacing = 2.34375e-09",
                        surface.replace("64", "256"))
    r = run(["texture", big, "--out", tmp_path / "t2.h5"])
    assert r.returncode == 0 and "spectral surfaces of" not in r.stderr, r.stderr


def test_plan_and_run_say_the_unresolved_variance_and_the_result_records_it(tmp_path):
    hertz = (SOURCE / "studies" / "seed001-beam-s-hertz.ini").read_text()
    study = hertz[hertz.index("[study]"):].replace("realisations = 25", "realisations = 2").replace(
        "end = 0.38", "end = 0.12")
    scan = SOURCE / "studies" / "data" / "seed001-profiles" / "beam-s-01.csv"
    study = re.sub(r"\[texture\]\n(.*\n)*?\n", f"[texture]\nsource = profiles\nprofiles = {scan}\n"
                   "table_extension = zero\n\n", study, count=1)
    (tmp_path / "s.ini").write_text(study)
    r = run(["plan", tmp_path / "s.ini"])
    assert r.returncode == 0, r.stderr
    note = re.search(r"note: \[texture\] profiles: 1 scan of 7501 samples at 2 um .*unresolved \(longer waves\): "
                     r"([0-9.]+) % \(rms", r.stdout)
    assert note, r.stdout
    r = run(["run", tmp_path / "s.ini", "--out", tmp_path / "r.h5"])
    assert r.returncode == 0, r.stderr
    assert "rollspec: note: [texture] profiles: 1 scan of 7501 samples" in r.stderr
    with h5py.File(tmp_path / "r.h5") as f:
        a = f["/profiles"].attrs
        assert a["scans"][0] == 1 and a["samples"][0] == 7501 and a["spacing"][0] == 2e-6
        assert abs(a["resolved_variance"][0] + a["unresolved_variance"][0] - a["variance"][0]) < 1e-9 * a["variance"][0]
        assert abs(100 * a["unresolved_variance"][0] / a["variance"][0] / float(note.group(1)) - 1) < 1e-3
        assert f["/profiles/periodogram"].shape == (3751,)
