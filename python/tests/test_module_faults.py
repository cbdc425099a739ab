"""The module's fault suite, generated: every public function and class method of rollspec.contact,
.spectra, .surfaces and .studies is listed from the module itself (and its stub, which gives each
parameter's type), called once with valid arguments (SAMPLES: a function without an entry fails, so a new
function is covered by default) and then with one parameter replaced by each hostile value of its kind:

  an array   complex, object, str and bool dtypes; a strided view and a Fortran-ordered copy (the answer
             of the C-contiguous array, or a clear error); NaN; inf; empty; 1xN and Nx1 (and 2-D where 1-D
             is expected); a 0-d array; a list (the array's answer, or a clear error); an extra axis
  a file     missing; a directory; an empty file; a text file that is not the format; a number; a name
             with a NUL byte (refused as such: the C library would open the name cut at it, another file)
  any other  a value of the wrong type; values out of range (NaN and +-1e300 for a float, -1 and 2^65 for
             an int, an unknown word for a str, an unknown key for a list of --set texts)

Each case returns, or raises ValueError, TypeError, OSError or KeyError with a one-line message (a
TypeError naming the argument). The cases
of one function run in a forked child (the module imported once, as python-post/tests/forked_run.py does
for the programs), which reports each case as it ends: a crash or a hang fails the test naming the case,
and the cases after it run in a new child."""
import ast
import configparser
import hashlib
import inspect
import json
import os
import selectors
import shutil
import signal
import time
import traceback

import numpy as np
import pytest

import rollspec

SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
STUBS = os.path.join(os.path.dirname(__file__), "..", "rollspec")
SUBMODULES = ("contact", "spectra", "studies", "surfaces")
ALLOWED = ("ValueError", "TypeError", "OSError", "KeyError")
CASE_SECONDS = 60  # a case still running after this is a hang

PROFILES = [os.path.abspath(os.path.join(SOURCE, "studies", "data", "seed001-profiles", "beam-r-%02d.csv" % i))
            for i in (1, 2)]
SIGNAL = os.path.abspath(os.path.join(SOURCE, "studies", "data", "example-signal.csv"))
# The random oscillator, short records (a run of 8 realisations takes a fraction of a second).
FAST = ["signal.duration=4", "signal.sample_rate=1024", "spectrum.segment=2048", "spectrum.band_min=20",
        "spectrum.band_max=200", "study.realisations=8"]
TABLE = ["surface.nx=16", "surface.ny=16", "stiffness.realisations=1", "stiffness.steps=2",
         "stiffness.approach_max=0.4e-6"]


# --- the module's functions and their stubs ---------------------------------------------------------------

def module_callables():
    """{"contact.solve": callable, "surfaces.ProfilePsd.line": unbound method, ...} from the module."""
    out = {}
    for name in SUBMODULES:
        module = getattr(rollspec, name)
        for attr in dir(module):
            value = getattr(module, attr)
            if attr.startswith("_") or not callable(value):
                continue
            if not isinstance(value, type):
                out[f"{name}.{attr}"] = value
                continue
            for m, v in vars(value).items():
                if (not m.startswith("_") or m == "__call__") and not isinstance(v, property):
                    out[f"{name}.{attr}.{m}"] = getattr(value, m)
    return out


INSTANCE_METHODS = set()


def stub_parameters():
    """{key: [(name, annotation text, keyword_only)]} of every function and class method in the stubs (of
    @overload variants the last; a method's self left out)."""
    out = {}
    for name in SUBMODULES:
        with open(os.path.join(STUBS, name + ".pyi")) as f:
            body = ast.parse(f.read()).body

        def add(key, node, method):
            if any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list):
                return
            static = any(isinstance(d, ast.Name) and d.id == "staticmethod" for d in node.decorator_list)
            a = node.args
            params = [(p.arg, ast.unparse(p.annotation) if p.annotation else "", False)
                      for p in a.posonlyargs + a.args]
            params += [(p.arg, ast.unparse(p.annotation) if p.annotation else "", True) for p in a.kwonlyargs]
            if method and not static:
                INSTANCE_METHODS.add(key)
                params = params[1:]
            out[key] = params  # of @overload variants the last, the most general

        for n in body:
            if isinstance(n, ast.FunctionDef):
                add(f"{name}.{n.name}", n, False)
            elif isinstance(n, ast.ClassDef):
                for m in n.body:
                    if isinstance(m, ast.FunctionDef) and m.name != "__getattr__":
                        add(f"{name}.{n.name}.{m.name}", m, True)
    return out


def module_parameter_names(function):
    """The parameter names of a pybind11 function (its docstring's signature line) or a Python function."""
    function = getattr(function, "__wrapped__", function)
    if inspect.isfunction(function):
        return [p for p in inspect.signature(function).parameters]
    head = function.__doc__.splitlines()[0]
    a = ast.parse("def " + head[head.index("("):].join([head[:head.index("(")].split(".")[-1], ""]) + ": ...")
    a = a.body[0].args
    names = [p.arg for p in a.posonlyargs + a.args + a.kwonlyargs]
    return names[1:] if names and names[0] == "self" else names


CALLABLES = module_callables()
STUB = stub_parameters()


def test_every_function_and_method_has_a_stub_with_its_parameters():
    assert set(STUB) == set(CALLABLES)
    for key, function in CALLABLES.items():
        assert [p[0] for p in STUB[key]] == module_parameter_names(function), key


# --- valid arguments, one call per function -------------------------------------------------------------

class Inputs:
    """The files and objects the samples call with; objects of the module are made in the child."""

    def __init__(self, root):
        self.root = root
        self.oscillator = str(root / "oscillator.ini")
        self.table_study = str(root / "table.ini")
        self.result = str(root / "model.h5")
        self.psd_table = str(root / "own.csv")
        parser = configparser.ConfigParser(inline_comment_prefixes=("#",), interpolation=None)
        parser.read(self.oscillator)
        self.sections = {s: dict(parser[s]) for s in parser.sections()}
        self._profile_psd = None
        self.parent = False

    def profile_psd(self):
        if self.parent:
            return None
        if self._profile_psd is None:
            self._profile_psd = rollspec.surfaces.read_profiles(PROFILES, extension="zero")
        return self._profile_psd


def table_psd():
    k = np.logspace(3, 6, 24)
    return k, 1e-20 * (k / 1e3) ** -2.5


def heights_2d():
    y, x = np.mgrid[0:16, 0:16]
    return 1e-6 * (1.0 + np.sin(0.7 * x) * np.cos(1.3 * y) + 0.1 * x)


def signal_1d():
    return np.sin(np.arange(512) * 0.3) + 0.01 * np.cos(np.arange(512) * 2.1) ** 3


# key: inputs -> (positional arguments, keyword arguments); a method's first argument is its object.
SAMPLES = {
    "contact.solve": lambda i: ((heights_2d().max() - heights_2d(), 1e-6), dict(e_star=1e11, approach=2e-7)),
    "contact.ball_gap": lambda i: ((1e-3, 1e-6, 8, 6), {}),
    "contact.effective_modulus": lambda i: ((2e11, 0.3, 7e10, 0.33), {}),
    "contact.stiffness_table": lambda i: ((i.table_study,), dict(set=TABLE)),
    "contact.tables": lambda i: ((i.table_study,), dict(set=TABLE)),
    "contact.Table.read": lambda i: ((i.stiffness_table_file(),), {}),
    "spectra.welch": lambda i: ((signal_1d(), 1000.0), dict(segment=64)),
    "spectra.bands": lambda i: ((signal_1d(), 1000.0), dict(segment=64, band_min=20.0, band_max=400.0)),
    "spectra.read_measurement": lambda i: ((SIGNAL,), {}),
    "studies.Study.from_file": lambda i: ((i.oscillator,), {}),
    "studies.Study.from_text": lambda i: ((open(i.oscillator).read(),), dict(path=i.oscillator)),
    "studies.Study.from_dict": lambda i: ((i.sections,), {}),
    "studies.run": lambda i: ((i.oscillator, str(i.root / "run-out.h5")), dict(set=FAST)),
    "studies.plan": lambda i: ((i.oscillator,), dict(set=FAST)),
    "studies.compare": lambda i: ((i.result, i.psd_table), dict(measured_averages=16)),
    # A narrow range and few runs: a hostile value the fit accepts runs a whole fit.
    "studies.fit": lambda i: ((i.oscillator, i.psd_table), dict(vary="force.level=0.5:2", measured_averages=16,
                                                                set=FAST + ["study.realisations=16"])),
    "studies.open": lambda i: ((i.result,), dict(group="psd")),
    "surfaces.line": lambda i: (table_psd() + (1e-6, 256), dict(seed=7, extension="zero")),
    "surfaces.isotropic": lambda i: (table_psd() + (2e-6, 16), dict(seed=7, extension="zero")),
    "surfaces.profile_psd": lambda i: ((signal_1d() * 1e-6, 1e-6), {}),
    "surfaces.read_profiles": lambda i: ((PROFILES,), dict(extension="zero")),
    "surfaces.read_profile": lambda i: ((PROFILES[0],), {}),
    "surfaces.ProfilePsd.__call__": lambda i: ((i.profile_psd(), np.array([1e4, 1e5, 1e6])), {}),
    "surfaces.ProfilePsd.line": lambda i: ((i.profile_psd(), 1e-6, 256), dict(seed=7)),
    "surfaces.ProfilePsd.isotropic": lambda i: ((i.profile_psd(), 2e-6, 16), dict(seed=7)),
}


def stiffness_table_file(self):
    """The stiffness table the fixture's study built (Table.read's valid file)."""
    (name,) = [n for n in os.listdir(self.root / "tables") if n.startswith("stiffness-")]
    return str(self.root / "tables" / name)


Inputs.stiffness_table_file = stiffness_table_file


# --- hostile values by the parameter's kind --------------------------------------------------------------

def kind_of(name, annotation):
    if "ArrayLike" in annotation or "NDArray" in annotation or "ndarray" in annotation:
        return "array"
    if "PathLike" in annotation or "_Path" in annotation or name in ("path", "paths"):
        return "paths" if annotation.startswith(("List", "Sequence")) else "path"
    return "other"


def base_type(annotation):
    a = annotation
    while a.startswith("Optional["):
        a = a[len("Optional["):-1]
    return a


def array_cases(a):
    """[(label, value, same)] for the sample array a: same says the answer must be a's (or an error)."""
    first = np.unravel_index(0, a.shape)
    nan, inf = a.copy(), a.copy()
    nan[first], inf[first] = np.nan, np.inf
    wide = np.zeros(a.shape[:-1] + (2 * a.shape[-1],))
    wide[..., ::2] = a
    cases = [("complex dtype", a.astype(complex), False), ("object dtype", a.astype(object), False),
             ("str dtype", a.astype(str), False), ("bool dtype", a > a.mean(), False),
             ("strided view", wide[..., ::2], True), ("NaN", nan, False), ("inf", inf, False),
             ("-inf", -inf, False), ("empty", np.zeros((0,) * a.ndim), False),
             ("0-d", np.array(a.flat[0]), False), ("list", a.tolist(), True), ("extra axis", a[None], False),
             ("float32", a.astype(np.float32), False), ("int", np.rint(a * 1e6).astype(np.int64), False)]
    if a.ndim == 2:
        cases += [("Fortran order", np.asfortranarray(a), True), ("1xN", a[:1].copy(), False),
                  ("Nx1", a[:, :1].copy(), False), ("1-D", a.ravel(), False), ("2x2", a[:2, :2].copy(), False)]
    else:
        cases += [("1xN", a.reshape(1, -1), False), ("Nx1", a.reshape(-1, 1), False),
                  ("one value", a[:1].copy(), False), ("two values", a[:2].copy(), False),
                  ("reversed view", a[::-1].copy()[::-1], True)]
    return cases


def path_cases(root):
    directory = root / "a-directory"
    empty = root / "empty.h5"
    text = root / "not-the-format.h5"
    directory.mkdir(exist_ok=True)
    empty.write_bytes(b"")
    text.write_text("this is not an HDF5, CSV, INI or sound file\n\x00\x01\x02\n")
    return [("missing file", str(root / "no-such-file.h5")), ("a directory", str(directory)),
            ("an empty file", str(empty)), ("a text file", str(text)), ("a NUL byte", str(root / "a\0b.h5")),
            ("a number", 3)]


def other_cases(annotation):
    """[(label, value)]: a wrong type and values out of range, by the stub's type."""
    t = base_type(annotation)
    if t == "bool":
        return [("wrong type", "yes"), ("None", None)]
    if t == "float":
        return [("wrong type", "one"), ("NaN", float("nan")), ("-1e300", -1e300), ("1e300", 1e300)]
    if t == "int":
        return [("wrong type", "one"), ("a float", 1.5), ("-1", -1), ("2^65", 2 ** 65)]
    if t == "str":
        return [("wrong type", 3), ("unknown word", "no-such-value"), ("empty", "")]
    if t in ("_Sets", "List[str]"):
        return [("wrong type", 3), ("a list of numbers", [1, 2]), ("unknown key", ["no_such.key=1"]),
                ("one string", "study.seed=1"), ("a dict of objects", {"study.seed": object()})]
    if t.startswith("Mapping"):
        return [("wrong type", 3), ("unknown section", {"no_such": {"key": 1}}), ("not a dict", {"study": 3}),
                ("a line break", {"study": {"description": "a\nb"}})]
    if "Sequence[float]" in t:  # measured_averages: one count or one per measurement
        return [("wrong type", "one"), ("NaN", float("nan")), ("0", 0.0), ("a list with NaN", [float("nan")]),
                ("a list of words", ["one"])]
    if "Sequence[str]" in t:  # column: a name or names
        return [("wrong type", 3), ("unknown name", "no-such-column"), ("a list of numbers", [1, 2])]
    if t.startswith("Union") and "Study" in t:
        return [("wrong type", 3)]
    raise AssertionError(f"no hostile values for the type {annotation!r}: add them to other_cases")


def cases_of(key, inputs):
    """[(label, make)] of the function `key`: make() -> (args, kwargs, same), `same` True where the answer
    must be the valid call's."""
    sample = SAMPLES[key]
    shift = 1 if key in INSTANCE_METHODS else 0  # a method's object comes first

    def replaced(index, name, value, same=False):
        def make():
            args, kwargs = sample(inputs)
            args, kwargs = list(args), dict(kwargs)
            v = value(args, kwargs) if callable(value) else value
            if index + shift < len(args):
                args[index + shift] = v
            else:
                kwargs[name] = v
            return args, kwargs, same
        return make

    out = [("valid", lambda: (*[list(x) if isinstance(x, tuple) else x for x in sample(inputs)], False))]
    for index, (name, annotation, _) in enumerate(STUB[key]):
        kind = kind_of(name, annotation)
        if kind == "array":
            def sample_array(args, kwargs, index=index, name=name):
                return np.asarray(args[index + shift] if index + shift < len(args) else kwargs[name], dtype=float)
            inputs.parent = True  # the sample's arrays only: no module object is made in the test process
            try:
                ndim = sample_array(*sample(inputs)).ndim
            finally:
                inputs.parent = False
            for label, _, same in array_cases(np.zeros((3,) * ndim)):
                def hostile(args, kwargs, label=label, sample_array=sample_array):
                    return dict((c[0], c[1]) for c in array_cases(sample_array(args, kwargs)))[label]
                out.append((f"{name}: {label}", replaced(index, name, hostile, same)))
        elif kind in ("path", "paths"):
            for label, value in path_cases(inputs.root):
                v = [value] if kind == "paths" and not isinstance(value, int) else value
                out.append((f"{name}: {label}", replaced(index, name, v)))
            if kind == "paths":
                out.append((f"{name}: an empty list", replaced(index, name, [])))
            if "Optional" in annotation or "Union" in annotation:
                out.append((f"{name}: None", replaced(index, name, None)))
        else:
            for label, value in other_cases(annotation):
                out.append((f"{name}: {label}", replaced(index, name, value)))
    return out


# --- running cases in a forked child -------------------------------------------------------------------------

def digest(value):
    """A JSON-able fingerprint of an answer: arrays by dtype, shape and bytes; objects by their properties."""
    if isinstance(value, np.ndarray):
        return [str(value.dtype), list(value.shape), hashlib.sha1(np.ascontiguousarray(value).tobytes()).hexdigest()]
    if isinstance(value, dict):
        return {str(k): digest(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [digest(v) for v in value]
    if isinstance(value, float):
        return repr(value)
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if hasattr(value, "__dict__") or type(value).__module__.startswith("rollspec"):
        props = sorted(n for n, v in vars(type(value)).items() if isinstance(v, property) and n not in ("path",
                                                                                                          "status"))
        return {n: digest(getattr(value, n)) for n in props} or repr(type(value))
    return repr(value)


def call(key, args, kwargs):
    parts = key.split(".")
    target = getattr(rollspec, parts[0])
    for p in parts[1:]:
        target = getattr(target, p)
    return target(*args, **kwargs)


def run_in_child(key, cases, start, write):
    """In the fork: cases[start:], each reported as a JSON line; never returns."""
    code = 0
    try:
        for sig in (signal.SIGTERM, signal.SIGPIPE):
            signal.signal(sig, signal.SIG_DFL)
        os.chdir(str(INPUTS_ROOT[0]))
        valid = None
        for n in range(start, len(cases)):
            label, make = cases[n]
            os.write(write, (json.dumps({"start": n}) + "\n").encode())
            report = {"case": n}
            try:
                args, kwargs, same = make()
                answer = call(key, args, kwargs)
                report["returned"] = True
                if same:
                    if valid is None:
                        a, k, _ = cases[0][1]()
                        valid = digest(call(key, a, k))
                    report["same"] = digest(answer) == valid
            except BaseException as e:  # noqa: B902 -- any exception is reported, the suite judges it
                names = [c.__name__ for c in type(e).__mro__]
                message = e.args[0] if isinstance(e, KeyError) and e.args else str(e)
                report.update(raised=names, message=str(message), where=traceback.format_exc(limit=-3))
            os.write(write, (json.dumps(report) + "\n").encode())
    except BaseException:
        code = 3
    finally:
        os._exit(code)


INPUTS_ROOT = [None]


def run_cases(key, cases):
    """{case index: report}, the child's JSON lines; a child that dies or hangs reports its case as such."""
    reports = {}
    start = 0
    while start < len(cases):
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(read)
            run_in_child(key, cases, start, write)
        os.close(write)
        buffer, current, deadline = b"", None, time.monotonic() + CASE_SECONDS
        with selectors.DefaultSelector() as sel:
            sel.register(read, selectors.EVENT_READ)
            while True:
                if not sel.select(timeout=max(0.0, deadline - time.monotonic())):
                    os.kill(pid, signal.SIGKILL)
                    reports[current] = {"case": current, "hang": True}
                    break
                chunk = os.read(read, 65536)
                if not chunk:
                    break
                buffer += chunk
                *lines, buffer = buffer.split(b"\n")
                for line in lines:
                    r = json.loads(line)
                    if "start" in r:
                        current, deadline = r["start"], time.monotonic() + CASE_SECONDS
                    else:
                        reports[r["case"]] = r
                        current = None
        os.close(read)
        _, status = os.waitpid(pid, 0)
        if current is None:  # every case reported (one left unreported is said by the test)
            break
        if current not in reports:
            how = f"signal {os.WTERMSIG(status)}" if os.WIFSIGNALED(status) else f"exit {os.WEXITSTATUS(status)}"
            reports[current] = {"case": current, "died": how}
        start = current + 1
    return reports


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    """The study files, a small result and its own mean as a PSD table, and a stiffness table, made by a
    forked child (the test process keeps OpenMP and FFTW unstarted, so its forks may start them)."""
    root = tmp_path_factory.mktemp("module-faults")
    shutil.copy(os.path.join(SOURCE, "studies", "random-oscillator.ini"), root / "oscillator.ini")
    shutil.copy(os.path.join(SOURCE, "studies", "seed002-table.ini"), root / "table.ini")
    INPUTS_ROOT[0] = root
    i = Inputs(root)

    def prepare():
        import h5py
        rollspec.studies.run(i.oscillator, i.result, set=FAST)
        with h5py.File(i.result) as f:
            freq, psd = f["/psd/frequency"][...], f["/psd/mean"][...][-1]
        with open(i.psd_table, "w") as out:
            out.write("frequency_hz,psd\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(freq, psd)))
        rollspec.contact.stiffness_table(i.table_study, set=TABLE)

    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            prepare()
            code = 0
        except BaseException:
            traceback.print_exc()
        finally:
            os._exit(code)
    _, status = os.waitpid(pid, 0)
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0, "preparing the inputs failed"
    return i


@pytest.mark.parametrize("key", sorted(CALLABLES))
def test_every_hostile_argument_returns_or_raises_one_line(key, inputs):
    assert key in SAMPLES, f"{key}: no valid arguments in SAMPLES; add one call, and its hostile cases follow"
    cases = cases_of(key, inputs)
    reports = run_cases(key, cases)
    log = os.environ.get("ROLLSPEC_MODULE_FAULTS_LOG")  # every case's outcome, one JSON line each
    if log:
        with open(log, "a") as f:
            for n, (label, _) in enumerate(cases):
                f.write(json.dumps({"function": key, **reports.get(n, {}), "case": label}) + "\n")
    bad = []
    for n, (label, _) in enumerate(cases):
        r = reports.get(n)
        if r is None:
            bad.append(f"{label}: no report")
        elif r.get("hang"):
            bad.append(f"{label}: still running after {CASE_SECONDS} s")
        elif "died" in r:
            bad.append(f"{label}: the process died ({r['died']})")
        elif n == 0 and not r.get("returned"):
            bad.append(f"valid arguments raised {r['raised'][0]}: {r['message']}")
        elif r.get("returned"):
            if r.get("same") is False:
                bad.append(f"{label}: returned an answer other than the C-contiguous array's")
        elif not set(r["raised"]) & set(ALLOWED):
            bad.append(f"{label}: raised {r['raised'][0]}: {r['message']}\n{r['where']}")
        elif not r["message"].strip() or "\n" in r["message"].strip():
            bad.append(f"{label}: {r['raised'][0]} message not one line: {r['message']!r}")
        elif label.endswith(": a NUL byte") and not ("null byte" in r["message"] or "\\x00" in r["message"]):
            # the C library would open the name cut at the NUL: another file
            bad.append(f"{label}: not refused as a name with a NUL byte: {r['message']!r}")
        elif "TypeError" in r["raised"] and label.split(":")[0] not in r["message"]:
            bad.append(f"{label}: the TypeError does not name the argument: {r['message']!r}")
    assert not bad, f"{key}, {len(bad)} of {len(cases)} cases:\n" + "\n".join(bad)
