"""`run`'s check that K realisations suffice for the band intervals (kernels/spectral D-29): the
skewness G1 of the realisations' band logs, Cochran's rule K >= 25 (G1 - 2 se)^2, the /bands
attributes tail_check and tail_check_realisations_needed, and one warning line when K falls short."""
import re

import h5py
import numpy as np

from conftest import SOURCE, oscillator_study, run


def tail_attributes(path):
    with h5py.File(path) as f:
        a = f["/bands"].attrs
        text = a["tail_check"]
        return (text.decode() if isinstance(text, bytes) else text), int(np.ravel(a["tail_check_realisations_needed"])[0])


def cochran(logs):
    """G1 of each band's logs over realisations (axis 0), its normal-sample standard error and the K asked for."""
    K = logs.shape[0]
    d = logs - logs.mean(axis=0)
    g1 = (d ** 3).mean(axis=0) / (d ** 2).mean(axis=0) ** 1.5 * np.sqrt(K * (K - 1)) / (K - 2)
    se = np.sqrt(6.0 * K * (K - 1) / ((K - 2) * (K + 1) * (K + 3)))
    return g1, se, np.ceil(25.0 * np.maximum(g1 - 2.0 * se, 0.0) ** 2)


def test_the_check_reads_the_realisations_own_band_logs(tmp_path):
    # The ensemble's sums of y, y^2, y^3 against the K realisations run one by one (--only).
    K = 8
    study = oscillator_study(tmp_path, realisations=K)
    ens = tmp_path / "ens.h5"
    r = run(["run", study, "--out", ens, "--quiet"])
    assert r.returncode == 0, r.stderr
    logs = []
    for i in range(K):
        one = tmp_path / f"one{i}.h5"
        r = run(["run", study, "--out", one, "--quiet", "--only", i])
        assert r.returncode == 0, r.stderr
        with h5py.File(one) as f:
            logs.append(f["/bands/level_db"][0] * np.log(10.0) / 10.0)
    g1, se, needed = cochran(np.array(logs))
    text, need = tail_attributes(ens)
    worst = int(np.lexsort((g1, needed))[-1])  # the largest K asked for, then the largest G1
    assert need == int(needed[worst])
    assert f"G1 = {g1[worst]:.4g}" in text, (text, g1)
    assert f"se = {se:.4g}" in text


def test_a_gaussian_scene_and_the_table_law_scene_do_not_warn(tmp_path):
    # Measured (kernels/spectral D-29): these scenes' intervals cover at K = 8 and 25, and their
    # band logs are nearly symmetric; neither may warn at their fixed seeds.
    (tmp_path / "tables").mkdir()
    cases = [("random-oscillator.ini", 25, []),
             ("seed001-beam-r.ini", 25, ["stiffness.realisations=4", f"stiffness.table_dir={tmp_path}/tables"])]
    for study, K, sets in cases:
        out = tmp_path / "r.h5"
        args = ["run", SOURCE / "studies" / study, "--out", out, "--set", f"study.realisations={K}"]
        for s in sets:
            args += ["--set", s]
        r = run(args)
        assert r.returncode == 0, r.stderr
        assert "too few for the" not in r.stderr, r.stderr
        text, need = tail_attributes(out)
        assert text.startswith(f"{K} realisations enough in every band"), text
        assert 0 <= need <= K
        assert re.search(r"G1 = -?[0-9.]+", text)


def test_fewer_than_five_realisations_are_not_checked(tmp_path):
    out = tmp_path / "r.h5"
    r = run(["run", oscillator_study(tmp_path, realisations=4), "--out", out, "--quiet"])
    assert r.returncode == 0, r.stderr
    assert tail_attributes(out) == ("not checked: no band intervals", 0)
