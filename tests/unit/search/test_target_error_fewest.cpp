// test_target_error_fewest.cpp: on tests/data/torus.obj, --target-error E returns no more balls than
// --target-count finds within E. The target-count runs (select_step with target_count K, connected
// at connect_step's defaults, a sized selection's thorough fit, and measured at evaluate's
// defaults, as the tool and bench_target_error measure them) at K = 6 .. 13 give, per E, the
// fewest balls whose measured HD is <= E; select_step with target_error E must return no more,
// and the skeleton connect_step gives it at the defaults must measure the HD it reports, <= E.
#include <doctest/doctest.h>

#include "evaluate.h"
#include "steps.h"
#include "support/test_candidates.h"

#include <string>
#include <vector>

namespace {

// The selection connected at connect_step's defaults and measured at evaluate's: its balls and HD.
std::pair<size_t, double> measured(const ca::CandidateSet& set, const ca::Selection& sel) {
    ca::ConnectResult c;
    REQUIRE(ca::connect_step(set, sel, ca::ConnectRequest{}, ca::Monitor{}, c).ok());
    ca::EvaluateResult ev;
    REQUIRE(ca::evaluate(set.surface.mesh, c.skeleton, ca::EvaluateOptions{}, ca::Monitor{}, ev).ok());
    return {sel.indices.size(), ev.hd_two_sided};
}

}  // namespace

TEST_CASE("test_target_error_fewest: torus: target-error returns no more balls than target-count finds within E") {
    const ca::CandidateSet set = candidate_set_of("torus.obj", 600, 1500);
    std::vector<std::pair<size_t, double>> counts;  // (balls, HD) of each target-count run
    for (uint32_t K = 6; K <= 13; ++K) {
        ca::SelectRequest request;
        request.select.target_count = K;
        ca::SelectResult r;
        const ca::Status st = ca::select_step(set, request, ca::Monitor{}, r);
        REQUIRE_MESSAGE(st.ok(), st.message);
        counts.push_back(measured(set, r.selection));
        CHECK(counts.back().first <= K);
    }
    int compared = 0;
    for (double E : {1.5, 2.0, 2.5, 3.0}) {
        CAPTURE(E);
        size_t fewest = SIZE_MAX;
        for (const auto& [balls, hd] : counts)
            if (hd <= E) fewest = std::min(fewest, balls);
        ca::SelectRequest request;
        request.target_error = E;
        ca::SelectResult r;
        const ca::Status st = ca::select_step(set, request, ca::Monitor{}, r);
        REQUIRE_MESSAGE(st.ok(), st.message);
        CHECK(r.hd_reached <= E);
        const auto [balls, hd] = measured(set, r.selection);
        CHECK(hd == doctest::Approx(r.hd_reached).epsilon(1e-9));
        if (fewest == SIZE_MAX) continue;
        ++compared;
        CAPTURE(fewest);
        CHECK(balls <= fewest);
    }
    CHECK(compared >= 3);  // else the counts above do not reach the targets and the test tells nothing
}
