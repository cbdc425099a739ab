"""Reading the C++ of src/ for the source tests (test_choice_literals.py, test_scene_literals.py,
test_keys_once.py): the code with comments blanked and literals kept, each file by its path from the repository root, the
comparisons with a string literal, and scratch trees the tests break each rule in."""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOKENS = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|//[^\n]*|/\*.*?\*/', re.S)
LITERAL = r'"((?:\\.|[^"\\\n])*)"'
# A string literal compared: `x == "v"`, `"v" != x`, `x.compare("v")`, `x.find("v")`, `x.rfind("v")`.
COMPARISONS = [re.compile(r'(?:==|!=)\s*' + LITERAL),
               re.compile(LITERAL + r'\s*(?:==|!=)'),
               re.compile(r'\.\s*(?:compare|find|rfind)\s*\(\s*' + LITERAL)]


def code_only(text):
    """The text with comments blanked (their line breaks kept, so line numbers hold) and string/char
    literals kept (a literal may hold //)."""
    return TOKENS.sub(lambda m: m.group(0) if m.group(0)[0] in "\"'" else " " + "\n" * m.group(0).count("\n"), text)


def calls(text, name):
    """The argument text of each call `name(...)`, parentheses matched outside literals."""
    out = []
    for m in re.finditer(r"\b" + name + r"\s*\(", text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            lit = TOKENS.match(text, i)
            if lit:
                i = lit.end()
                continue
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        out.append(text[m.end():i - 1])
    return out


def sources(root):
    """(path from root, code_only text) of every C++ file under src/, in path order."""
    for f in sorted((root / "src").rglob("*")):
        if f.suffix in (".hpp", ".cpp", ".h") and f.is_file():
            yield pathlib.PurePosixPath(f.relative_to(root).as_posix()), code_only(f.read_text(errors="replace"))


def compared_literals(line):
    """The string literals a line compares (COMPARISONS), in order."""
    return [m.group(1) for pattern in COMPARISONS for m in pattern.finditer(line)]


def scratch(tmp_path, files):
    """A tree of `files` ({path: text}) under tmp_path, for a test to break a rule in."""
    for name, text in files.items():
        p = tmp_path / name
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text)
    return tmp_path
