#!/usr/bin/env bash
# install-deps.sh: installs the Debian packages the build needs, only those that are missing.
# Runs apt-get as root (or through sudo when available). Safe to run again.
# usage: install-deps.sh [EXTRA_PACKAGE...]
set -euo pipefail
# The library needs the first line. The binding tests add: python3 with numpy, setuptools and pip
# (Python binding, its pip install, the layout checks, the CLI's tests), cargo (Rust binding;
# Debian's cargo brings rustc), mono-mcs, mono-runtime and libmono-system-core4.0-cil (C# binding:
# compiler, runtime, LINQ).
packages=(build-essential cmake pkg-config libeigen3-dev libnanoflann-dev coinor-libcbc-dev libqhull-dev doctest-dev
          python3 python3-numpy python3-setuptools python3-pip cargo mono-mcs mono-runtime libmono-system-core4.0-cil)
# the rig's test (tests/e2e/rig.sh) runs node and installs npm's gltf-validator under the build
# folder: Debian's nodejs and npm, unless node and npm are there already (another distribution's
# nodejs brings its own npm, which Debian's npm package would conflict with)
command -v node > /dev/null || packages+=(nodejs)
command -v npm > /dev/null || packages+=(npm)
# ccache: the Makefile compiles through it, so a rebuild and the consumer_subproject test (the
# library built again inside a parent project, with the same compile commands) reuse the objects
command -v ccache > /dev/null || packages+=(ccache)
# the command-line tool (examples/): libcli11-dev (arguments), nlohmann-json3-dev (JSON, glTF),
# libstb-dev (PNG), libtinygltf-dev (glTF reader) and libassimp-dev (FBX, DAE, 3DS, ...)
packages+=(libcli11-dev nlohmann-json3-dev libstb-dev libtinygltf-dev libassimp-dev)
# extra packages a make target needs (make test-blender: blender; make test-distributed:
# python3-distributed python3-cryptography; make fuzz: clang libclang-rt-14-dev)
packages+=("$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
