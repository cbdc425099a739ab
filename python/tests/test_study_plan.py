"""rollspec.studies.plan against `rollspec plan` on the same study: the stages, their status and reason, the
memory estimate and its terms, the checkpoint disk and the study's header are what the command prints."""
import os
import re
import subprocess

import pytest

from rollspec import studies

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")


def format_bytes(b):
    """src/scenes/memory_estimate.cpp's format_bytes."""
    units, u = ["B", "KiB", "MiB", "GiB", "TiB", "PiB"], 0
    while b >= 1024.0 and u < 5:
        b, u = b / 1024.0, u + 1
    return "%.3g %s" % (b, units[u]) if u else "%.0f %s" % (b, units[u])


def command_plan(study, sets, threads):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    r = subprocess.run([ROLLSPEC, "plan", study, *[a for s in sets for a in ("--set", s)]], capture_output=True,
                       text=True, env=env)
    assert r.returncode == 0, r.stderr
    return r.stdout.splitlines()


@pytest.mark.parametrize("name, sets", [
    ("random-oscillator.ini", ["study.realisations=300", "ensemble.chunk_size=16"]),
    ("seed001-beam-r.ini", []),
    ("hertz.ini", []),
])
def test_plan_is_what_the_command_prints(name, sets, monkeypatch):
    study = os.path.join(SOURCE, "studies", name)
    monkeypatch.setenv("OMP_NUM_THREADS", "2")
    p = studies.plan(study, set=sets)
    lines = command_plan(study, sets, 2)
    assert lines[0] == (f"study {study}: scene {p['scene']}, {p['realisations']} realisation"
                        f"{'' if p['realisations'] == 1 else 's'}, seed {p['seed']}")
    assert p["threads"] == 2 and p["study"] == study
    memory = lines[1]
    assert memory.startswith(f"memory: estimated peak {format_bytes(p['memory_bytes'])} on 2 threads")
    if p["memory_largest"]:
        assert f"(largest: {p['memory_largest']}, from {', '.join(p['memory_keys'])})" in memory
    terms = [f"  {format_bytes(t['bytes'])}: {t['what']}" for t in p["memory_terms"]]
    assert lines[2:2 + len(terms)] == terms
    assert not p["over_memory"]
    rest = lines[2 + len(terms):]
    if p["checkpoint_chunks"]:
        n = p["checkpoint_chunks"]
        assert rest.pop(0) == (f"checkpoint disk: {n} chunk{'' if n == 1 else 's'} of "
                               f"{format_bytes(p['checkpoint_chunk_bytes'])} = "
                               f"{format_bytes(n * p['checkpoint_chunk_bytes'])} beside the result while the run lasts")
    for w in p["warnings"]:
        assert rest.pop(0) == "warning: " + w
    if p["note"]:
        assert rest.pop(0) == "note: " + p["note"]
    assert re.split(r"\s+", rest.pop(0)) == ["stage", "status", "reason"]
    assert p["stages"]
    for s in p["stages"]:
        assert s["status"] in ("run", "cached", "skipped")
        assert rest.pop(0) == "%-16s %-8s %s" % (s["stage"], s["status"], s["reason"])
    if p["jackknife"]:
        assert rest.pop(0).startswith(f"table jackknife: the {p['jackknife']['table']}'s own error")
    for t in p["tables"]:
        assert rest.pop(0).startswith(f"table {t['table']}: about ")
    assert rest == []
    assert p["seconds_per_realisation"] is None and p["not_probed"] is None


def test_plan_takes_a_study_from_text_and_its_errors_are_the_commands(tmp_path):
    study = os.path.join(SOURCE, "studies", "random-oscillator.ini")
    with open(study) as f:
        text = f.read()
    a = studies.plan(studies.Study.from_text(text), set={"study.realisations": 300})
    b = studies.plan(study, set=["study.realisations=300"])
    assert a["study"] == "<string>" and {**a, "study": study} == {**b, "available_bytes": a["available_bytes"]}
    r = subprocess.run([ROLLSPEC, "plan", study, "--set", "oscillator.mass=0"], capture_output=True, text=True)
    assert r.returncode == 78
    with pytest.raises(ValueError) as e:
        studies.plan(study, set=["oscillator.mass=0"])
    assert str(e.value) == r.stderr.strip().splitlines()[-1][len("rollspec plan: error: "):]


def test_a_probe_times_realisation_zero():
    study = os.path.join(SOURCE, "studies", "random-oscillator.ini")
    p = studies.plan(study, set=["signal.duration=4", "study.realisations=100"], probe=True)
    assert p["seconds_per_realisation"] > 0
    assert p["ensemble_seconds"] == p["seconds_per_realisation"] * 100 / p["threads"]
    lines = command_plan(study, ["signal.duration=4", "study.realisations=100", "--probe"][:2], 2)
    assert not any(line.startswith("run time") for line in lines)  # without --probe: no probe line
    r = subprocess.run([ROLLSPEC, "plan", study, "--set", "signal.duration=4", "--set", "study.realisations=100",
                        "--probe"], capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="2"))
    assert re.search(r"^run time: \S+ s per realisation \(probe of realisation 0\); the ensemble of 100 on 2 "
                     r"thread\(s\): about \S+ s", r.stdout, re.M), r.stdout


def test_a_missing_table_is_estimated_from_its_first_solves_as_the_command_does(tmp_path, monkeypatch):
    """The seed 002 rig on a coarse strip with the equivalent roughness from the contact solver
    (tests/cli/test_solver_filter.py's study): its table is not built, and plan times its first solves.
    The times are measured, so they differ between the two calls; the table, its threads and what was
    solved are the command's, and wall = CPU / threads."""
    study = tmp_path / "rig.ini"
    study.write_bytes(open(os.path.join(SOURCE, "studies", "seed002-rig-1ms.ini"), "rb").read())
    sets = ["contact.law=hertz", "contact.filter=solver", "surface.spacing=12e-6", "texture.short_wavelength=24e-6",
            "blocked_force.segment=128", "blocked_force.strip_length=6.6e-3", "ball.start=0.1", "ball.end=0.106",
            "spectrum.segment=128", "spectrum.band_min=400", "spectrum.band_max=5000", "study.realisations=2"]
    monkeypatch.setenv("OMP_NUM_THREADS", "2")
    p = studies.plan(study, set=sets)
    lines = command_plan(str(study), sets, 2)
    assert [s["status"] for s in p["stages"] if s["stage"] == "equivalent_roughness"] == ["run"]
    assert len(p["tables"]) == 1
    t = p["tables"][0]
    assert t["cpu_seconds"] > 0 and t["wall_seconds"] == t["cpu_seconds"] / t["threads"]
    printed = [line for line in lines if line.startswith("table ") and "(probe: " in line]
    assert len(printed) == 1
    m = re.match(r"table (\S+): about \S+ s CPU, \S+ s wall on (\d+) threads? \(probe: (.*)\)$", printed[0])
    assert m and (m.group(1), int(m.group(2))) == (t["table"], t["threads"]), printed
    timed = r"solved in [\d.e+-]+ s CPU"
    assert re.sub(timed, "", m.group(3)) == re.sub(timed, "", t["probe"]) and re.search(timed, t["probe"])
    assert not list(tmp_path.rglob("*.h5"))
