"""Unit slips are refused before any work (src/scenes/dimension_plausibility.hpp). For every scene listed
by `rollspec keys`, every key whose unit is a length or a speed (read from `rollspec keys SCENE`, so a new
key is covered by default) and every shipped study of that scene, study files are written with the key
(as the study states it, or its default) multiplied by 1e3 and 1e6: mm or um written where the key is in
m. Each must be refused with exit 78 and no output file, in one line naming the key and a reason.

Division is the slip only for keys whose values are micrometres (default below 1 mm: grid spacings,
correlation lengths, approaches, wavelengths): nm written for um, so those are divided by 1e3 and 1e6
too. A wavelength 10^3 smaller is a finer surface that exists, so only 1e6 (below an atom) is written;
a smaller rms height is a smoother surface, down to the "smooth" the tests write as 1e-20, and a line
sampled below 1 nm is an atomic-force microscope's, so those are not divided (NOT_DIVIDED). For the
keys of millimetres and more a value 10^3 or 10^6 smaller is a physically possible study (a smaller
ball, a slower roll, a start at the support): no physical reason refuses it, and it is not written.
EXEMPT lists, with the reason, the few slipped values that are studies someone can mean."""
import concurrent.futures
import re
import shutil
import subprocess

import pytest

from conftest import BIN, SOURCE, scene_keys

UNIT = re.compile(r"allowed: a (?:finite|whole) number.*\((m|m/s|m \(height\) or - \(slope\))\)$")
COMMAND = {"stiffness": "stiffness", "texture": "texture"}  # the scene's own command; others: run
TIMEOUT = 10  # a refusal takes milliseconds; a study accepted starts its work and is stopped here

# Smaller is a real study: a smoother surface, down to the "smooth" the tests write as rms = 1e-20; an
# atomic-force microscope's profile sampled below 1 nm.
NOT_DIVIDED = {"texture.rms", "surface.sigma", "stiffness.ball_rms", "lines.spacing"}
# The texture scene's grid is where heights are drawn, not a contact grid: an AFM's too (below 10 nm).
NOT_DIVIDED_IN = {"texture": {"surface.spacing"}}
# Wavelengths 10^3 smaller (nm) are a finer surface that exists; 10^6 smaller is below an atom.
ONLY_MILLION = {"texture.short_wavelength", "texture.long_wavelength", "texture.rolloff_wavelength"}
SHIPPED_ROLLOFF = ("the value seed 002's rig studies ship (50 mm): a roll-off at 5 cm on a 39-40 cm span is a "
                   "real surface's")
# (study, key, factor): why the slipped value is a study that can be meant.
EXEMPT = {
    ("texture-demo.ini", "lines.length", 1e3):
        "a 4 m profile at 1 um spacing is a legal texture (4e6 samples per line); only its memory could refuse it",
    ("seed001-beam-r-hertz.ini", "texture.rolloff_wavelength", 1e3): SHIPPED_ROLLOFF,
    ("seed001-beam-s-hertz.ini", "texture.rolloff_wavelength", 1e3): SHIPPED_ROLLOFF,
    ("seed002-rig-1ms-seed-route.ini", "texture.rolloff_wavelength", 1e3): SHIPPED_ROLLOFF,
    ("seed002-table.ini", "texture.rolloff_wavelength", 1e3): SHIPPED_ROLLOFF,
    ("seed002-rig-3ms-seed-route.ini", "texture.rolloff_wavelength", 1e3): SHIPPED_ROLLOFF,
    ("rolling-pipe.ini", "surface.correlation_x", 1e3):
        "a 1 cm correlation length on a 32 cm floor is a surface that exists (and [surface] method = spectral draws "
        "its heights from [texture], not from it)",
    ("rolling-pipe.ini", "surface.correlation_y", 1e3):
        "a 1 cm correlation length on a 1.15 m floor is a surface that exists (and [surface] method = spectral draws "
        "its heights from [texture], not from it)",
    ("seed002-rig-1ms.ini", "texture.short_wavelength", 1e3):
        "a surface smooth below 4 mm (polished waviness) exists; run warns that its bands above 250 Hz get no "
        "roughness excitation",
    ("seed002-rig-3ms.ini", "texture.short_wavelength", 1e3):
        "a surface smooth below 4 mm (polished waviness) exists; run warns that its bands above 750 Hz get no "
        "roughness excitation",
}


def scenes():
    text = subprocess.run([BIN, "keys"], capture_output=True, text=True, check=True).stdout
    return [line.split(":", 1)[0].strip() for line in text.splitlines() if ":" in line]


def dimensional_keys(scene):
    """[(section, key, default)] of the keys whose unit is a length or a speed."""
    return [(section, key, default) for section, key, default, described in scene_keys(scene)
            for line in described if UNIT.search(line)]


def value_in(text, section, key):
    current = None
    for line in text.splitlines():
        s = line.split("#")[0].strip()
        m = re.match(r"^\[(\w+)\]$", s)
        if m:
            current = m.group(1)
        elif current == section and re.match(rf"^{key}\s*=", s):
            return s.split("=", 1)[1].strip()
    return None


def with_value(text, section, key, value):
    """The study text with `key` of `section` set to `value` (replaced, or added to its section)."""
    lines, current, done = [], None, False
    for line in text.splitlines():
        s = line.split("#")[0].strip()
        m = re.match(r"^\[(\w+)\]$", s)
        if m:
            if current == section and not done:
                lines.append(f"{key} = {value}")
                done = True
            current = m.group(1)
        if current == section and re.match(rf"^{key}\s*=", s):
            lines.append(f"{key} = {value}")
            done = True
            continue
        lines.append(line)
    if not done:
        lines += [f"{key} = {value}"] if current == section else ["", f"[{section}]", f"{key} = {value}"]
    return "\n".join(lines) + "\n"


def cases(scene):
    """(study, section, key, value, factor) for each shipped study of the scene."""
    out = []
    for study in sorted((SOURCE / "studies").glob("*.ini")):
        text = study.read_text()
        if value_in(text, "study", "scene") != scene:
            continue
        for section, key, default in dimensional_keys(scene):
            written = value_in(text, section, key)
            try:
                value = float(written if written is not None else default)
            except ValueError:
                continue
            if value == 0.0:  # 0: derived from the other keys; no slip multiplies it
                continue
            micro = float(default) < 1e-3 if re.match(r"^[\d.e+-]+$", default or "") else False
            name = f"{section}.{key}"
            smaller = () if name in NOT_DIVIDED | NOT_DIVIDED_IN.get(scene, set()) else (1e-6,) if name in ONLY_MILLION else (1e-3, 1e-6)
            for factor in (1e3, 1e6) + (smaller if micro and float(default) > 0 else ()):
                out.append((study.name, section, key, value, factor))
    return out


def attempt(directory, scene, study, section, key, value, factor):
    """Runs the slipped study; returns a fault (text) or None."""
    name = f"x-{study[:-4]}-{section}-{key}-{factor:g}"
    path = directory / f"{name}.ini"
    path.write_text(with_value((directory / study).read_text(), section, key, f"{value * factor:.6g}"))
    out = directory / f"{name}.h5"
    try:
        r = subprocess.run([BIN, COMMAND.get(scene, "run"), str(path), "--out", str(out), "--quiet"], cwd=directory,
                           capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return f"accepted: still working after {TIMEOUT} s"
    finally:
        made = out.exists()
        subprocess.run(["rm", "-rf", str(out), f"{out}.checkpoint", str(path)])
    errors = [line for line in r.stderr.splitlines() if "error:" in line]
    if r.returncode != 78:
        return f"exit {r.returncode}: {r.stderr.strip()[-300:]}"
    if made:
        return "refused, but the output file was written"
    if len(errors) != 1 or f"[{section}] {key} = " not in errors[0]:
        return f"the message does not name [{section}] {key}: {r.stderr.strip()[-300:]}"
    reason = errors[0].split(f"[{section}] {key} = ", 1)[1]
    if len(reason.split(": ", 1)[-1]) < 30:
        return f"no reason given: {errors[0]}"
    return None


@pytest.fixture(scope="module")
def studies(tmp_path_factory):
    """The shipped studies with their data files (relative paths), in a directory of the test's own."""
    d = tmp_path_factory.mktemp("studies") / "studies"
    shutil.copytree(SOURCE / "studies", d)
    return d


SCENES = scenes()


def test_every_scene_with_dimensional_keys_has_shipped_studies():
    assert SCENES and all(any(True for _ in cases(s)) for s in SCENES if dimensional_keys(s)), SCENES


@pytest.mark.parametrize("scene", [s for s in SCENES if dimensional_keys(s)])
def test_unit_slips_are_refused_before_any_work(studies, scene):
    todo = [c for c in cases(scene) if (c[0], f"{c[1]}.{c[2]}", c[4]) not in EXEMPT]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        faults = list(pool.map(lambda c: (c, attempt(studies, scene, *c)), todo))
    bad = [f"{study} [{section}] {key} = {value:g} x {factor:g}: {why}"
           for (study, section, key, value, factor), why in faults if why]
    print(f"\n{scene}: {len(todo)} slipped studies, {len(todo) - len(bad)} refused before any work")
    assert not bad, f"{len(bad)} of {len(todo)} slips not refused as they should be:\n" + "\n".join(bad[:60])
