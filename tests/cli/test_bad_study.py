"""Every kind of bad study input is refused before any work starts: exit code, a message naming
file, line, key, value and what is allowed, and no output file created or touched."""
import pytest

from conftest import EX_CONFIG, EX_NOINPUT, EX_USAGE, SMALL_OSCILLATOR, run

GOOD = SMALL_OSCILLATOR.format(realisations=4, chunk=4, duration=4)


def replace(old, new):
    assert old in GOOD
    return GOOD.replace(old, new)


def line_of(text, fragment):
    return next(i + 1 for i, l in enumerate(text.splitlines()) if fragment in l)


CASES = [
    # name, study text, extra args, exit code, fragments the message must contain
    ("unknown key", replace("mass = 1.5", "mass = 1.5\nmas = 2"), [], EX_CONFIG,
     ["unknown key [oscillator] mas = 2", "allowed keys in [oscillator]: mass, natural_frequency, damping_ratio"]),
    ("unknown section", GOOD + "\n[beam]\nlength = 1\n", [], EX_CONFIG, ["unknown section [beam]", "allowed sections"]),
    ("nan", replace("damping_ratio = 0.05", "damping_ratio = nan"), [], EX_CONFIG,
     ["[oscillator] damping_ratio = nan", "NaN", "allowed: a finite number in (0, 10]"]),
    ("inf", replace("level = 2.0", "level = inf"), [], EX_CONFIG, ["[force] level = inf", "not finite"]),
    ("huge number", replace("level = 2.0", "level = 1e999"), [], EX_CONFIG, ["[force] level = 1e999", "not finite"]),
    ("wrong sign", replace("mass = 1.5", "mass = -1.5"), [], EX_CONFIG,
     ["[oscillator] mass = -1.5", "out of range", "a finite number > 0 (kg)"]),
    ("out of range", replace("damping_ratio = 0.05", "damping_ratio = 12"), [], EX_CONFIG,
     ["damping_ratio = 12", "out of range"]),
    ("not a number", replace("mass = 1.5", "mass = heavy"), [], EX_CONFIG, ["mass = heavy", "not a number"]),
    ("not whole", replace("realisations = 4", "realisations = 4.5"), [], EX_CONFIG,
     ["[study] realisations = 4.5", "not a whole number"]),
    ("huge integer", replace("realisations = 4", "realisations = 99999999999999999999999"), [], EX_CONFIG,
     ["realisations = 99999999999999999999999", "too large"]),
    ("zero realisations", replace("realisations = 4", "realisations = 0"), [], EX_CONFIG, ["realisations = 0", "out of range"]),
    ("duplicated key", replace("mass = 1.5", "mass = 1.5\nmass = 2"), [], EX_CONFIG,
     ["duplicated key [oscillator] mass = 2", "first set at line"]),
    ("empty value", replace("mass = 1.5", "mass ="), [], EX_CONFIG, ["[oscillator] mass has no value"]),
    ("unknown choice", replace("[spectrum]", "[spectrum]\nwindow = hamming"), [], EX_CONFIG,
     ["window = hamming", "one of hann, rectangular"]),
    ("unknown scene", replace("scene = random-oscillator", "scene = ball-on-moon"), [], EX_CONFIG,
     ["scene = ball-on-moon", "unknown scene", "random-oscillator"]),
    ("missing required", replace("natural_frequency = 40\n", ""), [], EX_CONFIG,
     ["missing required key [oscillator] natural_frequency"]),
    ("malformed line", replace("mass = 1.5", "mass 1.5"), [], EX_CONFIG, ["cannot read 'mass 1.5'"]),
    ("key before section", "seed = 1\n" + GOOD, [], EX_CONFIG, ["stands before any [section]"]),
    ("not a power of two", replace("chunk_size = 4", "chunk_size = 6"), [], EX_CONFIG,
     ["chunk_size = 6", "not a power of two"]),
    ("cross-key: segment longer than record", GOOD, ["--set", "spectrum.segment=8192"], EX_CONFIG,
     ["[spectrum] segment = 8192", "longer than one realisation's record"]),
    ("cross-key: above Nyquist", replace("natural_frequency = 40", "natural_frequency = 600"), [], EX_CONFIG,
     ["natural_frequency = 600", "Nyquist"]),
    ("--set unknown key", GOOD, ["--set", "oscillator.stiffness=3"], EX_CONFIG,
     ["command line", "unknown key [oscillator] stiffness = 3"]),
    ("--set bad value", GOOD, ["--set", "study.realisations=-3"], EX_CONFIG,
     ["command line", "[study] realisations = -3", "out of range"]),
    ("--set malformed", GOOD, ["--set", "realisations"], EX_USAGE, ["expected section.key=value"]),
    ("binary garbage", "\x00\x01\x02garbage", [], EX_CONFIG, ["binary data"]),
    ("empty file", "", [], EX_CONFIG, ["empty"]),
]


@pytest.mark.parametrize("name,text,extra,code,fragments", CASES, ids=[c[0] for c in CASES])
def test_bad_study_is_refused(tmp_path, name, text, extra, code, fragments):
    study = tmp_path / "bad.ini"
    study.write_text(text)
    out = tmp_path / "result.h5"
    r = run(["run", study, "--out", out, *extra])
    assert r.returncode == code, r.stderr
    for frag in fragments:
        assert frag in r.stderr, f"{frag!r} not in {r.stderr!r}"
    if "--set" not in extra and name not in ("empty file", "missing required"):
        assert "bad.ini:" in r.stderr, "the message names the file and line"
    assert not out.exists()
    assert not list(tmp_path.glob("result.h5*")), "no output or temporary file may appear"


def test_messages_carry_the_line_number(tmp_path):
    text = replace("mass = 1.5", "mass = -1.5")
    study = tmp_path / "bad.ini"
    study.write_text(text)
    r = run(["run", study, "--out", tmp_path / "r.h5"])
    assert f"bad.ini:{line_of(text, 'mass = -1.5')}:" in r.stderr


def test_missing_study_file_and_existing_output_untouched(tmp_path):
    out = tmp_path / "result.h5"
    out.write_bytes(b"precious")
    r = run(["run", tmp_path / "nope.ini", "--out", out])
    assert r.returncode == EX_NOINPUT and "nope.ini" in r.stderr
    study = tmp_path / "bad.ini"
    study.write_text(replace("mass = 1.5", "mass = -1"))
    assert run(["run", study, "--out", out]).returncode == EX_CONFIG
    assert out.read_bytes() == b"precious"


def test_missing_referenced_file(tmp_path):
    # A path key naming a file that does not exist: exit 66 naming file, line and key.
    # (The random-oscillator scene has no path keys; the checkpoint store, `compare` and later scenes do.)
    r = run(["compare", tmp_path / "none.h5", tmp_path / "none.csv"])
    assert r.returncode == EX_NOINPUT and "none.h5" in r.stderr


def test_plan_validates_and_prints_stages(small_study):
    r = run(["plan", small_study()])
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert any(l.split()[:2] == ["stiffness_table", "skipped"] for l in lines[2:])
    assert any(l.split()[:2] == ["dynamics", "run"] for l in lines[2:])


def test_usage_errors_and_help():
    assert run([]).returncode == EX_USAGE
    assert run(["frobnicate"]).returncode == EX_USAGE
    for cmd in ("run", "plan", "psd", "compare", "keys"):
        r = run([cmd, "--help"])
        assert r.returncode == 0 and "usage: rollspec " + cmd in r.stdout
    r = run(["keys", "random-oscillator"])
    assert "natural_frequency = (required)" in r.stdout and "(Hz)" in r.stdout
    assert run(["version"]).stdout.startswith("rollspec ")
