"""Every command's --help prints each default as its text (`(=0.05)`), never as the binary double Boost
would print without one (`(=0.050000000000000003)`); `run --help` names the schema the result file carries."""
import re

import h5py
import pytest

from conftest import oscillator_study, run, study_result


def commands():
    r = run(["--help"])
    block = r.stdout.split("commands:\n")[1].split("\n\n")[0]
    return re.findall(r"^  ([a-z]+) ", block, re.M)


@pytest.mark.parametrize("command", commands())
def test_defaults_are_printed_as_written(command):
    r = run([command, "--help"])
    assert r.returncode == 0, r.stderr
    for default in re.findall(r"\(=([^)]*)\)", r.stdout):
        try:
            value = float(default)
        except ValueError:
            continue  # a word: table, hann, ...
        assert default == f"{value:g}", f"rollspec {command} --help prints the default {default!r}"


def test_the_commands_with_numeric_defaults_are_seen():
    shown = {c: re.findall(r"\(=([^)]*)\)", run([c, "--help"]).stdout) for c in commands()}
    assert {"0.05", "10", "inf"} <= set(shown["compare"]) and {"1024", "0.5"} <= set(shown["psd"])


def test_run_help_names_the_schema_a_result_carries(tmp_path):
    out = study_result(oscillator_study(tmp_path), tmp_path, "r")
    with h5py.File(out, "r") as f:
        version = f.attrs["schema_version"]
    version = version.decode() if isinstance(version, bytes) else version
    assert f"(HDF5, schema {version}:" in run(["run", "--help"]).stdout
