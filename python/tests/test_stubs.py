"""The type stubs (rollspec/*.pyi) name every function of the module with the module's own parameters: the
same names, in the same order, positional or keyword-only alike, with the same defaults (read from the
signature line pybind11 writes at the head of each docstring)."""
import ast
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
    head = function.__doc__.splitlines()[0]  # "name(x: handle, *, segment: int = 1024) -> dict"
    return parameters(ast.parse("def " + head + ": ...").body[0])


@pytest.mark.parametrize("name", ["spectra", "contact", "surfaces", "studies"])
def test_each_stub_matches_the_module(name):
    module = getattr(rollspec, name)
    with open(os.path.join(STUBS, name + ".pyi")) as f:
        stub = {n.name: parameters(n) for n in ast.parse(f.read()).body if isinstance(n, ast.FunctionDef)}
    functions = {n for n in dir(module) if not n.startswith("_") and callable(getattr(module, n))}
    assert set(stub) == functions
    for function in functions:
        assert stub[function] == module_signature(getattr(module, function)), function
