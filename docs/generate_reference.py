#!/usr/bin/python3
"""Writes the documentation's generated pages from the rollspec binary and the repository, so that the
reference cannot drift from the program:

  reference/generated/commands.md    every command of `rollspec --help`, each with its `--help` text
  reference/generated/keys.md        every key of every scene (`rollspec keys SCENE`): default, allowed, unit
  reference/generated/exit-codes.md  exit codes: the man page's list (cmake/rollspec.h2m) and the
                                     <sysexits.h> codes the sources use (src/)
  reference/generated/schema.md      the HDF5 result schema, walked with h5py from a file written now
                                     (random-oscillator study, 5 realisations, in a temporary directory)
  validation/generated/goals-table.md, goals.png   the benchmark goals table and figure from bench/goals.json
  validation/generated/work-precision.png  from python-post/docs/work-precision.csv
  validation/generated/bench-records.md  every benchmark record of bench/records/ (written by the bench
                                     scripts, bench/bench_record.py), a table each with its command;
                                     a malformed record stops the build with one line naming it
  validation/generated/validation-records.md  the same for bench/records/validation/ (the seeds page)
  validation/generated/records/NAME.md  each record of bench/records/validation/ alone, for a page
                                     that quotes it where its figures belong (```{include}```); a
                                     page's include of a record that does not exist renders a warning
                                     that says so, and a stale record (bench/record_versions.py) its
                                     command instead of its figures
  howto/generated/profiles-note.md   the note `rollspec texture` prints for the Dektak scan shipped in
                                     studies/data/measured-profiles (the profiles how-to quotes it)

  /usr/bin/python3 docs/generate_reference.py --bin build/werror/rollspec --out DOCS_SOURCE_DIR
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


EX_DATAERR, EX_SOFTWARE, EX_IOERR = 65, 70, 74


def fail(message, code):
    """One line on stderr and a sysexits code: the build stops there."""
    print(f"generate_reference: {' '.join(str(message).split())}", file=sys.stderr)
    sys.exit(code)


def run(argv, stderr=False, **kw):
    """The command's stdout (stderr too where `stderr`: the pair); one line and a stop if it fails."""
    try:
        r = subprocess.run(argv, capture_output=True, text=True, errors="replace", timeout=300, **kw)
    except OSError as e:
        fail(f"cannot run {argv[0]}: {e.strerror}", EX_SOFTWARE)
    except subprocess.TimeoutExpired:
        fail(f"{' '.join(map(str, argv))}: no answer within 300 s", EX_SOFTWARE)
    if r.returncode != 0:
        last = (r.stderr.strip().splitlines() or [""])[-1]
        fail(f"{' '.join(map(str, argv))} exited {r.returncode}: {last}", EX_SOFTWARE)
    return (r.stdout, r.stderr) if stderr else r.stdout


def commands(binary):
    """The command names of `rollspec --help`, in its order, with their one-line meaning."""
    text = run([binary, "--help"])
    block = text.split("commands:", 1)[1].split("\n\n", 1)[0]
    return [(m.group(1), m.group(2).strip()) for m in re.finditer(r"^\s{2}(\S+)\s+(.*)$", block, re.M)]


def scenes(binary):
    return [(line.split(":", 1)[0].strip(), line.split(":", 1)[1].strip())
            for line in run([binary, "keys"]).splitlines() if ":" in line]


def parse_keys(text):
    """`rollspec keys SCENE` → [(section, [(key, default, meaning, allowed, unit)])]."""
    sections, current, key = [], None, None
    for line in text.splitlines():
        if not line.strip():
            continue
        m = re.match(r"^\[(.+)\]$", line)
        if m:
            current = (m.group(1), [])
            sections.append(current)
            continue
        m = re.match(r"^  (\S+) = ?(.*)$", line)
        if m and not line.startswith("    "):
            key = [m.group(1), m.group(2), "", "", ""]
            current[1].append(key)
            continue
        body = line.strip()
        if body.startswith("allowed:"):
            allowed = body[len("allowed:"):].strip()
            u = re.search(r"\(([^()]*)\)$", allowed)
            if u and not re.match(r"^[\d.,\s\[\]e+-]+$", u.group(1)):
                key[4] = u.group(1)
                allowed = allowed[:u.start()].strip()
            key[3] = allowed
        else:
            key[2] = (key[2] + " " + body).strip()
    return sections


def cell(s):
    return (s or " ").replace("|", "\\|").replace("\n", " ")


def code(s):
    if not s:
        return "(required)" if s == "(required)" else "—"
    tick = "``" if "`" in s else "`"
    return f"{tick}{s}{tick}"


def without_build_id(text):
    """`rollspec version` prints the commit it was built from; the page shows where it goes instead."""
    return re.sub(r"\(git [0-9a-f]+(-dirty)?\)", "(git <commit of the build>)", text)


def write_commands(binary, out):
    lines = ["# Commands and options", "",
             "Generated at build time from `rollspec --help` and `rollspec COMMAND --help` of the binary the "
             "documentation was built with; `man rollspec` holds the same text.", "",
             "```text", run([binary, "--help"]).rstrip(), "```", ""]
    for name, meaning in commands(binary):
        lines += [f"(command-{name})=", f"## `rollspec {name}`", "", meaning[:1].upper() + meaning[1:] + ".", "",
                  "```text", without_build_id(run([binary, name, "--help"])).rstrip(), "```", ""]
    (out / "commands.md").write_text("\n".join(lines))


def write_keys(binary, out):
    lines = ["# Study keys", "",
             "Generated at build time from `rollspec keys SCENE` for every scene of `rollspec keys`. A study "
             "file is INI (`[section]`, `key = value`); a key without a default is required. Anything "
             "unknown, duplicated, non-finite, out of range or missing is refused before any work starts "
             "(exit 78).", ""]
    for scene, meaning in scenes(binary):
        lines += [f"(scene-{scene})=", f"## `{scene}`", "", meaning[:1].upper() + meaning[1:] + ".", ""]
        for section, keys in parse_keys(run([binary, "keys", scene])):
            lines += [f"### `{scene}` `[{section}]`", "",
                      "| key | default | unit | allowed | meaning |", "|---|---|---|---|---|"]
            for key, default, meaning_, allowed, unit in keys:
                lines.append(f"| `{key}` | {cell(code(default))} | {cell(unit)} | {cell(allowed)} | {cell(meaning_)} |")
            lines.append("")
    lines += ["(sweep-section)=", "## `[sweep]` (every scene that runs)", "",
              "Not a key table: its keys name other keys of the study. `mode = crossed | zipped` (default "
              "crossed), and `section.key = v1, v2, ...` for each swept key (each must be a key of the scene "
              "above; each value is checked as that key's value). `rollspec run` and `rollspec plan` take "
              "`--sweep section.key=v1,v2,...` too. See the how-to *Sweeping a study key*.", ""]
    (out / "keys.md").write_text("\n".join(lines))


def sysexits():
    codes = {}
    for path in ("/usr/include/sysexits.h", "/usr/include/x86_64-linux-gnu/sysexits.h"):
        if Path(path).exists():
            for m in re.finditer(r"#define\s+(EX_\w+)\s+(\d+)\s*/\*\s*(.*?)\s*\*/", Path(path).read_text()):
                codes[m.group(1)] = (int(m.group(2)), m.group(3))
    return codes


def write_exit_codes(out):
    h2m = (REPO / "cmake" / "rollspec.h2m").read_text()
    block = h2m.split("[EXIT STATUS]", 1)[1].split("\n[", 1)[0]
    documented = [(int(m.group(1)), m.group(2).replace("\\-", "-").strip())
                  for m in re.finditer(r"^\.B (\d+)\n(.*)$", block, re.M)]
    used = set()
    for p in (REPO / "src").rglob("*.[ch]pp"):
        used |= set(re.findall(r"\bEX_[A-Z]+\b", p.read_text()))
    table = sysexits()
    lines = ["# Exit codes", "",
             "Generated at build time from the man page's list (`cmake/rollspec.h2m`, shown by `man rollspec`) "
             "and the `<sysexits.h>` names the sources (`src/`) exit with. Every error message names the file, "
             "line, key and value at fault and what is allowed.", "",
             "| code | meaning |", "|---|---|"]
    codes_documented = {c for c, _ in documented}
    missing = sorted((table[n][0], table[n][1]) for n in used if n in table and table[n][0] not in codes_documented)
    rows = sorted(documented + [(c, f"{text} (`<sysexits.h>`; used by the sources, not in the man page)")
                                for c, text in missing])
    lines += [f"| {c} | {cell(text)} |" for c, text in rows]
    lines += ["", "The `<sysexits.h>` names in the sources:", "", "| name | code | `<sysexits.h>` says | in the man page |",
              "|---|---|---|---|"]
    for name in sorted(used, key=lambda n: table.get(n, (999,))[0]):
        number, text = table.get(name, (None, ""))
        lines.append(f"| `{name}` | {number} | {cell(text)} | {'yes' if number in codes_documented else 'no'} |")
    (out / "exit-codes.md").write_text("\n".join(lines) + "\n")


def write_schema(binary, out):
    import h5py
    import numpy as np
    with tempfile.TemporaryDirectory() as tmp:
        result = Path(tmp) / "random-oscillator.h5"
        run([binary, "run", str(REPO / "studies" / "random-oscillator.ini"), "--out", str(result),
             "--set", "study.realisations=5", "--quiet"], cwd=tmp, env=dict(os.environ, OMP_NUM_THREADS="2"))
        lines = ["# Result file (HDF5)", "",
                 "Generated at build time by walking, with h5py, a result file written by this build: "
                 "`rollspec run studies/random-oscillator.ini --set study.realisations=5`. Other scenes add "
                 "their own groups (`/beam`, `/contact`, `/ball`, `/roughness`, `/reference`, `/time_history`); "
                 "the groups below are common to all. Shapes are those of this small run.", ""]

        def text(v):
            if isinstance(v, bytes):
                v = v.decode(errors="replace")
            if isinstance(v, np.ndarray):
                v = v.tolist() if v.size <= 4 else f"array {v.shape}"
            s = str(v).replace("\n", " ")
            return s if len(s) <= 120 else s[:117] + "…"

        with h5py.File(result, "r") as f:
            lines += ["## Root attributes", "", "| attribute | value in this run |", "|---|---|"]
            for k, v in f.attrs.items():
                value = "(the resolved study, INI)" if k == "study" else ("(differs per run)" if k in ("host", "created", "command_line", "git_sha") else text(v))
                lines.append(f"| `{k}` | {cell(value)} |")
            lines += ["", "## Datasets", "", "| dataset | shape | type | units | description |", "|---|---|---|---|---|"]
            rows = []

            def visit(name, obj):
                if isinstance(obj, h5py.Dataset):
                    units = obj.attrs.get("units", b"")
                    desc = obj.attrs.get("description", obj.attrs.get("long_name", b""))
                    rows.append(f"| `/{name}` | {obj.shape} | {obj.dtype} | {cell(text(units))} | {cell(text(desc))} |")
            f.visititems(visit)
            lines += rows
    (out / "schema.md").write_text("\n".join(lines) + "\n")


def write_goals(out):
    sys.path.insert(0, str(REPO / "bench"))
    import bench_goals  # noqa: E402  (the same rows its README table was made of)
    results = json.loads((REPO / "bench" / "goals.json").read_text())
    lines = ["| goal | measured (whole commands, one run) | |", "|---|---|---|"]
    lines += [f"| {g} | {m} | {ok} |" for g, m, ok, _ in bench_goals.rows(results)]
    (out / "goals-table.md").write_text("\n".join(lines) + "\n")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names, shares = [], []
    limits = {"1": ("wall_2_threads", 2.0), "2": ("cpu_ms", 10.0), "4": ("us_per_iteration", 30.0)}
    for g, (key, limit) in limits.items():
        if g in results:
            names.append(f"goal {g}: {key.replace('_', ' ')}")
            shares.append(results[g]["figures"][key] / limit)
    if "3" in results:
        m = results["3"]["figures"]
        names += ["goal 3: Hertz 512² wall", "goal 3: table wall"]
        shares += [m["hertz_wall"] / 0.6, m["table_wall"] / 8.0]
        names.append("goal 3: CG iteration (worst)")
        shares.append(max(x[2] for x in m["iteration"]) / 1.2)
    if "5" in results:
        names.append("goal 5: synthesis / c2r (worst)")
        shares.append(max(results["5"]["figures"]["ratio"]) / 2.0)
    fig, ax = plt.subplots(figsize=(7, 0.45 * len(names) + 1))
    ax.barh(names[::-1], shares[::-1], color=["#3a7" if s <= 1 else "#c33" for s in shares[::-1]])
    ax.axvline(1.0, color="k", lw=1)
    ax.set_xlabel("measured / goal (≤ 1: met)")
    fig.tight_layout()
    fig.savefig(out / "goals.png", dpi=110)
    plt.close(fig)


def write_work_precision(out):
    """The work-precision figure, drawn now from the CSV bench/beam/bench_beam's runs left."""
    run(["/usr/bin/python3", "-m", "rollspec_post", "bench", str(REPO / "python-post" / "docs" / "work-precision.csv"),
         "--out", str(out / "work-precision.png"), "--force"],
        env=dict(os.environ, PYTHONPATH=str(REPO / "python-post"), MPLBACKEND="Agg"))


def write_bench_records(records, out):
    """The bench scripts' records as tables, each under the command that measured it."""
    sys.path.insert(0, str(REPO / "bench"))
    import bench_record  # noqa: E402
    try:
        text = bench_record.render_all(records, level=3)
    except bench_record.RecordError as e:
        fail(e, EX_DATAERR)
    (out / "bench-records.md").write_text(text)


def write_validation_records(records, out):
    """The bench scripts' validation records (bench/records/validation/), for the seeds page."""
    import bench_record  # noqa: E402  (on the path: write_bench_records runs first)
    if not records.is_dir():  # another records directory ($ROLLSPEC_BENCH_RECORDS) may have none
        (out / "validation-records.md").write_text("")
        return
    try:
        text = bench_record.render_all(records, level=3)
    except bench_record.RecordError as e:
        fail(e, EX_DATAERR)
    (out / "validation-records.md").write_text(text)


INCLUDE = re.compile(r"^```\{include\}\s+(\S*generated/records/([A-Za-z0-9_.-]+)\.md)\s*$", re.M)


def write_record_pages(records, docs, out):
    """Every validation record alone (records/NAME.md), and for every include of one in the pages
    (docs/**/*.md) whose record is missing, the page that says so."""
    import bench_record  # noqa: E402  (on the path: write_bench_records runs first)
    out.mkdir(parents=True, exist_ok=True)
    names = {p.stem for p in records.glob("*.json")} if records.is_dir() else set()
    for page in docs.rglob("*.md"):
        if "generated" not in page.parts:
            names |= {m.group(2) for m in INCLUDE.finditer(page.read_text(encoding="utf-8"))}
    for name in sorted(names):
        try:
            text = bench_record.render_one(records / f"{name}.json", level=3)
        except bench_record.RecordError as e:
            fail(e, EX_DATAERR)
        (out / f"{name}.md").write_text(text)


def write_profiles_note(binary, out):
    """The note `rollspec texture` prints for a measured scan, quoted by the profiles how-to: made by this
    build from the shipped Dektak scan, so its figures are the program's own, never typed."""
    import textwrap
    scan = REPO / "studies" / "data" / "measured-profiles" / "dektak-1.csv"
    with tempfile.TemporaryDirectory() as tmp:
        study = Path(tmp) / "dektak.ini"
        study.write_text("[study]\nscene = texture\nrealisations = 1\nseed = 1\n[texture]\nsource = profiles\n"
                         f"profiles = {scan}\ntable_extension = zero\n[lines]\ncount = 1\nlength = 1.5e-3\n"
                         "spacing = 1.5625e-7\n[surface]\ncount = 0\n")
        _, err = run([binary, "texture", str(study), "--out", str(Path(tmp) / "dektak.h5")], stderr=True, cwd=tmp)
    note = next((line for line in err.splitlines() if "note: [texture] profiles:" in line), None)
    if note is None:
        fail(f"{binary} texture on {scan.name}: printed no 'note: [texture] profiles:' line", EX_SOFTWARE)
    note = note.split("rollspec texture: ", 1)[-1]
    text = textwrap.fill(note, 104, subsequent_indent="  ", break_on_hyphens=False, break_long_words=False)
    (out / "profiles-note.md").write_text("```text\n" + text + "\n```\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.environ.get("ROLLSPEC_BIN", str(REPO / "build" / "werror" / "rollspec")))
    ap.add_argument("--out", required=True, help="the documentation source directory (a copy of docs/)")
    ap.add_argument("--records", default=str(REPO / "bench" / "records"), help="the benchmark records' directory")
    a = ap.parse_args()
    binary = str(Path(a.bin).resolve())
    # It writes into a copy of docs/ (docs/build.sh makes one): never into the sources, never elsewhere.
    out = Path(a.out)
    if not (out / "conf.py").is_file() or out.resolve() == (REPO / "docs").resolve():
        fail(f"--out {a.out}: not a copy of docs/ (a folder holding conf.py, not docs/ itself); allowed: the folder "
             "docs/build.sh copies the sources into", 73)
    ref = Path(a.out) / "reference" / "generated"
    val = Path(a.out) / "validation" / "generated"
    ref.mkdir(parents=True, exist_ok=True)
    val.mkdir(parents=True, exist_ok=True)
    write_bench_records(Path(a.records), val)  # first: a malformed record fails before the slow pages
    write_validation_records(Path(a.records) / "validation", val)
    write_record_pages(Path(a.records) / "validation", Path(a.out), val / "records")
    write_commands(binary, ref)
    write_keys(binary, ref)
    write_exit_codes(ref)
    write_schema(binary, ref)
    howto = Path(a.out) / "howto" / "generated"
    howto.mkdir(parents=True, exist_ok=True)
    write_profiles_note(binary, howto)
    write_goals(val)
    write_work_precision(val)


if __name__ == "__main__":
    try:
        main()
    except OSError as e:  # a full disk, a folder that cannot be written: one line, not a traceback
        fail(f"{e.filename or ''}: {e.strerror or e}", EX_IOERR)
