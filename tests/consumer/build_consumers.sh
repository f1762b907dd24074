#!/usr/bin/env bash
# build_consumers.sh: builds examples/minimal.c against the library installed under PREFIX, twice,
# and runs both programs: with find_package from a C-only CMake project (static library; the
# package must bring the C++ runtime and the dependencies itself), and with pkg-config (shared
# library, found at run time through the .pc's rpath hint, without LD_LIBRARY_PATH). Each must
# have used PREFIX's copy, not one installed elsewhere on the system.
# usage: build_consumers.sh PREFIX SOURCE_DIR WORK_DIR
set -eu
prefix=$1
src=$2
work=$3
cmake -S "$src/tests/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > /dev/null
grep -qx "coverage_axis_DIR:PATH=$prefix/lib/cmake/coverage_axis" "$work/build/CMakeCache.txt" \
  || { echo "find_package found another coverage_axis:" >&2; grep coverage_axis_DIR "$work/build/CMakeCache.txt" >&2; exit 1; }
cmake --build "$work/build" > /dev/null
"$work/build/consumer_cmake" | grep -q "balls"
echo "find_package consumer: ok"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
# pkg-config's -lcoverage_axis picks the shared library (it links Qhull and CBC itself)
cc -std=c99 -o "$work/consumer_pc" "$src/examples/minimal.c" $(pkg-config --cflags --libs coverage_axis) \
  $(pkg-config --variable=rpath coverage_axis)
loaded=$(env -u LD_LIBRARY_PATH ldd "$work/consumer_pc" | awk '$1 ~ /^libcoverage_axis/ {print $3}')
[ "$(realpath "$(dirname "$loaded")")" = "$(realpath "$prefix/lib")" ] \
  || { echo "pkg-config consumer loads '$loaded', not the one in $prefix/lib" >&2; exit 1; }
env -u LD_LIBRARY_PATH "$work/consumer_pc" | grep -q "balls"
echo "pkg-config consumer: ok"
