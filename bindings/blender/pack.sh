#!/usr/bin/env bash
# pack.sh: builds the installable add-on zip: coverage_axis_blender/ with the Python binding
# (bindings/python/coverage_axis) and the built shared library bundled inside it, where the
# binding looks first after $CA_LIBRARY.
# usage: pack.sh BUILD_DIR OUT.zip
set -eu
here=$(cd "$(dirname "$0")" && pwd)
lib=$(readlink -f "$1/libcoverage_axis.so")
out=$(readlink -f "$(dirname "$2")")/$(basename "$2")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/coverage_axis_blender/coverage_axis"
cp "$here"/coverage_axis_blender/*.py "$tmp/coverage_axis_blender/"
cp "$here"/../python/coverage_axis/*.py "$tmp/coverage_axis_blender/coverage_axis/"
rm -f "$tmp/coverage_axis_blender/coverage_axis/_install_path.py"
cp "$lib" "$tmp/coverage_axis_blender/coverage_axis/libcoverage_axis.so.3"  # .3: the SOVERSION (ABI)
rm -f "$out"
(cd "$tmp" && python3 -m zipfile -c "$out" coverage_axis_blender)
echo "add-on: $out"
