"""Grid errors of line textures and surfaces name study keys the user can change (and only keys that
exist); an ISO 3095 PSD outside its band names [texture] table_extension and the spectrum's band."""
import re

from conftest import EX_CONFIG, assert_refused, run


def study(tmp_path, scene, body):
    s = tmp_path / "s.ini"
    s.write_text(f"[study]\nscene = {scene}\nrealisations = 1\nseed = 1\n{body}")
    return s


def listed_keys(scene):
    """{(section, key)} that `rollspec keys SCENE` lists."""
    r = run(["keys", scene])
    assert r.returncode == 0, r.stderr
    keys, section = set(), None
    for line in r.stdout.splitlines():
        m = re.fullmatch(r"\[([a-z_]+)\]", line.strip())
        if m:
            section = m.group(1)
        elif line.startswith("  ") and not line.startswith("    ") and "=" in line:
            keys.add((section, line.split("=")[0].strip()))
    return keys


def named_keys(message):
    return set(re.findall(r"\[([a-z_]+)\] ([a-z_0-9]+)", message))


def test_line_spacing_coarser_than_the_psd_names_the_spacing_and_the_cut_off(tmp_path):
    # Self-affine default: short_wavelength 1e-5 m, k_max = 2 pi / 1e-5; a 1e-5 m spacing resolves half of it.
    s = study(tmp_path, "texture", "[lines]\ncount = 1\nlength = 1e-3\nspacing = 1e-5\n")
    r = run(["texture", s, "--out", tmp_path / "t.h5"])
    assert_refused(r, EX_CONFIG, ["[lines] spacing = 1e-05", "[lines] spacing at most 5e-06 m",
                                  "[texture] short_wavelength at least 2e-05 m"])
    assert "truncation" not in r.stderr
    assert named_keys(r.stderr) <= listed_keys("texture"), r.stderr
    # Each way out the message offers works.
    assert run(["texture", s, "--out", tmp_path / "a.h5", "--set", "lines.spacing=5e-6"]).returncode == 0
    assert run(["texture", s, "--out", tmp_path / "b.h5", "--set", "texture.short_wavelength=2e-5"]).returncode == 0


def test_surface_grid_names_surface_spacing_with_the_anisotropy_stretch(tmp_path):
    # anisotropy 4: the grid must resolve k_max x 2 along y.
    s = study(tmp_path, "texture", "[lines]\ncount = 0\nspacing = 2e-6\n"
              "[surface]\ncount = 1\nnx = 16\nny = 16\nspacing = 4e-6\nanisotropy = 4\n")
    r = run(["texture", s, "--out", tmp_path / "t.h5"])
    assert_refused(r, EX_CONFIG, ["[surface] spacing = 4e-06", "[surface] spacing at most 2.5e-06 m",
                                  "[texture] short_wavelength at least 1.6e-05 m"])
    assert "truncation" not in r.stderr
    assert named_keys(r.stderr) <= listed_keys("texture"), r.stderr
    r = run(["texture", s, "--out", tmp_path / "a.h5", "--set", "surface.spacing=2e-6"])
    assert r.returncode == 0, r.stderr


def test_extended_table_names_table_extension(tmp_path):
    # A table extended as a power law carries power at every k: no spacing resolves it.
    (tmp_path / "psd.csv").write_text("wavenumber_rad_per_m,psd_m3\n1e3,1e-12\n1e5,1e-16\n")
    s = study(tmp_path, "texture", "[texture]\nsource = table\ntable = psd.csv\ntable_extension = power_law\n"
              "[lines]\ncount = 1\nlength = 1e-2\nspacing = 1e-5\n")
    r = run(["texture", s, "--out", tmp_path / "t.h5"])
    assert_refused(r, EX_CONFIG, ["[texture] table_extension = zero or error (now power_law)", "[lines] spacing"])
    assert named_keys(r.stderr) <= listed_keys("texture"), r.stderr
    r = run(["texture", s, "--out", tmp_path / "a.h5", "--set", "texture.table_extension=zero"])
    assert r.returncode == 0, r.stderr


def test_iso3095_defaults_name_table_extension_and_the_band(tmp_path):
    s = study(tmp_path, "ball-on-beam", "[texture]\nsource = iso3095\n")
    r = run(["plan", s])
    # 3.15 mm at the default [ball] speed = 1 m/s: 317.5 Hz.
    assert_refused(r, EX_CONFIG, ["[texture] table_extension set to zero, constant or power_law",
                                  "the ISO 3095 spectrum stops at 3.15 mm wavelength",
                                  "3.15 mm is 317.5 Hz at [ball] speed = 1 m/s"])
    assert named_keys(r.stderr) <= listed_keys("ball-on-beam"), r.stderr
    assert run(["plan", s, "--set", "texture.table_extension=zero"]).returncode == 0
