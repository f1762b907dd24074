#!/usr/bin/env python3
"""skeletonize_agree.py: the bindings' skeletonize does the same in each language. Python's
skeletonize(), Rust's Context::skeletonize (examples/skeletonize.rs) and C#'s Context.Skeletonize
(Skeletonize.cs) run at their defaults on one mesh (tests/data/torus.obj); their ball counts must be
equal and every centre coordinate and radius within 1e-9. A binding whose tools are missing fails the
test (scripts/install-deps.sh installs them: `make deps`). Julia is not packaged in Debian 12, so
it cannot run here: its skeletonize is the same three calls at the defaults, and julia_layout
checks its structs.

usage: skeletonize_agree.py SOURCE_DIR WORK_DIR LIBRARY (the shared library; PYTHONPATH: bindings/python)
environment for Rust: CARGO, RUSTC, RUSTDOC, CARGO_HOME, CARGO_TARGET_DIR (as the rust_binding test)"""
import os
import shutil
import subprocess
import sys

TOLERANCE = 1e-9


def read_obj(path):
    v, f = [], []
    for line in open(path):
        w = line.split()
        if w[:1] == ["v"]:
            v.append(w[1:4])
        elif w[:1] == ["f"]:
            idx = [int(x.split("/")[0]) - 1 for x in w[1:]]
            f += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
    return [tuple(float(x) for x in p) for p in v], f


def balls(text):
    return [tuple(float(x) for x in line.split()) for line in text.splitlines() if line.strip()]


def run(what, cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if p.returncode != 0:
        sys.exit("%s failed (%s):\n%s%s" % (what, " ".join(cmd), p.stdout, p.stderr))
    return p.stdout


def tool(name, env_name=None):
    path = os.environ.get(env_name) if env_name else None
    path = path or shutil.which(name)
    if not path:
        sys.exit("FAILED: %s not found; install the bindings' tools with `make deps`" % name)
    return path


def main():
    src, work, library = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    v, f = read_obj(os.path.join(src, "tests", "data", "torus.obj"))
    mesh = os.path.join(work, "torus.txt")
    with open(mesh, "w") as out:
        out.write("%d %d\n" % (len(v), len(f)))
        out.writelines("%r %r %r\n" % p for p in v)
        out.writelines("%d %d %d\n" % t for t in f)
    results = {}

    import coverage_axis
    sk = coverage_axis.skeletonize(v, f)
    results["python"] = [tuple(float(x) for x in c) + (float(r),) for c, r in zip(sk.centers, sk.radii)]

    cargo = tool("cargo", "CARGO")
    env = dict(os.environ, COVERAGE_AXIS_DIR=os.path.dirname(library),
               LD_LIBRARY_PATH=os.path.dirname(library))
    results["rust"] = balls(run("the Rust example", [cargo, "run", "--offline", "--quiet", "--example", "skeletonize",
                                                     "--manifest-path", os.path.join(src, "bindings", "rust", "Cargo.toml"),
                                                     "-p", "coverage-axis", "--", mesh], env=env))

    mcs, mono = tool("mcs"), tool("mono")
    dll, exe = os.path.join(work, "CoverageAxis.dll"), os.path.join(work, "Skeletonize.exe")
    run("mcs", [mcs, "-nologo", "-warnaserror", "-unsafe", "-target:library", "-out:" + dll,
                os.path.join(src, "bindings", "csharp", "CoverageAxis.cs")])
    run("mcs", [mcs, "-nologo", "-warnaserror", "-r:" + dll, "-out:" + exe,
                os.path.join(src, "tests", "bindings", "Skeletonize.cs")])
    results["csharp"] = balls(run("the C# program", [mono, exe, mesh], env=env))

    failed = []
    reference = results["python"]
    if not reference:
        failed.append("python: no balls")
    for lang, got in results.items():
        if len(got) != len(reference):
            failed.append("%s: %d balls, python %d" % (lang, len(got), len(reference)))
            continue
        worst = max((abs(a - b) for g, r in zip(got, reference) for a, b in zip(g, r)), default=0.0)
        if worst > TOLERANCE:
            failed.append("%s: a centre or radius differs from python's by %.3g" % (lang, worst))
        print("%s: %d balls, largest difference from python %.3g" % (lang, len(got), worst))
    for f_ in failed:
        print("FAILED", f_)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
