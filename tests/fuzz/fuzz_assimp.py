#!/usr/bin/env python3
"""fuzz_assimp.py: a mutation fuzzer of the formats the tool reads through assimp, run through the
tool itself (make fuzz-assimp; a short run is the ctest test fuzz_assimp_smoke).

Each seed first runs as it is, then the formats take turns: a seed of the format is mutated
(bytes flipped, set to boundary values, inserted, cut, repeated, spliced with another seed of the
format; 32-bit fields set to boundary counts) and written with the format's extension, and the
tool runs on it with --time-limit BOUND (which bounds the read too) and --quiet. A run is a
finding when the tool itself is killed by a signal, does not end within BOUND plus a margin for
starting and stopping processes, exits with a code other than 0, 1 or 3, or fails without exactly
one line (of at most 1000 characters) on standard error. Crashes, hangs and runaway memory inside the assimp reader are not
findings: the tool must turn them into an error for that file (they are counted, and the first few
inputs of each kind are kept as well, for reports to assimp). Findings are saved under --out;
the exit status is 1 if there was any.

usage: fuzz_assimp.py --tool build/coverage-axis [--seconds S] [--runs N] [--seed N] [--bound S]
       [--jobs N] [--formats md3,ac,...] [--out DIR] SEED_FILE_OR_FOLDER...
"""
import argparse
import concurrent.futures
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time

FORMATS = ["md3", "ac", "3ds", "x", "dae", "fbx", "blend", "b3d"]
# what the tool prints for a reader that crashed, hit its time limit or its memory limit
CONTAINED = {"reader crash": "the assimp reader crashed", "reader time limit": "did not end within its time limit",
             "reader memory limit": "memory limit is"}
KEEP_CONTAINED = 5  # inputs kept per kind of contained failure and format
MAX_MESSAGE = 1000  # characters of a failure's one line; more is not a message a person reads
INTERESTING_BYTES = [0x00, 0x01, 0x7F, 0x80, 0xFF, ord("-"), ord("9"), ord("{"), ord("}"), ord("\n")]
INTERESTING_INTS = [0, 1, 0x7F, 0xFF, 0x7FFF, 0xFFFF, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 1 << 20]


def mutate(data, rng, others):
    """One to four random edits of `data` (bytes); `others` are seeds of the same format to splice."""
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(8)
        at = rng.randrange(len(data) + 1)
        if kind == 0 and data:  # flip a bit
            at = min(at, len(data) - 1)
            data[at] ^= 1 << rng.randrange(8)
        elif kind == 1 and data:  # a boundary byte
            data[min(at, len(data) - 1)] = rng.choice(INTERESTING_BYTES)
        elif kind == 2:  # insert random bytes
            data[at:at] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 8)))
        elif kind == 3 and data:  # cut a range
            data[at:at + rng.randint(1, max(1, len(data) // 16))] = b""
        elif kind == 4 and data:  # repeat a range
            n = rng.randint(1, max(1, min(256, len(data) // 4)))
            data[at:at] = data[at:at + n] * rng.randint(1, 8)
        elif kind == 5 and len(data) >= 4:  # a 32-bit field set to a boundary count
            at = min(at, len(data) - 4)
            data[at:at + 4] = (rng.choice(INTERESTING_INTS) & 0xFFFFFFFF).to_bytes(4, rng.choice(["little", "big"]))
        elif kind == 6 and len(data) >= 2:  # a decimal number in text made huge or negative
            at = min(at, len(data) - 1)
            data[at:at + 1] = rng.choice([b"99999999", b"-1", b"2147483648", b"1e38", b"nan"])
        elif others:  # splice: this seed's head, another's tail
            other = rng.choice(others)
            data = data[:at] + other[rng.randrange(len(other) + 1):]
    return bytes(data)


def no_core():
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def run_tool(tool, path, bound, margin):
    """(returncode or None for a timeout, seconds, stderr text) of one run of the tool."""
    out = path + ".ma"
    args = [tool, path, "-o", out, "--quiet", "--time-limit", str(bound), "--threads", "1",
            "--samples", "100", "--voronoi-samples", "300"]
    start = time.monotonic()
    try:
        r = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=bound + margin,
                           preexec_fn=no_core)
        code, err = r.returncode, r.stderr.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        code, err = None, (e.stderr or b"").decode(errors="replace")
    if os.path.exists(out):
        os.remove(out)
    return code, time.monotonic() - start, err


def verdict(code, seconds, err, bound, margin):
    """The finding a run is ("" if none)."""
    if code is None:
        return "did not end within %g s" % (bound + margin)
    if code < 0:
        return "the tool was killed by signal %d" % -code
    if code not in (0, 1, 3):
        return "exit code %d" % code
    if seconds > bound + margin:
        return "took %.1f s, beyond %g s + %g s" % (seconds, bound, margin)
    lines = [l for l in err.splitlines() if l.strip()]
    if code != 0 and len(lines) != 1:
        return "exit %d with %d lines on standard error" % (code, len(lines))
    if code != 0 and len(lines[0]) > MAX_MESSAGE:
        return "a message of %d characters" % len(lines[0])
    return ""


def collect_seeds(paths, formats):
    seeds = {f: [] for f in formats}
    files = []
    for p in paths:
        if os.path.isdir(p):
            files += sorted(os.path.join(p, n) for n in os.listdir(p))
        elif os.path.isfile(p):
            files.append(p)
    for path in files:
        ext = os.path.splitext(path)[1][1:].lower()
        if ext in seeds and os.path.isfile(path) and os.path.getsize(path) <= 1 << 20:
            with open(path, "rb") as fh:
                seeds[ext].append((path, fh.read()))
    return seeds


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tool", required=True)
    ap.add_argument("--seconds", type=float, default=60, help="stop after this long (default 60)")
    ap.add_argument("--runs", type=int, default=0, help="stop after this many mutated runs (0 = no limit)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--bound", type=float, default=10, help="--time-limit of each run, seconds (default 10)")
    ap.add_argument("--margin", type=float, default=10, help="seconds a run may take beyond the bound (default 10)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--formats", default=",".join(FORMATS))
    ap.add_argument("--out", default="fuzz-assimp", help="where findings and kept inputs go")
    ap.add_argument("paths", nargs="+", help="seed files or folders")
    a = ap.parse_args()
    formats = [f for f in a.formats.split(",") if f]
    seeds = collect_seeds(a.paths, formats)
    missing = [f for f in formats if not seeds[f]]
    if missing:
        print("fuzz_assimp: no seed for %s" % ", ".join(missing), file=sys.stderr)
        return 2
    rng = random.Random(a.seed)
    work = tempfile.mkdtemp(prefix="fuzz_assimp_")
    os.makedirs(a.out, exist_ok=True)
    deadline = time.monotonic() + a.seconds
    stats = {f: {"runs": 0, "exit": {}, "contained": {}} for f in formats}
    findings = []
    submitted = [0]  # runs handed to the pool, which name their input files

    def submit(pool, fmt, data, label):
        submitted[0] += 1
        return pool.submit(job, fmt, data, label, os.path.join(work, "in%d.%s" % (submitted[0], fmt)))

    def job(fmt, data, label, path):
        with open(path, "wb") as fh:
            fh.write(data)
        code, seconds, err = run_tool(a.tool, path, a.bound, a.margin)
        return fmt, data, label, path, code, seconds, err

    def record(result):
        fmt, data, label, path, code, seconds, err = result
        os.remove(path)
        st = stats[fmt]
        st["runs"] += 1
        st["exit"][code] = st["exit"].get(code, 0) + 1
        finding = verdict(code, seconds, err, a.bound, a.margin)
        if finding:
            saved = os.path.join(a.out, "finding%d.%s" % (len(findings) + 1, fmt))
            with open(saved, "wb") as fh:
                fh.write(data)
            findings.append("%s (%s): %s; saved as %s; stderr: %s" % (label, fmt, finding, saved, err.strip()[:300]))
            print("FINDING: " + findings[-1], flush=True)
            return
        for kind, text in CONTAINED.items():
            if text in err:
                n = st["contained"][kind] = st["contained"].get(kind, 0) + 1
                if n <= KEEP_CONTAINED:
                    with open(os.path.join(a.out, "%s_%s%d.%s" % (kind.replace(" ", "_"), fmt, n, fmt)), "wb") as fh:
                        fh.write(data)

    start = time.monotonic()
    mutated = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        # every seed as it is
        for fmt in formats:
            for f in concurrent.futures.as_completed(
                    [submit(pool, fmt, data, "seed " + os.path.basename(p)) for p, data in seeds[fmt]]):
                record(f.result())
        # then mutations, the formats taking turns, `jobs` runs at a time
        turn = 0
        while time.monotonic() < deadline and (a.runs == 0 or mutated < a.runs):
            batch = []
            for _ in range(max(1, a.jobs)):
                if a.runs and mutated >= a.runs:
                    break
                fmt = formats[turn % len(formats)]
                turn += 1
                mutated += 1
                others = [d for _, d in seeds[fmt]]
                base = rng.choice(others)
                batch.append(submit(pool, fmt, mutate(base, rng, others), "mutation %d" % mutated))
            for f in concurrent.futures.as_completed(batch):
                record(f.result())
    shutil.rmtree(work, ignore_errors=True)

    total = sum(st["runs"] for st in stats.values())
    print("fuzz_assimp: %d runs (%d mutated) in %.0f s, seed %d, bound %g s" %
          (total, mutated, time.monotonic() - start, a.seed, a.bound))
    for fmt in formats:
        st = stats[fmt]
        exits = ", ".join("%s: %d" % ("timeout" if c is None else c, n) for c, n in sorted(
            st["exit"].items(), key=lambda kv: (kv[0] is None, kv[0] or 0)))
        contained = ", ".join("%s %d" % kv for kv in sorted(st["contained"].items())) or "none"
        print("  %-5s %5d runs; exit codes %s; contained in the reader: %s" % (fmt, st["runs"], exits, contained))
    print("fuzz_assimp: %d finding(s)%s" % (len(findings), "" if not findings else ", saved under " + a.out))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
