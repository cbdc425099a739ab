"""Physics checked before any work: a unit slip is refused at plan and at run (naming the key, its
value and the derived quantity, no realisation computed, nothing left behind); a legal but suspect
study is warned about on stderr and in plan's listing; a result that lost contact says so after run."""

import h5py

from conftest import BIN, assert_refused, run


def rig(tmp_path):
    r = run(["init", "ball-on-beam", "--out", tmp_path / "rig.ini"])
    assert r.returncode == 0, r.stderr
    return tmp_path / "rig.ini"


def test_radius_in_millimetres_is_refused_by_plan_and_run(tmp_path):
    study = rig(tmp_path)
    for cmd in (["plan", study], ["run", study, "--out", tmp_path / "r.h5"]):
        r = run([*cmd, "--set", "ball.radius=15"])
        assert_refused(r, 78, ["[ball] radius = 15", "a ball 30 m across does not fit on a span of 0.4 m"])
        assert "realisations" not in r.stderr, r.stderr  # refused before the ensemble
    assert not list(tmp_path.glob("r.h5*")), list(tmp_path.iterdir())


def test_a_ball_too_heavy_for_the_beam_is_refused_by_its_static_deflection(tmp_path):
    # A 0.2 m steel ball (W = 2.58e3 N) rolling over the middle of a 1 m x 300 x 6.8 mm clamped beam:
    # W L^3 / (192 EI) at midspan = 8.1e-3 m, more than the thickness.
    study = rig(tmp_path)
    sets = ["ball.radius=0.2", "beam.length=1", "beam.width=0.3", "ball.end=0.95"]
    r = run(["plan", study, *[a for kv in sets for a in ("--set", kv)]])
    assert_refused(r, 78, ["[ball] radius = 0.2", "static deflection", "more than the beam thickness 0.0068 m"])
    deflection = float(r.stderr.split("reaches ")[1].split(" m")[0])
    weight = 4 / 3 * 3.141592653589793 * 0.2**3 * 7850 * 9.81
    assert abs(deflection / (weight / (192 * 210e9 * 0.3 * 0.0068**3 / 12)) - 1.0) < 0.01


def test_a_speed_in_mm_per_s_is_refused(tmp_path):
    r = run(["plan", rig(tmp_path), "--set", "ball.speed=2000"])
    assert_refused(r, 78, ["[ball] speed = 2000", "7.2e+03 km/h"])


def test_suspect_values_are_warned_about_in_plan_and_on_stderr(tmp_path):
    study = rig(tmp_path)
    r = run(["plan", study, "--set", "texture.rms=1e-8"])
    assert r.returncode == 0 and "warning" not in r.stdout + r.stderr, r.stdout + r.stderr
    # A 1 um rms (the key's default) against a static compression of 0.24 um: the ball will fly.
    r = run(["plan", study, "--set", "texture.rms=1e-6"])
    assert r.returncode == 0, r.stderr
    warned = [ln for ln in r.stderr.splitlines() if ln.startswith("rollspec: warning: ")]
    listed = [ln for ln in r.stdout.splitlines() if ln.startswith("warning: ")]
    assert len(warned) == 1 and len(listed) == 1, r.stdout + r.stderr
    assert "static compression 2.41e-07 m" in listed[0] and "expect loss of contact" in listed[0]
    # Modes that stop below the band: the response above them has no resonances.
    r = run(["plan", study, "--set", "texture.rms=1e-8", "--set", "beam.max_frequency=2000"])
    assert r.returncode == 0 and "[beam] max_frequency = 2000: the highest kept mode" in r.stdout, r.stdout


def test_loss_of_contact_is_flagged_after_run(tmp_path):
    study = rig(tmp_path)
    # Hertz models the loss (a note with the share); under linearised, with 2 realisations no band has an
    # interval to size the loss's effect against (kernels/spectral D-35): a note with the largest shift.
    for law, kind, words in [("hertz", "note", "(more than 5 %)"),
                             ("linearised", "note", "no band has an interval to judge that by")]:
        out = tmp_path / f"{law}.h5"
        r = run(["run", study, "--set", "study.realisations=2", "--set", "texture.rms=1e-6", "--set", f"contact.law={law}",
                 "--out", out])
        assert r.returncode == 0, r.stderr
        lines = [ln for ln in r.stderr.splitlines() if ln.startswith(f"rollspec: {kind}: the ball lost contact")]
        assert len(lines) == 1 and words in lines[0], r.stderr
        with h5py.File(out, "r") as f:
            share = f["/contact/loss_of_contact_share"][0]
            assert share > 0.05 and f"{100 * share:.3g} %" in lines[0]
            attr = "loss_of_contact_warning" if kind == "WARNING" else "loss_of_contact_note"
            assert str(f["/contact"].attrs[attr], "utf-8") == lines[0].removeprefix(f"rollspec: {kind}: ")
    # A smooth beam: no loss of contact, no warning, no attribute.
    out = tmp_path / "smooth.h5"
    r = run(["run", study, "--set", "study.realisations=2", "--set", "texture.rms=1e-9", "--out", out, "--quiet"])
    assert r.returncode == 0 and "WARNING" not in r.stderr, r.stderr
    with h5py.File(out, "r") as f:
        assert f["/contact/loss_of_contact_share"][0] == 0.0 and "loss_of_contact_warning" not in f["/contact"].attrs
