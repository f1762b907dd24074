// test_pipeline.cpp: the core pipeline (candidates -> selection -> connection) on shapes whose
// medial axis is known: a sphere (its centre), a capsule (its axis segment), a torus (its core
// circle), and unit handling (results in the caller's units, independent of scale).
#include <doctest/doctest.h>

#include "support/core_run.h"
#include "support/shapes.h"

#include <cmath>

namespace {

// Runs the three steps (support/core_run.h), connected on the power route; with the exact cover,
// it must be proven optimal.
CoreRun run(ca::Mesh mesh, ca::CandidateOptions copt = {}, ca::SelectOptions sopt = {}) {
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(std::move(mesh), {}, surface).ok());
    ca::ConnectOptions power;   // the route these checks measure (the medial one: connect/test_connect.cpp)
    power.method = ca::ConnectMethod::power;
    CoreRun r = core_run(std::move(surface), copt, sopt, power);
    if (sopt.cover.solver == ca::Solver::exact) REQUIRE(r.sel.cover.proven_optimal == 1);
    return r;
}

}  // namespace

TEST_CASE("sphere: one ball at the centre with the sphere's radius") {
    const double R = 3.0;
    CoreRun r = run(shapes::sphere(R));
    CHECK(r.sel.cover.proven_optimal == 1);
    REQUIRE(r.skeleton.balls.size() == 1);
    CHECK(r.skeleton.balls[0].center.norm() < 0.03 * R);
    CHECK(std::abs(r.skeleton.balls[0].radius - R) < 0.03 * R);
    CHECK(r.skeleton.edges.empty());
}

TEST_CASE("capsule: every ball lies on the axis segment with the capsule's radius") {
    const double L = 2.0, R = 0.5;
    CoreRun r = run(shapes::capsule(L, R));
    CHECK(r.sel.cover.proven_optimal == 1);
    REQUIRE(r.skeleton.balls.size() >= 2);
    double min_x = 1e9, max_x = -1e9;
    for (const ca::Ball& b : r.skeleton.balls) {
        const double off_axis = std::hypot(b.center.y(), b.center.z());
        CHECK(off_axis < 0.05 * R);
        CHECK(std::abs(b.center.x()) < L + 0.05 * R);
        CHECK(std::abs(b.radius - R) < 0.05 * R);
        min_x = std::min(min_x, b.center.x());
        max_x = std::max(max_x, b.center.x());
    }
    // the balls span the segment: the end balls must reach the caps
    CHECK(max_x - min_x > 2 * L - 2 * (0.02 * (2 * L + 2 * R)) - 0.1 * R);
}

TEST_CASE("torus: a ring of balls on the core circle") {
    const double R = 1.0, r = 0.3;
    CoreRun run_ = run(shapes::torus(R, r));
    const auto& balls = run_.skeleton.balls;
    REQUIRE(balls.size() >= 4);
    double angle_gap = 0;
    std::vector<double> angles;
    for (const ca::Ball& b : balls) {
        const double from_core = std::hypot(std::hypot(b.center.x(), b.center.y()) - R, b.center.z());
        CHECK(from_core < 0.05 * r * 4);
        CHECK(std::abs(b.radius - r) < 0.1 * r);
        angles.push_back(std::atan2(b.center.y(), b.center.x()));
    }
    std::sort(angles.begin(), angles.end());
    for (size_t i = 0; i < angles.size(); ++i) {
        const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * 3.14159265358979;
        angle_gap = std::max(angle_gap, next - angles[i]);
    }
    // a ring: no large angular hole (each ball covers about 2*asin((r + delta)/R) of the circle)
    CHECK(angle_gap < 1.2);
}

TEST_CASE("results are in the caller's units and do not depend on them") {
    ca::Mesh small = shapes::capsule(1.0, 0.4, 48, 32);
    ca::Mesh big = small;
    const ca::Vec3 shift(1000, -50, 7);
    for (ca::Vec3& v : big.vertices) v = v * 250.0 + shift;
    CoreRun a = run(small), b = run(big);
    REQUIRE(a.skeleton.balls.size() == b.skeleton.balls.size());
    for (size_t i = 0; i < a.skeleton.balls.size(); ++i) {
        CHECK((a.skeleton.balls[i].center * 250.0 + shift - b.skeleton.balls[i].center).norm() < 1e-6 * 250);
        CHECK(std::abs(a.skeleton.balls[i].radius * 250.0 - b.skeleton.balls[i].radius) < 1e-6 * 250);
    }
}

TEST_CASE("an inward-facing mesh is detected and gives the same skeleton") {
    ca::Mesh m = shapes::capsule(1.0, 0.4, 48, 32);
    ca::Mesh flipped = m;
    for (ca::Tri& t : flipped.triangles) std::swap(t[1], t[2]);
    ca::Surface s;
    REQUIRE(ca::prepare_surface(flipped, {}, s).ok());
    CHECK(s.flipped);
    CoreRun a = run(m), b = run(flipped);
    // flipping back restores the very triangles of m, so every step computes the same values:
    // the same balls to the bit, the same edges and faces
    REQUIRE(a.skeleton.balls.size() == b.skeleton.balls.size());
    for (size_t i = 0; i < a.skeleton.balls.size(); ++i) {
        CAPTURE(i);
        CHECK(a.skeleton.balls[i].center == b.skeleton.balls[i].center);
        CHECK(a.skeleton.balls[i].radius == b.skeleton.balls[i].radius);
    }
    CHECK(a.skeleton.edges == b.skeleton.edges);
    CHECK(a.skeleton.faces == b.skeleton.faces);
}

TEST_CASE("random interior candidates: radius is the exact distance to the surface") {
    ca::CandidateOptions opt;
    opt.generator = ca::Generator::random;
    opt.random_candidates = 3000;
    CoreRun r = run(shapes::sphere(2.0, 32, 64), opt);
    for (const ca::Ball& b : r.set.balls) {
        // internal units: sphere of radius 0.5 centred at (0.5, 0.5, 0.5); the mesh is a polyhedron
        // inscribed in it, so the distance is at most 0.5 - |c - centre| and not much less
        const double ideal = 0.5 - (b.center - ca::Vec3(0.5, 0.5, 0.5)).norm();
        CHECK(b.radius <= ideal + 1e-9);
        CHECK(b.radius >= ideal - 0.01);
    }
    REQUIRE(r.skeleton.balls.size() >= 1);
}
