// test_target_error.cpp: the error-bounded selection (lib/search/target_error) on fox.obj. For a
// reachable E the returned HD is <= E and is what an independent select + connect + evaluate at
// the returned delta measures, and no probed delta gives a passing skeleton with fewer balls
// (brute force over the same deltas: returning, say, the last probe fails this); for an
// unreachable E the lowest-HD probe comes back unreached; with the fit, each probe's HD is that of
// the fitted skeleton (select + connect + fit + evaluate run independently) and differs from the
// unfitted one; invalid options are refused. The selection step (select_step) returns no more
// balls than the unfitted search alone, within E, and the skeleton connected at the defaults
// measures the HD it reports.
#include <doctest/doctest.h>

#include "candidates.h"
#include "connect.h"
#include "evaluate.h"
#include "fit.h"
#include "mesh_io.h"
#include "selection.h"
#include "steps.h"
#include "support/test_candidates.h"
#include "target_error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace {

ca::TargetErrorOptions options(double target) {
    ca::TargetErrorOptions te;
    te.target_error = target;
    te.connect.method = ca::ConnectMethod::medial;
    te.evaluate.surface_samples = 4000;
    te.evaluate.envelope_samples = 15000;
    te.max_probes = 7;  // at E = 2.6 the last of 7 probes fails and the best is the 4th
    return te;
}

// One probe, run independently: the ball count and two-sided HD at delta (fitted when te.fit).
std::pair<size_t, double> brute(const ca::CandidateSet& set, const ca::TargetErrorOptions& te, double delta) {
    ca::SelectOptions so;
    so.delta = delta;
    ca::Selection sel;
    REQUIRE(ca::select_balls(set, so, ca::Monitor{}, sel).ok());
    ca::Skeleton sk;
    REQUIRE(ca::connect_balls(set, sel, te.connect, ca::Monitor{}, sk).ok());
    ca::FitStats fs;
    if (te.fit) REQUIRE(ca::fit_skeleton(set, sel, *te.fit, ca::Monitor{}, sk, fs).ok());
    ca::EvaluateResult ev;
    REQUIRE(ca::evaluate(set.surface.mesh, sk, te.evaluate, ca::Monitor{}, ev).ok());
    return {sel.indices.size(), ev.hd_two_sided};
}

}  // namespace

TEST_CASE("test_target_error: fox with the fit: every probe's HD is the fitted skeleton's") {
    const ca::CandidateSet set = fox_candidate_set();
    const double target = 2.6;
    ca::TargetErrorOptions te = options(target);
    te.max_probes = 4;
    te.fit = ca::FitOptions{};
    te.fit->iterations = 3;
    te.fit->surface_samples = 1500;
    te.fit->envelope_samples = 1500;
    ca::TargetErrorResult r;
    const ca::Status st = ca::select_target_error(set, ca::SelectOptions{}, te, ca::Monitor{}, r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    REQUIRE(r.probes.size() >= 2);
    ca::TargetErrorOptions plain = te;
    plain.fit.reset();
    bool fit_changed_hd = false;
    for (const ca::TargetErrorProbe& p : r.probes) {
        CAPTURE(p.delta);
        const auto [balls, hd] = brute(set, te, p.delta);
        CHECK(balls == p.balls);
        CHECK(hd == doctest::Approx(p.hd).epsilon(1e-9));
        CHECK(p.passed == (p.hd <= target));
        fit_changed_hd |= std::abs(brute(set, plain, p.delta).second - p.hd) > 1e-6;
    }
    CHECK(fit_changed_hd);  // else this test could not tell a probe without the fit
    const auto [balls, hd] = brute(set, te, r.selection.delta);
    CHECK(balls == r.selection.indices.size());
    CHECK(hd == doctest::Approx(r.evaluation.hd_two_sided).epsilon(1e-9));
}

TEST_CASE("test_target_error: fox: HD <= E with no more balls than any passing probed delta and an unreachable E flagged") {
    const ca::CandidateSet set = fox_candidate_set();
    const double target = 2.6;
    const ca::TargetErrorOptions te = options(target);
    ca::TargetErrorResult r;
    const ca::Status st = ca::select_target_error(set, ca::SelectOptions{}, te, ca::Monitor{}, r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    REQUIRE(r.reached);
    CHECK(r.evaluation.hd_two_sided <= target);
    CHECK(r.probes.size() <= te.max_probes + te.max_count_down);
    CHECK(r.probes.size() >= 3);  // the start fails here: halving, then bisection
    CHECK(r.selection.probes == r.probes.size());
    CHECK(r.skeleton.balls.size() == r.selection.indices.size());
    // brute force over the probed deltas: the same figures, and none passes with fewer balls
    size_t fewest = SIZE_MAX;
    for (const ca::TargetErrorProbe& p : r.probes) {
        CAPTURE(p.delta);
        const auto [balls, hd] = brute(set, te, p.delta);
        CHECK(balls == p.balls);
        CHECK(hd == doctest::Approx(p.hd).epsilon(1e-9));
        if (hd <= target) fewest = std::min(fewest, balls);
    }
    REQUIRE(fewest != SIZE_MAX);
    CHECK(r.selection.indices.size() <= fewest);
    // the returned selection measures as reported at its delta
    const auto [balls, hd] = brute(set, te, r.selection.delta);
    CHECK(balls == r.selection.indices.size());
    CHECK(hd == doctest::Approx(r.evaluation.hd_two_sided).epsilon(1e-9));

    // unreachable: the lowest HD among the probes, flagged
    ca::TargetErrorOptions low = options(0.01);
    low.max_probes = 3;
    ca::TargetErrorResult u;
    REQUIRE(ca::select_target_error(set, ca::SelectOptions{}, low, ca::Monitor{}, u).ok());
    CHECK_FALSE(u.reached);
    REQUIRE(u.probes.size() == 3);
    double lowest = u.probes[0].hd;
    for (const ca::TargetErrorProbe& p : u.probes) lowest = std::min(lowest, p.hd);
    CHECK(u.evaluation.hd_two_sided == lowest);
    CHECK(u.evaluation.hd_two_sided > 0.01);
}

TEST_CASE("test_target_error: invalid options are refused") {
    const ca::CandidateSet set = fox_candidate_set();
    ca::TargetErrorResult r;
    auto code = [&](const ca::SelectOptions& so, const ca::TargetErrorOptions& te) {
        return ca::select_target_error(set, so, te, ca::Monitor{}, r).code;
    };
    const ca::SelectOptions so;
    CHECK(code(so, options(std::nan(""))) == ca::Code::invalid_argument);
    CHECK(code(so, options(-1)) == ca::Code::invalid_argument);
    CHECK(code(so, options(0)) == ca::Code::invalid_argument);
    ca::SelectOptions both = so;
    both.target_count = 10;
    CHECK(code(both, options(2)) == ca::Code::invalid_argument);
    ca::SelectOptions scale = so;
    scale.dilation = ca::Dilation::scale;
    CHECK(code(scale, options(2)) == ca::Code::invalid_argument);
    ca::TargetErrorOptions none = options(2);
    none.max_probes = 0;
    CHECK(code(so, none) == ca::Code::invalid_argument);
    ca::CandidateSet arrays;  // caller arrays: no surface to measure against
    arrays.cover_samples = set.cover_samples;
    arrays.balls = set.balls;
    CHECK(ca::select_target_error(arrays, so, options(2), ca::Monitor{}, r).code == ca::Code::invalid_argument);
}

TEST_CASE("test_target_error: fox: the selection step's search, fitted or not, returns no more balls than the unfitted one, within E") {
    const ca::CandidateSet set = fox_candidate_set();
    const double target = 2.6;
    // the unfitted search alone (connect and evaluation at the defaults)
    ca::TargetErrorOptions te;
    te.target_error = target;
    ca::TargetErrorResult unfitted;
    REQUIRE(ca::select_target_error(set, ca::SelectOptions{}, te, ca::Monitor{}, unfitted).ok());
    REQUIRE(unfitted.reached);
    ca::SelectRequest request;
    request.target_error = target;
    ca::SelectResult r;
    const ca::Status st = ca::select_step(set, request, ca::Monitor{}, r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(r.selection.indices.size() <= unfitted.selection.indices.size());
    CHECK(r.hd_reached <= target);
    // the skeleton the connection step gives at its defaults is the one measured
    ca::ConnectResult c;
    REQUIRE(ca::connect_step(set, r.selection, ca::ConnectRequest{}, ca::Monitor{}, c).ok());
    CHECK(c.fitted == r.selection.judged_fitted);
    ca::EvaluateResult ev;
    REQUIRE(ca::evaluate(set.surface.mesh, c.skeleton, ca::EvaluateOptions{}, ca::Monitor{}, ev).ok());
    CHECK(ev.hd_two_sided == doctest::Approx(r.hd_reached).epsilon(1e-9));
}
