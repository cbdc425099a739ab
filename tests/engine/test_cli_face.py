"""The command line is a face: src/cli/ reads options and prints, and what a command does is an engine
function (src/run/, src/fit/, src/compare/, ...) that the Python module calls the same way.

The rules, read from the sources:
- no file of the engine (src/ outside src/cli/), the Python module (python/) or the benches (bench/)
  includes a src/cli/ header: the engine never depends on its command face (tests of a printer may);
- every file in src/cli/ is a command (`*_command.cpp`, `main.cpp`, `commands.hpp`), an option reader
  (FACE, with what it reads), or a printer (FACE, with what it prints); a file that holds engine work
  not yet moved out is listed in PENDING with that work, and PENDING can only shrink (a file it names
  must still exist).
`violations` runs on the real tree and on scratch trees that break each rule, so the test can fail."""
import pathlib
import re

from source_scan import ROOT, scratch

INCLUDE = re.compile(r'^\s*#\s*include\s*"(src/cli/[^"]+)"', re.M)
COMMAND = re.compile(r"^(\w+_command\.cpp|main\.cpp|commands\.hpp)$")

# src/cli/ files that are no command but belong to the face: what each reads or prints.
FACE = {
    "parse_options": "the shared option parser (Boost.Program_options) and the study-file/--set options",
    "sweep_options": "run's and plan's --sweep and --max-points options",
    "fit_report": "fit's answer (src/fit/fit_answer.hpp) printed as text or json",
    "sweep_plan": "plan's lines for a sweep's points",
    "plan_tables": "plan's lines for the table stages it may probe",
    "section_order": "the order keys and init print the sections in",
    "study_template": "init's study template text",
    "study_template_keys": "init's first keys of a template, from the registry rows",
}

# src/cli/ files that still hold engine work, with that work: the list can only shrink.
PENDING = {}


def stem(name):
    return name.split(".")[0]


def violations(root, face=FACE, pending=PENDING):
    found = []
    cli = root / "src" / "cli"
    for top in ("src", "python", "bench"):
        for f in sorted((root / top).rglob("*")):
            if f.suffix not in (".cpp", ".hpp", ".h") or not f.is_file():
                continue
            rel = f.relative_to(root).as_posix()
            if rel.startswith("src/cli/"):
                continue
            for inc in INCLUDE.findall(f.read_text(errors="replace")):
                if any(stem(pathlib.PurePosixPath(inc).name) == p or pathlib.PurePosixPath(inc).name == p
                       for p in pending):
                    continue
                found.append(f"{rel}: includes {inc}: the engine and the module never depend on the command face; "
                             "move what it needs into the engine")
    names = sorted(f.name for f in cli.iterdir() if f.is_file()) if cli.is_dir() else []
    for name in names:
        if COMMAND.match(name) or stem(name) in face or name in pending or stem(name) in pending:
            continue
        found.append(f"src/cli/{name}: neither a command, an option reader or printer (FACE) nor listed engine "
                     "work (PENDING); put engine work in src/run, src/fit, src/compare, ...")
    for p in pending:
        if not any(n == p or stem(n) == p for n in names):
            found.append(f"PENDING names src/cli/{p}, which is gone: take it off the list")
    return found


def test_the_command_line_is_a_face():
    assert (ROOT / "src" / "cli" / "main.cpp").is_file()
    assert violations(ROOT) == []


def test_an_engine_file_including_the_face_is_found(tmp_path):
    root = scratch(tmp_path, {"src/cli/main.cpp": "int main() {}\n",
                              "src/run/run_phases.cpp": '#include "src/cli/parse_options.hpp"\n',
                              "python/spectra.cpp": '#include "src/cli/fit_report.hpp"\n'})
    found = violations(root, face={"parse_options": "", "fit_report": ""}, pending={})
    assert sorted(f.split(":")[0] for f in found) == ["python/spectra.cpp", "src/run/run_phases.cpp"]


def test_engine_work_in_the_face_is_found(tmp_path):
    root = scratch(tmp_path, {"src/cli/main.cpp": "int main() {}\n", "src/cli/run_command.cpp": "",
                              "src/cli/fit_search.cpp": "", "src/cli/fit_search.hpp": ""})
    found = violations(root, face={}, pending={})
    assert [f.split(":")[0] for f in found] == ["src/cli/fit_search.cpp", "src/cli/fit_search.hpp"]
    assert violations(root, face={}, pending={"fit_search": "the search"}) == []


def test_pending_can_only_shrink(tmp_path):
    root = scratch(tmp_path, {"src/cli/main.cpp": "int main() {}\n"})
    assert violations(root, face={}, pending={"fit_model.cpp": "the model"}) == [
        "PENDING names src/cli/fit_model.cpp, which is gone: take it off the list"]
