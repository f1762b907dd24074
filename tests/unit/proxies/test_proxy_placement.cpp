// test_proxy_placement.cpp: each primitive as an engine places it (proxy_placement): known
// answers for a rotated box and a capsule along X; on random capsules and boxes, the node's
// transform maps the canonical shape's points (ball centres, box corners) onto the library's
// primitive, and signed distances computed in the node's frame from the glTF parameters alone (a
// capsule as the union of its interpolated balls, minimised by ternary search; a box from its
// extents) agree with the library's at random points; capsules with one ball inside the other
// become that ball.
#include <doctest/doctest.h>

#include "proxies.h"

#include <cmath>
#include <random>

namespace {

using ca::Vec3;

// Signed distance to the glTF capsule {height, radiusTop, radiusBottom} in its node's frame, outside
// exactly (the capsule is the union of the balls interpolated between its two balls, and the
// distance to a union is the least distance to its balls, a convex function of the parameter);
// inside only its sign is meaningful.
double capsule_distance_local(const ca::ProxyPlacement& c, const Vec3& x) {
    auto f = [&](double t) {
        const Vec3 centre(0, c.height * (t - 0.5), 0);
        return (x - centre).norm() - (c.radius_bottom + t * (c.radius_top - c.radius_bottom));
    };
    double lo = 0, hi = 1;
    for (int i = 0; i < 200; ++i) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (f(m1) < f(m2)) hi = m2;
        else lo = m1;
    }
    return std::min({f(0.5 * (lo + hi)), f(0), f(1)});
}

double box_distance_local(const ca::ProxyPlacement& b, const Vec3& x) {
    const Vec3 q = x.cwiseAbs() - 0.5 * b.size;
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

Vec3 to_node(const ca::ProxyPlacement& p, const Vec3& x) { return p.rotation.conjugate() * (x - p.translation); }
Vec3 to_world(const ca::ProxyPlacement& p, const Vec3& x) { return p.rotation * x + p.translation; }

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

}  // namespace

TEST_CASE("proxy_placement: a box turned a quarter about Z, and a capsule along X") {
    Eigen::Matrix3d axes;
    axes.col(0) = Vec3(0, 1, 0);
    axes.col(1) = Vec3(-1, 0, 0);
    axes.col(2) = Vec3(0, 0, 1);
    const ca::ProxyPlacement box = ca::proxy_placement(ca::make_box(Vec3(1, 2, 3), axes, Vec3(1, 2, 3)));
    CHECK(box.kind == ca::ProxyKind::box);
    CHECK((box.translation - Vec3(1, 2, 3)).norm() < 1e-15);
    CHECK((box.size - Vec3(2, 4, 6)).norm() < 1e-15);
    const double h = std::sqrt(0.5);
    CHECK((box.rotation.coeffs() - Eigen::Vector4d(0, 0, h, h)).norm() < 1e-12);   // x y z w
    CHECK((box.axis - Vec3(-1, 0, 0)).norm() < 1e-12);

    const ca::Proxy capsule{ca::ProxyKind::capsule, {Vec3(0, 0, 0), 0.5}, {Vec3(2, 0, 0), 0.25}};
    const ca::ProxyPlacement c = ca::proxy_placement(capsule);
    CHECK(c.kind == ca::ProxyKind::capsule);
    CHECK((c.translation - Vec3(1, 0, 0)).norm() < 1e-15);
    CHECK(c.height == doctest::Approx(2).epsilon(1e-15));
    CHECK(c.radius_top == 0.25);      // b on top
    CHECK(c.radius_bottom == 0.5);
    CHECK((c.axis - Vec3(1, 0, 0)).norm() < 1e-15);
    CHECK((c.rotation.coeffs() - Eigen::Vector4d(0, 0, -h, h)).norm() < 1e-12);   // +Y turned onto +X

    const ca::ProxyPlacement s = ca::proxy_placement({ca::ProxyKind::sphere, {Vec3(4, 5, 6), 2}, {Vec3(4, 5, 6), 2}});
    CHECK(s.kind == ca::ProxyKind::sphere);
    CHECK(s.radius_top == 2);
    CHECK(s.radius_bottom == 2);
    CHECK((s.translation - Vec3(4, 5, 6)).norm() == 0);
    CHECK(s.rotation.coeffs() == Eigen::Quaterniond::Identity().coeffs());
}

TEST_CASE("proxy_placement: random capsules and boxes map onto the library's primitives") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1);
    std::normal_distribution<double> g;
    int capsules = 0, boxes = 0;
    for (int trial = 0; trial < 300; ++trial) {
        ca::Proxy p;
        const Vec3 c(3 * u(rng), 3 * u(rng), 3 * u(rng));
        if (trial % 2 == 0) {
            Vec3 d(g(rng), g(rng), g(rng));
            if (trial % 10 == 0) d = Vec3(0, -1, 0);   // straight down: the turn of +Y onto -Y
            if (trial % 10 == 2) d = Vec3(0, 1, 0);    // straight up: no turn
            d = d.normalized() * (1 + 2 * pos(rng));   // longer than the radii differ: a capsule
            const double ra = pos(rng), rb = trial % 4 == 0 ? ra : pos(rng);   // tapered, and not
            p = {ca::ProxyKind::capsule, {c, ra}, {c + d, rb}};
        } else {
            Eigen::Matrix3d axes = random_rotation(rng);
            if (trial % 6 == 1) axes.col(2) = -axes.col(2);   // left-handed: the same box
            p = ca::make_box(c, axes, Vec3(pos(rng), pos(rng), pos(rng)));
        }
        const ca::ProxyPlacement pl = ca::proxy_placement(p);
        REQUIRE(pl.kind == p.kind);
        CHECK(std::abs(pl.rotation.norm() - 1) < 1e-14);
        CHECK(pl.rotation.w() >= 0);
        CHECK((pl.axis - pl.rotation * Vec3::UnitY()).norm() < 1e-14);
        double worst = 0;
        if (p.kind == ca::ProxyKind::capsule) {
            ++capsules;
            CHECK(pl.height > 0);
            // the canonical balls land on the library's
            worst = std::max((to_world(pl, Vec3(0, pl.height / 2, 0)) - p.b.center).norm(),
                             (to_world(pl, Vec3(0, -pl.height / 2, 0)) - p.a.center).norm());
            CHECK(pl.radius_top == p.b.radius);
            CHECK(pl.radius_bottom == p.a.radius);
        } else {
            ++boxes;
            for (int corner = 0; corner < 8; ++corner) {
                Vec3 local, world = p.a.center;
                for (int k = 0; k < 3; ++k) {
                    const double s = (corner >> k) & 1 ? 1 : -1;
                    local[k] = s * pl.size[k] / 2;
                    world += s * p.half[k] * p.axes.col(k);
                }
                // the node's corner is one of the library box's corners (a flipped edge swaps them)
                double nearest = INFINITY;
                for (int other = 0; other < 8; ++other) {
                    Vec3 w = p.a.center;
                    for (int k = 0; k < 3; ++k) w += ((other >> k) & 1 ? 1 : -1) * p.half[k] * p.axes.col(k);
                    nearest = std::min(nearest, (to_world(pl, local) - w).norm());
                }
                worst = std::max(worst, nearest);
            }
        }
        CHECK(worst < 1e-12);
        // signed distances from the glTF parameters alone agree with the library's
        for (int i = 0; i < 50; ++i) {
            const Vec3 x = p.a.center + Vec3(2 * u(rng), 2 * u(rng), 2 * u(rng));
            const double lib = ca::proxy_distance(p, x);
            const Vec3 local = to_node(pl, x);
            const double ours = p.kind == ca::ProxyKind::capsule ? capsule_distance_local(pl, local)
                                                                 : box_distance_local(pl, local);
            if (p.kind == ca::ProxyKind::box || lib > 0) CHECK(std::abs(lib - ours) < 1e-9);
            else CHECK(ours <= 1e-9);   // inside: the union-of-balls value keeps only its sign
        }
    }
    CHECK(capsules == 150);
    CHECK(boxes == 150);
}

TEST_CASE("proxy_placement: a capsule with one ball inside the other is that ball, a sphere") {
    const Vec3 a(1, 1, 1);
    // b inside a
    ca::ProxyPlacement p = ca::proxy_placement({ca::ProxyKind::capsule, {a, 1.0}, {a + Vec3(0.3, 0, 0), 0.5}});
    CHECK(p.kind == ca::ProxyKind::sphere);
    CHECK(p.radius_top == 1.0);
    CHECK((p.translation - a).norm() == 0);
    // a inside b
    p = ca::proxy_placement({ca::ProxyKind::capsule, {a, 0.2}, {a + Vec3(0, 0, 0.5), 0.75}});
    CHECK(p.kind == ca::ProxyKind::sphere);
    CHECK(p.radius_top == 0.75);
    CHECK((p.translation - (a + Vec3(0, 0, 0.5))).norm() == 0);
    // the same ball twice
    p = ca::proxy_placement({ca::ProxyKind::capsule, {a, 0.5}, {a, 0.5}});
    CHECK(p.kind == ca::ProxyKind::sphere);
    CHECK(p.radius_top == 0.5);
    // just out of each other: still a capsule
    p = ca::proxy_placement({ca::ProxyKind::capsule, {a, 1.0}, {a + Vec3(0.51, 0, 0), 0.5}});
    CHECK(p.kind == ca::ProxyKind::capsule);
}
