#!/usr/bin/env bash
# deb.sh: the Debian package of `make package` (cpack on BUILD_DIR, written to a scratch folder):
# its files (libraries, header, CMake package, pkg-config file, the tool; no Python package), its
# Depends (the development packages the static library and the CMake package need, and the package
# of every shared library the packaged binaries load), apt's acceptance of it (a simulated
# install), then, unpacked into a scratch root with dpkg-deb -x, the tool run and examples/minimal.c
# built and run against it with find_package and with pkg-config (build_consumers.sh).
# usage: deb.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "$*" >&2; exit 1; }

cpack --config "$build/CPackConfig.cmake" -B "$tmp/pkg" > "$tmp/cpack.log" 2>&1 || { cat "$tmp/cpack.log" >&2; exit 1; }
debs=("$tmp"/pkg/*.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || fail "cpack wrote ${#debs[@]} packages: ${debs[*]}"
deb=${debs[0]}
echo "package: $(basename "$deb"), $(dpkg-deb -f "$deb" Installed-Size) KiB installed"

dpkg-deb -x "$deb" "$tmp/root"
for f in usr/lib/libcoverage_axis.a usr/lib/libcoverage_axis.so usr/lib/libcoverage_axis.so.3 \
         usr/include/coverage_axis.h usr/lib/cmake/coverage_axis/coverage_axisConfig.cmake \
         usr/lib/cmake/coverage_axis/coverage_axisConfigVersion.cmake \
         usr/lib/cmake/coverage_axis/coverage_axisTargets.cmake usr/lib/pkgconfig/coverage_axis.pc \
         usr/bin/coverage-axis; do
  [ -e "$tmp/root/$f" ] || fail "not in the package: /$f"
done
if dpkg-deb -c "$deb" | grep -q '\.py$'; then fail "the package holds Python files"; fi
echo "files: ok"

# the package names of Depends (alternatives, versions and architectures dropped)
depends=$(dpkg-deb -f "$deb" Depends | tr ',|' '\n\n' | sed 's/(.*//; s/:.*//; s/ //g')
needs() { grep -qx "$1" <<< "$depends" || fail "Depends lacks $1 ($2): $(dpkg-deb -f "$deb" Depends)"; }
for p in coinor-libcbc-dev libqhull-dev pkg-config; do needs "$p" "static library, CMake package"; done
owner() {  # the package holding a library file; /lib and /usr/lib are one folder on Debian 12
  local path=$1 alt
  case $path in /usr/*) alt=${path#/usr} ;; *) alt=/usr$path ;; esac
  { dpkg -S "$path" 2>/dev/null || dpkg -S "$alt" 2>/dev/null; } | grep -v '^diversion' | head -1 | cut -d: -f1
}
for bin in usr/bin/coverage-axis usr/lib/libcoverage_axis.so.3; do
  for soname in $(readelf -d "$tmp/root/$bin" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
    path=$(ldd "$tmp/root/$bin" | awk -v s="$soname" '$1 == s {print $3}')
    [ -n "$path" ] || fail "$bin: $soname not found"
    pkg=$(owner "$path")
    [ -n "$pkg" ] || fail "$bin: $path belongs to no package"
    needs "$pkg" "$soname for $bin"
  done
done
echo "Depends: ok ($(dpkg-deb -f "$deb" Depends))"

apt-get install --simulate "$deb" > "$tmp/apt.log" 2>&1 || { cat "$tmp/apt.log" >&2; fail "apt refuses the package"; }
echo "apt install (simulated): ok"

"$tmp/root/usr/bin/coverage-axis" --version | grep -q . || fail "the packaged tool does not run"
bash "$src/tests/consumer/build_consumers.sh" "$tmp/root/usr" "$src" "$tmp"
echo "deb: 5 passed, 0 failed"
