"""test_distributed.py: the cluster route on a 2-worker LocalCluster over TLS on 127.0.0.1 (test
certificates made here with python3-cryptography). Checks: every input is in the report once, in
input order; the broken files are error lines with the tool's failure (a file error, the library's
status); every .ma is byte-identical to the coverage-axis tool's on the same file; a worker killed
while it runs an asset does not lose it (run again, same result); an asset whose workers keep dying
ends as an error line; the script's command line against the running scheduler; a client whose
certificate another CA signed is refused.

usage: test_distributed.py CLI TEST_DATA  (PYTHONPATH: the binding and examples/distributed)"""
import datetime
import ipaddress
import json
import os
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import unittest

import dask
from cryptography import x509
from cryptography.hazmat.primitives import hashes, serialization
from cryptography.hazmat.primitives.asymmetric import ec
from cryptography.x509.oid import NameOID
from distributed import Client

import coverage_axis as ca
import mesh_files
import skeletonize_cluster as sc

CLI, DATA = sys.argv[1], sys.argv[2]
MODELS = ["fox.obj", "hourglass.obj", "wall.obj", "cow_spot.obj", "torus.obj", "chair_soup.obj"]
HOLD_ONCE, HOLD_ALWAYS = "fox", "doomed"  # stems whose task waits to be killed: first attempt / every attempt


def make_certificates(folder, name):
    """A CA and a certificate it signs for 127.0.0.1 (PEM files in `folder`): (ca, cert, key) paths."""
    def write(path, data):
        with open(path, "wb") as f:
            f.write(data)
        return path
    now = datetime.datetime.utcnow()
    ca_key = ec.generate_private_key(ec.SECP256R1())
    ca_name = x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, name + " test CA")])
    ca = (x509.CertificateBuilder().subject_name(ca_name).issuer_name(ca_name).public_key(ca_key.public_key())
          .serial_number(x509.random_serial_number()).not_valid_before(now - datetime.timedelta(hours=1))
          .not_valid_after(now + datetime.timedelta(days=1))
          .add_extension(x509.BasicConstraints(ca=True, path_length=None), critical=True).sign(ca_key, hashes.SHA256()))
    key = ec.generate_private_key(ec.SECP256R1())
    cert = (x509.CertificateBuilder().subject_name(x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, "127.0.0.1")]))
            .issuer_name(ca_name).public_key(key.public_key()).serial_number(x509.random_serial_number())
            .not_valid_before(now - datetime.timedelta(hours=1)).not_valid_after(now + datetime.timedelta(days=1))
            .add_extension(x509.SubjectAlternativeName([x509.IPAddress(ipaddress.ip_address("127.0.0.1")),
                                                        x509.DNSName("localhost")]), critical=False)
            .sign(ca_key, hashes.SHA256()))
    pem = serialization.Encoding.PEM
    return (write(os.path.join(folder, name + "-ca.pem"), ca.public_bytes(pem)),
            write(os.path.join(folder, name + "-cert.pem"), cert.public_bytes(pem)),
            write(os.path.join(folder, name + "-key.pem"), key.private_bytes(
                pem, serialization.PrivateFormat.PKCS8, serialization.NoEncryption())))


def held_task(path, options, threads):
    """Runs on a worker: for the HOLD_* stems, writes MARKERS/<stem>.<attempt>.pid with this worker's
    pid and waits to be killed (HOLD_ONCE on its first attempt only), then skeletonize_asset()."""
    stem = os.path.splitext(os.path.basename(path))[0]
    markers = os.environ["CA_TEST_MARKERS"]
    attempt = 1 + sum(n.startswith(stem + ".") for n in os.listdir(markers))
    if stem == HOLD_ALWAYS or (stem == HOLD_ONCE and attempt == 1):
        with open(os.path.join(markers, "%s.%d.pid.part" % (stem, attempt)), "w") as f:
            f.write(str(os.getpid()))
        os.replace(os.path.join(markers, "%s.%d.pid.part" % (stem, attempt)), os.path.join(markers, "%s.%d.pid" % (stem, attempt)))
        threading.Event().wait()  # until the test kills this worker process
    with open(os.path.join(markers, "%s.%d.ran" % (stem, attempt)), "w") as f:
        f.write(str(os.getpid()))
    return sc.skeletonize_asset(path, options, threads)


def write_off_and_ply(source, off, ply):
    """`source` (OBJ) as ASCII OFF and as binary little-endian PLY (double coordinates, uchar/int
    face lists), for the readers of those formats."""
    v, t = mesh_files.read_mesh(source)
    with open(off, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(v), len(t)))
        f.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in v.tolist())
        f.writelines("3 %d %d %d\n" % tuple(tri) for tri in t.tolist())
    with open(ply, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
                 "property double z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                 % (len(v), len(t))).encode("ascii"))
        f.write(b"".join(struct.pack("<3d", *p) for p in v.tolist()))
        f.write(b"".join(struct.pack("<B3i", 3, *tri) for tri in t.tolist()))


class Killer(threading.Thread):
    """Kills (SIGKILL) the worker process named by each new MARKERS/*.pid file."""

    def __init__(self, markers):
        super().__init__(daemon=True)
        self.markers, self.killed, self.stop = markers, [], threading.Event()

    def run(self):
        while not self.stop.is_set():
            for name in sorted(os.listdir(self.markers)):
                if name.endswith(".pid") and name not in self.killed:
                    with open(os.path.join(self.markers, name)) as f:
                        os.kill(int(f.read()), signal.SIGKILL)
                    self.killed.append(name)
            self.stop.wait(0.05)


class ClusterRoute(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="ca-distributed-")
        cls.markers = os.environ["CA_TEST_MARKERS"] = os.path.join(cls.tmp, "markers")
        os.makedirs(cls.markers)
        cls.ca, cls.cert, cls.key = make_certificates(cls.tmp, "cluster")
        broken = os.path.join(cls.tmp, "broken.obj")  # a face refers to a vertex the file lacks
        with open(broken, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
        line = os.path.join(cls.tmp, "line.obj")  # readable, but no triangle has area: the library refuses it
        with open(line, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 2 3 4\n")
        inputs = [os.path.join(DATA, m) for m in MODELS] + [line]
        doomed = os.path.join(cls.tmp, HOLD_ALWAYS + ".obj")
        shutil.copy(os.path.join(DATA, "hourglass.obj"), doomed)
        off, ply = os.path.join(cls.tmp, "fox_off.off"), os.path.join(cls.tmp, "cow_ply.ply")
        write_off_and_ply(os.path.join(DATA, "fox.obj"), off, os.path.join(cls.tmp, "fox_unused.ply"))
        write_off_and_ply(os.path.join(DATA, "cow_spot.obj"), os.path.join(cls.tmp, "cow_unused.off"), ply)
        cls.inputs = inputs[:3] + [broken] + inputs[3:] + [off, ply, doomed]
        args = sc.parse_args(["-O", "x", "--local-workers", "2", "--tls-ca-file", cls.ca, "--tls-cert", cls.cert,
                              "--tls-key", cls.key, "unused"])
        cls.security = sc.security_from(args)
        # The scheduler gives a task up at its first dead worker (KilledWorker), so the script's own
        # resubmission is what is tested; one task per worker at a time, so a kill hits only the
        # asset it is aimed at.
        cls.config = dask.config.set({"distributed.scheduler.allowed-failures": 0,
                                      "distributed.scheduler.worker-saturation": 1.0})
        cls.cluster = sc.start_local_cluster(2, 1, cls.security)
        cls.client = Client(cls.cluster, security=cls.security)
        cls.outdir = os.path.join(cls.tmp, "out")
        killer = Killer(cls.markers)
        killer.start()
        cls.lines = list(sc.run_batch(cls.client, cls.inputs, cls.outdir, {}, threads=1, attempts=2, task=held_task))
        killer.stop.set()
        killer.join()
        cls.killed = killer.killed

    @classmethod
    def tearDownClass(cls):
        cls.client.close()
        cls.cluster.close()
        cls.config.__exit__(None, None, None)
        shutil.rmtree(cls.tmp)

    def cli(self, path):
        """The tool's exit code and .ma bytes (None when it failed) on `path`."""
        out = os.path.join(self.tmp, "cli-" + os.path.basename(path) + ".ma")
        r = subprocess.run([CLI, path, "-o", out, "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        if r.returncode:
            return r.returncode, None
        with open(out, "rb") as f:
            return 0, f.read()

    def test_every_input_once_in_order(self):
        self.assertEqual([line["input"] for line in self.lines], self.inputs)
        for line in self.lines:
            self.assertEqual(line["format_version"], 1)

    def test_results_equal_the_tool(self):
        for path, line in zip(self.inputs, self.lines):
            if os.path.basename(path) == HOLD_ALWAYS + ".obj":
                continue
            code, ma = self.cli(path)
            with self.subTest(path=path):
                if ma is None:
                    self.assertIn("error", line)
                    # the tool's exit codes: 3 a file it cannot read, 1 the library refused
                    self.assertEqual(code, 3 if line["error"]["status"] == "FILE_ERROR" else 1)
                    continue
                self.assertNotIn("error", line)
                with open(line["output"], "rb") as f:
                    self.assertEqual(f.read(), ma)
                self.assertEqual(line["selected"], int(ma.split(b" ", 1)[0]))

    def test_ma_lists_every_face_edge(self):
        # a face whose edges the skeleton does not list: they follow its edges, in face order
        sk = ca.Skeleton([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [0.5, 0.25, 0.125, 1e-10],
                         edges=[[1, 0], [2, 3]], faces=[[0, 1, 2]])
        self.assertEqual(mesh_files.ma_bytes(sk), b"4 4 1\nv 0 0 0 0.5\nv 1 0 0 0.25\nv 0 1 0 0.125\nv 0 0 1 1e-10\n"
                                                  b"e 1 0\ne 2 3\ne 1 2\ne 2 0\nf 0 1 2\n")

    def test_broken_files_are_error_lines(self):
        by_name = {os.path.basename(line["input"]): line for line in self.lines}
        self.assertEqual(by_name["broken.obj"]["error"]["status"], "FILE_ERROR")
        self.assertIn("out of range", by_name["broken.obj"]["error"]["message"])
        self.assertEqual(by_name["line.obj"]["error"]["status"], "CA_ERROR_DEGENERATE_INPUT")
        self.assertEqual(by_name["line.obj"]["error"]["code"], 5)

    def test_killed_worker_does_not_lose_its_asset(self):
        self.assertIn(HOLD_ONCE + ".1.pid", self.killed)  # its first run was killed ...
        self.assertTrue(os.path.exists(os.path.join(self.markers, HOLD_ONCE + ".2.ran")))  # ... it ran again
        line = next(line for line in self.lines if line["input"].endswith(HOLD_ONCE + ".obj"))
        self.assertNotIn("error", line)

    def test_asset_whose_workers_keep_dying_is_an_error_line(self):
        self.assertIn(HOLD_ALWAYS + ".1.pid", self.killed)
        self.assertIn(HOLD_ALWAYS + ".2.pid", self.killed)
        self.assertEqual(self.lines[-1]["error"]["status"], "WORKER_DIED")

    def test_command_line_against_the_running_scheduler(self):
        outdir = os.path.join(self.tmp, "cmdline")
        inputs = [os.path.join(DATA, "hourglass.obj"), os.path.join(DATA, "wall.obj")]
        r = subprocess.run([sys.executable, sc.__file__, "-O", outdir, "--scheduler", self.cluster.scheduler_address,
                            "--tls-ca-file", self.ca, "--tls-cert", self.cert, "--tls-key", self.key, "--threads", "1"]
                           + inputs, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = [json.loads(s) for s in r.stdout.splitlines()]
        self.assertEqual([line["input"] for line in lines], inputs)
        for path, line in zip(inputs, lines):
            with open(line["output"], "rb") as f:
                self.assertEqual(f.read(), self.cli(path)[1])

    def test_scheduler_listens_on_loopback_over_tls(self):
        self.assertTrue(self.cluster.scheduler_address.startswith("tls://127.0.0.1:"))

    def test_certificate_of_another_ca_is_refused(self):
        other = os.path.join(self.tmp, "other")
        os.makedirs(other)
        ca, cert, key = make_certificates(other, "other")
        args = sc.parse_args(["-O", "x", "--scheduler", "x", "--tls-ca-file", ca, "--tls-cert", cert, "--tls-key", key, "x"])
        with self.assertRaises(Exception):
            Client(self.cluster.scheduler_address, security=sc.security_from(args), timeout=10)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
