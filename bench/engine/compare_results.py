#!/usr/bin/python3
"""Bitwise comparison of two rollspec binaries on the shipped studies.

usage: compare_results.py BIN_BEFORE BIN_AFTER [STUDY[,section.key=value...] ...]

Each study (a name in studies/, default: every studies/*.ini) runs with both binaries, each in a
fresh copy of studies/ at the same path (so paths in texts agree): `plan` text, the result file
(2 realisations, as tests/cli/test_every_study.py runs them) and every table file the run built
are compared dataset by dataset and attribute by attribute, bit for bit. Ignored: /run/wall_seconds,
/run/reduce_seconds, the memory available in plan texts, the provenance attributes that name the build, host, time or command line,
and the /provenance groups (the papers a run cites: provenance, not result data).
Extra `section.key=value` items after a study name are passed as --set overrides to both binaries,
to reach code paths no shipped study takes. Exit 1 if anything differs.
"""
import difflib
import re
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

AVAILABLE = re.compile(r"available [0-9.]+ [KMGT]?i?B")
SOURCE = Path(__file__).resolve().parents[2]
IGNORED_DATASETS = {"run/wall_seconds", "run/reduce_seconds"}
IGNORED_GROUP = "provenance"  # /provenance, and a sweep point's: what the run cites
IGNORED_ATTRIBUTES = {"rollspec_version", "git_sha", "library_versions", "created", "host", "command_line"}


def scene_of(path):
    scene = study_scene(path.read_text())
    if scene is None:
        raise SystemExit(f"{path}: no scene")
    return scene


def run(binary, args, cwd):
    r = subprocess.run([str(binary), *map(str, args)], cwd=cwd, capture_output=True, text=True)
    # The memory available changes from one moment to the next: not the binary's doing.
    return r.returncode, AVAILABLE.sub("available *", r.stdout), AVAILABLE.sub("available *", r.stderr)


def one_binary(binary, tag, work, name, overrides):
    """Runs plan and the study in a fresh copy of studies/ at `work`; returns texts and h5 files."""
    studies = work / "studies"
    if studies.exists():
        shutil.rmtree(studies)
    shutil.copytree(SOURCE / "studies", studies, ignore=shutil.ignore_patterns("tables"))
    study = studies / name
    sets = [a for o in overrides for a in ("--set", o)]
    scene = scene_of(study)
    out = work / "out.h5"
    if out.exists():
        out.unlink()
    plan = run(binary, ["plan", study, *sets], work)
    if scene == "texture":
        result = run(binary, ["texture", study, "--count", 2, "--out", out, "-q", *sets], work)
    elif scene == "stiffness":
        result = run(binary, ["stiffness", study, "--set", "stiffness.realisations=2", "-q", *sets], work)
    elif scene == "rolling-beam":
        result = run(binary, ["run", study, "--out", out, "-q", *sets], work)
    else:
        result = run(binary, ["run", study, "--out", out, "--set", "study.realisations=2", "-q", *sets], work)
    replan = run(binary, ["plan", study, *sets], work)  # tables now cached: their status lines
    kept = work / f"kept-{tag}"
    if kept.exists():
        shutil.rmtree(kept)
    kept.mkdir()
    files = {}
    if out.exists():
        files["out.h5"] = shutil.move(str(out), kept / "out.h5")
    for h5 in sorted(studies.rglob("*.h5")):
        rel = str(h5.relative_to(studies))
        target = kept / rel.replace("/", "__")
        shutil.move(str(h5), target)
        files[rel] = target
    return {"plan": plan, "result": result, "replan": replan}, files




def dimension_scales(obj):
    """The dataset's attached dimension scales by name (the attributes hold object references)."""
    if not isinstance(obj, h5py.Dataset):
        return []
    return [[scale.name for scale in dim.values()] for dim in obj.dims]


def attributes_differ(name, a, b):
    diffs = []
    if dimension_scales(a) != dimension_scales(b):
        diffs.append(f"{name}: dimension scales differ")
    for key in sorted(set(a.attrs) | set(b.attrs)):
        if key in IGNORED_ATTRIBUTES or key in ("DIMENSION_LIST", "REFERENCE_LIST"):
            continue
        if key not in a.attrs or key not in b.attrs:
            diffs.append(f"{name}@{key}: only in one file")
            continue
        va, vb = a.attrs[key], b.attrs[key]
        same = np.asarray(va).tolist() == np.asarray(vb).tolist() if np.asarray(va).dtype.kind == "O" \
            else np.asarray(va).tobytes() == np.asarray(vb).tobytes()
        if not same:
            diffs.append(f"{name}@{key}: differs")
    return diffs


def compare_h5(pa, pb):
    diffs = []
    with h5py.File(pa, "r") as fa, h5py.File(pb, "r") as fb:
        names_a, names_b = [], []
        fa.visit(names_a.append)
        fb.visit(names_b.append)
        names_a = [n for n in names_a if IGNORED_GROUP not in n.split("/")]
        names_b = [n for n in names_b if IGNORED_GROUP not in n.split("/")]
        diffs += [f"/{n}: only in one file" for n in sorted(set(names_a) ^ set(names_b))]
        diffs += attributes_differ("/", fa, fb)
        count = 0
        for n in sorted(set(names_a) & set(names_b)):
            oa, ob = fa[n], fb[n]
            diffs += attributes_differ("/" + n, oa, ob)
            if isinstance(oa, h5py.Dataset) and n not in IGNORED_DATASETS:
                count += 1
                va, vb = oa[()], ob[()]
                if oa.dtype != ob.dtype or oa.shape != ob.shape:
                    diffs.append(f"/{n}: dtype or shape differs")
                elif oa.dtype.kind == "O":  # variable-length strings: their bytes are pointers
                    if np.asarray(va).tolist() != np.asarray(vb).tolist():
                        diffs.append(f"/{n}: values differ")
                elif np.asarray(va).tobytes() != np.asarray(vb).tobytes():
                    diffs.append(f"/{n}: values differ")
    return count, diffs


def compare(before, after, item, work):
    name, *overrides = item.split(",")
    label = item
    texts_a, files_a = one_binary(before, "a", work, name, overrides)
    texts_b, files_b = one_binary(after, "b", work, name, overrides)
    problems = []
    for key in ("plan", "result", "replan"):
        ra, rb = texts_a[key], texts_b[key]
        if ra[0] != rb[0]:
            problems.append(f"{key}: exit {ra[0]} vs {rb[0]}")
        if key != "result" and ra[1] != rb[1]:
            lines = difflib.unified_diff(ra[1].splitlines(), rb[1].splitlines(), lineterm="", n=0)
            problems.append(f"{key}: stdout differs: " + " | ".join(list(lines)[2:8]))
        if ra[2] != rb[2]:
            problems.append(f"{key}: stderr differs")
    if texts_a["result"][0] != 0:
        problems.append("result: exit " + str(texts_a["result"][0]) + ": " + texts_a["result"][2].strip()[-300:])
    if set(files_a) != set(files_b):
        problems.append(f"files differ: {sorted(set(files_a) ^ set(files_b))}")
    datasets = 0
    for rel in sorted(set(files_a) & set(files_b)):
        n, d = compare_h5(files_a[rel], files_b[rel])
        datasets += n
        problems += [f"{rel}: {x}" for x in d]
    status = "identical" if not problems else "DIFFERS"
    print(f"{label}: {status} ({len(files_a)} files, {datasets} datasets, plan {len(texts_a['plan'][1].splitlines())} lines)",
          flush=True)
    for p in problems:
        print("   ", p, flush=True)
    return not problems


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    before, after = (str(Path(b).resolve()) for b in sys.argv[1:3])
    # a study by its name in studies/ (a path to one there is taken by its name)
    items = [Path(a).name for a in sys.argv[3:]] or sorted(p.name for p in (SOURCE / "studies").glob("*.ini"))
    missing = [i for i in items if not (SOURCE / "studies" / i.split(",")[0]).is_file()]
    if missing:
        raise SystemExit(f"compare_results.py: no study {', '.join(missing)} in {SOURCE / 'studies'}")
    for b in (before, after):
        if not os.access(b, os.X_OK):
            raise SystemExit(f"compare_results.py: {b}: not an executable rollspec")
    ok = True
    with tempfile.TemporaryDirectory(prefix="rollspec-compare-") as tmp:
        for item in items:
            ok = compare(before, after, item, Path(tmp)) and ok
    sys.exit(0 if ok else 1)


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.rig_summary import study_scene  # noqa: E402  (the scene as the tests read it)
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
