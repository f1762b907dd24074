// test_search_time_limit.cpp: a time limit that runs out inside the delta searches (lib/search) on
// fox.obj. The progress callback moves the monitor's deadline to just ahead of now in the middle of
// the search (the third probe), so the limit falls inside it wherever the machine's speed puts the
// probes: the search must end within 0.1 s of that limit and return the best skeleton of the probes
// it ran (target_count: at most K balls, marked stopped; target_error: a result with its reached flag,
// marked stopped). Through the selection step (what ca_select runs) both end with Code::time_limit
// and the best selection so far in the result (out.stopped), which ca_select hands to the caller.
#include <doctest/doctest.h>

#include "steps.h"
#include "support/test_candidates.h"
#include "target_count_hd.h"
#include "target_error.h"

#include <chrono>
#include <cstring>

namespace {

// Moves `mon`'s deadline to 1 ms from now at the n-th call of `trigger` (returns the limit's time).
struct LimitAt {
    ca::Monitor& mon;
    int n;
    int calls = 0;
    ca::Clock::time_point limit{};
    bool set = false;
    void hit() {
        if (set || ++calls < n) return;
        mon.deadline = ca::Deadline::after(0.001);
        limit = ca::Clock::now() + std::chrono::milliseconds(1);
        set = true;
    }
};

double seconds_after(ca::Clock::time_point t) { return std::chrono::duration<double>(ca::Clock::now() - t).count(); }

}  // namespace

TEST_CASE("search time limit: target_count ends within 0.1 s of a limit inside it, with the best skeleton so far") {
    const ca::CandidateSet set = fox_candidate_set();
    ca::TargetCountHdOptions tc;
    tc.connect.method = ca::ConnectMethod::medial;
    tc.evaluate.surface_samples = 4000;
    tc.evaluate.envelope_samples = 15000;
    ca::SelectOptions so;
    so.target_count = 12;
    ca::Monitor mon;
    LimitAt at{mon, 3};
    mon.progress = [&](const char* stage, double) {
        if (std::strcmp(stage, "target count: probes") == 0) at.hit();
        return true;
    };
    ca::TargetCountHdResult r;
    const ca::Status st = ca::select_target_count_hd(set, so, tc, mon, r);
    REQUIRE(at.set);
    CHECK(seconds_after(at.limit) < 0.1);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(r.stopped);
    CHECK(r.probes.size() < tc.max_probes);
    CHECK(r.selection.indices.size() <= 12);
    CHECK(r.skeleton.balls.size() == r.selection.indices.size());
    // the best of the probes it ran: no probe with at most K balls reported lower
    for (const ca::TargetErrorProbe& p : r.probes)
        if (p.passed) CHECK(r.evaluation.hd_two_sided <= p.hd);
}

TEST_CASE("search time limit: target_error ends within 0.1 s of a limit inside it, with the best skeleton so far") {
    const ca::CandidateSet set = fox_candidate_set();
    ca::TargetErrorOptions te;
    te.target_error = 0.01;  // never reached: the search would run all its probes
    te.connect.method = ca::ConnectMethod::medial;
    te.evaluate.surface_samples = 4000;
    te.evaluate.envelope_samples = 15000;
    ca::Monitor mon;
    LimitAt at{mon, 3};
    mon.progress = [&](const char* stage, double fraction) {
        if (std::strcmp(stage, "selection") == 0 && fraction == 0) at.hit();  // the start of a probe's cover
        return true;
    };
    ca::TargetErrorResult r;
    const ca::Status st = ca::select_target_error(set, ca::SelectOptions{}, te, mon, r);
    REQUIRE(at.set);
    CHECK(seconds_after(at.limit) < 0.1);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK_FALSE(r.reached);
    CHECK(r.stopped);
    CHECK(r.probes.size() >= 1);  // the probes before the limit (an uncoverable delta is no probe)
    CHECK(r.probes.size() <= 2);
    CHECK(r.skeleton.balls.size() == r.selection.indices.size());
    for (const ca::TargetErrorProbe& p : r.probes) CHECK(r.evaluation.hd_two_sided <= p.hd);
}

TEST_CASE("search time limit: through the selection step, both searches end with the time-limit status and the best selection so far") {
    const ca::CandidateSet set = fox_candidate_set();
    for (const bool count : {false, true}) {
        CAPTURE(count);
        ca::SelectRequest request;
        if (count) request.select.target_count = 12;
        else request.target_error = 0.01;  // never reached: the search would run all its probes
        ca::Monitor mon;
        LimitAt at{mon, count ? 3 : 2};  // target_error: before its second probe
        const char* stage = count ? "target count: probes" : "target error: probes";
        int probes_started = 0;
        mon.progress = [&](const char* s, double) {
            if (std::strcmp(s, stage) == 0) {
                ++probes_started;
                at.hit();
            }
            return true;
        };
        ca::SelectResult r;
        const ca::Status st = ca::select_step(set, request, mon, r);
        REQUIRE(at.set);
        CHECK(seconds_after(at.limit) < 0.1);
        CHECK(st.code == ca::Code::time_limit);
        CHECK(st.message.find("best selection so far") != std::string::npos);
        CHECK(r.stopped);
        CHECK_FALSE(r.selection.indices.empty());
        CHECK(r.hd_reached > 0);
        if (count) CHECK(r.selection.indices.size() <= 12);
        else CHECK(r.selection.probes <= 2);  // the probe before the limit, and the one it stopped
        CHECK(probes_started < 9);
    }
}
