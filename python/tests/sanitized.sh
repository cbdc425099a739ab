#!/bin/bash
# The module's pytest suite with the module and the engine built under AddressSanitizer and UBSan, run
# in Debian's /usr/bin/python3 (itself not built with them) with clang's sanitizer runtime preloaded.
# Not part of CI (its time: a second build of the engine, and the suite at several times its speed);
# run it after changing the bindings:
#
#   python/tests/sanitized.sh                               # every test but the pip install
#   python/tests/sanitized.sh python/tests/test_module_faults.py
#
# BUILD (default build/asan-python) is configured here the first time, as the asan-ubsan preset's
# flags with the module on (the preset leaves it off) and the shared sanitizer runtime, which a module
# loaded into an uninstrumented interpreter needs. ROLLSPEC_BIN (default the werror build's) is the
# command the tests compare with. Leaks are not reported: CPython keeps its objects at exit by design.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$src/build/asan-python}
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
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
if [ $# -eq 0 ]; then
  set -- "$src/python/tests" --deselect "$src/python/tests/test_pip_install.py"
fi
LD_PRELOAD=$(clang -print-file-name=libclang_rt.asan-x86_64.so) \
  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
  ROLLSPEC_BIN=${ROLLSPEC_BIN:-$src/build/werror/rollspec} PYTHONPATH="$build/python:$src/python-post" \
  /usr/bin/python3 -m pytest -q -p no:cacheprovider "$@"
