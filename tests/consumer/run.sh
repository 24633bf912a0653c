#!/usr/bin/env bash
# The consumer test: install acodrill into a temporary prefix, build
# tests/consumer against it with find_package, run it.
#   run.sh BUILD_DIR SOURCE_DIR [CXX_FLAGS]   (flags: the sanitizers the libraries were built with)
set -euo pipefail
build="$1"; src="$2"; flags="${3:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/tests/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" >/dev/null
cmake --build "$work/build" >/dev/null
out=$("$work/build/consumer")
echo "$out"
[ "$(echo "$out" | head -n 1)" = "holes 10 length 10.000" ]
echo "$out" | grep -q "^tools 1 time "
echo "$out" | grep -q "^job holes 10 tools 1 program "
