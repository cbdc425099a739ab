"""`python3 -m rollspec_post texture` on a file made by `rollspec texture` in the test run."""
import subprocess

from conftest import BIN, SOURCE, is_png_with_content, post


def test_texture_plot(tmp_path):
    tex = tmp_path / "t.h5"
    r = subprocess.run([BIN, "texture", SOURCE / "studies" / "texture-demo.ini", "--out", tex, "--count", "4"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = tmp_path / "t.png"
    r = post("texture", tex, "--out", out)
    assert r.returncode == 0, r.stderr
    assert is_png_with_content(out)


def test_texture_plot_refuses_a_result_file(oscillator_result, tmp_path):
    r = post("texture", oscillator_result, "--out", tmp_path / "x.png")
    assert r.returncode == 65 and "rollspec-texture" in r.stderr
