// test_candidates.cpp: candidate generation details: fallback balls make every sample coverable
// and grow towards the medial axis (on a sphere: towards the centre); Voronoi radii never exceed
// the distance to the nearest sample (empty balls).
#include <doctest/doctest.h>

#include "candidates.h"
#include "distance.h"
#include "kdtree.h"
#include "sampling.h"
#include "selection.h"
#include "support/shapes.h"
#include "winding.h"

#include <algorithm>
#include <atomic>
#include <cmath>

TEST_CASE("fallback balls: a stop request adds none") {
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(shapes::sphere(1.0, 32, 64), {}, surface).ok());
    ca::CandidateSet set;
    set.surface = surface;
    set.cover_samples = ca::sample_surface(surface.mesh, 200, 7);
    set.balls.push_back({ca::Vec3(0.8, 0.5, 0.5), 0.05});
    const ca::WindingNumber winding(surface.mesh);
    const ca::MeshDistance distance(surface.mesh);
    std::atomic<int> flag{1};
    ca::Monitor cancelled;
    cancelled.cancel_flag = &flag;
    CHECK(ca::add_fallback_balls(set, winding, distance, nullptr, 1, cancelled) == 0);
    CHECK(set.balls.size() == 1);
    CHECK(ca::add_fallback_balls(set, winding, distance, nullptr, 1, ca::Monitor{}) > 100);
}

TEST_CASE("fallback balls: every unreachable sample gets an inner ball that reaches it") {
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(shapes::sphere(1.0, 32, 64), {}, surface).ok());
    ca::CandidateSet set;
    set.surface = surface;
    set.cover_samples = ca::sample_surface(surface.mesh, 200, 7);
    const ca::Vec3 centre(0.5, 0.5, 0.5);   // unit-cube units: the sphere has radius 0.5
    set.balls.push_back({centre + ca::Vec3(0.3, 0, 0), 0.05});   // reaches only samples near +x
    const ca::WindingNumber winding(surface.mesh);
    const ca::MeshDistance distance(surface.mesh);
    const size_t added = ca::add_fallback_balls(set, winding, distance);
    CHECK(added > 100);
    REQUIRE(set.balls.size() == 1 + added);
    for (const ca::Vec3& s : set.cover_samples) {
        bool reached = false;
        for (const ca::Ball& b : set.balls) reached = reached || (b.center - s).norm() <= b.radius + ca::kFallbackReach;
        CHECK(reached);
    }
    for (size_t i = 1; i < set.balls.size(); ++i) {
        const ca::Ball& b = set.balls[i];
        CHECK(winding.inside(b.center));
        CHECK(std::abs(b.radius - distance.distance(b.center)) < 1e-12);
        // grown along the normal towards the centre: deep inside, radius a good part of 0.5
        CHECK(b.radius > 0.2);
        CHECK((b.center - centre).norm() + b.radius < 0.5 + 0.01);
    }
}

TEST_CASE("Voronoi candidates are empty balls: radius <= distance to the nearest Voronoi sample") {
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(shapes::capsule(1.0, 0.3, 48, 32), {}, surface).ok());
    ca::CandidateOptions opt;
    opt.voronoi_samples = 1500;
    opt.cover_samples = 300;
    ca::CandidateSet set;
    REQUIRE(ca::generate_candidates(surface, opt, ca::Monitor{}, set).ok());
    REQUIRE(!set.dense_samples.empty());
    const ca::PointTree tree(set.dense_samples);
    const ca::WindingNumber winding(set.surface.mesh);
    for (size_t i = 0; i + set.report.fallback_balls < set.balls.size(); ++i) {
        const ca::Ball& b = set.balls[i];
        size_t idx;
        double d2;
        REQUIRE(tree.nearest(b.center, 1, &idx, &d2) == 1);
        CHECK(b.radius <= std::sqrt(d2) + 1e-12);
        CHECK(winding(b.center) > 0.5);
    }
}

TEST_CASE("open mesh: oriented by the signed volume with its holes capped (a horn open away from the origin)") {
    // A horn around the x axis, radius (x / 2)^2 for x in [0, 2], closed by a flat lid at x = 2.
    // Without the lid its signed volume about the bbox corner is pi 2/5 - pi 2/3 < 0 although it
    // faces outward: deciding by it flips the outward horn and keeps the inward one, and then no
    // point is inside (winding number below 1/2 everywhere).
    const ca::Mesh closed = shapes::revolve(
        [](double t) {
            if (t <= 0.9) return std::pair<double, double>{std::min(2.0, 2 * t / 0.9), (t / 0.9) * (t / 0.9)};
            return std::pair<double, double>{2.0, (1 - t) / 0.1};
        },
        40, 32);
    ca::Mesh open = closed;
    open.triangles.clear();
    for (const ca::Tri& t : closed.triangles)
        if (std::min({closed.vertices[t[0]].x(), closed.vertices[t[1]].x(), closed.vertices[t[2]].x()}) < 1.999)
            open.triangles.push_back(t);
    REQUIRE(open.triangles.size() < closed.triangles.size());
    CHECK(ca::signed_volume(open) < 0);
    // the caps are the lid, oriented like the mesh: the capped volume is the closed horn's
    const ca::Mesh caps = ca::hole_caps(open);
    CHECK(caps.triangles.size() == 32);
    CHECK(ca::signed_volume(open) + ca::signed_volume(caps) == doctest::Approx(ca::signed_volume(closed)).epsilon(1e-9));
    ca::Mesh inward = open;
    for (ca::Tri& t : inward.triangles) std::swap(t[1], t[2]);
    for (const ca::Mesh* m : {static_cast<const ca::Mesh*>(&open), static_cast<const ca::Mesh*>(&inward)}) {
        CAPTURE(m == &inward);
        ca::Surface surface;
        REQUIRE(ca::prepare_surface(*m, {}, surface).ok());
        CHECK(surface.flipped == (m == &inward));
        ca::CandidateSet set;
        const ca::Status st = ca::generate_candidates(std::move(surface), {}, ca::Monitor{}, set);
        REQUIRE_MESSAGE(st.ok(), st.message);
        CHECK(set.balls.size() > 100);
        // no ball beyond the rim's plane (x = 1 in internal units: the horn is 2 long)
        double beyond = -1;
        for (const ca::Ball& b : set.balls) beyond = std::max(beyond, b.center.x() + b.radius - 1.0);
        CHECK(beyond < 0.005);
    }
}

TEST_CASE("open mesh: a hole beside a T-junction whose sliver is dropped is still capped") {
    // A unit box without its bottom (z = 0). The front wall (y = 0) is cut along x = 0.5: its left
    // half ends on the edge (0.5,0,0)-(0.5,0,1), its right half on (0.5,0,0)-(0.5,0,0.8)-(0.5,0,1),
    // and a zero-area sliver on those three points seals the T-junction, as exporters write it.
    // The sliver is dropped as zero-area; without it the bottom corner (0.5,0,0) would lie on four
    // boundary edges (the bottom loop and the slit). The bottom must still be capped, or balls
    // under it reach out below the box.
    ca::Mesh m;
    auto v = [&m](double x, double y, double z) {
        for (uint32_t i = 0; i < m.vertices.size(); ++i)
            if (m.vertices[i] == ca::Vec3(x, y, z)) return i;
        m.vertices.emplace_back(x, y, z);
        return uint32_t(m.vertices.size() - 1);
    };
    const ca::Vec3 middle(0.5, 0.5, 0.5);
    auto tri = [&m, &middle](uint32_t a, uint32_t b, uint32_t c) {   // faces away from the middle
        const ca::Vec3 &pa = m.vertices[a], &pb = m.vertices[b], &pc = m.vertices[c];
        if ((pb - pa).cross(pc - pa).dot((pa + pb + pc) / 3 - middle) < 0) std::swap(b, c);
        m.triangles.push_back({a, b, c});
    };
    auto quad = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) { tri(a, b, c), tri(a, c, d); };
    quad(v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1));   // back
    quad(v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1));   // left
    quad(v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1));   // right
    quad(v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1));   // top
    const uint32_t p0 = v(0.5, 0, 0), p1 = v(0.5, 0, 0.8), p2 = v(0.5, 0, 1);
    tri(v(0, 0, 0), p0, p2), tri(v(0, 0, 0), p2, v(0, 0, 1));                       // front, left half
    tri(p0, v(1, 0, 0), p1), tri(p1, v(1, 0, 0), v(1, 0, 1)), tri(p1, v(1, 0, 1), p2);   // right half
    // the sliver, oriented so that each of its edges meets its neighbour's reversed
    auto has_edge = [&m](uint32_t a, uint32_t b) {
        for (const ca::Tri& t : m.triangles)
            for (int k = 0; k < 3; ++k)
                if (t[k] == a && t[(k + 1) % 3] == b) return true;
        return false;
    };
    const bool forward = has_edge(p1, p0) && has_edge(p2, p1) && has_edge(p0, p2);
    REQUIRE((forward || (has_edge(p0, p1) && has_edge(p1, p2) && has_edge(p2, p0))));
    m.triangles.push_back(forward ? ca::Tri{p0, p1, p2} : ca::Tri{p0, p2, p1});

    ca::Surface surface;
    REQUIRE(ca::prepare_surface(m, {}, surface).ok());
    CHECK(surface.dropped_triangles == 1);
    CHECK_FALSE(surface.flipped);
    // the caps close the bottom: the box's volume
    REQUIRE_FALSE(surface.caps.triangles.empty());
    CHECK(ca::signed_volume(surface.mesh) + ca::signed_volume(surface.caps) == doctest::Approx(1.0).epsilon(1e-9));
    ca::CandidateSet set;
    const ca::Status st = ca::generate_candidates(std::move(surface), {}, ca::Monitor{}, set);
    REQUIRE_MESSAGE(st.ok(), st.message);
    REQUIRE(set.balls.size() > 100);
    double below = -1;   // internal units: the box's lowest point is at z = 0
    for (const ca::Ball& b : set.balls) below = std::max(below, b.radius - b.center.z());
    CHECK(below < 0.005);
}

TEST_CASE("open mesh: no candidate ball reaches out through a hole, closed meshes are unchanged") {
    // A sphere (axis x) without its cap beyond x = 0.6 R: Voronoi balls under the hole would reach
    // R - 0.6 R = 0.2 of the diameter beyond the hole's plane (the fallback balls too).
    const ca::Mesh closed = shapes::sphere(1.0, 24, 48);
    CHECK(ca::hole_caps(closed).triangles.empty());
    ca::Mesh open = closed;
    open.triangles.clear();
    for (const ca::Tri& t : closed.triangles)
        if ((closed.vertices[t[0]].x() + closed.vertices[t[1]].x() + closed.vertices[t[2]].x()) / 3 < 0.6)
            open.triangles.push_back(t);
    const ca::Mesh caps = ca::hole_caps(open);
    {
        std::atomic<int> flag{1};
        ca::Monitor cancelled;
        cancelled.cancel_flag = &flag;
        CHECK(ca::hole_caps(open, cancelled).triangles.empty());   // stopped while welding
    }
    CHECK(caps.triangles.size() == 48);   // one loop of 48 edges
    for (const ca::Mesh* m : {&closed, static_cast<const ca::Mesh*>(&open)}) {
        ca::Surface surface;
        REQUIRE(ca::prepare_surface(*m, {}, surface).ok());
        ca::CandidateSet set;
        REQUIRE(ca::generate_candidates(std::move(surface), {}, ca::Monitor{}, set).ok());
        if (m == &closed) {
            CHECK(set.report.hole_clamped == 0);
            continue;
        }
        CHECK(set.report.hole_clamped > 0);
        double plane = -1e9;   // the rim's x, internal units
        for (const ca::Tri& t : set.surface.mesh.triangles)
            for (uint32_t v : t) plane = std::max(plane, set.surface.mesh.vertices[v].x());
        double beyond = 0;
        for (const ca::Ball& b : set.balls) beyond = std::max(beyond, b.center.x() + b.radius - plane);
        CHECK(beyond < 0.005);
        // every sample stays coverable
        ca::SelectOptions sopt;
        sopt.cover.solver = ca::Solver::greedy;
        ca::Selection sel;
        const ca::Status st = ca::select_balls(set, sopt, ca::Monitor{}, sel);
        CHECK_MESSAGE(st.ok(), st.message);
    }
}
