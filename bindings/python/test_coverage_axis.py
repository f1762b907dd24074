"""test_coverage_axis.py: tests of the Python binding (unittest, standard library only). Run with
CA_LIBRARY=/path/to/libcoverage_axis.so python3 -m unittest test_coverage_axis (CTest does)."""
import math
import unittest

import coverage_axis as ca

BOX_V = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0), (0, 0, 1), (2, 0, 1), (2, 1, 1), (0, 1, 1)]
BOX_F = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
         (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]


class BindingTest(unittest.TestCase):
    def test_version(self):
        self.assertRegex(ca.version(), r"^\d+\.\d+\.\d+$")

    def test_box_skeleton_is_on_the_medial_axis(self):
        sk = ca.skeletonize(BOX_V, BOX_F, cover_samples=400, voronoi_samples=800)
        self.assertGreaterEqual(len(sk.radii), 2)
        self.assertTrue(sk.stats["proven_optimal"])
        for (x, y, z), r in zip(sk.centers, sk.radii):
            nearest_face = min(x, 2 - x, y, 1 - y, z, 1 - z)
            self.assertGreater(nearest_face, 0)
            self.assertGreaterEqual(r, nearest_face - 1e-9)
            self.assertLessEqual(r, nearest_face + 0.1)
        for i, j in sk.edges:
            self.assertLess(i, len(sk.radii))
            self.assertLess(j, len(sk.radii))

    def test_target_count_and_routes(self):
        full = ca.skeletonize(BOX_V, BOX_F, cover_samples=400, voronoi_samples=800)
        k = max(1, len(full.radii) - 2)
        small = ca.skeletonize(BOX_V, BOX_F, cover_samples=400, voronoi_samples=800, target_count=k)
        self.assertLessEqual(len(small.radii), k)
        self.assertGreater(small.stats["delta_absolute"], full.stats["delta_absolute"])
        for route in ("power", "medial"):
            sk = ca.skeletonize(BOX_V, BOX_F, cover_samples=400, voronoi_samples=800, connect=route)
            self.assertEqual(sk.stats["components"], 1)

    def test_effort_levels_agree_when_proven(self):
        fast = ca.skeletonize(BOX_V, BOX_F, cover_samples=400, voronoi_samples=800, effort="fast")
        prove = ca.skeletonize(BOX_V, BOX_F, cover_samples=400, voronoi_samples=800, effort="prove")
        self.assertTrue(prove.stats["proven_optimal"])
        self.assertGreaterEqual(len(fast.radii), len(prove.radii))
        self.assertLessEqual(fast.stats["lower_bound"], prove.stats["objective"])
        if fast.stats["proven_optimal"]:
            self.assertEqual(len(fast.radii), len(prove.radii))

    def test_results_in_caller_units(self):
        a = ca.skeletonize(BOX_V, BOX_F, cover_samples=400, voronoi_samples=800)
        big = [(1000 * x, 1000 * y, 1000 * z) for x, y, z in BOX_V]
        b = ca.skeletonize(big, BOX_F, cover_samples=400, voronoi_samples=800)
        self.assertEqual(len(a.radii), len(b.radii))
        for ra, rb in zip(a.radii, b.radii):
            self.assertAlmostEqual(1000 * ra, rb, delta=1e-6 * rb)

    def test_bad_input_raises_with_status_and_message(self):
        bad = list(BOX_V)
        bad[2] = (2, float("nan"), 0)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(bad, BOX_F)
        self.assertEqual(cm.exception.status, 4)
        self.assertIn("vertex 2", str(cm.exception))
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V, [(0, 1, 99)])
        self.assertEqual(cm.exception.status, 4)
        with self.assertRaises(ca.CoverageAxisError) as cm:
            ca.skeletonize(BOX_V[:4], [(0, 1, 2), (0, 2, 3)])
        self.assertEqual(cm.exception.status, 5)

    def test_evaluate_one_ball(self):
        sk = ca.Skeleton([(1, 0.5, 0.5)], [0.5], [], [], {})
        e = ca.evaluate(BOX_V, BOX_F, sk, surface_samples=5000, envelope_samples=20000)
        diag = math.sqrt(6)
        self.assertAlmostEqual(e["hd_surface_to_recon"], 100 * (math.sqrt(1.5) - 0.5) / diag, delta=0.01)
        self.assertLessEqual(e["hd_recon_to_surface"], 100 * 0.5 / diag + 1e-9)


if __name__ == "__main__":
    unittest.main()
