"""The contact resolution holds on a light ball (kernels/beam README B37a, B37b): a 0.26 g ball
(radius 2 mm) under 1e5 m/s^2 on a smooth beam, no contact damping. The step check D-23
(h <= T_c / 20) accepts 46 substeps, but the quadratic hold lets the free bounce grow by
(w_c h)^4 / 48 per step: over the 0.36 s record a factor 3e7, and rounding became 21 % spurious
loss of contact. Refused now, with the substeps that hold (261: growth <= 1.1), which run without
loss; the linear hold (no growth) and a little contact damping run clean at 46. The result records
the contact period and the growth the step allows."""
import math

import h5py
import pytest

from conftest import SOURCE, assert_refused, run

STUDY = SOURCE / "studies" / "seed001-beam-s-hertz.ini"
LIGHT = ["study.realisations=1", "ball.radius=0.002", "ball.gravity=1e5", "contact.filter=none",
         "texture.rms=1e-9", "contact.damping=0"]


def light(tmp_path, name, *sets):
    out = tmp_path / f"{name}.h5"
    args = [a for kv in [*LIGHT, *sets] for a in ("--set", kv)]
    return run(["run", STUDY, "--out", out, "--quiet", *args]), out


def test_the_light_ball_at_46_substeps_is_refused_with_the_substeps_that_hold(tmp_path):
    r, out = light(tmp_path, "r46", "signal.substeps=46")
    assert_refused(r, 78, ["[signal] substeps = 46", "quadratic hold", "T_c = 2.537e-05 s",
                           "allowed: substeps >= 261", "[signal] hold = linear", "[contact] damping >= 0.02512"])
    assert not out.exists()
    r, _ = light(tmp_path, "r260", "signal.substeps=260")
    assert_refused(r, 78, ["[signal] substeps = 260", "allowed: substeps >= 261"])


@pytest.mark.parametrize("sets", [["signal.substeps=261"], ["signal.substeps=46", "signal.hold=linear"],
                                  ["signal.substeps=46", "contact.damping=0.03"]])
def test_what_the_refusal_allows_keeps_the_contact(tmp_path, sets):
    r, out = light(tmp_path, "ok", *sets)
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        c = f["/contact"]
        assert f["/contact/loss_of_contact_share"][0] == 0.0 and "loss_of_contact_warning" not in c.attrs
        m = 4 / 3 * math.pi * 0.002**3 * 7850
        k = 2 * c.attrs["effective_modulus"][0] * math.sqrt(0.002 * c.attrs["static_compression"][0])
        tc = 2 * math.pi * math.sqrt(m / k)
        assert c.attrs["contact_period"][0] == pytest.approx(tc, rel=1e-12)
        h = 1 / (25600 * int(sets[0].split("=")[1]))
        quadratic = "signal.hold=linear" not in sets
        damping = 0.03 if "contact.damping=0.03" in sets else 0.0
        rate = (2 * math.pi * h / tc) ** 4 / (48 * h) - damping / (2 * m) if quadratic else 0.0
        growth = math.exp(max(rate, 0.0) * 0.36)
        assert c.attrs["free_bounce_growth"][0] == pytest.approx(growth, rel=1e-9)
        assert 1.0 <= growth <= 1.1
