"""rollspec_post's modules import each other without a cycle (imports inside functions count: they are
cycles in the design all the same). `cycle` runs on the real package (none allowed) and on a scratch
package that has one, so the test can fail."""
import ast
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[1] / "rollspec_post"


def imports(package):
    """{module: set of the package's modules it imports}, from the sources."""
    modules = {p.stem for p in package.glob("*.py")}
    graph = {}
    for path in package.glob("*.py"):
        found = set()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                found |= {node.module.split(".")[0]} if node.module else {a.name for a in node.names}
            elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith(package.name + "."):
                found.add(node.module.split(".")[1])
            elif isinstance(node, ast.Import):
                found |= {a.name.split(".")[1] for a in node.names if a.name.startswith(package.name + ".")}
        graph[path.stem] = found & modules - {path.stem}
    return graph


def cycle(graph):
    """One import cycle as a list of modules, or None."""
    state, path = {}, []

    def visit(m):
        state[m] = "open"
        path.append(m)
        for d in sorted(graph[m]):
            if state.get(d) == "open":
                return path[path.index(d):] + [d]
            if d not in state:
                found = visit(d)
                if found:
                    return found
        state[m] = "done"
        path.pop()
        return None

    for m in sorted(graph):
        if m not in state:
            found = visit(m)
            if found:
                return found
    return None


def test_the_package_has_no_import_cycle():
    graph = imports(ROOT)
    assert {"result_file", "safe_output", "post_error"} <= set(graph)
    assert cycle(graph) is None, " -> ".join(cycle(graph))


def test_a_cycle_is_found(tmp_path):
    package = tmp_path / "rollspec_post"
    package.mkdir()
    (package / "a.py").write_text("from .b import x\n")
    (package / "b.py").write_text("def f():\n    from rollspec_post.c import y\n")
    (package / "c.py").write_text("import rollspec_post.a\n")
    assert cycle(imports(package)) == ["a", "b", "c", "a"]
    (package / "c.py").write_text("import os\n")
    assert cycle(imports(package)) is None
