"""The layering, read from the sources: kernels/ include only kernels/ (never src/, never a path with
'..'), and each kernel area includes only itself and the areas its CMakeLists.txt DEPENDS on, with
no cycle. `violations` runs on the real tree (none allowed) and on scratch trees that break each
rule (each must be found), so the test can fail."""
import pathlib
import re

import pytest

from source_scan import scratch

ROOT = pathlib.Path(__file__).resolve().parents[2]
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
DEPENDS = re.compile(r"rollspec_kernel_area\(\s*(\w+)(?:\s+DEPENDS((?:\s+rollspec_\w+)+))?")


def declared_areas(kernels):
    """{area: set of areas it DEPENDS on}, from each kernels/<area>/CMakeLists.txt."""
    out = {}
    for cmake in sorted(kernels.glob("*/CMakeLists.txt")):
        m = DEPENDS.search(cmake.read_text())
        if m:
            out[m.group(1)] = {d.replace("rollspec_", "") for d in (m.group(2) or "").split()}
    return out


def cycle(graph):
    """An area on a dependency cycle, or None."""
    state = {}

    def visit(a):
        state[a] = "open"
        for b in graph.get(a, ()):
            if state.get(b) == "open" or (b not in state and visit(b)):
                return True
        state[a] = "done"
        return False

    return next((a for a in graph if a not in state and visit(a)), None)


def violations(root):
    kernels = root / "kernels"
    graph = declared_areas(kernels)
    found = []
    for f in sorted(kernels.rglob("*")):
        if f.suffix not in (".hpp", ".cpp", ".h") or not f.is_file():
            continue
        area = f.relative_to(kernels).parts[0]
        for inc in INCLUDE.findall(f.read_text(errors="replace")):
            where = f"{f.relative_to(root)}: #include {inc}"
            parts = pathlib.PurePosixPath(inc).parts
            if ".." in parts:
                found.append(f"{where}: a path with '..'")
            elif parts[0] == "src":
                found.append(f"{where}: kernels never include the engine")
            elif parts[0] in ("tests", "bench", "python-post", "studies"):
                found.append(f"{where}: outside kernels/")
            elif parts[0] == "kernels" and len(parts) > 2 and parts[1] != area and parts[1] not in graph.get(area, set()):
                found.append(f"{where}: area {area} does not DEPEND on {parts[1]}")
    loop = cycle(graph)
    if loop:
        found.append(f"kernel areas depend on each other in a cycle through {loop}")
    return found


def test_the_tree_keeps_its_layers():
    assert declared_areas(ROOT / "kernels"), "no kernel area found"
    assert violations(ROOT) == []


AREAS = {"kernels/a/CMakeLists.txt": "rollspec_kernel_area(a SOURCES x.cpp)\n",
         "kernels/b/CMakeLists.txt": "rollspec_kernel_area(b DEPENDS rollspec_a SOURCES y.cpp)\n"}


@pytest.mark.parametrize("name, files, expected", [
    ("the engine", {"kernels/a/x.cpp": '#include "src/error.hpp"\n'}, "never include the engine"),
    ("the engine through ..", {"kernels/a/x.cpp": '#include "kernels/../src/error.hpp"\n'}, "'..'"),
    ("a sibling by ..", {"kernels/b/y.cpp": '#include "../a/x.hpp"\n'}, "'..'"),
    ("an undeclared area", {"kernels/a/x.cpp": '#include "kernels/b/y.hpp"\n'}, "does not DEPEND on b"),
    ("a cycle", {"kernels/a/CMakeLists.txt": "rollspec_kernel_area(a DEPENDS rollspec_b SOURCES x.cpp)\n"}, "cycle"),
])
def test_each_rule_can_fail(tmp_path, name, files, expected):
    root = scratch(tmp_path, {**AREAS, **files})
    found = violations(root)
    assert any(expected in v for v in found), f"{name}: {found}"


def test_a_clean_scratch_tree_passes(tmp_path):
    root = scratch(tmp_path, {**AREAS, "kernels/b/y.cpp": '#include "kernels/a/x.hpp"\n#include <vector>\n'})
    assert violations(root) == []
