#!/usr/bin/env python3
"""check_version.py: the version lives in one place, the public header (CA_VERSION_*, CA_ABI_VERSION, CA_SOVERSION).
Everything that states or reports a version must agree with it: the tool's --version, the shared
library's SOVERSION, the pkg-config file, the .deb's version, the Python package (its manifest and
what version() reports from the built library), the Rust crates, the Julia package and the Blender
add-on. CMake reads the header; the manifests that need a literal are checked here.

usage: check_version.py SOURCE_DIR BUILD_DIR TOOL PYTHON
"""
import os
import re
import subprocess
import sys


def main():
    src, build, tool, python = sys.argv[1:5]
    header = open(os.path.join(src, "include", "coverage_axis.h")).read()

    def define(name):
        m = re.search(r"^#define CA_%s +(\d+)" % name, header, re.M)
        if not m:
            sys.exit("check_version: CA_%s not found in the header" % name)
        return m.group(1)

    version = ".".join(define(p) for p in ("VERSION_MAJOR", "VERSION_MINOR", "VERSION_PATCH"))
    abi = define("ABI_VERSION")
    soversion = define("SOVERSION")
    failed, passed = [], 0

    def expect(what, found, wanted):
        nonlocal passed
        if found == wanted:
            passed += 1
        else:
            failed.append("%s: %r, the header says %r" % (what, found, wanted))

    def first(path, pattern):
        text = open(os.path.join(src, path)).read()
        m = re.search(pattern, text, re.M)
        return m.group(1) if m else None

    out = subprocess.run([tool, "--version"], capture_output=True, text=True).stdout.strip()
    expect("coverage-axis --version", out, "coverage-axis %s (library %s, ABI %s)" % (version, version, abi))
    pc = open(os.path.join(build, "coverage_axis.pc")).read()
    expect("coverage_axis.pc", re.search(r"^Version: (\S+)", pc, re.M).group(1), version)
    cpack = open(os.path.join(build, "CPackConfig.cmake")).read()
    expect("the .deb (CPACK_PACKAGE_VERSION)", re.search(r'CPACK_PACKAGE_VERSION "([^"]+)"', cpack).group(1), version)
    expect("libcoverage_axis.so.%s (SOVERSION)" % soversion,
           os.path.exists(os.path.join(build, "libcoverage_axis.so.%s" % soversion)), True)
    expect("bindings/python/pyproject.toml", first("bindings/python/pyproject.toml", r'^version = "([^"]+)"'), version)
    for crate in ("coverage-axis", "coverage-axis-sys"):
        expect("bindings/rust/%s/Cargo.toml" % crate,
               first("bindings/rust/%s/Cargo.toml" % crate, r'^version = "([^"]+)"'), version)
        expect("bindings/rust/Cargo.lock (%s)" % crate,
               first("bindings/rust/Cargo.lock", r'^name = "%s"\nversion = "([^"]+)"' % re.escape(crate)), version)
    expect("bindings/julia/Project.toml", first("bindings/julia/Project.toml", r'^version = "([^"]+)"'), version)
    blender = first("bindings/blender/coverage_axis_blender/__init__.py", r'"version": \((\d+, \d+, \d+)\)')
    expect("the Blender add-on's bl_info", blender.replace(", ", ".") if blender else None, version)
    env = dict(os.environ, PYTHONPATH=os.path.join(src, "bindings", "python"),
               CA_LIBRARY=os.path.join(build, "libcoverage_axis.so"))
    py = subprocess.run([python, "-c", "import coverage_axis; print(coverage_axis.version())"],
                        capture_output=True, text=True, env=env)
    expect("the Python package's version()", py.stdout.strip(), version)

    for f in failed:
        print("FAILED", f)
    print("check_version: %d passed, %d failed" % (passed, len(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
