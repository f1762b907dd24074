#!/usr/bin/env bash
# run_test.sh: runs tests/test_distributed.py with Debian's python3 (python3-distributed,
# python3-cryptography, python3-numpy), the binding from the source tree and the built library.
# usage: run_test.sh BUILD_DIR SOURCE_DIR
set -eu
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
export CA_LIBRARY="$build/libcoverage_axis.so"
export PYTHONPATH="$src/bindings/python:$src/examples/distributed${PYTHONPATH:+:$PYTHONPATH}"
exec /usr/bin/python3 "$src/examples/distributed/tests/test_distributed.py" "$build/coverage-axis" "$src/tests/data"
