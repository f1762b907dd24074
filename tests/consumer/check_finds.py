#!/usr/bin/env python3
"""check_finds.py: whether a CMake configure looked for nothing beyond the library's dependencies.

Reads the configure's trace (cmake --trace-expand --trace-format=json-v1 --trace-redirect=TRACE)
and its CMakeCache.txt. The library may look for Eigen3, Qhull, CBC (pkg-config module cbc) and
nanoflann's header, with Threads and PkgConfig as plumbing; CMake's own modules may look for
compilers and tools. Anything else (a find_package, a pkg-config module, or a find_path,
find_library, find_program or find_file outside CMake's modules, or a path entry in the cache)
is printed, one line each ("trace: find_package(assimp)", "cache: assimp_DIR"), and fails the
check; so does a missing one of the library's own finds (a trace that was not read as meant).

usage: check_finds.py TRACE BUILD_DIR
"""
import json
import os
import re
import sys

PACKAGES = {"Eigen3", "Qhull", "PkgConfig", "Threads"}
PKG_MODULES = {"cbc"}
FIND_RESULTS = {"NANOFLANN_INCLUDE_DIR"}
# path entries of the cache that the allowed finds and CMake itself leave
CACHE_PATHS = {"Eigen3_DIR", "Qhull_DIR", "NANOFLANN_INCLUDE_DIR", "PKG_CONFIG_EXECUTABLE"}
CACHE_PREFIXES = ("CMAKE_", "FETCHCONTENT_", "pkgcfg_lib_CBC_")

PKG_KEYWORDS = {"REQUIRED", "QUIET", "NO_CMAKE_PATH", "NO_CMAKE_ENVIRONMENT_PATH", "IMPORTED_TARGET",
                "GLOBAL"}
CMAKE_MODULES = re.compile(r"/share/cmake(-[0-9.]+)?/Modules/")


def trace_finds(path):
    """The finds of a JSON trace, as (kind, name) pairs."""
    finds = set()
    with open(path) as f:
        for line in f:
            entry = json.loads(line)
            cmd = entry.get("cmd", "").lower()
            args = entry.get("args", [])
            if not args:
                continue
            if cmd in ("find_package", "find_dependency"):
                finds.add(("find_package", args[0]))
            elif cmd in ("pkg_check_modules", "pkg_search_module"):
                for spec in args[1:]:
                    if spec not in PKG_KEYWORDS:
                        finds.add(("pkg-config", re.split(r"[<>=]", spec)[0]))
            elif cmd in ("find_path", "find_library", "find_program", "find_file"):
                if not CMAKE_MODULES.search(entry.get("file", "")):
                    finds.add((cmd, args[0]))
    return finds


def allowed(kind, name):
    if kind == "find_package":
        return name in PACKAGES
    if kind == "pkg-config":
        return name in PKG_MODULES
    return name in FIND_RESULTS


def cache_paths(build_dir):
    """Names of the cache's PATH and FILEPATH entries."""
    names = []
    with open(os.path.join(build_dir, "CMakeCache.txt")) as f:
        for line in f:
            m = re.match(r"([A-Za-z0-9_.+-]+):(PATH|FILEPATH)=", line)
            if m:
                names.append(m.group(1))
    return names


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    finds = trace_finds(sys.argv[1])
    problems = ["trace: %s(%s)" % f for f in sorted(finds) if not allowed(*f)]
    for name in sorted(PACKAGES - {"PkgConfig", "Threads"}):
        if ("find_package", name) not in finds:
            problems.append("trace: no find_package(%s) (the library's own)" % name)
    for name in sorted(PKG_MODULES):
        if ("pkg-config", name) not in finds:
            problems.append("trace: no pkg-config module %s (the library's own)" % name)
    for name in sorted(FIND_RESULTS):
        if ("find_path", name) not in finds:
            problems.append("trace: no find_path(%s) (the library's own)" % name)
    for name in cache_paths(sys.argv[2]):
        if name not in CACHE_PATHS and not name.startswith(CACHE_PREFIXES):
            problems.append("cache: " + name)
    for p in problems:
        print(p)
    if problems:
        return 1
    print("only the library's dependencies: %s" % ", ".join("%s(%s)" % f for f in sorted(finds)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
