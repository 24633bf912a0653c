#!/usr/bin/env bash
# The consumer test: install acodrill into a temporary prefix, build
# tests/consumer against it with find_package, run it.
#   run.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1"; src="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/tests/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
out=$("$work/build/consumer")
echo "$out"
[ "$out" = "holes 10 length 10.000" ]
