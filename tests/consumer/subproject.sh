#!/usr/bin/env bash
# subproject.sh: the library built from source inside a parent project (subproject/): configured
# through add_subdirectory and through FetchContent, each of which must look for nothing beyond
# the library's dependencies (check_finds.py: the tool, bindings, tests and benchmarks are off by
# default when the project is not the top level) and define no tool or test target; then the
# add_subdirectory one is built (the library and examples/minimal.c only) and run.
# WORK_DIR (ctest gives one in the build folder; default: a temporary folder) is emptied first and
# kept. CMAKE_ARGs go to both configures: ctest gives its build folder's type and compilers, so that
# with ccache present (the build then goes through it) the library's compile commands are that
# folder's own (the same flags, absolute paths into the same tree) and reuse its objects. The
# caller's CCACHE_BASEDIR is left alone: paths made relative would differ between the two folders.
# usage: subproject.sh SOURCE_DIR [JOBS] [WORK_DIR] [CMAKE_ARG...]
set -eu
src=$(cd "$1" && pwd)
jobs=${2:-2}
if [ -n "${3:-}" ]; then
  tmp=$3
  rm -rf "$tmp"
  mkdir -p "$tmp"
  tmp=$(cd "$tmp" && pwd)
else
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
fi
shift $(($# < 3 ? $# : 3))
cmake_args=("$@")
if command -v ccache > /dev/null; then
  cmake_args+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
configure() {  # BUILD_DIR USE_FETCHCONTENT
  cmake -S "$src/tests/consumer/subproject" -B "$tmp/$1" -DCA_SOURCE_DIR="$src" -DUSE_FETCHCONTENT="$2" ${cmake_args[@]+"${cmake_args[@]}"} \
    --trace-expand --trace-format=json-v1 --trace-redirect="$tmp/$1.trace" > "$tmp/$1.log" 2>&1 \
    || { cat "$tmp/$1.log" >&2; exit 1; }
  python3 "$src/tests/consumer/check_finds.py" "$tmp/$1.trace" "$tmp/$1"
  targets=$(cmake --build "$tmp/$1" --target help)
  for target in coverage_axis coverage_axis_shared consumer_subproject; do
    grep -qx "\.\.\. $target" <<< "$targets" || { echo "$1: no target $target" >&2; exit 1; }
  done
  for target in coverage-axis ca_io example_c unit_tests abi_layout; do
    if grep -qx "\.\.\. $target" <<< "$targets"; then echo "$1: target $target defined" >&2; exit 1; fi
  done
}
configure fetchcontent ON
echo "FetchContent configure: ok"
configure subdirectory OFF
echo "add_subdirectory configure: ok"
cmake --build "$tmp/subdirectory" --target consumer_subproject -j "$jobs" > "$tmp/build.log" 2>&1 \
  || { tail -50 "$tmp/build.log" >&2; exit 1; }
"$tmp/subdirectory/consumer_subproject" | grep -q "balls"
echo "add_subdirectory consumer: ok"
echo "subproject: 3 passed, 0 failed"
