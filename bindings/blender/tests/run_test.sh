#!/usr/bin/env bash
# run_test.sh: packs the add-on and runs tests/test_blender.py in headless Blender with a temporary
# user folder (the add-on is installed there, not in the user's Blender) and without $CA_LIBRARY
# (the add-on's bundled library is the one under test).
# usage: run_test.sh BUILD_DIR SOURCE_DIR
set -eu
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bash "$src/bindings/blender/pack.sh" "$build" "$tmp/coverage_axis_blender.zip"
export BLENDER_USER_CONFIG="$tmp/config" BLENDER_USER_SCRIPTS="$tmp/scripts"
env -u CA_LIBRARY blender -b --factory-startup --python-exit-code 1 \
  --python "$src/bindings/blender/tests/test_blender.py" -- \
  "$tmp/coverage_axis_blender.zip" "$build/coverage-axis" "$src/tests/data"
