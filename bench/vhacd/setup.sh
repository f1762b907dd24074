#!/usr/bin/env bash
# setup.sh: builds BUILD_DIR/vhacd_driver, V-HACD 4.1 for bench_proxies (vhacd_driver.cpp). Installs
# the npm package vhacd-js (BSD-3-Clause; its include/VHACD.h is V-HACD 4.1's single header) under
# BUILD_DIR/npm on first use, as tests/e2e/rig.sh installs gltf-validator, copies the header to
# BUILD_DIR/vhacd/VHACD.h with one patch, and compiles the driver against it. Nothing of V-HACD is
# kept in this repository.
# The patch: IVHACD declares a second GetConvexHull (`ConvexHull const* GetConvexHull(uint32_t)
# const`, pure virtual) that VHACDAsyncImpl does not override, so the header does not compile
# natively; one forwarding override in that class (to its inner VHACDImpl) makes it build.
# Optional: without npm, the network or a compiler it says why and exits 1; bench_proxies then
# prints that V-HACD is missing and measures the rest.
# usage: bench/vhacd/setup.sh BUILD_DIR [CXX]
set -euo pipefail
build=${1:?usage: setup.sh BUILD_DIR [CXX]}
cxx=${2:-${CXX:-c++}}
here="$(cd "$(dirname "$0")" && pwd)"
version=0.0.1
npm_dir="$build/npm"
header="$npm_dir/node_modules/vhacd-js/include/VHACD.h"
driver="$build/vhacd_driver"

if [ -x "$driver" ] && [ "$driver" -nt "$here/vhacd_driver.cpp" ] && [ "$driver" -nt "$here/setup.sh" ]; then
  exit 0
fi
if [ ! -f "$header" ]; then
  command -v npm > /dev/null || { echo "vhacd setup: npm is missing (scripts/install-deps.sh installs it)" >&2; exit 1; }
  npm install --no-audit --no-fund --silent --prefix "$npm_dir" "vhacd-js@$version" > /dev/null ||
    { echo "vhacd setup: npm could not install vhacd-js@$version" >&2; exit 1; }
fi
grep -q 'VHACD_VERSION_MAJOR 4' "$header" && grep -q 'VHACD_VERSION_MINOR 1' "$header" ||
  { echo "vhacd setup: $header is not V-HACD 4.1" >&2; exit 1; }

mkdir -p "$build/vhacd"
awk '
  /^class VHACDAsyncImpl / { in_class = 1 }
  in_class && !done && /uint32_t GetNConvexHulls\(\) const override final;/ {
    print "    ConvexHull const* GetConvexHull(const uint32_t index) const override final { return m_VHACD.GetConvexHull(index); }"
    print ""
    done = 1
  }
  { print }
  END { if (!done) exit 1 }
' "$header" > "$build/vhacd/VHACD.h" || { echo "vhacd setup: the patch did not apply to $header" >&2; exit 1; }

"$cxx" -std=c++17 -O2 -DNDEBUG -w -pthread -I "$build/vhacd" "$here/vhacd_driver.cpp" -o "$driver.tmp" ||
  { echo "vhacd setup: $cxx could not build the driver" >&2; exit 1; }
mv "$driver.tmp" "$driver"
echo "vhacd setup: built $driver (V-HACD 4.1 from vhacd-js@$version)" >&2
