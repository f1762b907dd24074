#!/usr/bin/env python3
"""skeletonize_cluster.py: the cluster route - skeletonizes many assets on a Dask cluster, one task
per asset through the Python binding, over TLS. Each worker reads its asset, runs candidates ->
select -> connect and returns the `.ma` text and the report; the client writes OUTDIR/<stem>.ma and
prints one JSON line per input, in input order, in the format of `coverage-axis batch` (docs/cli.md):
the report with "input", or {"input": ..., "error": {"status", "code", "message"}}.

A task whose worker died is run again (Dask reschedules it; after the scheduler gives up, KilledWorker,
this script submits it again, up to --attempts times); an input whose attempts are used up, or whose
task failed in any other way, ends as an error line, so every input is in the report.

usage: skeletonize_cluster.py -O OUTDIR (--scheduler tls://HOST:PORT | --local-workers N) [options] INPUT...
(see --help, and examples/distributed/README.md)."""
import argparse
import json
import os
import sys
import uuid

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from mesh_files import MESH_EXTENSIONS, MeshError, ma_bytes, read_mesh  # noqa: E402

FORMAT_VERSION = 1
# the run options passed through to the library (each keeps the library's default when not given)
RUN_OPTIONS = {"samples": "cover_samples", "delta": "delta", "scale": "scale", "solver": "solver",
               "effort": "effort", "target_count": "target_count", "seed": "seed", "connect": "method"}


def list_inputs(arguments):
    """The inputs as given: a file as it is, a folder as its mesh files sorted by name."""
    inputs = []
    for a in arguments:
        if os.path.isdir(a):
            inputs += [os.path.join(a, n) for n in sorted(os.listdir(a)) if os.path.splitext(n)[1].lower() in MESH_EXTENSIONS]
        else:
            inputs.append(a)
    return inputs


def error_line(path, status, code, message):
    """The batch format's error object (the report's version fields, then input and error)."""
    return dict(_header(), input=path, error={"status": status, "code": code, "message": message})


def _header():
    import coverage_axis as ca
    return {"format_version": FORMAT_VERSION, "tool_version": ca.version(), "library_version": ca.version(),
            "abi_version": ca.ABI_VERSION}


def task_threads(requested):
    """Library threads for one task: `requested` if > 0, else this worker's cores divided by the
    tasks it runs at once (its Dask threads), so concurrent tasks share the cores."""
    if requested > 0:
        return requested
    from distributed import get_worker
    return max(1, local_cores() // max(1, get_worker().nthreads))


def skeletonize_asset(path, options, threads=0):
    """Runs on a worker: reads `path`, skeletonizes it, returns (report, .ma bytes or None); a failure
    is an error report, never an exception (an exception here would be a lost asset's reason)."""
    import coverage_axis as ca
    header = dict(_header(), input=path)
    try:
        vertices, triangles = read_mesh(path)
    except MeshError as e:
        return error_line(path, "FILE_ERROR", -1, str(e)), None
    ctx = ca.Context(threads=task_threads(threads))
    lib = {RUN_OPTIONS[k]: v for k, v in options.items() if v is not None}
    if "scale" in lib:
        lib["dilation"] = "scale"
    step_options = {step: {k: v for k, v in lib.items() if k in ca.defaults(step)} for step in ("candidates", "select", "connect")}
    step = "candidates"
    try:
        cset = ca.candidates(vertices, triangles, context=ctx, **step_options["candidates"])
        step = "selection"
        sel = ca.select(cset, context=ctx, **step_options["select"])
        step = "connection"
        sk = ca.connect(sel, context=ctx, **step_options["connect"])
    except ca.CoverageAxisError as e:
        return error_line(path, ca.STATUS_NAMES[e.status], e.status, "%s failed: %s" % (step, e.message)), None
    finally:
        ctx.close()
    ss, ks = sel.stats, sk.stats
    scaled = "scale" in lib
    report = dict(header, input_vertices=len(vertices), input_triangles=len(triangles),
                  surface_samples=cset.sample_count, candidates=cset.count, selected=len(sk),
                  edges=ks["edges"], faces=ks["faces"], components=ks["components"], isolated=ks["isolated"],
                  betti1=ks["betti1"], uncovered=len(sel.uncovered), optimal=bool(ss["proven_optimal"]),
                  objective=ss["objective"], lower_bound=ss["lower_bound"], gap=ss["gap"],
                  delta=0.0 if scaled else ss["delta_absolute"], scale=ss["scale_used"] if scaled else 0.0,
                  reference_length=cset.reference_length, solver=options.get("solver") or ca.defaults("select")["solver"],
                  effort=options.get("effort") or ca.defaults("select")["effort"], connect=ks["method"],
                  probes=ss["probes"], parts=ss["parts"],
                  reduction={k: ss[k] for k in ("rows_before", "cols_before", "rows_after", "cols_after", "forced")})
    return report, ma_bytes(sk)


def _write_result(outdir, path, report, ma):
    """Writes OUTDIR/<stem>.ma (through a temporary name: a reader never sees half a file) and
    completes the report with the output's path."""
    out = os.path.join(outdir, os.path.splitext(os.path.basename(path))[0] + ".ma")
    tmp = out + ".part"
    with open(tmp, "wb") as f:
        f.write(ma)
    os.replace(tmp, out)
    return dict(report, output=out, outputs={"ma": out})


def run_batch(client, inputs, outdir, options, threads=0, attempts=3, task=skeletonize_asset):
    """Runs one task per input on `client`'s cluster and yields the report lines in input order.
    `task(path, options, threads)` -> (report, ma bytes or None). Same-stem inputs: the second is an
    error line (its .ma would overwrite the first's)."""
    from distributed import as_completed
    from distributed.scheduler import KilledWorker
    os.makedirs(outdir, exist_ok=True)
    batch = uuid.uuid4().hex  # task keys unique to this batch: other clients may share the scheduler
    lines, pending, tries, stems = {}, {}, {}, {}
    for i, path in enumerate(inputs):
        stem = os.path.splitext(os.path.basename(path))[0]
        if stem in stems:
            lines[i] = error_line(path, "FILE_ERROR", -1, "same output stem as %s" % inputs[stems[stem]])
            continue
        stems[stem] = i
    todo = [i for i in range(len(inputs)) if i not in lines]

    def submit(i):
        tries[i] = tries.get(i, 0) + 1
        future = client.submit(task, inputs[i], options, threads, pure=False, key="coverage-axis-%s-%d-%d" % (batch, i, tries[i]))
        pending[future.key] = i
        return future

    queue = as_completed([submit(i) for i in todo])
    done_up_to = 0
    for future in queue:
        i = pending.pop(future.key)
        try:
            report, ma = future.result()
            lines[i] = _write_result(outdir, inputs[i], report, ma) if ma is not None else report
        except KilledWorker as e:
            if tries[i] < attempts:
                queue.add(submit(i))
            else:
                lines[i] = error_line(inputs[i], "WORKER_DIED", -1, "the workers running it died %d times: %s" % (tries[i], e))
        except Exception as e:  # noqa: BLE001 - any other failure of the task is this input's error line
            lines[i] = error_line(inputs[i], "TASK_ERROR", -1, "%s: %s" % (type(e).__name__, e))
        future.release()
        while done_up_to < len(inputs) and done_up_to in lines:
            yield lines[done_up_to]
            done_up_to += 1
    while done_up_to < len(inputs):  # the same-stem error lines after the last task
        yield lines[done_up_to]
        done_up_to += 1


def security_from(args):
    """Dask's TLS settings from the --tls-* files; for a LocalCluster without them, temporary
    certificates (distributed's Security.temporary(), made with python3-cryptography)."""
    from distributed.security import Security
    if args.tls_ca_file:
        return Security(tls_ca_file=args.tls_ca_file, tls_client_cert=args.tls_cert, tls_client_key=args.tls_key,
                        tls_scheduler_cert=args.tls_cert, tls_scheduler_key=args.tls_key,
                        tls_worker_cert=args.tls_cert, tls_worker_key=args.tls_key, require_encryption=True)
    if args.scheduler:
        raise SystemExit("skeletonize_cluster.py: --scheduler needs --tls-ca-file, --tls-cert and --tls-key")
    return Security.temporary()


def start_local_cluster(workers, worker_threads, security):
    """A LocalCluster on 127.0.0.1 only, over TLS: `workers` processes of `worker_threads` threads."""
    from distributed import LocalCluster
    return LocalCluster(n_workers=workers, threads_per_worker=worker_threads, processes=True, protocol="tls://",
                        host="127.0.0.1", dashboard_address=None, security=security)


def local_cores():
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("inputs", nargs="+", metavar="INPUT", help="mesh files (.obj .off .ply) or folders of them")
    p.add_argument("-O", "--outdir", required=True, help="folder for <stem>.ma")
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--scheduler", help="address of a running scheduler, tls://HOST:PORT")
    where.add_argument("--local-workers", type=int, help="start a LocalCluster on 127.0.0.1 with this many workers")
    p.add_argument("--worker-threads", type=int, default=1, help="tasks a local worker runs at once (default 1)")
    p.add_argument("--threads", type=int, default=0,
                   help="library threads per task (default 0: the worker's cores / its Dask threads; a LocalCluster: cores / (workers x worker threads))")
    p.add_argument("--attempts", type=int, default=3, help="runs of a task whose worker died before it is an error line (default 3)")
    p.add_argument("--tls-ca-file", help="CA certificate that signed every cluster member's certificate")
    p.add_argument("--tls-cert", help="this client's certificate (PEM); with a LocalCluster also the scheduler's and workers'")
    p.add_argument("--tls-key", help="the private key of --tls-cert")
    p.add_argument("--samples", type=int, help="surface samples to cover")
    p.add_argument("--delta", type=float, help="dilation offset, fraction of the longest bbox side")
    p.add_argument("--scale", type=float, help="dilation factor r' = r * S instead of --delta")
    p.add_argument("--solver", choices=["exact", "greedy", "capp"])
    p.add_argument("--effort", choices=["fast", "prove"])
    p.add_argument("--target-count", type=int, help="at most K balls (smallest delta)")
    p.add_argument("--seed", type=int)
    p.add_argument("--connect", choices=["auto", "medial", "power"])
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    if args.local_workers is not None and args.local_workers < 1:
        raise SystemExit("skeletonize_cluster.py: --local-workers takes a count >= 1")
    from distributed import Client
    inputs = list_inputs(args.inputs)
    options = {k: getattr(args, k) for k in RUN_OPTIONS if getattr(args, k) is not None}
    security = security_from(args)
    cluster = None
    threads = args.threads
    if args.local_workers:
        if threads <= 0:
            threads = max(1, local_cores() // (args.local_workers * args.worker_threads))
        cluster = start_local_cluster(args.local_workers, args.worker_threads, security)
    failed = 0
    try:
        with Client(cluster if cluster else args.scheduler, security=security) as client:
            for line in run_batch(client, inputs, args.outdir, options, threads, args.attempts):
                failed += "error" in line
                print(json.dumps(line, separators=(",", ":")), flush=True)
    finally:
        if cluster:
            cluster.close()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
