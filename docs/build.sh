#!/usr/bin/env bash
# Builds the rollspec documentation into BUILD_DIR/html (default build/docs), warnings as errors.
#   bash docs/build.sh [BUILD_DIR]        binary: $ROLLSPEC_BIN, else build/werror/rollspec
# The reference (commands, options, study keys, exit codes, result-file schema) is generated from the
# binary by docs/generate_reference.py, and the benchmark figures from bench/goals.json and the bench
# scripts' records (bench/records/; $ROLLSPEC_BENCH_RECORDS names another directory), on every build;
# every link inside the built site is then checked (docs/check_links.py).
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
out="$(realpath -m "${1:-$repo/build/docs}")"
bin="$(realpath -m "${ROLLSPEC_BIN:-$repo/build/werror/rollspec}")"
[ -x "$bin" ] || { echo "docs/build.sh: no rollspec binary at $bin (build it, or set ROLLSPEC_BIN)" >&2; exit 66; }
python=/usr/bin/python3
export PYTHONDONTWRITEBYTECODE=1   # nothing written into the sources (docs/, bench/)
rm -rf "$out/src"
mkdir -p "$out"
cp -r "$repo/docs" "$out/src"
ln -s "$repo" "$out/src/_repo"
"$python" "$repo/docs/generate_reference.py" --bin "$bin" --out "$out/src" \
  --records "${ROLLSPEC_BENCH_RECORDS:-$repo/bench/records}"
ROLLSPEC_SOURCE="$repo" ROLLSPEC_BIN="$bin" MPLBACKEND=Agg "$python" -m sphinx -W --keep-going -q -b html -d "$out/doctrees" "$out/src" "$out/html"
"$python" "$repo/docs/check_links.py" "$out/html"
echo "docs: $out/html/index.html"
