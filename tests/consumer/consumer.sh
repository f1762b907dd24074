#!/usr/bin/env bash
# consumer.sh: installs the built library into a temporary (non-system) prefix, then builds and
# runs examples/minimal.c against it with find_package and with pkg-config (build_consumers.sh).
# usage: consumer.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > /dev/null
bash "$src/tests/consumer/build_consumers.sh" "$tmp/prefix" "$src" "$tmp"
echo "consumer: 2 passed, 0 failed"
