"""The type stubs (rollspec/*.pyi) name every function of the module with the module's own parameters: the
same names, in the same order, positional or keyword-only alike, with the same defaults (read from the
signature line pybind11 writes at the head of each docstring, or a Python function's own signature), and
every class with its static methods and properties."""
import ast
import inspect
import os

import pytest

import rollspec

STUBS = os.path.join(os.path.dirname(__file__), "..", "rollspec")


def parameters(function):
    """[(name, keyword_only, default or None)] of a def node; a default is a literal, compared by value."""
    a = function.args
    positional = a.posonlyargs + a.args
    defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
    out = [(p.arg, False, d) for p, d in zip(positional, defaults)]
    out += [(p.arg, True, d) for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    return [(name, kw, None if d is None else ast.literal_eval(d)) for name, kw, d in out]


def module_signature(function):
    function = getattr(function, "__wrapped__", function)  # rollspec._arguments.wrap's call: the function's own
    if inspect.isfunction(function):  # a function of the package's Python (rollspec.studies.open)
        return [(p.name, p.kind == p.KEYWORD_ONLY, None if p.default is p.empty else p.default)
                for p in inspect.signature(function).parameters.values()]
    head = function.__doc__.splitlines()[0]  # "name(x: handle, *, segment: int = 1024) -> dict"
    return parameters(ast.parse("def " + head + ": ...").body[0])


def is_property(node):
    return any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list)


@pytest.mark.parametrize("name", ["spectra", "contact", "surfaces", "studies"])
def test_each_stub_matches_the_module(name):
    module = getattr(rollspec, name)
    with open(os.path.join(STUBS, name + ".pyi")) as f:
        body = ast.parse(f.read()).body
    stub = {}
    for n in body:  # of @overload variants the first, whose defaults are the function's
        if isinstance(n, ast.FunctionDef):
            stub.setdefault(n.name, parameters(n))
    classes = {n.name: n for n in body if isinstance(n, ast.ClassDef)}
    public = {n for n in dir(module) if not n.startswith("_") and callable(getattr(module, n))}
    functions = {n for n in public if not isinstance(getattr(module, n), type)}
    assert set(stub) == functions
    assert set(classes) == public - functions
    for function in functions:
        assert stub[function] == module_signature(getattr(module, function)), function
    # A class's stub: its properties and its methods (self included), as the class has them.
    for name, node in classes.items():
        cls = getattr(module, name)
        defs = [n for n in node.body if isinstance(n, ast.FunctionDef)]
        properties = {n for n in vars(cls) if isinstance(vars(cls)[n], property) and not n.startswith("_")}
        assert {n.name for n in defs if is_property(n)} == properties, name
        methods = {n for n in vars(cls) if not n.startswith("_") and n not in properties} | (
            {"__call__"} if "__call__" in vars(cls) else set())
        assert {n.name for n in defs if not is_property(n) and n.name != "__getattr__"} == methods, name
        for n in defs:
            if not is_property(n) and n.name != "__getattr__":
                assert parameters(n) == module_signature(getattr(cls, n.name)), (name, n.name)
