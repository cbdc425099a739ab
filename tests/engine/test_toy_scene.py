"""A new scene is its folder plus one registry row (issue: architecture III). The test-only scene white-noise
(tests/engine/toy_scene/) lives in its own folder and reaches the registry only by being linked into a build of
the command (rollspec_toy, ROLLSPEC_TOY_BIN); no other file names it. Through that build, `keys`, `init`, `plan`,
`run` and the generated key reference (docs/generate_reference.py's write_keys) all pick it up, and its run
meets its exact answer: a Welch estimate of white noise is unbiased, so the ensemble mean of every bin is the
level S, within the interval the result itself states."""
import importlib.util
import os
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
TOY = os.environ.get("ROLLSPEC_TOY_BIN", str(ROOT / "build" / "werror" / "tests" / "engine" / "rollspec_toy"))
SCENE = "white-noise"


def toy(*args, cwd=None):
    r = subprocess.run([TOY, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=300)
    assert r.returncode == 0, f"rollspec_toy {' '.join(map(str, args))} exited {r.returncode}: {r.stderr}"
    return r.stdout


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    d = tmp_path_factory.mktemp("toy")
    toy("init", SCENE, "--out", d / "noise.ini")
    return d / "noise.ini"


def test_keys_lists_the_scene_and_its_own_keys():
    assert any(line.startswith(f"{SCENE}: test-only scene") for line in toy("keys").splitlines())
    keys = toy("keys", SCENE)
    assert "[noise]" in keys and "level" in keys and "[signal]" in keys


def test_no_code_of_the_engine_names_the_scene():
    named = [str(f.relative_to(ROOT)) for f in (ROOT / "src").rglob("*")
             if f.suffix in (".cpp", ".hpp", ".txt") and SCENE in f.read_text(errors="replace")]
    assert named == []


def test_init_writes_the_rows_first_keys_uncommented(study):
    text = study.read_text()
    assert f"scene = {SCENE}" in text
    for line in ("level = ", "sample_rate = ", "duration = 4", "segment = 1024"):
        assert any(l.startswith(line) for l in text.splitlines()), line


def test_plan_shows_the_scenes_stages(study):
    out = toy("plan", study)
    assert "noise" in out and "spectra" in out


def test_run_meets_the_exact_level(study, tmp_path):
    out = tmp_path / "noise.h5"
    level = 2.5e-3
    toy("run", study, "--out", out, "--quiet", "--set", f"noise.level={level}", "--set", "study.realisations=40")
    with h5py.File(out, "r") as f:
        mean = f["/psd/mean"][0, 1:-1]
        lower, upper = f["/psd/ci_lower"][0, 1:-1], f["/psd/ci_upper"][0, 1:-1]
        assert np.allclose(f["/reference/psd"][0], level)
        cited = [r.decode().split(" | ")[0] for r in f["/provenance/references"][...]]
    assert cited[:4] == ["Welch 1967", "D-15", "D-16", "D-17"]  # the row's references reach the result
    inside = np.mean((lower <= level) & (level <= upper))
    assert 0.90 <= inside <= 0.995, inside  # the 95 % intervals of the bins (interior: DC and Nyquist aside)
    assert abs(np.mean(mean) / level - 1.0) < 0.01  # the mean over ~500 bins of 40 realisations


def test_the_generated_key_reference_has_the_scene(tmp_path):
    spec = importlib.util.spec_from_file_location("generate_reference", ROOT / "docs" / "generate_reference.py")
    gen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(gen)
    gen.write_keys(TOY, tmp_path)
    page = (tmp_path / "keys.md").read_text()
    assert f"## `{SCENE}`" in page and f"### `{SCENE}` `[noise]`" in page
