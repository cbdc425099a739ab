#!/bin/bash
# The module's pytest suite with the module built under AddressSanitizer and UBSan, run in Debian's
# /usr/bin/python3 (itself not built with them) with clang's sanitizer runtime preloaded. Not part of
# CI (its time); run it after changing the bindings:
#
#   python/tests/sanitized.sh                               # every test but the pip install
#   python/tests/sanitized.sh python/tests/test_module_faults.py
#
# Default: BUILD (default build/asan-python) configured here the first time with the asan-ubsan preset's
# flags and the module on (the preset leaves it off), the module and the engine instrumented, and the
# shared sanitizer runtime, which a module loaded into an uninstrumented interpreter needs (a second
# build of the engine: long on two cores). BINDINGS_ONLY=1: only python/*.cpp compiled with the
# sanitizers, linked with the werror build's engine archives (WERROR, default build/werror, built
# first), into build/asan-bindings: minutes, and the binding layer checked (the engine's heap use
# still goes through the sanitizer's malloc, but its own accesses are not instrumented).
# ROLLSPEC_BIN (default the werror build's) is the command the tests compare with, run without the
# sanitizer runtime. Leaks are not
# reported: CPython keeps its objects at exit by design.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$src/build/asan-python}
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
werror=${WERROR:-$src/build/werror}
fail() { echo "sanitized.sh: $1" >&2; exit 73; }
# BUILD is configured and written into: a new or empty folder, or a build folder of these sources (its
# CMakeCache.txt names them), never a folder or file of the user's.
if [ "${BINDINGS_ONLY:-0}" != 1 ] && { [ -e "$build" ] || [ -L "$build" ]; }; then
  { [ -d "$build" ] && [ ! -L "$build" ]; } ||
    fail "BUILD $build is not a folder; allowed: a new or empty folder, or a build folder of $src"
  if [ -n "$(ls -A -- "$build")" ] && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$src" "$build/CMakeCache.txt" 2>/dev/null; then
    fail "BUILD $build holds files that are not a build of $src; allowed: a new or empty folder, or a build folder of these sources"
  fi
fi
if [ "${BINDINGS_ONLY:-0}" = 1 ]; then
  build=$src/build/asan-bindings
  mkdir -p "$build/obj" "$build/python/rollspec"
  # The werror build's compile and link lines of the module, with clang and the sanitizers instead of
  # gcc -O3 -Werror.
  /usr/bin/python3 - "$werror" "$build" "$flags" <<'EOF'
import json, os, shlex, subprocess, sys
from concurrent.futures import ThreadPoolExecutor
werror, build, flags = sys.argv[1:]
objects = []
for c in json.load(open(os.path.join(werror, "compile_commands.json"))):
    if "/python/" not in c["file"] or not c["file"].endswith(".cpp"):
        continue
    args = shlex.split(c["command"])
    o = args.index("-o")
    out = os.path.join(build, "obj", os.path.basename(c["file"]) + ".o")
    args[o + 1] = out
    args = ["clang++"] + [a for a in args[1:] if a not in ("-O3", "-Werror")] + shlex.split(flags) + [
        "-O1", "-gline-tables-only"]
    objects.append((out, args, c["directory"]))
with ThreadPoolExecutor(2) as pool:  # two at a time, as the presets build
    list(pool.map(lambda o: subprocess.run(o[1], cwd=o[2], check=True), objects))
objects = [o[0] for o in objects]
link = shlex.split(open(os.path.join(werror, "python/CMakeFiles/rollspec_python.dir/link.txt")).read())
o = link.index("-o")
module = os.path.join(build, "python", "rollspec", os.path.basename(link[o + 1]))
rest = [a for a in link[o + 2:] if not a.endswith(".cpp.o")]
subprocess.run(["clang++", "-fsanitize=address,undefined", "-shared-libasan", "-shared", "-o", module, *objects,
                *rest, "-lstdc++"], cwd=os.path.join(werror, "python"), check=True)
EOF
  cp "$src"/python/rollspec/*.py "$src"/python/rollspec/*.pyi "$src"/python/rollspec/py.typed "$build/python/rollspec/"
else
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$src" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
      "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
      "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_C_FLAGS=$flags" \
      "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" \
      "-DCMAKE_MODULE_LINKER_FLAGS=-fsanitize=address,undefined -shared-libasan" \
      "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=address,undefined -shared-libasan" \
      -DROLLSPEC_PYTHON_MODULE=ON -DROLLSPEC_TESTS=OFF -DROLLSPEC_BENCH=OFF -DROLLSPEC_FUZZ=OFF
  fi
  cmake --build "$build" --target rollspec_python -j2
fi
# The command the tests compare with runs without the preloaded runtime (the werror command with it
# hung in a run here, its threads waiting on a futex).
real_bin=${ROLLSPEC_BIN:-$werror/rollspec}
mkdir -p "$build"
printf '#!/bin/sh\nunset LD_PRELOAD\nexec "%s" "$@"\n' "$real_bin" > "$build/rollspec-unsanitized"
chmod +x "$build/rollspec-unsanitized"
if [ $# -eq 0 ]; then
  set -- "$src/python/tests" --deselect "$src/python/tests/test_pip_install.py"
fi
LD_PRELOAD=$(clang -print-file-name=libclang_rt.asan-x86_64.so) \
  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
  ROLLSPEC_BIN=$build/rollspec-unsanitized PYTHONPATH="$build/python:$src/python-post" \
  /usr/bin/python3 -m pytest -q -p no:cacheprovider "$@"
