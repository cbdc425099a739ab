"""rollspec.contact.Table.read against the table files small study runs write into their tables folder
(stiffness, blocked force, equivalent roughness, path table): the columns bit for bit, the scalars and
provenance as stored, the input hash the file's name carries and FNV-1a of the inputs recomputed here;
damaged, edited and foreign files refused as a study refuses to reuse them."""
import glob
import os
import re
import shutil
import subprocess

import h5py
import numpy as np
import pytest

from rollspec import contact

ROLLSPEC = os.environ.get("ROLLSPEC_BIN", "rollspec")
STUDIES = os.path.join(os.path.dirname(__file__), "..", "..", "studies")
GROUP = {"stiffness": "/stiffness", "blocked_force": "/blocked_force",
         "equivalent_roughness": "/equivalent_roughness", "path": "/path_table"}
PREFIX = {"stiffness": "stiffness-", "blocked_force": "blocked-force-",
          "equivalent_roughness": "equivalent-roughness-", "path": "path-table-"}
# The seed 002 rig on a coarse strip (12 um cells), a 5 mm path: the equivalent-roughness and path tables.
STRIP = ["surface.spacing=12e-6", "texture.short_wavelength=24e-6", "ball.start=0.1", "ball.end=0.105",
         "spectrum.segment=64", "spectrum.band_min=200", "spectrum.band_max=5000", "study.realisations=1"]


def rollspec(study, *args, sets=()):
    subprocess.run([ROLLSPEC, *args, str(study), "--quiet", *[a for kv in sets for a in ("--set", kv)]], check=True,
                   capture_output=True, cwd=os.path.dirname(study))


# The seed 002 rig's runs that build the other kinds: kind -> (the run's stage, its --set).
RIG_RUNS = {
    "blocked_force": ("blocked_force", [
        "contact.blocked_force=solver", "study.realisations=1", "ball.end=0.12", "surface.spacing=8e-6",
        "texture.short_wavelength=16e-6", "surface.ny=96", "blocked_force.window=96", "blocked_force.strip_length=3e-3",
        "stiffness.hardness=6e9", "blocked_force.segment=64"]),
    "equivalent_roughness": ("equivalent_roughness",
                             [*STRIP, "contact.law=hertz", "contact.filter=solver", "equivalent_roughness.line=strip"]),
    "path": ("path_table", [*STRIP, "contact.law=path", "path_table.approaches=4"]),
}
TABLE_SETS = ["surface.nx=64", "surface.ny=64", "stiffness.realisations=2", "stiffness.steps=4",
              "stiffness.approach_max=0.4e-6"]


@pytest.fixture(scope="module")
def tables(tmp_path_factory):
    """{kind: path} of one table of each kind, built by the command (about 5 s in all)."""
    d = tmp_path_factory.mktemp("tables")
    shutil.copy(os.path.join(STUDIES, "seed002-table.ini"), d / "table.ini")
    rollspec(d / "table.ini", "stiffness", sets=TABLE_SETS)
    shutil.copy(os.path.join(STUDIES, "seed002-rig-1ms.ini"), d / "rig.ini")
    for kind, (_, sets) in RIG_RUNS.items():
        rollspec(d / "rig.ini", "run", "--out", kind + ".h5", sets=sets)
    out = {}
    for kind, prefix in PREFIX.items():
        (path,) = glob.glob(str(d / "tables" / (prefix + "*.h5")))
        out[kind] = path
    return out


def fnv1a64(text):
    h = 0xCBF29CE484222325
    for b in text.encode():
        h = ((h ^ b) * 0x100000001B3) % 2**64
    return "%016x" % h


@pytest.mark.parametrize("kind", list(PREFIX))
def test_a_table_reads_as_the_file_holds_it(tables, kind):
    t = contact.Table.read(tables[kind])
    assert t.kind == kind and t.path == tables[kind]
    with h5py.File(tables[kind]) as f:
        g = f[GROUP[kind]]
        # The hash a study compares: the file's, its name's, and FNV-1a of the inputs recomputed here.
        assert t.input_hash == g.attrs["input_hash"].decode() == fnv1a64(t.inputs)
        assert os.path.basename(t.path) == PREFIX[kind] + t.input_hash + ".h5"
        assert t.inputs == g.attrs["inputs"].decode() and t.inputs.startswith("[contact kernel]\nversion = ")
        assert t.data_checksum == g.attrs["data_checksum"].decode()
        assert t.kernel_version == g.attrs["kernel_version"]
        assert t.provenance["filetype"] == f.attrs["filetype"].decode()
        assert t.provenance["study"] == f.attrs["study"].decode()
        assert t.provenance["seed"] == f.attrs["seed"]
        # Every dataset is a column but the dimension scales the writer adds to unlabelled axes.
        datasets = {n for n, v in g.items() if isinstance(v, h5py.Dataset)}
        assert set(t.columns) <= datasets
        assert all(g[n].attrs.get("CLASS") == b"DIMENSION_SCALE" for n in datasets - set(t.columns))
        for name, column in t.columns.items():
            stored = g[name][:]
            assert column.shape == stored.shape and column.tobytes() == stored.tobytes(), name
            assert getattr(t, name).tobytes() == stored.tobytes()
            assert not column.flags.writeable
        for name, value in t.scalars.items():
            stored = g.attrs[name] if name in g.attrs else g["fit"].attrs[name[len("fit_"):]]
            if name == "solver_tolerance":
                stored = g.attrs["solver_tolerance"]
            assert value == stored and getattr(t, name) == value, name
    with pytest.raises(AttributeError, match="table has no column or scalar 'nothing'"):
        t.nothing


def test_columns_are_views_that_keep_the_table(tables):
    t = contact.Table.read(tables["stiffness"])
    force = t.force_mean
    assert force.base is not None and not force.flags.owndata
    expected = force.copy()
    del t
    assert force.tobytes() == expected.tobytes()
    # The table itself: force grows with the approach from 0 at first contact; the stiffness is positive.
    assert force[0] == 0.0 and (np.diff(force) > 0).all()
    assert (contact.Table.read(tables["stiffness"]).stiffness_mean[1:] > 0).all()


def test_damaged_edited_and_foreign_files_are_refused(tables, tmp_path):
    edited = tmp_path / "edited.h5"
    shutil.copy(tables["stiffness"], edited)
    with h5py.File(edited, "r+") as f:
        f["/stiffness/force_mean"][2] *= 1.001
    with pytest.raises(ValueError, match=r"edited.h5: the stiffness table's data do not match its checksum"):
        contact.Table.read(str(edited))
    shutil.copy(tables["stiffness"], edited)
    with h5py.File(edited, "r+") as f:
        f["/stiffness"].attrs["input_hash"] = np.bytes_("0123456789abcdef")
    with pytest.raises(ValueError, match=r"input_hash 0123456789abcdef is not the hash of its inputs \([0-9a-f]{16};"):
        contact.Table.read(str(edited))
    foreign = tmp_path / "foreign.h5"
    with h5py.File(foreign, "w") as f:
        f.attrs["filetype"] = np.bytes_("rollspec-texture")
    with pytest.raises(ValueError, match=r"foreign.h5: filetype is 'rollspec-texture'; allowed: a rollspec table "
                                         r"\(rollspec-stiffness-table, rollspec-blocked-force"):
        contact.Table.read(str(foreign))
    (tmp_path / "text.h5").write_text("not hdf5")
    with pytest.raises(ValueError, match="text.h5"):
        contact.Table.read(str(tmp_path / "text.h5"))
    with pytest.raises(OSError, match="missing.h5"):
        contact.Table.read(str(tmp_path / "missing.h5"))


def test_stiffness_table_builds_the_commands_table_and_reuses_it(tables, tmp_path):
    study = tmp_path / "table.ini"
    shutil.copy(os.path.join(STUDIES, "seed002-table.ini"), study)
    sets = TABLE_SETS
    built = contact.stiffness_table(study, set=sets)
    command = contact.Table.read(tables["stiffness"])  # the same study and keys, built by `rollspec stiffness`
    assert built.status == "built " + built.path and built.path.startswith(str(tmp_path / "tables"))
    assert built.input_hash == command.input_hash and built.inputs == command.inputs
    for name, column in command.columns.items():
        assert built.columns[name].tobytes() == column.tobytes(), name
    assert built.scalars == command.scalars
    again = contact.stiffness_table(str(study), set=sets)
    assert again.status == "cached " + built.path and again.data_checksum == built.data_checksum
    # Any thread count: the same bits.
    (tmp_path / "one").mkdir()
    single = contact.stiffness_table(shutil.copy(study, tmp_path / "one"), set=sets, threads=1)
    assert single.status.startswith("built ") and single.data_checksum == built.data_checksum
    assert single.force_mean.tobytes() == built.force_mean.tobytes()
    with pytest.raises(ValueError, match=r"^threads = 0: fewer than one; allowed: a thread count >= 1"):
        contact.stiffness_table(study, set=sets, threads=0)
    # A key the table depends on: another hash, another file.
    other = contact.stiffness_table(study, set=[*sets, "stiffness.steps=3"])
    assert other.input_hash != built.input_hash and other.approach.shape == (4,)
    with pytest.raises(ValueError, match=r"^command line \(--set\): unknown key \[stiffness\] realisation = 2 for "
                                         r"scene stiffness; allowed keys"):
        contact.stiffness_table(study, set=["stiffness.realisation=2"])
    with pytest.raises(ValueError, match=r"rollspec stiffness needs a .* study"):
        contact.stiffness_table(os.path.join(STUDIES, "texture-demo.ini"))


@pytest.mark.parametrize("kind", list(RIG_RUNS))
def test_tables_builds_a_runs_tables_as_the_run_does(tables, kind, tmp_path):
    # rollspec.contact.tables on the study of a run: the run's table bit for bit, built where the run puts
    # it, and nothing else (no result); called again, and by the run itself, it is reused.
    stage, sets = RIG_RUNS[kind]
    study = shutil.copy(os.path.join(STUDIES, "seed002-rig-1ms.ini"), tmp_path / "rig.ini")
    built = contact.tables(study, set=sets)
    assert list(built) == [stage]
    t, command = built[stage], contact.Table.read(tables[kind])
    assert t.kind == kind and t.status == "built " + t.path and t.path.startswith(str(tmp_path / "tables"))
    assert t.input_hash == command.input_hash and t.data_checksum == command.data_checksum
    for name, column in command.columns.items():
        assert t.columns[name].tobytes() == column.tobytes(), name
    assert sorted(os.listdir(tmp_path)) == ["rig.ini", "tables"]
    again = contact.tables(study, set=sets, threads=1)
    assert again[stage].status == "cached " + t.path
    plan = subprocess.run([ROLLSPEC, "plan", str(study), *[a for kv in sets for a in ("--set", kv)]],
                          capture_output=True, text=True, cwd=tmp_path)
    assert plan.returncode == 0 and re.search(r"^\s*%s\s+cached" % stage, plan.stdout, re.M), plan.stdout


def test_tables_of_a_study_without_tables_and_bad_requests(tmp_path):
    assert contact.tables(os.path.join(STUDIES, "random-oscillator.ini")) == {}
    assert contact.tables(os.path.join(STUDIES, "seed002-rig-1ms.ini"), set=["contact.law=hertz"]) == {}
    with pytest.raises(ValueError, match=r"^threads = 0: fewer than one; allowed: a thread count >= 1"):
        contact.tables(os.path.join(STUDIES, "random-oscillator.ini"), threads=0)
    with pytest.raises(OSError, match="none.ini"):
        contact.tables(tmp_path / "none.ini")
