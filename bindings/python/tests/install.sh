#!/usr/bin/env bash
# install.sh: the Python package as a user installs it, outside the source tree:
# 1. `cmake --install` into a temporary prefix: the package imports from there and finds the
#    installed library by the path written at install time (no $CA_LIBRARY);
# 2. `pip install --no-build-isolation --no-index` of bindings/python (offline, system setuptools).
# Each skeletonizes the bundled torus and checks b1 = 1.
# usage: install.sh BUILD_DIR PYTHON_SOURCE_DIR PYTHON
set -eu
build=$1
src=$(cd "$2" && pwd)
py=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > /dev/null
pkg=$(dirname "$(find "$tmp/prefix" -path '*/coverage_axis/_install_path.py')")
cd "$tmp"
check='
import sys, coverage_axis as ca
v, f = [], []
for line in open(sys.argv[1]):
    p = line.split()
    if p and p[0] == "v": v.append([float(x) for x in p[1:4]])
    if p and p[0] == "f": f.append([int(x.split("/")[0]) - 1 for x in p[1:4]])
sk = ca.skeletonize(v, f)
print(ca.load_library(), len(sk), "balls, b1", sk.stats["betti1"])
assert sk.stats["betti1"] == 1, sk.stats
'
torus=$src/../../tests/data/torus.obj
out=$(env -u CA_LIBRARY PYTHONPATH="$(dirname "$pkg")" "$py" -c "$check" "$torus")
echo "installed: $out"
case "$out" in "$tmp/prefix/lib/"*) ;; *) echo "the installed package did not load the installed library" >&2; exit 1 ;; esac

cp -r "$src" "$tmp/src"
rm -rf "$tmp/src/tests" "$tmp/src/coverage_axis/_install_path.py"
"$py" -m pip install --quiet --no-build-isolation --no-index --target "$tmp/pip" "$tmp/src" > "$tmp/pip.log" 2>&1 ||
  { cat "$tmp/pip.log" >&2; exit 1; }
out=$(CA_LIBRARY="$tmp/prefix/lib/libcoverage_axis.so" PYTHONPATH="$tmp/pip" "$py" -c "$check" "$torus")
echo "pip: $out"
echo "python_install: 2 passed, 0 failed"
