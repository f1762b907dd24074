#!/usr/bin/env bash
# consumer.sh: installs the built library into a temporary (non-system) prefix, then builds
# examples/minimal.c against it twice and runs both programs: with find_package from a C-only
# CMake project (static library), and with pkg-config (shared library, found at run time through
# the .pc's rpath hint, without LD_LIBRARY_PATH).
# usage: consumer.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > /dev/null
cmake -S "$src/tests/consumer" -B "$tmp/build" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$tmp/build" > /dev/null
"$tmp/build/consumer_cmake" | grep -q "balls"
echo "find_package consumer: ok"
export PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig"
# pkg-config's -lcoverage_axis picks the shared library (it links Qhull and CBC itself)
cc -std=c99 -o "$tmp/consumer_pc" "$src/examples/minimal.c" $(pkg-config --cflags --libs coverage_axis) \
  $(pkg-config --variable=rpath coverage_axis)
env -u LD_LIBRARY_PATH "$tmp/consumer_pc" | grep -q "balls"
echo "pkg-config consumer: ok"
echo "consumer: 2 passed, 0 failed"
