// test_point_winding.cpp: the point-cloud winding number: about 1 inside and 0 outside a sampled
// sphere and torus, the hierarchical sum against the brute-force sum, tangent-plane Voronoi
// areas summing to the surface area, reversed normals giving -w.
#include "point_winding.h"
#include "rng.h"
#include "support/clouds.h"
#include "support/shapes.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ca;

TEST_CASE("point-cloud winding number: sphere inside/outside, areas, brute force, reversed normals") {
    const double R = 1.0;
    const shapes::Cloud c = shapes::sample_cloud(shapes::sphere(R, 96, 192), 6000);
    PointCloudWinding w(c.points, c.normals);
    double total = 0;
    for (double a : w.areas()) total += a;
    CHECK(total == doctest::Approx(4 * 3.14159265358979323846 * R * R).epsilon(0.05));
    CHECK(w(Vec3(0, 0, 0)) == doctest::Approx(1.0).epsilon(0.03));
    CHECK(w(Vec3(0.5, 0.3, -0.2)) == doctest::Approx(1.0).epsilon(0.03));
    CHECK(std::abs(w(Vec3(2.5, 0, 0))) < 0.03);
    CHECK(std::abs(w(Vec3(1.3, 1.0, 0.4))) < 0.05);
    Rng rng(3);
    double worst = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 q(3 * rng.uniform() - 1.5, 3 * rng.uniform() - 1.5, 3 * rng.uniform() - 1.5);
        if (std::abs(q.norm() - R) < 0.1) continue;   // near the surface the sum is dominated by a few points
        const double exact = point_winding_brute_force(c.points, c.normals, w.areas(), q);
        worst = std::max(worst, std::abs(w(q) - exact));
        CHECK((q.norm() < R) == (exact > 0.5));
    }
    CHECK(worst < 0.02);
    std::vector<Vec3> flipped = c.normals;
    for (Vec3& n : flipped) n = -n;
    PointCloudWinding inv(c.points, flipped);
    CHECK(inv(Vec3(0.1, 0.2, 0)) == doctest::Approx(-w(Vec3(0.1, 0.2, 0))).epsilon(1e-9));
}

TEST_CASE("point-cloud winding number: torus hole is outside, tube inside") {
    const shapes::Cloud c = shapes::sample_cloud(shapes::torus(1.0, 0.35, 128, 48), 8000);
    PointCloudWinding w(c.points, c.normals);
    CHECK(w(Vec3(1.0, 0, 0)) == doctest::Approx(1.0).epsilon(0.05));
    CHECK(w(Vec3(0, -1.0, 0.1)) == doctest::Approx(1.0).epsilon(0.05));
    CHECK(std::abs(w(Vec3(0, 0, 0))) < 0.05);
    CHECK(std::abs(w(Vec3(0, 0, 0.8))) < 0.05);
}

TEST_CASE("point-cloud winding number: empty and mismatched input give 0") {
    PointCloudWinding empty({}, {});
    CHECK(empty(Vec3(0, 0, 0)) == 0.0);
    PointCloudWinding bad({Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 0, 1)});
    CHECK(bad(Vec3(0, 0, 0.5)) == 0.0);
}
