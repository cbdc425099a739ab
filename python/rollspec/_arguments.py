"""One-line TypeErrors for arguments pybind11 cannot convert to a function's C++ types.

pybind11's own message is every signature of the function and the call's arguments, over several lines,
without saying which argument failed; the module's other errors are one line in the command's style,
"NAME = VALUE: PROBLEM; allowed: WHAT". wrap() puts a function behind a call that turns pybind11's message
into that line, the argument found from the signature line pybind11 writes at the head of the docstring
(its types: float, int, str, bool, List[str], os.PathLike, Optional[...] of them; handle and object take
anything). The call is otherwise the function's: the same arguments, answer, docstring and errors."""
import ast
import functools
import numbers
import os

_MISMATCH = "incompatible function arguments"


def _parameters(function):
    """[(name, type text, has a default)] of the signature line "name(a: float, *, b: int = 1) -> dict"."""
    head = function.__doc__.splitlines()[0]
    head = head[head.index("("):head.rindex(")") + 1]
    a = ast.parse("def f" + head + ": ...").body[0].args
    positional = a.posonlyargs + a.args
    defaults = [False] * (len(positional) - len(a.defaults)) + [True] * len(a.defaults)
    out = [(p.arg, ast.unparse(p.annotation) if p.annotation else "", d) for p, d in zip(positional, defaults)]
    out += [(p.arg, ast.unparse(p.annotation) if p.annotation else "", d is not None)
            for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    return out, len(positional)


def _a(kind):
    if kind.startswith("Optional["):
        return _a(kind[len("Optional["):-1]) + " or None"
    return ("an " if kind[:1] in "aeiou" else "a ") + kind


def _text(value):
    r = repr(value).replace("\n", " ")
    return r if len(r) <= 60 else r[:57] + "..."


def _problem(kind, value):
    """Why pybind11 refuses `value` for the C++ type written `kind`, or None where it takes it."""
    if kind.startswith("Optional["):
        return None if value is None else _problem(kind[len("Optional["):-1], value)
    if kind == "float":
        ok = not isinstance(value, (str, bytes)) and (hasattr(type(value), "__float__") or
                                                      hasattr(type(value), "__index__"))
        return None if ok else "not a number"
    if kind == "int":
        if isinstance(value, (float, str, bytes)) or not (isinstance(value, numbers.Integral) or
                                                         hasattr(type(value), "__index__")):
            return "not a whole number"
        v = int(value)
        if not -2 ** 63 <= v < 2 ** 64:
            return "out of the 64-bit range"
        return None  # a negative value for an unsigned parameter: said by the caller, when nothing else fails
    if kind == "bool":
        return None if value is None or hasattr(type(value), "__bool__") else "not a bool"
    if kind == "str":
        return None if isinstance(value, (str, bytes)) else "not a str"
    if kind == "os.PathLike":
        if not (isinstance(value, (str, bytes)) or hasattr(value, "__fspath__")):
            return "not a path"
        return "a name with an embedded null byte" if "\0" in os.fsdecode(value) else None
    if kind == "List[str]":
        if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
            return "not a list of str"
        return None if all(isinstance(v, (str, bytes)) for v in value) else "holds an item that is not a str"
    return None


def _refusal(qualname, function, args, kwargs):
    """The one line saying which argument of `qualname` pybind11 could not convert, and why."""
    params, npositional = _parameters(function)
    names = [p[0] for p in params]
    if len(args) > npositional:
        return f"{qualname}(): {len(args)} positional arguments; allowed: at most {npositional} ({', '.join(names)})"
    given = dict(zip(names, args))
    for k, v in kwargs.items():
        if k not in names:
            return f"{qualname}(): {k}: no such argument; allowed: {', '.join(names)}"
        if k in given:
            return f"{qualname}(): {k}: given twice, by position and by name"
        given[k] = v
    for name, kind, has_default in params:
        if name not in given and not has_default:
            return f"{qualname}(): {name}: missing; allowed: {_a(kind)}"
    for name, kind, _ in params:
        if name in given:
            problem = _problem(kind, given[name])
            if problem:
                what = _a(type(given[name]).__name__)
                return f"{name} = {_text(given[name])}: {problem} ({what}); allowed: {_a(kind)}"
    for name, kind, _ in params:  # every type fits: a negative whole number for an unsigned one
        v = given.get(name)
        if "int" in kind and isinstance(v, numbers.Integral) and not isinstance(v, bool) and v < 0:
            return f"{name} = {v}: negative; allowed: a whole number >= 0"
    types = ", ".join(f"{n}: {type(v).__name__}" for n, v in given.items())
    return f"{qualname}(): arguments ({types}) that do not convert; allowed: {function.__doc__.splitlines()[0]}"


def wrap(function, qualname):
    """`function` (a pybind11 function) with its argument TypeErrors on one line naming the argument."""
    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as e:
            if _MISMATCH not in str(e).split("\n", 1)[0]:
                raise
        message = _refusal(qualname, function, args, kwargs)
        raise (ValueError if "embedded null byte" in message else TypeError)(message)  # as the module's own

    return call


def wrap_module(module, name):
    """Every public function of `module`, and every method of its classes, wrapped in place."""
    builtin = type(len)
    for attr, value in list(vars(module).items()):
        if attr.startswith("_"):
            continue
        if isinstance(value, builtin):
            setattr(module, attr, wrap(value, f"{name}.{attr}"))
        elif isinstance(value, type):
            for m, v in list(vars(value).items()):
                if m.startswith("_") and m != "__call__":
                    continue
                if isinstance(v, staticmethod) and isinstance(v.__func__, builtin):
                    setattr(value, m, staticmethod(wrap(v.__func__, f"{name}.{attr}.{m}")))
                elif isinstance(getattr(v, "__func__", None), builtin):  # pybind11's instancemethod
                    setattr(value, m, wrap(v.__func__, f"{name}.{attr}.{m}"))
