#!/usr/bin/env bash
# library_only.sh: configures the repository with the tool, the bindings, the tests and the
# benchmarks off, in a scratch build folder, and checks (check_finds.py, on the configure's trace
# and cache) that it looked for nothing beyond the library's dependencies. Then the same
# configure with the tool on, which must be caught looking for assimp and tinygltf.
# usage: library_only.sh SOURCE_DIR
set -eu
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
configure() {  # BUILD_DIR TOOLS
  cmake -S "$src" -B "$tmp/$1" -DCA_BUILD_TOOLS="$2" -DCA_BUILD_BINDINGS=OFF -DCA_BUILD_TESTS=OFF \
    -DCA_BUILD_BENCH=OFF --trace-expand --trace-format=json-v1 --trace-redirect="$tmp/$1.trace" > "$tmp/$1.log" 2>&1 \
    || { cat "$tmp/$1.log" >&2; exit 1; }
}
configure library OFF
python3 "$src/tests/consumer/check_finds.py" "$tmp/library.trace" "$tmp/library"
echo "library-only configure: ok"
configure tools ON
if python3 "$src/tests/consumer/check_finds.py" "$tmp/tools.trace" "$tmp/tools" > "$tmp/tools.out"; then
  echo "the configure with the tool passed the check" >&2; exit 1
fi
for finding in "trace: find_package(assimp)" "trace: find_path(TINYGLTF_INCLUDE_DIR)" "cache: assimp_DIR"; do
  grep -qxF "$finding" "$tmp/tools.out" || { echo "not caught: $finding" >&2; cat "$tmp/tools.out" >&2; exit 1; }
done
echo "configure with the tool: caught ($(wc -l < "$tmp/tools.out") finds beyond the library's)"
echo "library_only: 2 passed, 0 failed"
