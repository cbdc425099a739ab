"""Sizes the house keeps, read from the sources: no file in src/, kernels/ or python/ over 500 lines and no
function over 150 lines (function extents from Universal Ctags, installed by .ci/setup). Each rule
also runs on a scratch tree that breaks it, so the test can fail."""
import pathlib
import shutil
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
MAX_FILE_LINES = 500
MAX_FUNCTION_LINES = 150
SUFFIXES = (".cpp", ".hpp", ".h")


def sources(root):
    for area in ("src", "kernels", "python"):
        for f in sorted((root / area).rglob("*")):
            if f.suffix in SUFFIXES and f.is_file():
                yield f


def long_files(root):
    out = []
    for f in sources(root):
        n = len(f.read_text(errors="replace").splitlines())
        if n > MAX_FILE_LINES:
            out.append(f"{f.relative_to(root)}: {n} lines")
    return out


def long_functions(root):
    """Functions (definitions, lambdas counted in the function that holds them) over the limit."""
    ctags = shutil.which("ctags")
    assert ctags, "Universal Ctags is missing: apt-get install universal-ctags (bash .ci/setup does)"
    files = [str(f) for f in sources(root)]
    r = subprocess.run([ctags, "--languages=C++", "--language-force=C++", "--kinds-C++=f", "--fields=+ne", "-f", "-", *files],
                       capture_output=True, text=True, check=True)
    out = []
    for row in r.stdout.splitlines():
        cols = row.split("\t")
        fields = dict(c.split(":", 1) for c in cols[3:] if ":" in c)
        if "line" in fields and "end" in fields:
            n = int(fields["end"]) - int(fields["line"]) + 1
            if n > MAX_FUNCTION_LINES:
                out.append(f"{pathlib.Path(cols[1]).relative_to(root)}: {cols[0]} {n} lines")
    return out


def test_no_file_over_500_lines():
    assert long_files(ROOT) == []


def test_no_function_over_150_lines():
    assert long_functions(ROOT) == []


def scratch(tmp_path, name, text):
    f = tmp_path / "kernels" / "area" / name
    f.parent.mkdir(parents=True)
    (tmp_path / "src").mkdir()
    f.write_text(text)
    return tmp_path


@pytest.mark.parametrize("lines,found", [(500, False), (501, True)])
def test_a_long_file_is_found(tmp_path, lines, found):
    root = scratch(tmp_path, "long.cpp", "int x;\n" * lines)
    assert bool(long_files(root)) == found


@pytest.mark.parametrize("body,found", [(147, False), (148, True)])
def test_a_long_function_is_found(tmp_path, body, found):
    # body + 3 lines: the signature, the return and the closing brace.
    text = "namespace a {\nint f(int x) {\n" + "  x += 1;\n" * body + "  return x;\n}\n}  // namespace a\n"
    root = scratch(tmp_path, "long_function.cpp", text)
    assert bool(long_functions(root)) == found, long_functions(root)
