"""test_coverage_axis.py: tests of the Python binding (unittest). CTest runs it with CA_LIBRARY (the
built library), CA_CLI (the coverage-axis tool) and CA_TEST_DATA (tests/data) set:
    python3 -m unittest test_coverage_axis
It runs once with numpy (which must be installed: scripts/install-deps.sh) and, from
test_runs_without_numpy, once more in a subprocess with numpy hidden (CA_TEST_HIDE_NUMPY=1 makes
`import numpy` fail), where inputs are lists and results lists of tuples."""
import ctypes
import gc
import inspect
import math
import os
import re
import subprocess
import sys
import threading
import unittest
import weakref

if os.environ.get("CA_TEST_HIDE_NUMPY"):
    sys.modules["numpy"] = None  # `import numpy` now raises ImportError

import coverage_axis as ca
from coverage_axis import _steps

if ca.HAVE_NUMPY:
    import numpy as np

BOX_V = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0), (0, 0, 1), (2, 0, 1), (2, 1, 1), (0, 1, 1)]
BOX_F = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
         (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
SMALL = dict(cover_samples=400, voronoi_samples=800)
DATA = os.environ.get("CA_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "tests", "data"))


def rows(a):
    """Nested lists of a numpy array or a list of tuples."""
    return [list(r) if isinstance(r, (tuple, list)) or hasattr(r, "__len__") else r for r in
            (a.tolist() if hasattr(a, "tolist") else a)]


def records(path, kind):
    """The fields after the keyword of each line of a text file that starts with `kind` (OBJ, .ma)."""
    with open(path) as f:
        return [line.split()[1:] for line in f if line.split()[:1] == [kind]]


def read_obj(path):
    """Vertices and triangles (polygons fanned) of an OBJ file, 0-based."""
    f = []
    for face in records(path, "f"):
        idx = [int(x.split("/")[0]) - 1 for x in face]
        f += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
    return [tuple(float(x) for x in p[:3]) for p in records(path, "v")], f


def sphere_points(n):
    """n points on the unit sphere (a Fibonacci spiral); each is its own outward normal."""
    golden = math.pi * (3 - math.sqrt(5))
    pts = []
    for i in range(n):
        z = 1 - 2 * (i + 0.5) / n
        r = math.sqrt(1 - z * z)
        pts.append((r * math.cos(golden * i), r * math.sin(golden * i), z))
    return pts


def read_ma(path):
    """Balls (x, y, z, r), edge and face counts of a .ma file."""
    return ([tuple(float(x) for x in p[:4]) for p in records(path, "v")], len(records(path, "e")),
            len(records(path, "f")))


class CommonTest(unittest.TestCase):
    """Runs with and without numpy."""

    def test_version_and_library(self):
        self.assertRegex(ca.version(), r"^\d+\.\d+\.\d+$")
        self.assertTrue(os.path.exists(ca.load_library()))

    def test_status_names_are_the_librarys(self):
        for code, name in enumerate(ca.STATUS_NAMES):
            self.assertEqual(getattr(ca, name), code)
            self.assertTrue(ca._lib().ca_status_string(code).decode().startswith(name + ":"), name)

    def test_a_library_that_cannot_load_is_reported(self):
        script = ("import coverage_axis as ca\ntry:\n    ca.load_library(%s)\nexcept ca.LibraryNotFoundError as e:\n"
                  "    print(isinstance(e, ImportError), e)\n")
        for arg, env in (("'/nonexistent/libcoverage_axis.so'", {}), ("", {"CA_LIBRARY": "/nonexistent/libcoverage_axis.so"})):
            r = subprocess.run([sys.executable, "-c", script % arg], env=dict(os.environ, **env),
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertTrue(r.stdout.startswith("True libcoverage_axis not found"), r.stdout)
            self.assertIn("/nonexistent/libcoverage_axis.so", r.stdout)

    def test_box_skeleton_is_on_the_medial_axis(self):
        sk = ca.skeletonize(BOX_V, BOX_F, **SMALL)
        self.assertGreaterEqual(len(sk.radii), 2)
        self.assertTrue(sk.stats["proven_optimal"])
        for (x, y, z), r in zip(rows(sk.centers), rows(sk.radii)):
            nearest_face = min(x, 2 - x, y, 1 - y, z, 1 - z)
            self.assertGreater(nearest_face, 0)
            self.assertGreaterEqual(r, nearest_face - 1e-9)
            self.assertLessEqual(r, nearest_face + 0.1)
        for i, j in rows(sk.edges):
            self.assertLess(max(i, j), len(sk.radii))

    def test_point_normals_trust(self):
        # a sphere cloud (Fibonacci points, exact normals); random signs passed as given are re-oriented
        n = 2000
        pts = sphere_points(n)
        signs = [1 if (i * 7919) % 13 < 6 else -1 for i in range(n)]
        shuffled = [(s * x, s * y, s * z) for s, (x, y, z) in zip(signs, pts)]
        opts = dict(cover_samples=300, voronoi_samples=600)
        self.assertEqual(ca.candidates(pts, None, pts, **opts).normals, "given")
        self.assertEqual(ca.candidates(pts, None, shuffled, **opts).normals, "oriented")
        self.assertEqual(ca.candidates(pts, None, shuffled, point_normals="unoriented", **opts).normals, "oriented")
        self.assertEqual(ca.candidates(pts, None, shuffled, point_normals="estimate", **opts).normals, "estimated")
        self.assertEqual(ca.candidates(BOX_V, BOX_F, **SMALL).normals, "none")
        with self.assertRaises(ca.CoverageAxisError):
            ca.candidates(pts, None, pts, point_normals="sometimes")

    def test_defaults_come_from_the_library(self):
        # the binding states no option default itself: its functions default every option to None
        for fn in (ca.candidates, ca.select, ca.connect, ca.evaluate, ca.skeletonize, ca.Context):
            for p in inspect.signature(fn).parameters.values():
                self.assertIn(p.default, (inspect.Parameter.empty, None), (fn.__name__, p.name))
        # the library's defaults, as the CLI's usage text (made from the same functions) prints them
        usage = subprocess.run([os.environ["CA_CLI"], "--help"], capture_output=True, text=True).stdout
        # (CLI11's format: "--delta FLOAT:>= 0=0.02", the default after the last "=" of the option's column)
        printed = {flag: re.search(r"(?m)^\s*%s \S[^\n]*?=(\S+)\s" % flag, usage).group(1)
                   for flag in ("--delta", "--samples", "--voronoi-samples", "--seed", "--time-limit")}
        d = dict(ca.defaults("candidates"), **ca.defaults("select"))
        self.assertEqual(printed, {"--delta": repr(d["delta"]), "--samples": str(d["cover_samples"]),
                                   "--voronoi-samples": str(d["voronoi_samples"]), "--seed": str(d["seed"]),
                                   "--time-limit": "%g" % d["time_limit_s"]})
        self.assertEqual((d["solver"], d["effort"], ca.defaults("connect")["method"]), ("exact", "fast", "auto"))
        # options not given keep those defaults: skeletonize() equals passing them all explicitly
        explicit = dict(ca.defaults("candidates"), **ca.defaults("select"), **ca.defaults("connect"))
        explicit.update(SMALL)
        a, b = ca.skeletonize(BOX_V, BOX_F, **SMALL), ca.skeletonize(BOX_V, BOX_F, **explicit)
        self.assertEqual(rows(a.centers), rows(b.centers))

    def test_steps_equal_skeletonize(self):
        one = ca.skeletonize(BOX_V, BOX_F, delta=0.03, method="power", **SMALL)
        cset = ca.candidates(BOX_V, BOX_F, **SMALL)
        sel = ca.select(cset, delta=0.03)
        sk = ca.connect(sel, method="power")
        self.assertEqual(rows(sk.centers), rows(one.centers))
        self.assertEqual(rows(sk.radii), rows(one.radii))
        self.assertEqual(rows(sk.edges), rows(one.edges))
        self.assertEqual(rows(sk.faces), rows(one.faces))
        self.assertEqual(rows(sel.centers), rows(one.centers))
        self.assertEqual(sel.stats["objective"], one.stats["objective"])
        self.assertEqual(cset.count, one.stats["candidates"])
        centers = rows(cset.centers)
        self.assertEqual([centers[i] for i in rows(sel.indices)], rows(sel.centers))
        for r, d in zip(rows(sel.radii), rows(sel.dilated_radii)):
            self.assertAlmostEqual(d, r + 0.03 * cset.reference_length, delta=1e-12)
        self.assertEqual(sk.stats["method"], "power")

    def test_results_outlive_their_inputs_and_context(self):
        with ca.Context() as ctx:
            cset = ca.candidates(BOX_V, BOX_F, context=ctx, **SMALL)
        sel = ca.select(cset)
        centers = sel.centers
        del cset, sel  # the arrays keep their selection (and it its candidate set) alive
        sk = ca.connect(ca.select(ca.candidates(BOX_V, BOX_F, **SMALL)))
        self.assertEqual(rows(centers), rows(sk.centers))

    def test_target_count_and_routes(self):
        full = ca.skeletonize(BOX_V, BOX_F, **SMALL)
        k = max(1, len(full.radii) - 2)
        small = ca.skeletonize(BOX_V, BOX_F, target_count=k, **SMALL)
        self.assertLessEqual(len(small.radii), k)
        self.assertGreater(small.stats["delta_absolute"], full.stats["delta_absolute"])
        for route in ("power", "medial"):
            self.assertEqual(ca.skeletonize(BOX_V, BOX_F, connect=route, **SMALL).stats["components"], 1)

    def test_target_error_not_reached_carries_the_best_result(self):
        with self.assertRaises(ca.TargetNotReachedError) as raised:
            ca.skeletonize(BOX_V, BOX_F, target_error=1e-4, **SMALL)
        e = raised.exception
        self.assertIsInstance(e, ca.CoverageAxisError)
        self.assertEqual(e.status, ca.CA_ERROR_TARGET_NOT_REACHED)
        self.assertIn("not reached", e.message)
        self.assertGreater(e.selection.stats["hd_reached"], 1e-4)
        self.assertEqual(len(e.skeleton.radii), len(e.selection.radii))
        self.assertGreater(len(e.skeleton.radii), 0)
        # the skeleton carried is the one evaluate measures at the HD the search reported
        hd = ca.evaluate(BOX_V, BOX_F, e.skeleton)["hd_two_sided"]
        self.assertAlmostEqual(hd, e.selection.stats["hd_reached"], delta=1e-9 * hd)
        self.assertEqual(len(ca.skeletonize(BOX_V, BOX_F, target_error=50, **SMALL).radii) > 0, True)

    def test_masks(self):
        cset = ca.candidates(BOX_V, BOX_F, **SMALL)
        free = ca.select(cset)
        out = [i in set(rows(free.indices)) for i in range(cset.count)]
        sel = ca.select(cset, forced_out=out)
        self.assertFalse(set(rows(sel.indices)) & set(rows(free.indices)))
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.select(cset, forced_in=[0, 1])
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_INPUT)

    def test_lengths_are_checked_before_the_call(self):
        points = sphere_points(200)
        called = []
        real = _steps.lib

        def spy():  # records every library function the steps fetch
            lib = real()

            class Spy:
                def __getattr__(self, name):
                    called.append(name)
                    return getattr(lib, name)
            return Spy()
        _steps.lib = spy
        try:
            for short in (points[:10], points + points[:1]):
                with self.assertRaises(ca.CoverageAxisError) as cm:
                    ca.skeletonize(points, normals=short)
                self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_INPUT)
                self.assertIn("normals: %d rows for 200 vertices" % len(short), cm.exception.message)
            self.assertNotIn("ca_candidates", called)
        finally:
            _steps.lib = real
        # the library refuses the mismatch on its own too: a view whose normal_count is short
        view, keep = _steps._surface(points, None, points)
        view.normal_count = 10
        out = ctypes.c_void_p()
        with ca.Context() as ctx:
            with self.assertRaises(ca.CoverageAxisError) as cm:
                ctx.run(real().ca_candidates, ctypes.byref(view), None, ctypes.byref(out))
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_INPUT)
        self.assertIn("normals", cm.exception.message)
        del keep

    def test_results_in_caller_units(self):
        a = ca.skeletonize(BOX_V, BOX_F, **SMALL)
        b = ca.skeletonize([(1000 * x, 1000 * y, 1000 * z) for x, y, z in BOX_V], BOX_F, **SMALL)
        self.assertEqual(len(a.radii), len(b.radii))
        for ra, rb in zip(rows(a.radii), rows(b.radii)):
            self.assertAlmostEqual(1000 * ra, rb, delta=1e-6 * rb)

    def test_errors_carry_status_and_message(self):
        bad = list(BOX_V)
        bad[2] = (2, float("nan"), 0)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(bad, BOX_F)
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_INPUT)
        self.assertIn("vertex 2", cm.exception.message)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V, [(0, 1, 99)])
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_INPUT)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V, [(0, 1, -1)])
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_INPUT)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize([(0, 0, 0), (0, 0, 0), (0, 0, 0)], [(0, 1, 2)])
        self.assertEqual(cm.exception.status, ca.CA_ERROR_DEGENERATE_INPUT)
        # a flat face is a sheet: surface balls (radius 0) unless only inner balls are asked for
        flat = ca.skeletonize(BOX_V[:4], [(0, 1, 2), (0, 2, 3)])
        self.assertTrue(len(flat.radii) > 0 and all(r == 0 for r in flat.radii))
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V[:4], [(0, 1, 2), (0, 2, 3)], volumetric_only=1)
        self.assertEqual(cm.exception.status, ca.CA_ERROR_NO_CANDIDATES)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V, BOX_F, delta=-1)
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)
        self.assertTrue(cm.exception.message)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V, BOX_F, solver="fastest")
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.Context(threads=-1)
        self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)
        with self.assertRaises(TypeError):
            ca.skeletonize(BOX_V, BOX_F, deltaa=0.1)

    def test_progress_is_called_and_cancel_from_it_stops_the_step(self):
        calls = []
        ctx = ca.Context(progress=lambda stage, f: calls.append((stage, f)) or True)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V, BOX_F, context=ctx, **SMALL)
        self.assertEqual(cm.exception.status, ca.CA_ERROR_CANCELLED)
        self.assertEqual(len(calls), 1)
        calls.clear()
        ctx = ca.Context(progress=lambda stage, f: calls.append((stage, f)) and False)
        ca.skeletonize(BOX_V, BOX_F, context=ctx, **SMALL)
        stages = [s for s, _ in calls]
        for stage in ("sampling", "delaunay", "inside", "coverage", "selection", "connect"):
            self.assertIn(stage, stages)
        self.assertTrue(all(0 <= f <= 1 for _, f in calls))

    def test_cancel_from_another_thread(self):
        calls = []

        def progress(stage, fraction):
            calls.append(stage)
            if len(calls) == 1:  # the first update: another thread cancels, this one waits for it
                t = threading.Thread(target=ctx.cancel)
                t.start()
                t.join()
            return False

        ctx = ca.Context(progress=progress)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.candidates(BOX_V, BOX_F, context=ctx, **SMALL)
        self.assertEqual(cm.exception.status, ca.CA_ERROR_CANCELLED)
        self.assertEqual(len(calls), 1)
        with self.assertRaises(ca.CoverageAxisError):  # the request stays until cleared
            ca.candidates(BOX_V, BOX_F, context=ctx, **SMALL)
        ctx.clear_cancel()
        self.assertGreater(ca.candidates(BOX_V, BOX_F, context=ctx, **SMALL).count, 0)

    def test_callback_exception_cancels_and_is_raised(self):
        def progress(stage, fraction):
            raise KeyError("from the callback")

        ctx = ca.Context(progress=progress)
        with self.assertRaises(KeyError):
            ca.candidates(BOX_V, BOX_F, context=ctx, **SMALL)

    def test_log_and_threads(self):
        messages = []
        ctx = ca.Context(threads=1, log=lambda level, m: messages.append((level, m)))
        self.assertEqual(ctx.threads, 1)
        serial = ca.skeletonize(BOX_V, BOX_F, context=ctx, **SMALL)
        self.assertTrue(any("surface samples" in m for _, m in messages))
        parallel = ca.skeletonize(BOX_V, BOX_F, context=ca.Context(threads=4), **SMALL)
        self.assertEqual(rows(serial.centers), rows(parallel.centers))

    def test_evaluate_one_ball(self):
        sk = ca.Skeleton([(1, 0.5, 0.5)], [0.5])
        e = ca.evaluate(BOX_V, BOX_F, sk, surface_samples=5000, envelope_samples=20000)
        diag = math.sqrt(6)
        self.assertAlmostEqual(e["diagonal"], diag, delta=1e-12)
        self.assertAlmostEqual(e["hd_surface_to_recon"], 100 * (math.sqrt(1.5) - 0.5) / diag, delta=0.01)
        self.assertLessEqual(e["hd_recon_to_surface"], 100 * 0.5 / diag + 1e-9)

    def test_fox_equals_the_cli(self):
        import tempfile
        fox = os.path.join(DATA, "fox.obj")
        with tempfile.TemporaryDirectory() as tmp:
            ma = os.path.join(tmp, "fox.ma")
            subprocess.run([os.environ["CA_CLI"], fox, "-o", ma, "--quiet"], check=True)
            balls, edges, faces = read_ma(ma)
        v, f = read_obj(fox)
        sk = ca.skeletonize(v, f)
        self.assertEqual(len(sk), len(balls))
        self.assertEqual((len(sk.edges), len(sk.faces)), (edges, faces))
        for (x, y, z), r, ball in zip(rows(sk.centers), rows(sk.radii), balls):
            for mine, printed in zip((x, y, z, r), ball):
                # the .ma file prints 9 significant digits: at most half a unit of the 9th off
                self.assertLessEqual(abs(mine - printed), 5e-9 * abs(printed), (mine, printed))

    def test_correspondence_and_rig_equal_the_cli(self):
        import json
        import tempfile
        fox = os.path.join(DATA, "fox.obj")
        with tempfile.TemporaryDirectory() as tmp:
            ma, cj = os.path.join(tmp, "fox.ma"), os.path.join(tmp, "fox.json")
            report = json.loads(subprocess.run([os.environ["CA_CLI"], fox, "-o", ma, "--correspondence", cj, "--json"],
                                               check=True, capture_output=True, text=True).stdout)
            with open(cj) as fh:
                cli = json.load(fh)["vertices"]
        v, f = read_obj(fox)
        sk = ca.skeletonize(v, f)
        c = ca.correspond(v, f, sk)
        self.assertEqual(len(c), len(v))
        self.assertEqual(len(cli), len(v))
        for i, entry in enumerate(cli):
            balls, weights = rows(c.balls)[i], rows(c.weights)[i]
            used = [k for k in range(ca.INFLUENCES) if weights[k] > 0]
            self.assertEqual([balls[k] for k in used], entry["balls"], i)
            for k, w in zip(used, entry["weights"]):
                self.assertAlmostEqual(weights[k], w, delta=1e-9)
            self.assertEqual(ca.NEAREST_KINDS[rows(c.nearest_kinds)[i]], entry["nearest"]["kind"])
            self.assertEqual(rows(c.nearest_indices)[i], entry["nearest"]["index"])
        r = ca.rig(v, f, sk)
        self.assertEqual((len(r), r.branch_count), (report["rig"]["joints"], report["rig"]["branches"]))
        self.assertEqual(rows(r.branches), [e["branch"] for e in cli])
        parents = rows(r.parents)
        self.assertEqual(parents[0], -1)
        self.assertTrue(all(0 <= p < j for j, p in enumerate(parents) if j > 0))
        for w in rows(r.weights):
            self.assertAlmostEqual(sum(w), 1.0, delta=1e-12)
        self.assertEqual(ca.defaults("rig")["max_joints"], 64)
        few = ca.rig(v, f, sk, max_joints=5)
        self.assertLessEqual(len(few), 5)
        with self.assertRaises(ca.CoverageAxisError) as e:
            ca.rig(v, f, sk, max_joints=0)
        self.assertEqual(e.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)
        with self.assertRaises(ca.CoverageAxisError) as e:
            ca.correspond(v, f, ca.Skeleton([(0, 0, 0)], [1.0, 2.0]))
        self.assertEqual(e.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)


    def test_proxies_equal_the_cli(self):
        import json
        import tempfile
        fox = os.path.join(DATA, "fox.obj")
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "fox.json")
            subprocess.run([os.environ["CA_CLI"], fox, "-o", os.path.join(tmp, "fox.ma"), "--quiet", "--proxies",
                            "capsules", "--proxy-count", "8", "--proxy-mode", "conservative", "--proxies-json", out],
                           check=True)
            with open(out) as f:
                cli = json.load(f)
        v, f = read_obj(fox)
        cset = ca.candidates(v, f)
        sk = ca.connect(ca.select(cset))
        px = ca.proxies(cset, sk, shapes="capsules", count=8, mode="conservative")
        self.assertEqual(len(px), len(cli["proxies"]))
        self.assertTrue(1 <= len(px) <= 8)
        for mine, printed in zip(px.primitives, cli["proxies"]):
            self.assertEqual(set(mine), set(printed))
            for key, value in mine.items():
                if key == "kind":
                    self.assertEqual(value, printed[key])
                else:  # the JSON file prints doubles exactly (shortest round trip)
                    self.assertEqual(list(value) if isinstance(value, tuple) else value, printed[key], key)
        for key in ("hd_two_sided", "hd_surface_to_proxies", "outside_volume", "outside_bound", "candidates"):
            self.assertEqual(px.stats[key], cli[key], key)
        self.assertEqual(ca.defaults("proxies")["mode"], "inscribed")
        # lengths are checked before the call; names of modes too
        bad = ca.Skeleton(sk.centers, list(rows(sk.radii))[:-1], sk.edges, sk.faces)
        with self.assertRaises(ca.CoverageAxisError) as e:
            ca.proxies(cset, bad)
        self.assertEqual(e.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)
        with self.assertRaises(ca.CoverageAxisError) as e:
            ca.proxies(cset, sk, mode="outside")
        self.assertEqual(e.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)
        with self.assertRaises(ca.CoverageAxisError) as e:
            ca.proxies(cset, sk, count=0)
        self.assertEqual(e.exception.status, ca.CA_ERROR_INVALID_ARGUMENT)

    def test_bone_colliders(self):
        # a 2 x 1 x 1 box: its x = 0 end weighted to joint 0, its x = 2 end to joint 1 (a child whose
        # inverse bind turns the frame about z and moves it), so each joint dominates one half
        v = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0), (0, 0, 1), (2, 0, 1), (2, 1, 1), (0, 1, 1)]
        f = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7),
             (2, 7, 6), (3, 0, 4), (3, 4, 7)]
        joints = [(0, 1) if x == 0 else (1, 0) for x, _, _ in v]
        weights = [(1.0, 0.0)] * 8
        ib = [(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1), (0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, -1, 2, 0.5, 1)]
        cset = ca.candidates(v, f, cover_samples=300, voronoi_samples=800)
        bc = ca.bone_colliders(cset, [-1, 0], joints, weights, ib)
        self.assertEqual([c["joint"] for c in bc.colliders], [0, 1])
        self.assertEqual(bc.stats["contained_fraction"], 1.0)
        self.assertEqual(bc.stats["joints_with_collider"], 2)
        self.assertEqual(ca.defaults("bone_colliders")["mode"], "conservative")

        def distance(c, x):  # to the capsule as placed, by ternary search along its axis
            top = [c["center"][k] + 0.5 * c["height"] * c["axis"][k] for k in range(3)]
            bottom = [c["center"][k] - 0.5 * c["height"] * c["axis"][k] for k in range(3)]
            g = lambda t: math.dist(x, [bottom[k] + t * (top[k] - bottom[k]) for k in range(3)]) - \
                (c["radius_bottom"] + t * (c["radius_top"] - c["radius_bottom"]))
            lo, hi = 0.0, 1.0
            for _ in range(100):
                m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
                lo, hi = (lo, m2) if g(m1) <= g(m2) else (m1, hi)
            return min(g(0), g(1), g(0.5 * (lo + hi)))

        for c in bc.colliders:
            m = ib[c["joint"]]
            x0 = 0 if c["joint"] == 0 else 1
            for x in [(x0 + a, b, d) for a in (0, 1) for b in (0, 1) for d in (0, 1)]:
                y = [m[r] * x[0] + m[4 + r] * x[1] + m[8 + r] * x[2] + m[12 + r] for r in range(3)]
                self.assertLessEqual(distance(c, y), 1e-9)
        self.assertEqual([c["joint"] for c in ca.bone_colliders(cset, [-1, 0], joints, weights, ib,
                                                                 skip_joints=[0]).colliders], [1])
        for bad in (dict(parents=[1, 0]), dict(weights=[(float("nan"), 0.0)] * 8), dict(mode="outside"),
                    dict(ib=[ib[0], [2.0] + list(ib[1][1:])])):
            with self.assertRaises(ca.CoverageAxisError) as e:
                opts = {"mode": bad["mode"]} if "mode" in bad else {}
                ca.bone_colliders(cset, bad.get("parents", [-1, 0]), joints, bad.get("weights", weights),
                                  bad.get("ib", ib), **opts)
            self.assertIn(e.exception.status, (ca.CA_ERROR_INVALID_INPUT, ca.CA_ERROR_INVALID_ARGUMENT))


class NumpyTest(unittest.TestCase):
    """numpy in and out; runs where numpy is installed, which this run requires."""

    def setUp(self):
        self.assertTrue(ca.HAVE_NUMPY, "numpy is not installed for %s (scripts/install-deps.sh)" % sys.executable)
        self.v, self.f = np.array(BOX_V, dtype=np.float64), np.array(BOX_F, dtype=np.uint32)

    def test_numpy_out(self):
        sk = ca.skeletonize(self.v, self.f, **SMALL)
        n = len(sk)
        for a, dtype, shape in ((sk.centers, np.float64, (n, 3)), (sk.radii, np.float64, (n,)),
                                (sk.edges, np.uint32, (len(sk.edges), 2)), (sk.faces, np.uint32, (len(sk.faces), 3))):
            self.assertIsInstance(a, np.ndarray)
            self.assertEqual((a.dtype, a.shape), (dtype, shape))
            self.assertFalse(a.flags.writeable)
        cset = ca.candidates(self.v, self.f, **SMALL)
        self.assertEqual(cset.samples.shape, (cset.sample_count, 3))
        self.assertEqual(cset.sample_count, SMALL["cover_samples"])

    def test_triangle_arrays_are_not_truth_tested(self):
        # a numpy triangle array used to raise "The truth value of an array ... is ambiguous"
        sk = ca.skeletonize(self.v, self.f, **SMALL)
        self.assertEqual(sk.stats["method"], "medial")  # a mesh, not a point cloud
        self.assertEqual(ca.skeletonize(BOX_V, BOX_F, **SMALL).centers.tolist(), sk.centers.tolist())

    def test_dtype_conversions(self):
        want = ca.skeletonize(self.v, self.f, **SMALL).centers.tolist()
        for vd in (np.float32, np.int64, np.int32):
            for fd in (np.int64, np.int32, np.uint16, np.uint64, np.float64):
                sk = ca.skeletonize(self.v.astype(vd), self.f.astype(fd), **SMALL)
                self.assertEqual(sk.centers.tolist(), want, (vd, fd))
        for bad in (self.f.astype(np.float64) + 0.5, self.f.astype(np.int64) - 1, self.f[:, :2]):
            with self.assertRaises(ca.CoverageAxisError) as cm:
                ca.skeletonize(self.v, bad)
            self.assertEqual(cm.exception.status, ca.CA_ERROR_INVALID_INPUT)
        with self.assertRaises(ca.CoverageAxisError):
            ca.skeletonize(self.v.astype(str), self.f)

    def test_no_copy_of_contiguous_float64_and_uint32(self):
        view, keep = _steps._surface(self.v, self.f, None)
        self.assertEqual(view.positions, self.v.ctypes.data)
        self.assertEqual(view.triangles, self.f.ctypes.data)
        wide = np.hstack([self.v, np.ones((len(self.v), 2))])  # rows of 5 doubles: a strided view
        view, keep = _steps._surface(wide[:, :3], self.f, None)
        self.assertEqual((view.positions, view.position_stride), (wide.ctypes.data, 40))
        view, keep = _steps._surface(self.v.astype(np.float32), self.f.astype(np.int64), None)
        self.assertNotEqual(view.positions, self.v.ctypes.data)
        self.assertEqual(ca.skeletonize(wide[:, :3], self.f, **SMALL).centers.tolist(),
                         ca.skeletonize(self.v, self.f, **SMALL).centers.tolist())

    def test_results_view_the_library_memory(self):
        sk = ca.connect(ca.select(ca.candidates(self.v, self.f, **SMALL)))
        again = ca.evaluate(self.v, self.f, sk, surface_samples=2000, envelope_samples=5000)
        listed = ca.Skeleton(sk.centers.tolist(), sk.radii.tolist(), sk.edges.tolist(), sk.faces.tolist())
        self.assertEqual(again, dict(ca.evaluate(self.v, self.f, listed, surface_samples=2000, envelope_samples=5000),
                                     time_s=again["time_s"]))

    def test_arrays_keep_their_result_alive_and_nothing_else(self):
        gc.disable()  # reference counts alone must free a result: the views form no cycle with it
        try:
            cset = ca.candidates(self.v, self.f, **SMALL)
            handle = weakref.ref(cset._handle)
            centers = cset.centers
            del cset
            self.assertIsNotNone(handle())
            self.assertEqual(centers.shape[1], 3)
            del centers
            self.assertIsNone(handle())
        finally:
            gc.enable()

    def test_evaluate_packs_strided_arrays(self):
        sk = ca.skeletonize(self.v, self.f, **SMALL)
        opts = dict(surface_samples=2000, envelope_samples=5000)
        want = ca.evaluate(self.v, self.f, sk, **opts)
        wide = np.hstack([sk.centers, sk.radii[:, None]])  # rows of 4: strided centers and radii
        got = ca.evaluate(self.v, self.f, ca.Skeleton(wide[:, :3], wide[:, 3], sk.edges, sk.faces), **opts)
        self.assertEqual(dict(got, time_s=0), dict(want, time_s=0))

    def test_runs_without_numpy(self):
        env = dict(os.environ, CA_TEST_HIDE_NUMPY="1")
        r = subprocess.run([sys.executable, "-m", "unittest", "test_coverage_axis"], env=env,
                           cwd=os.path.dirname(os.path.abspath(__file__)), capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("OK", r.stderr)
        r = subprocess.run([sys.executable, "-c", "import sys; sys.modules['numpy'] = None\n"
                            "import coverage_axis as ca; print(ca.HAVE_NUMPY)\n"
                            "sk = ca.skeletonize(%r, %r, cover_samples=400, voronoi_samples=800)\n"
                            "print(type(sk.centers).__name__, type(sk.centers[0]).__name__, sk.centers)"
                            % (BOX_V, BOX_F)], env=env, capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        have, kind, item, centers = r.stdout.split(maxsplit=3)
        self.assertEqual((have, kind, item), ("False", "list", "tuple"))
        self.assertEqual(eval(centers), [tuple(c) for c in ca.skeletonize(self.v, self.f, **SMALL).centers.tolist()])


def load_tests(loader, tests, pattern):
    """With numpy hidden, the common tests only; else all, and NumpyTest requires numpy."""
    classes = [CommonTest] if os.environ.get("CA_TEST_HIDE_NUMPY") else [CommonTest, NumpyTest]
    return unittest.TestSuite(loader.loadTestsFromTestCase(c) for c in classes)


if __name__ == "__main__":
    unittest.main()
