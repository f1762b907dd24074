// test_fit.cpp: the post-connection fit (lib/fit): one misplaced ball in a sphere moves to the
// sphere's centre and radius; on a capsule and a torus (medial route) the fit lowers the
// evaluator's two-sided Hausdorff distance, keeps edges and faces, keeps every centre inside and
// every radius within the distance to the surface plus its allowance (brute force), and reports
// the cover samples left uncovered as an independent count does; a power below 2 is refused.
#include <doctest/doctest.h>

#include <algorithm>

#include "candidates.h"
#include "connect.h"
#include "coverage.h"
#include "distance.h"
#include "evaluate.h"
#include "fit.h"
#include "selection.h"
#include "support/shapes.h"
#include "winding.h"

namespace {

ca::CandidateSet candidates(ca::Mesh mesh) {
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(std::move(mesh), {}, surface).ok());
    ca::CandidateSet set;
    REQUIRE(ca::generate_candidates(std::move(surface), {}, ca::Monitor{}, set).ok());
    return set;
}

double two_sided(const ca::CandidateSet& set, const ca::Skeleton& sk) {
    ca::EvaluateResult r;
    const ca::Status st = ca::evaluate(set.surface.mesh, sk, ca::EvaluateOptions{}, ca::Monitor{}, r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    return r.hd_two_sided;
}

}  // namespace

TEST_CASE("test_fit: one misplaced ball in a sphere moves to the sphere's centre and radius, bad options refused") {
    const ca::CandidateSet set = candidates(shapes::sphere(1.0, 32, 64));
    // internal units: the sphere is centred at (0.5, 0.5, 0.5) with radius 0.5
    ca::Selection sel;
    sel.indices = {0};
    sel.dilated_radii = {0.3};
    sel.delta = 0.02;
    ca::Skeleton sk;
    sk.balls = {{ca::Vec3(0.6, 0.45, 0.5), 0.3}};
    ca::FitOptions opt;
    opt.iterations = 20;
    ca::FitStats stats;
    REQUIRE(ca::fit_skeleton(set, sel, opt, ca::Monitor{}, sk, stats).ok());
    CHECK(stats.error_after < stats.error_before);
    CHECK((sk.balls[0].center - ca::Vec3(0.5, 0.5, 0.5)).norm() < 0.01);
    CHECK(std::abs(sk.balls[0].radius - 0.5) < 0.01);
    opt.power = 1;   // below 2: refused
    CHECK(ca::fit_skeleton(set, sel, opt, ca::Monitor{}, sk, stats).code == ca::Code::invalid_argument);
}

TEST_CASE("test_fit: capsule and torus: lower Hausdorff distance, same topology, balls inside") {
    for (int shape = 0; shape < 2; ++shape) {
        CAPTURE(shape);
        const ca::CandidateSet set = candidates(shape == 0 ? shapes::capsule(2.0, 0.5, 48, 32)
                                                           : shapes::torus(1.0, 0.3, 64, 24));
        ca::Selection sel;
        REQUIRE(ca::select_balls(set, {}, ca::Monitor{}, sel).ok());
        ca::ConnectOptions copt;
        copt.method = ca::ConnectMethod::medial;
        ca::Skeleton sk;
        REQUIRE(ca::connect_balls(set, sel, copt, ca::Monitor{}, sk).ok());
        const double before = two_sided(set, sk);
        ca::Skeleton fitted = sk;
        ca::FitOptions opt;
        ca::FitStats stats;
        REQUIRE(ca::fit_skeleton(set, sel, opt, ca::Monitor{}, fitted, stats).ok());
        CHECK(stats.accepted > 0);
        CHECK(stats.error_after < stats.error_before);
        CHECK(two_sided(set, fitted) < before);
        CHECK(fitted.edges == sk.edges);
        CHECK(fitted.faces == sk.faces);
        REQUIRE(fitted.balls.size() == sk.balls.size());
        const ca::Mesh& mesh = set.surface.mesh;
        for (size_t i = 0; i < fitted.balls.size(); ++i) {
            const ca::Ball& b = fitted.balls[i];
            const ca::Ball& c = sk.balls[i];
            CHECK(ca::winding_number_brute_force(mesh, b.center) > 0.5);
            // the allowance: the tolerance, or the connected ball's own excess
            const double allow = std::max(opt.radius_tolerance, c.radius - ca::mesh_distance_brute_force(mesh, c.center));
            CHECK(b.radius <= ca::mesh_distance_brute_force(mesh, b.center) + allow + 1e-12);
        }
        size_t uncovered = 0;
        for (const ca::Vec3& s : set.cover_samples) {
            bool ok = false;
            for (const ca::Ball& b : fitted.balls) ok = ok || ca::covers(b.center, b.radius + sel.delta, s);
            uncovered += !ok;
        }
        CHECK(stats.uncovered == uncovered);
    }
}

// Brute force: the thorough fit returns, ball for ball, whichever of the regular fit and the
// second fit (second_fit_options) evaluate() at its defaults measures closer, the first on a tie.
TEST_CASE("test_fit: the thorough fit keeps the fit of lower evaluated Hausdorff distance") {
    for (int shape = 0; shape < 2; ++shape) {
        const ca::CandidateSet set =
            candidates(shape == 0 ? shapes::torus(1.0, 0.3, 64, 24) : shapes::capsule(1.0, 0.3, 48, 24));
        ca::Selection sel;
        REQUIRE(ca::select_balls(set, {}, ca::Monitor{}, sel).ok());
        ca::ConnectOptions copt;
        copt.method = ca::ConnectMethod::medial;
        ca::Skeleton sk;
        REQUIRE(ca::connect_balls(set, sel, copt, ca::Monitor{}, sk).ok());
        ca::FitOptions opt;
        ca::FitStats stats;
        ca::Skeleton first = sk, second = sk, thorough = sk;
        REQUIRE(ca::fit_skeleton(set, sel, opt, ca::Monitor{}, first, stats).ok());
        REQUIRE(ca::fit_skeleton(set, sel, ca::second_fit_options(opt), ca::Monitor{}, second, stats).ok());
        opt.thorough = true;
        REQUIRE(ca::fit_skeleton(set, sel, opt, ca::Monitor{}, thorough, stats).ok());
        const double h1 = two_sided(set, first), h2 = two_sided(set, second);
        CHECK(h1 != h2);   // the two fits differ, so the choice is tested
        const ca::Skeleton& want = h2 < h1 ? second : first;
        CHECK(stats.kept == (h2 < h1 ? 1u : 0u));
        CHECK(stats.hd_first == h1);
        CHECK(stats.hd_second == h2);
        REQUIRE(thorough.balls.size() == want.balls.size());
        for (size_t i = 0; i < want.balls.size(); ++i) {
            CHECK(thorough.balls[i].center == want.balls[i].center);
            CHECK(thorough.balls[i].radius == want.balls[i].radius);
        }
        CHECK(two_sided(set, thorough) == std::min(h1, h2));
        CHECK(thorough.faces == sk.faces);
    }
}
