"""Benchmark records: one JSON file per benchmark in bench/records/, written by the bench script that
measured it and rendered into the documentation's benchmarks page (docs/generate_reference.py), so no
measured figure on that page is typed by hand.

A record holds
  title     what was measured (a heading on the page)
  command   the command that measured it, as run (shown above the table)
  date      the day it was measured (YYYY-MM-DD)
  machine   {"cores": N, ...}: the machine's facts (cores are required; other_work_cores: the cores
            other work kept busy during the measurement, from /proc/stat, where the script measured it)
  builds    {name: {"description": text, ...}}: the builds measured; other fields (for example the
            build's own `rollspec version` line, which names its commit) are kept but not printed
  settings  how it was run (threads, repeats, medians), one sentence
  columns   the table's headings; rows: the table's rows, one cell (text or number) per column
  notes     optional text printed under the table
  data      optional raw figures for scripts; never printed
  versions  {component: version}: the figure versions of the code that computed it
            (bench/record_versions.py), stamped by `write`; a record whose versions are older than the
            code's is stale, and its table is not printed (the page says which command remakes it)

`write` is what a bench script calls; `load` checks a file and raises RecordError with one line that
names the file and the fault; `markdown` renders a checked record.
"""
import contextlib
import datetime
import json
import os
import platform
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "python-post"))
from rollspec_post import safe_output  # noqa: E402  (the one atomic writer)
from rollspec_post.script_main import fail, flush_stdout, script_main  # noqa: E402,F401  (the scripts' rule)
sys.path.insert(0, str(ROOT / "bench"))
import record_versions  # noqa: E402  (figure versions: when a record is stale)
RECORDS = ROOT / "bench" / "records"
REQUIRED = {"title": str, "command": str, "date": str, "machine": dict, "builds": dict, "settings": str,
            "columns": list, "rows": list}


class RecordError(ValueError):
    exit_code = 73  # EX_CANTCREAT: a script that lets it through ends in one line (script_main), not "internal error"


def command_line(argv):
    """The command as a user in the repository root would type it: paths inside the repository relative."""
    def rel(a):
        p = Path(a)
        if p.is_absolute():
            try:
                return str(p.resolve().relative_to(ROOT))
            except ValueError:
                return a
        return a
    return shlex.join(["/usr/bin/python3"] + [rel(a) for a in argv])


def machine():
    model = ""
    if Path("/proc/cpuinfo").exists():
        m = re.search(r"^model name\s*:\s*(.*)$", Path("/proc/cpuinfo").read_text(), re.M)
        model = m.group(1).strip() if m else ""
    return {"cores": os.cpu_count(), "cpu": model or platform.processor(), "system": platform.system()}


def busy_seconds():
    """CPU seconds every core of the machine has been busy since boot (/proc/stat; 0 where there is none)."""
    stat = Path("/proc/stat")
    if not stat.exists():
        return 0.0
    ticks = [int(x) for x in stat.read_text().split("\n", 1)[0].split()[1:]]
    idle = ticks[3] + (ticks[4] if len(ticks) > 4 else 0)
    return (sum(ticks[:8]) - idle) / os.sysconf("SC_CLK_TCK")


def own_cpu():
    """CPU seconds of this process and its finished children."""
    import resource
    return sum(u.ru_utime + u.ru_stime for u in (resource.getrusage(resource.RUSAGE_SELF),
                                                  resource.getrusage(resource.RUSAGE_CHILDREN)))


def other_work(busy_before, own_cpu, wall):
    """Cores that other work kept busy while a benchmark ran: the machine's busy seconds minus its own."""
    return max(0.0, (busy_seconds() - busy_before - own_cpu) / wall) if wall > 0 else 0.0


@contextlib.contextmanager
def scratch_studies(prefix):
    """A temporary folder holding a copy of studies/ without its cached tables (the runs build their own
    there, and relative paths in the studies resolve as they do in the checkout); removed afterwards."""
    work = Path(tempfile.mkdtemp(prefix=prefix))
    try:
        shutil.copytree(Path(__file__).resolve().parents[1] / "studies", work / "studies",
                        ignore=shutil.ignore_patterns("tables"))
        yield work
    finally:
        shutil.rmtree(work, ignore_errors=True)


@contextlib.contextmanager
def study_run(binary, study, settings, threads, prefix):
    """`binary run` of a copy of `study` with --set SETTINGS, in an empty folder (every table built anew), on
    `threads` OpenMP threads. Yields (the result's path, the run's stderr, its wall seconds, the CPU seconds
    it used); the folder is removed afterwards. A failed run ends the script: exit 1, the run's last line."""
    import resource
    import time
    work = Path(tempfile.mkdtemp(prefix=prefix))
    try:
        shutil.copy(study, work / Path(study).name)
        args = [a for kv in settings for a in ("--set", kv)]
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        r = subprocess.run([binary, "run", Path(study).name, "--out", "r.h5", *args], cwd=work, capture_output=True,
                           text=True, env=dict(os.environ, OMP_NUM_THREADS=str(threads)))
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if r.returncode != 0:
            fail(f"{binary} run {' '.join(settings)} failed ({r.returncode}): "
                 f"{(r.stderr.strip().splitlines() or ['no message'])[-1]}", 1)
        yield work / "r.h5", r.stderr, wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def build_version(binary):
    """The binary's own `rollspec version` line (kept in the record, not printed)."""
    r = subprocess.run([str(binary), "version"], capture_output=True, text=True)
    return r.stdout.splitlines()[0] if r.returncode == 0 and r.stdout else "unknown"


def write(path, *, title, argv, builds, settings, columns, rows, notes="", data=None, other_cores=None,
          components=None):
    """components: the figure-version components (bench/record_versions.json) whose code computes the
    figures; None: all of them (a change anywhere makes the record stale)."""
    try:
        versions = record_versions.current_versions(components)
    except record_versions.VersionError as e:
        raise RecordError(str(e)) from None
    facts = machine()
    if other_cores is not None:
        facts["other_work_cores"] = round(other_cores, 2)
    record = {"title": title, "command": command_line(argv), "date": datetime.date.today().isoformat(),
              "machine": facts, "builds": builds, "settings": settings, "columns": columns, "rows": rows}
    if notes:
        record["notes"] = notes
    if data is not None:
        record["data"] = data
    record["versions"] = versions
    check(record, str(path))
    replace_text(path, json.dumps(record, indent=1, ensure_ascii=False) + "\n", own=is_record)


def write_measured(path, binary, **fields):
    """write() of a record measured with one build (named by its `rollspec version` line). A record that cannot
    be written ends the script as every script ends: one line, exit 73 (sysexits EX_CANTCREAT)."""
    try:
        write(path, builds={"current": {"description": "the build measured", "version": build_version(binary)}},
              **fields)
    except RecordError as e:
        fail(e, 73)


def is_record(path):
    try:
        load(path)
        return True
    except (RecordError, OSError, UnicodeDecodeError):
        return False


def check_target(path, own=lambda target: True):
    """The file `path` would replace (symbolic links resolved); RecordError, in one line, for a directory,
    FIFO or device, a missing directory, or an existing file that own(target) does not recognise. Bench
    scripts call it before measuring, so a long measurement is not lost at the end."""
    target = os.path.realpath(path)
    if os.path.exists(target) and not os.path.isfile(target):
        raise RecordError(f"{path}: is not a regular file; allowed: a new file or one this script wrote")
    if os.path.exists(target) and not own(target):
        raise RecordError(f"{path}: exists and is not a benchmark record; allowed: a new file or a record "
                          "written by a bench script")
    if not os.path.isdir(os.path.dirname(target)):
        raise RecordError(f"{path}: no directory {os.path.dirname(target)}")
    return target


def check_targets(targets, code=73):
    """check_target of each (path, own) in `targets` whose path was given (an option left out is None), before
    any measurement: a refused one ends the script in one line, exit `code` (73, EX_CANTCREAT, unless the
    script has always said 1)."""
    for path, own in targets:
        if path:
            try:
                check_target(path, own)
            except RecordError as e:
                fail(e, code)


def check_record_target(path, code=73):
    """--record (None: not given) checked as a record's target, as check_targets does."""
    check_targets([(path, is_record)], code)


def record_script_parser(description, default_bin):
    """The options every validation-record script shares: --bin (the rollspec binary) and --record (the
    record to write); a script adds its own before calling record_script_arguments."""
    import argparse
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--bin", default=str(default_bin))
    p.add_argument("--record", help="write the table as a record (bench/records/validation/*.json)")
    return p


def record_script_arguments(parser):
    """(arguments, the binary's resolved path): --record checked as a record's target (73 if it is not one)
    and --bin an executable file (66 if not), before any run, in one line each (script_main's rule)."""
    a = parser.parse_args()
    check_record_target(a.record)
    binary = str(Path(a.bin).resolve())
    if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
        fail(f"--bin {a.bin}: not an executable file; allowed: a rollspec binary", 66)
    return a, binary


def generated_block_owner(begin, title):
    """The pages a script writes a generated block of: a regular UTF-8 file that holds the block's begin
    marker, or the page before its first block (its title line starts with `title`)."""
    def own(target):
        try:
            text = Path(target).read_text()
        except (OSError, UnicodeDecodeError):
            return False
        return begin in text or text.startswith(title)
    return own


def splice_block(path, lines, begin, end, title):
    """Puts the block `lines` (its first line the begin marker, its last the end marker) in place of the
    page's block between those markers, or at the page's end when it has none; written as replace_text
    writes, to a page generated_block_owner(begin, title) accepts. The page is checked before it is read (a
    FIFO or directory at its name is refused, not waited on)."""
    own = generated_block_owner(begin, title)
    doc = Path(check_target(path, own)).read_text()
    text = "\n".join(lines) + "\n"
    if begin in doc:
        if end not in doc[doc.index(begin):]:
            raise RecordError(f"{path}: the block's begin marker has no end marker {end!r} after it; allowed: a page "
                              "whose generated block is whole (restore the end marker)")
        doc = doc[:doc.index(begin)] + text + doc[doc.index(end, doc.index(begin)) + len(end) + 1:]
    else:
        doc = doc.rstrip("\n") + "\n\n" + text
    replace_text(path, doc, own=own)


def replace_text(path, text, own=lambda target: True):
    """Writes `text` to `path` through a temporary and a rename: the old file stays whole if the write
    fails; a symbolic link's target is replaced."""
    target = check_target(path, own)
    try:
        safe_output.write_atomic(target, lambda fh: fh.write(text.encode()))
    except safe_output.PostError as e:
        raise RecordError(str(e)) from None


def looks_like_commit(text):
    # 1.509577e-03 is a number, not a commit.
    text = re.sub(r"(?<![0-9a-f.])\d*\.?\d+e[-+]?\d+(?![0-9a-f])", " ", text)
    return [w for w in re.findall(r"\b[0-9a-f]{7,40}\b", text)
            if re.search(r"[a-f]", w) and re.search(r"\d", w) and not re.fullmatch(r"\d+e\d+", w)]


def check(record, name):
    def fail(what):
        raise RecordError(f"benchmark record {name}: {what}")

    if not isinstance(record, dict):
        fail("not a JSON object")
    for key, kind in REQUIRED.items():
        if key not in record:
            fail(f"no '{key}'")
        if not isinstance(record[key], kind) or (kind is str and not record[key].strip()):
            fail(f"'{key}' is not a non-empty {kind.__name__}")
    if not re.fullmatch(r"\d{4}-\d{2}-\d{2}", record["date"]):
        fail(f"'date' {record['date']!r} is not YYYY-MM-DD")
    if not isinstance(record["machine"].get("cores"), int) or record["machine"]["cores"] < 1:
        fail("'machine' has no 'cores' (a positive integer)")
    if not record["builds"]:
        fail("'builds' names no build")
    for b, v in record["builds"].items():
        if not isinstance(v, dict) or not isinstance(v.get("description"), str) or not v["description"].strip():
            fail(f"build '{b}' has no 'description'")
    if not record["columns"] or not all(isinstance(c, str) for c in record["columns"]):
        fail("'columns' is not a list of headings")
    if not record["rows"]:
        fail("'rows' is empty")
    for i, row in enumerate(record["rows"], 1):
        if not isinstance(row, list) or len(row) != len(record["columns"]):
            fail(f"row {i} has {len(row) if isinstance(row, list) else 'no'} cells, the columns "
                 f"{len(record['columns'])}")
        if not all(isinstance(c, (str, int, float)) for c in row):
            fail(f"row {i} has a cell that is neither text nor a number")
    printed = " ".join([record["title"], record["command"], record["settings"], record.get("notes", "")]
                       + [v["description"] for v in record["builds"].values()] + record["columns"]
                       + [str(c) for row in record["rows"] for c in row])
    if looks_like_commit(printed):
        fail(f"printed text names a commit ({looks_like_commit(printed)[0]}); describe the build instead")
    if re.search(r"load average", printed, re.I):
        fail("printed text names a load average")
    versions = record.get("versions", {})
    if not isinstance(versions, dict) or not all(isinstance(k, str) and isinstance(v, int) and not isinstance(v, bool)
                                                  for k, v in versions.items()):
        fail("'versions' is not an object of component: integer version")


MAX_RECORD_BYTES = 16 * 2**20  # the largest record written is a few kB


def load(path):
    path = Path(path)
    try:
        if not path.is_file():  # a FIFO would block the read, a device never end
            raise RecordError(f"benchmark record {path.name}: not a regular file")
        if path.stat().st_size > MAX_RECORD_BYTES:
            raise RecordError(f"benchmark record {path.name}: larger than {MAX_RECORD_BYTES // 2**20} MiB")
        record = json.loads(path.read_bytes().decode("utf-8"))
    except UnicodeDecodeError as e:
        raise RecordError(f"benchmark record {path.name}: not UTF-8 text (byte {e.start})") from None
    except json.JSONDecodeError as e:
        raise RecordError(f"benchmark record {path.name}: not JSON ({e})") from None
    except OSError as e:
        raise RecordError(f"benchmark record {path.name}: cannot read ({e.strerror})") from None
    check(record, path.name)
    return record


def cell(value):
    text = f"{value:.4g}" if isinstance(value, float) else str(value)
    return text.replace("|", "\\|").replace("\n", " ")


def markdown(record, level=3, manifest=None):
    """A record as Markdown: heading, command, builds and machine, the table, the notes. A stale record
    (older figure versions than the code's, bench/record_versions.py) gives its heading, its command and
    why it is stale, not its figures; one written before versions were kept says so above its table."""
    m = record["machine"]
    why = record_versions.stale(record, manifest)
    if why and record.get("versions"):
        return "\n".join([f"{'#' * level} {record['title']}", "", "```{warning}",
                          f"This record is older than the code that computes its figures ({'; '.join(why)}), "
                          "so they are not shown. Running its command again remakes it:", "```", "",
                          "```text", record["command"], "```", ""])
    lines = [f"{'#' * level} {record['title']}", "", "Measured by", "", "```text", record["command"], "```", "",
             f"on {record['date']}, {m['cores']} cores" + (f" ({m['cpu']})" if m.get("cpu") else "")
             + (f"; other work kept {m['other_work_cores']:.1f} of them busy meanwhile"
                if isinstance(m.get("other_work_cores"), (int, float)) else "") + ". "
             + record["settings"][:1].upper() + record["settings"][1:], ""]
    lines += [f"- **{name}**: {v['description']}" for name, v in record["builds"].items()]
    if why:
        lines += ["", "Measured before the records kept the versions of the code that computed them: not "
                  "checked against the current code."]
    else:
        lines += ["", "Figure versions: " + ", ".join(f"{c} {v}" for c, v in record["versions"].items()) + "."]
    lines += ["", "| " + " | ".join(cell(c) for c in record["columns"]) + " |",
              "|" + "---|" * len(record["columns"])]
    lines += ["| " + " | ".join(cell(c) for c in row) + " |" for row in record["rows"]]
    if record.get("notes"):
        lines += ["", record["notes"]]
    return "\n".join(lines) + "\n"


def render_all(directory=RECORDS, level=3):
    """Every record of a directory, in file-name order, as one Markdown text; RecordError on the first fault."""
    files = sorted(Path(directory).glob("*.json"))
    if not files:
        raise RecordError(f"benchmark records: none in {directory}")
    manifest = manifest_or_fail()
    return "\n".join(markdown(load(f), level, manifest) for f in files)


def manifest_or_fail():
    try:
        return record_versions.load_manifest()
    except record_versions.VersionError as e:
        raise RecordError(str(e)) from None


def render_one(path, level=3):
    """One record as Markdown, or, where the file is missing, a warning that says so (the page's text
    names the command that writes it); RecordError for a malformed one."""
    path = Path(path)
    if not path.exists():
        try:
            name = path.resolve().relative_to(ROOT).as_posix()
        except ValueError:
            name = f"{path.parent.name}/{path.name}"
        return "\n".join(["```{warning}", f"The record `{name}` is missing: its "
                          "figures are not shown until the script that measures them writes it.", "```", ""])
    return markdown(load(path), level, manifest_or_fail())
