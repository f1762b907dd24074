// test_candidates.cpp: candidate generation details: fallback balls make every sample coverable
// and grow towards the medial axis (on a sphere: towards the centre); Voronoi radii never exceed
// the distance to the nearest sample (empty balls).
#include <doctest/doctest.h>

#include "candidates.h"
#include "distance.h"
#include "kdtree.h"
#include "sampling.h"
#include "support/shapes.h"
#include "winding.h"

#include <cmath>

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
    for (size_t i = 0; i + set.fallback_balls < set.balls.size(); ++i) {
        const ca::Ball& b = set.balls[i];
        size_t idx;
        double d2;
        REQUIRE(tree.nearest(b.center, 1, &idx, &d2) == 1);
        CHECK(b.radius <= std::sqrt(d2) + 1e-12);
        CHECK(winding(b.center) > 0.5);
    }
}
