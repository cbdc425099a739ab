"""The path a new user takes, as the commands a person would type: `init` a study for their rig, edit
six keys (as sed would), `plan`, `run`, then their logger's export (';' separated, decimal commas,
a preamble line, time stamps rounded to their printed digits) through `psd`, `compare` and `report`,
with no --column, no --skip-rows, no --fs and no hand editing of any file."""

import os
import re
import subprocess

import h5py
import numpy as np

from conftest import BIN, SOURCE

PYTHON = "/usr/bin/python3"


def sh(argv, cwd):
    """One typed command; it must succeed."""
    r = subprocess.run([str(a) for a in argv], cwd=cwd, capture_output=True, text=True, timeout=600,
                       env=dict(os.environ, PYTHONPATH=str(SOURCE / "python-post")))
    assert r.returncode == 0, f"{' '.join(map(str, argv))}\nexit {r.returncode}\n{r.stderr[-3000:]}"
    return r


def sed(path, key, old, new):
    """sed -i 's/^KEY = OLD$/KEY = NEW/' PATH: the one line must be there."""
    text = path.read_text()
    pattern = re.compile(rf"^{key} = {re.escape(old)}$", re.M)
    assert len(pattern.findall(text)) == 1, f"{key} = {old} not found once in the template"
    path.write_text(pattern.sub(f"{key} = {new}", text))


def logger_export(path, fs=25600.0, seconds=2.0, rms_g=0.05):
    """A logger's CSV: a preamble line, 'Time (s);Acc (g)', decimal commas, 6-digit time stamps."""
    rng = np.random.default_rng(7)
    n = int(fs * seconds)
    acc = rms_g * rng.standard_normal(n)
    rows = [f"{i / fs:.6f};{a:.6f}".replace(".", ",") for i, a in enumerate(acc)]
    path.write_text("Logger XY-3000 export 2026-11-26 14:02\nTime (s);Acc (g)\n" + "\n".join(rows) + "\n")
    return acc


def test_init_edit_plan_run_psd_compare_report(tmp_path):
    sh([BIN, "init", "ball-on-beam", "--out", "rig.ini"], tmp_path)
    rig = tmp_path / "rig.ini"
    # A 1 m steel beam, a 30 mm ball at 2 m/s over most of the span, a ground surface of 10 nm rms (with
    # the template's 1 um the ball would fly: plan warns and run flags it, test_plausibility.py), a few
    # realisations to start with.
    sed(rig, "realisations", "100", "8")
    sed(rig, "length", "0.4", "1.0")
    sed(rig, "radius", "0.02", "0.015")
    sed(rig, "speed", "1", "2")
    sed(rig, "end", "0.35", "0.95")
    sed(rig, "rms", "1e-6", "1e-8")
    plan = sh([BIN, "plan", "rig.ini"], tmp_path)
    assert "dynamics" in plan.stdout and "warning" not in plan.stdout, plan.stdout
    run = sh([BIN, "run", "rig.ini", "--out", "r.h5"], tmp_path)
    assert "WARNING" not in run.stderr, run.stderr
    with h5py.File(tmp_path / "r.h5", "r") as f:
        assert f["/psd/frequency"].shape[0] > 100
        assert f["/contact/loss_of_contact_share"][0] < 0.05

    acc = logger_export(tmp_path / "logger.csv")
    sh([BIN, "psd", "logger.csv", "--unit", "g", "--out", "measured.csv"], tmp_path)
    data = np.genfromtxt(tmp_path / "measured.csv", delimiter=",", names=True, comments="#")
    psd = data[data.dtype.names[1]]
    # White noise of rms sigma g over 0..fs/2: one-sided level sigma^2 g^2 / (fs / 2), in (m/s^2)^2/Hz.
    expected = (0.05 * 9.80665) ** 2 / 12800.0
    assert abs(np.median(psd[1:-1]) / expected - 1.0) < 0.1
    assert abs(np.var(acc) / 0.05**2 - 1.0) < 0.02

    cmp = sh([BIN, "compare", "r.h5", "measured.csv"], tmp_path)
    assert re.search(r"rms_db_error: [-0-9.]+", cmp.stdout), cmp.stdout
    sh([PYTHON, "-m", "rollspec_post", "report", "r.h5", "--measurement", "measured.csv", "--out", "report.html"],
       tmp_path)
    html = (tmp_path / "report.html").read_text()
    assert "measured.csv" in html and "data:image" in html
