#!/usr/bin/python3
"""Figure versions: when a benchmark or validation record (bench/records/) is older than the code that
computes its figures.

bench/record_versions.json names the components whose code computes a record's figures (each a list of
source folders and files, e.g. the contact kernel kernels/contact/, and optionally under "except" the files in
them that another component owns, so that a change there stales only the records that use it), and for each a
version and the hash
of its sources as that version was declared. The hash is over the code with comments and blank space
taken out (C++, Python and CMake files), so rewording a comment or reformatting leaves it as it is.
bench/bench_record.py stamps every record it writes with the versions of the components its script
names (all of them when it names none).

The rule (tests/cli/test_record_versions.py enforces it):
  - a component whose sources no longer match its hash fails the test until someone decides:
      bump COMPONENT    the change can move a figure: its version goes up, every record stamped with
                        the old one is stale (the documentation shows it as such) until its script runs again
      accept COMPONENT  the change cannot move any figure (a renamed variable, a new error message):
                        the same version, the new hash; the diff of bench/record_versions.json says so
  - a record stamped with an older version than the component's is stale: the test fails, naming the
    record and the command that remakes it.

  /usr/bin/python3 bench/record_versions.py check | bump COMPONENT... | accept COMPONENT... | stale [DIR]
"""
import argparse
import hashlib
import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MANIFEST = ROOT / "bench" / "record_versions.json"
CODE_SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".py", ".txt", ".cmake", ".in"}

# A C++ string or character literal, a // or /* */ comment: strings are kept whole so that "//" in one
# is not taken for a comment.
_CXX = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|//[^\n]*|/\*.*?\*/', re.S)
_HASH_LINE = re.compile(r"^\s*#(?!(?:include|define|if|ifdef|ifndef|else|elif|endif|pragma|undef)\b)[^\n]*", re.M)


class VersionError(ValueError):
    pass


def code_of(path):
    """The text of a source file without comments and blank space: what can change a figure."""
    text = Path(path).read_text(encoding="utf-8", errors="replace")
    if path.suffix in (".cpp", ".hpp", ".h", ".c", ".in"):
        text = _CXX.sub(lambda m: m.group(0) if m.group(0)[0] in "\"'" else " ", text)
    elif path.suffix in (".py", ".txt", ".cmake"):
        text = _HASH_LINE.sub("", text)  # whole-line comments (and docstring-free: docstrings stay)
    return " ".join(text.split())


def files_of(paths, root=ROOT, exclude=()):
    """The code files under the component's folders and files but not under `exclude`, in a stable order."""
    def listed(ps):
        found = []
        for p in ps:
            q = root / p
            if q.is_file():
                found.append(q)
            elif q.is_dir():
                found += [f for f in q.rglob("*") if f.is_file() and f.suffix in CODE_SUFFIXES]
            else:
                raise VersionError(f"{MANIFEST.name}: source {p} does not exist")
        return set(found)
    return sorted(listed(paths) - listed(exclude), key=lambda f: f.relative_to(root).as_posix())


def sources_hash(paths, root=ROOT, exclude=()):
    h = hashlib.sha256()
    for f in files_of(paths, root, exclude):
        h.update(f.relative_to(root).as_posix().encode() + b"\0" + code_of(f).encode() + b"\0")
    return h.hexdigest()[:16]


def load_manifest(path=MANIFEST):
    if not Path(path).is_file():  # a FIFO would block the read, a folder or device is no manifest
        raise VersionError(f"{path}: not a regular file; allowed: the figure versions this script writes")
    try:
        m = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        raise VersionError(f"{path}: cannot read the figure versions ({e})") from None
    comps = m.get("components") if isinstance(m, dict) else None
    if not isinstance(comps, dict) or not comps:
        raise VersionError(f"{path}: no 'components'")
    for name, c in comps.items():
        if not (isinstance(c, dict) and isinstance(c.get("version"), int) and c["version"] >= 1
                and isinstance(c.get("paths"), list) and c["paths"] and isinstance(c.get("sources"), str)
                and isinstance(c.get("except", []), list)):
            raise VersionError(f"{path}: component '{name}' needs 'paths' (a list), 'version' (an integer "
                               "from 1) and 'sources' (the hash); 'except' (optional) is a list")
    return m


def current_versions(components=None, manifest=None):
    """{component: version} for the named components (all when None); VersionError for an unknown name."""
    comps = (manifest or load_manifest())["components"]
    names = list(comps) if components is None else list(components)
    unknown = [n for n in names if n not in comps]
    if unknown:
        raise VersionError(f"unknown component '{unknown[0]}'; allowed: {', '.join(comps)}")
    return {n: comps[n]["version"] for n in names}


def changed(manifest=None, root=ROOT):
    """The components whose sources no longer match their declared hash: [(name, declared, now)]."""
    comps = (manifest or load_manifest())["components"]
    return [(n, c["sources"], h) for n, c in comps.items()
            if (h := sources_hash(c["paths"], root, c.get("except", []))) != c["sources"]]


def stale(record, manifest=None):
    """Why a record (a loaded dict) is older than the code: [] when it is current."""
    comps = (manifest or load_manifest())["components"]
    stamped = record.get("versions")
    if not isinstance(stamped, dict) or not stamped:
        return ["it carries no figure versions (written before they were kept)"]
    why = []
    for name, v in stamped.items():
        if name not in comps:
            why.append(f"component '{name}' is no longer declared")
        elif v != comps[name]["version"]:
            why.append(f"{name} version {v}, now {comps[name]['version']}")
    return why


def _write(manifest):
    sys.path.insert(0, str(ROOT / "bench"))
    import bench_record  # noqa: E402  (the one atomic writer)
    bench_record.replace_text(MANIFEST, json.dumps(manifest, indent=1) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("action", choices=["check", "bump", "accept", "stale"])
    p.add_argument("names", nargs="*", help="components (bump, accept) or a records folder (stale)")
    a = p.parse_args()
    try:
        m = load_manifest()
        if a.action == "check":
            bad = changed(m)
            for n, old, new in bad:
                print(f"{n}: sources changed since version {m['components'][n]['version']} ({old} -> {new}); "
                      f"run `bench/record_versions.py bump {n}` or `accept {n}`")
            sys.exit(1 if bad else 0)
        if a.action == "stale":
            sys.path.insert(0, str(ROOT / "bench"))
            import bench_record  # noqa: E402
            folders = [Path(x) for x in a.names] or [bench_record.RECORDS, bench_record.RECORDS / "validation"]
            n_stale = 0
            for d in folders:
                if not d.is_dir():
                    raise VersionError(f"{d}: not a folder of records")
                for f in sorted(d.glob("*.json")):
                    why = stale(bench_record.load(f), m)
                    if why:
                        n_stale += 1
                        print(f"{f}: stale: {'; '.join(why)}")
            sys.exit(1 if n_stale else 0)
        if not a.names:
            raise VersionError(f"{a.action}: name at least one component; allowed: {', '.join(m['components'])}")
        current_versions(a.names, m)  # unknown names refused before anything is written
        for n in a.names:
            c = m["components"][n]
            if a.action == "bump":
                c["version"] += 1
            c["sources"] = sources_hash(c["paths"], exclude=c.get("except", []))
            print(f"{n}: version {c['version']}, sources {c['sources']}")
        _write(m)
    except VersionError as e:
        print(f"record_versions: {e}", file=sys.stderr)
        sys.exit(65)


sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)

if __name__ == "__main__":
    script_main(main)
