"""bench/engine/bench_recording_verdict.py on a tiny case (2 recordings of 3 rolls per case, each against its own
model run, about 10 s): the README's rig, recordings as CSV files through `compare`, the record written where asked
and nothing else. The wrong models are rejected in every recording: with the logger noise's terms T^2's law comes
from the bootstrap of kernels/spectral D-31b (D-33f), and no one of its 10 000 draws reaches the observed T^2, so
p is its smallest, 1 / 10 001 (the F law put these at about 1e-26 for twice the loss factor, which the bands below the
first mode, scattering by hundredths of a dB, decide), the mode case's first mode is
1.1 x the model's (E x 1.21), the 3 dB case's level offset lies near -3.01 dB; the full figures are the bench's
(bench/records/recording-verdict.json)."""
import json
import math
import os
import subprocess

import h5py
import numpy as np

from conftest import BIN, EX_CANTCREAT, EX_NOINPUT, EX_USAGE, SOURCE

SCRIPT = SOURCE / "bench" / "engine" / "bench_recording_verdict.py"


def bench(*args, cwd):
    return subprocess.run(["/usr/bin/python3", str(SCRIPT), "--bin", BIN, *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, PYTHONPATH=str(SOURCE / "python-post")))


def test_a_tiny_case_writes_its_record_and_nothing_else(tmp_path):
    r = bench("--recordings", "2", "--rolls", "3", "--model-seeds", "2", "--work", "w", "--record", "r.json",
              cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.json", "w"]
    assert sorted(p.name for p in (tmp_path / "w").glob("verdicts-*.json")) == [
        "verdicts-level.json", "verdicts-loss.json", "verdicts-mode.json", "verdicts-right.json"]
    record = json.loads((tmp_path / "r.json").read_text())
    assert record["columns"] == ["figure", "value", "95 % interval", "target", "met", "recordings"]
    cases = record["data"]["cases"]
    assert all(c["tested"] == 2 and c["no_test"] == 0 for c in cases.values())
    for name in ("level", "loss", "mode"):
        assert cases[name]["rejected"] == 2 and max(cases[name]["p_values"]) == 1.0 / 10001, (name, cases[name])
        assert cases[name]["per_model_seed"] == [[1, 1, 1], [2, 1, 1]], (name, cases[name])
    assert cases["right"]["rejected"] < 2 and all(0 < p <= 1 for p in cases["right"]["p_values"])
    # block j of every case against the model at study seed 1 + j; the two runs are two draws, not one
    assert record["data"]["model_seeds"] == [1, 2]
    for name in cases:
        found = json.loads((tmp_path / "w" / f"verdicts-{name}.json").read_text())
        assert [v["model_seed"] for v in found] == [1, 2] and min(v["seed"] for v in found) >= 7000
        assert all("the logger noise's terms by a parametric bootstrap" in v["verdict"] for v in found), found
    with h5py.File(tmp_path / "w" / "model-seed1.h5") as one, h5py.File(tmp_path / "w" / "model-seed2.h5") as two:
        assert one["/psd/mean"].shape == two["/psd/mean"].shape
        assert not np.array_equal(one["/psd/mean"][()], two["/psd/mean"][()])
    spread = [row for row in record["rows"] if row[0].startswith("size: right model, conditional on one model run")]
    blocks = [r / t for _, r, t in cases["right"]["per_model_seed"]]
    assert len(spread) == 1 and spread[0][1] == round(float(np.median(blocks)), 3), spread
    assert "a new model run and a new recording" in record["settings"]
    f1 = record["data"]["first_mode_hz"]
    assert abs(f1["mode"] / f1["right"] - 1.1) < 1e-9, f1  # f ~ sqrt(E)
    assert cases["loss"]["set"] == ["beam.loss_factor=0.02"]
    assert abs(cases["level"]["offset_mean_db"] - 10 * math.log10(0.5)) < 0.5
    assert 0.0 <= record["data"]["coverage"]["pooled"] <= 1.0 and record["data"]["M"] == 3
    # the README's rig: its edits in the settings, the template's K
    assert "beam.length=1.0" in record["settings"] and "K = 100" in record["settings"]


def test_bad_arguments_and_targets_are_one_line_and_change_nothing(tmp_path):
    r = bench("--recordings", "0", cwd=tmp_path)
    assert r.returncode == EX_USAGE and len(r.stderr.strip().splitlines()) == 1, r.stderr
    r = bench("--recordings", "4", "--model-seeds", "3", cwd=tmp_path)  # S must divide N
    assert r.returncode == EX_USAGE and "--model-seeds 3" in r.stderr and len(r.stderr.splitlines()) == 1, r.stderr
    r = bench("--noise-db", "loud", cwd=tmp_path)
    assert r.returncode == EX_USAGE and "--noise-db loud" in r.stderr, r.stderr
    r = subprocess.run(["/usr/bin/python3", str(SCRIPT), "--bin", str(tmp_path / "none")], capture_output=True,
                       text=True, env=dict(os.environ, PYTHONPATH=str(SOURCE / "python-post")))
    assert r.returncode == EX_NOINPUT and len(r.stderr.strip().splitlines()) == 1, r.stderr
    mine = tmp_path / "mine.json"
    mine.write_text("precious\n")
    r = bench("--record", mine, cwd=tmp_path)
    assert r.returncode == EX_CANTCREAT and mine.read_text() == "precious\n", r.stderr
    (tmp_path / "folder").mkdir()
    (tmp_path / "folder" / "keep.txt").write_text("precious\n")
    r = bench("--work", "folder", "--record", "r.json", cwd=tmp_path)
    assert r.returncode == EX_CANTCREAT and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["folder", "mine.json"]
