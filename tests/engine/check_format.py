#!/usr/bin/python3
"""The C++ of src/, kernels/, tests/ and python/ as .clang-format says (`clang-format --dry-run -Werror`): prints
each drifting line as clang-format reports it and exits 1; exits 77 (CTest: skipped) with one line if
clang-format is not installed. The tree is formatted with Debian 12's clang-format 14 (package
clang-format, which .ci/setup installs); fix a drift with `clang-format -i FILE`.

usage: check_format.py SOURCE_DIR"""
import pathlib
import shutil
import subprocess
import sys

SUFFIXES = {".cpp", ".hpp", ".h", ".cc"}


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    if not root.is_dir():  # a file, a FIFO or a device: refused in one line, never read
        print(f"{root}: not a folder; give the repository's root (the folder with src/, kernels/ and tests/)",
              file=sys.stderr)
        return 66
    tool = shutil.which("clang-format")
    if not tool:
        print("clang-format not found: the format check is skipped (Debian: apt-get install clang-format)")
        return 77
    style = f"--style=file:{root / '.clang-format'}"
    # The check must be able to fail: a line .clang-format would change is reported (a style file that is
    # empty or ignored, or a clang-format without -Werror, would pass everything).
    probe = subprocess.run([tool, "--dry-run", "-Werror", style, "--assume-filename=probe.cpp"], input="int  x ;\n",
                           capture_output=True, text=True)
    if probe.returncode == 0:
        print(f"{tool} {style} reports no drift in 'int  x ;': this check could not fail")
        return 1
    files = sorted(str(p) for d in ("src", "kernels", "tests", "python") for p in (root / d).rglob("*")
                   if p.suffix in SUFFIXES and p.is_file())
    if not files:
        print(f"{root}: no C++ files under src/, kernels/ or tests/", file=sys.stderr)
        return 1
    r = subprocess.run([tool, "--dry-run", "-Werror", style, *files],
                       capture_output=True, text=True)
    if r.returncode != 0:
        drifting = sorted({line.split(":")[0] for line in r.stderr.splitlines() if ": error: " in line})
        print(r.stderr, end="")
        print(f"{len(drifting)} of {len(files)} files drift from .clang-format: clang-format -i " + " ".join(
            str(pathlib.Path(f).relative_to(root)) for f in drifting))
        return 1
    version = subprocess.run([tool, "--version"], capture_output=True, text=True).stdout.strip()
    print(f"{len(files)} files as .clang-format says ({version})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
