#!/usr/bin/env bash
# Builds the rollspec documentation into BUILD_DIR/html (default build/docs), warnings as errors.
#   bash docs/build.sh [BUILD_DIR]        binary: $ROLLSPEC_BIN, else build/werror/rollspec, else build/release/rollspec
# The reference (commands, options, study keys, exit codes, result-file schema) is generated from the
# binary by docs/generate_reference.py, and the benchmark figures from bench/goals.json and the bench
# scripts' records (bench/records/; $ROLLSPEC_BENCH_RECORDS names another directory), on every build;
# every link inside the built site is then checked (docs/check_links.py).
# BUILD_DIR is a folder of the script's own: a new or empty one, or one it built before (it holds the
# file .rollspec-docs, which the script writes). Only src/, doctrees/ and html/ in it are ever replaced;
# any other folder is refused (exit 73) and left as it is.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
fail() { echo "docs/build.sh: $2" >&2; exit "$1"; }
[ "$#" -le 1 ] || fail 64 "expected at most one argument, BUILD_DIR; got $#"
[ "${1-x}" != "" ] || fail 64 "BUILD_DIR is empty; allowed: a new or empty folder, or one docs/build.sh built"
[ ! -L "${1:-$repo/build/docs}" ] || fail 73 "BUILD_DIR ${1:-$repo/build/docs} is a symbolic link; allowed: a new folder, or one docs/build.sh built"
out="$(realpath -m -- "${1:-$repo/build/docs}")"
marker="$out/.rollspec-docs"
if [ -n "${ROLLSPEC_BIN:-}" ]; then
  bin="$(realpath -m -- "$ROLLSPEC_BIN")"
  [ -f "$bin" ] && [ -x "$bin" ] || fail 66 "ROLLSPEC_BIN=$ROLLSPEC_BIN is not an executable rollspec binary"
else
  bin=""
  for b in "$repo/build/werror/rollspec" "$repo/build/release/rollspec"; do
    if [ -f "$b" ] && [ -x "$b" ]; then bin="$b"; break; fi
  done
  [ -n "$bin" ] || fail 66 "no rollspec binary in build/werror or build/release; build one (cmake --preset release && cmake --build --preset release) or set ROLLSPEC_BIN"
fi
# The folder must be the script's own: never the sources, never a folder of the user's.
case "$out/" in
  "$repo/"|"$repo/docs/"*|"$repo/src/"*|"$repo/kernels/"*|"$repo/python-post/"*|"$repo/bench/"*|"$repo/studies/"*|"$repo/tests/"*)
    fail 73 "BUILD_DIR $out is the repository or inside its sources; allowed: a new folder, e.g. build/docs" ;;
esac
case "$repo/" in "$out/"*) fail 73 "BUILD_DIR $out holds the repository; allowed: a new folder, e.g. build/docs" ;; esac
if [ -e "$out" ]; then
  [ -d "$out" ] || fail 73 "BUILD_DIR $out exists and is not a folder; allowed: a new folder, or one docs/build.sh built"
  # A folder built before the marker existed holds only src/ (with conf.py), doctrees/ and html/.
  own=1
  for e in "$out"/* "$out"/.[!.]* "$out"/..?*; do
    [ -e "$e" ] || [ -L "$e" ] || continue
    case "${e##*/}" in doctrees|html) ;; src) [ -f "$e/conf.py" ] || own=0 ;; *) own=0 ;; esac
  done
  if [ ! -f "$marker" ] && [ "$own" = 0 ]; then
    fail 73 "BUILD_DIR $out holds files docs/build.sh did not write; allowed: a new or empty folder, or one it built (it holds .rollspec-docs)"
  fi
  for d in src doctrees html; do
    if [ -L "$out/$d" ] || { [ -e "$out/$d" ] && [ ! -d "$out/$d" ]; }; then
      fail 73 "$out/$d is not a folder docs/build.sh wrote; move it away"
    fi
  done
fi
python=/usr/bin/python3
# The module rollspec built beside the binary: the Python reference documents it, and the gallery runs its
# studies in-process through it (rollspec_post.run does when ROLLSPEC_BIN is unset; what else runs the
# command finds this binary first on PATH). Without it, the gallery runs the binary.
module="$(dirname "$bin")/python"
sphinx_env=(env ROLLSPEC_BIN="$bin")
if [ -d "$module/rollspec" ]; then
  export PYTHONPATH="$module${PYTHONPATH:+:$PYTHONPATH}"
  sphinx_env=(env -u ROLLSPEC_BIN PATH="$(dirname "$bin"):$PATH")
fi
export PYTHONDONTWRITEBYTECODE=1   # nothing written into the sources (docs/, bench/)
mkdir -p -- "$out" || fail 73 "cannot create BUILD_DIR $out"
touch -- "$marker" || fail 73 "cannot write $marker"
rm -rf -- "$out/src"   # a folder of this script's own (checked above), never one named by the user
cp -r -- "$repo/docs" "$out/src"
ln -s -- "$repo" "$out/src/_repo"
"$python" "$repo/docs/generate_reference.py" --bin "$bin" --out "$out/src" \
  --records "${ROLLSPEC_BENCH_RECORDS:-$repo/bench/records}"
"${sphinx_env[@]}" ROLLSPEC_SOURCE="$repo" MPLBACKEND=Agg "$python" -m sphinx -W --keep-going -q -b html -d "$out/doctrees" "$out/src" "$out/html"
"$python" "$repo/docs/check_links.py" "$out/html"
echo "docs: $out/html/index.html"
