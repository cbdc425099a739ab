"""200 random in-range ball-on-beam studies, seeded and so the same every run: each ends with exit 0
or a clean user error (exit 64-78 but not 70, one error line that names a [section] key), never an
internal error, a traceback or a signal, at plan or at run. The values are drawn inside the ranges
`rollspec keys` prints, around each default (and now and then a radius a thousand times too large, the
millimetre slip), with short records and two realisations so the whole test stays short. The laws
that build a table first (table, literal, path, blocked_force = solver) are left out: their builds
take minutes; their refusals have their own tests."""

import math
import random
import re
import subprocess
from concurrent.futures import ThreadPoolExecutor

from conftest import BIN, scene_keys

STUDIES = 200
INTERNAL = 70  # EX_SOFTWARE: an internal error


def key_ranges():
    """{'section.key': (default, allowed)} from `rollspec keys ball-on-beam`."""
    keys = {}
    for section, key, default, described in scene_keys("ball-on-beam"):
        keys[f"{section}.{key}"] = [default.strip(), ""]
        for line in described:
            m = re.match(r"^\s+allowed: (.*)$", line)
            if m:
                keys[f"{section}.{key}"][1] = m.group(1)
    return keys


def bounds(allowed):
    """(lo, hi, whole) of a numeric allowed text, or None."""
    whole = "whole number" in allowed
    m = re.search(r"in [\[(]([-0-9.e+]+), ([-0-9.e+]+)[\])]", allowed)
    if m:
        return float(m.group(1)), float(m.group(2)), whole
    m = re.search(r"number >=? ([-0-9.e+]+)", allowed)
    if m:
        return float(m.group(1)), math.inf, whole
    return None


def draw(rng, keys, key, spread):
    """The default times 10^U(-spread, spread), inside the key's range (open ends kept open)."""
    default, allowed = keys[key]
    lo, hi, whole = bounds(allowed)
    v = float(default) * 10 ** rng.uniform(-spread, spread)
    if v <= lo:
        v = lo + abs(float(default)) * 1e-3 + 1e-12
    v = min(v, hi if math.isfinite(hi) else v)
    return str(int(round(v))) if whole else f"{v:.6g}"


def choice(rng, keys, key, leave_out=()):
    options = [o.strip() for o in keys[key][1].removeprefix("one of ").split(",")]
    return rng.choice([o for o in options if o not in leave_out])


def random_study(rng, keys):
    """One study as {section: {key: value}}."""
    s = {"study": {"scene": "ball-on-beam", "realisations": "2", "seed": str(rng.randrange(1000))}}
    s["ensemble"] = {"chunk_size": "2"}
    put = lambda key, v: s.setdefault(key.split(".")[0], {}).__setitem__(key.split(".")[1], v)  # noqa: E731
    for key, spread in [("beam.length", 0.4), ("beam.width", 0.7), ("beam.thickness", 0.7),
                        ("beam.youngs_modulus", 1.0), ("beam.density", 0.5), ("beam.loss_factor", 1.0),
                        ("beam.max_frequency", 0.5), ("ball.radius", 1.2), ("ball.density", 0.6),
                        ("ball.youngs_modulus", 1.0), ("ball.speed", 1.0), ("ball.gravity", 0.2),
                        ("contact.damping", 1.5), ("texture.rms", 1.0), ("texture.rolloff_wavelength", 0.7),
                        ("texture.short_wavelength", 0.5), ("signal.sample_rate", 0.3)]:
        put(key, draw(rng, keys, key, spread))
    for key in ["beam.poisson", "ball.poisson", "texture.hurst", "spectrum.overlap"]:
        lo, hi, _ = bounds(keys[key][1])
        put(key, f"{rng.uniform(max(lo, -0.9), min(hi, 0.9)):.3g}")
    if rng.random() < 0.05:  # millimetres meant
        put("ball.radius", f"{float(s['ball']['radius']) * 1000:.6g}")
    put("beam.support", choice(rng, keys, "beam.support"))
    put("contact.law", rng.choice(["hertz", "linearised"]))
    put("contact.loss", choice(rng, keys, "contact.loss"))
    put("contact.filter", rng.choice(["none", "patch", "iso2d"]))
    put("texture.source", choice(rng, keys, "texture.source", leave_out=("table", "profiles")))
    put("texture.road_class", choice(rng, keys, "texture.road_class"))
    put("signal.substeps", str(rng.randint(1, 8)))
    put("signal.hold", choice(rng, keys, "signal.hold"))
    put("spectrum.segment", str(rng.choice([256, 512, 1024])))
    # A record of at most 0.1 s: the ball rolls speed x 0.1 s, inside the middle half of the span.
    length, speed = float(s["beam"]["length"]), float(s["ball"]["speed"])
    start = 0.25 * length
    put("ball.start", f"{start:.6g}")
    put("ball.end", f"{start + min(0.5 * length, speed * 0.1):.6g}")
    put("sensors.positions", f"{rng.uniform(0.0, length):.6g}")
    return s


def study_text(s):
    return "".join(f"[{sec}]\n" + "".join(f"{k} = {v}\n" for k, v in kv.items()) for sec, kv in s.items())


def clean(r):
    """'' for exit 0 or a clean user error, else what is wrong."""
    if r.returncode == 0:
        return ""
    lines = [ln for ln in r.stderr.splitlines() if "error" in ln]
    if r.returncode < 0:
        return f"signal {-r.returncode}"
    if r.returncode == INTERNAL or not 64 <= r.returncode <= 78:
        return f"exit {r.returncode}"
    if "internal error" in r.stderr or "Traceback" in r.stderr:
        return "internal error"
    if len(lines) != 1 or not re.search(r"\[\w+\] \w+", lines[0]):
        return "not one error line naming a key"
    return ""


def one(args):
    i, text, tmp = args
    path = tmp / f"s{i:03d}.ini"
    path.write_text(text)
    out = []
    for cmd in (["plan", path], ["run", path, "--out", tmp / f"r{i:03d}.h5", "--quiet"]):
        try:
            r = subprocess.run([BIN, *map(str, cmd)], capture_output=True, text=True, timeout=120)
        except subprocess.TimeoutExpired:
            return i, cmd[0], "timeout", ""
        out.append((cmd[0], r))
        if r.returncode != 0:
            break
    cmd, r = out[-1]
    return i, cmd, clean(r), r


def test_random_in_range_studies_end_cleanly(tmp_path):
    keys = key_ranges()
    rng = random.Random(20261126)
    jobs = [(i, study_text(random_study(rng, keys)), tmp_path) for i in range(STUDIES)]
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(one, jobs))
    bad = [(i, cmd, why, r.stderr[-600:] if r else "") for i, cmd, why, r in results if why]
    ran = sum(1 for _, cmd, why, r in results if not why and r.returncode == 0)
    refused = STUDIES - ran - len(bad)
    print(f"\n{STUDIES} random studies: {ran} ran, {refused} refused cleanly, {len(bad)} not clean")
    assert not bad, "\n".join(f"study {i} ({cmd}): {why}\n{jobs[i][1]}\n{err}" for i, cmd, why, err in bad[:5])
    assert ran >= STUDIES // 10, f"only {ran} of {STUDIES} ran: the draw tests refusals only"
