// target_count_hd.cpp: the lowest two-sided HD with at most K balls (target_count_hd.h): the
// target size's probe, then probes at growing deltas; the best one with at most K balls is kept.
#include "target_count_hd.h"

#include <cmath>

namespace ca {

namespace {

// The better of two probes that both have at most K balls: lower HD, then fewer balls, then the
// smaller delta (the order they ran in, so the choice is deterministic).
bool better(const TargetErrorProbe& a, const TargetErrorProbe& b) {
    if (a.hd != b.hd) return a.hd < b.hd;
    if (a.balls != b.balls) return a.balls < b.balls;
    return a.delta < b.delta;
}

}  // namespace

Status select_target_count_hd(const CandidateSet& set, const SelectOptions& opt, const TargetCountHdOptions& tc,
                              const Monitor& monitor, TargetCountHdResult& out) {
    const auto t0 = Clock::now();
    out = TargetCountHdResult{};
    if (opt.target_count == 0) return fail(Code::invalid_argument, "the lowest-HD search needs target_count > 0");
    if (opt.dilation != Dilation::offset)
        return fail(Code::invalid_argument, "the lowest-HD search for target_count varies delta: it needs the offset dilation");
    if (set.surface.mesh.vertices.empty())
        return fail(Code::invalid_argument,
                    "the lowest-HD search measures the skeleton against the surface: the candidate set has none (caller arrays)");
    if (tc.max_probes == 0) return fail(Code::invalid_argument, "max_probes must be at least 1");
    if (!(std::isfinite(tc.step) && tc.step > 0)) return fail(Code::invalid_argument, "step must be a finite number > 0");

    std::shared_ptr<const EvaluationSurface> surface;
    Status st = prepare_evaluation(set.surface.mesh, tc.evaluate, surface);
    if (!st.ok()) return st;
    const size_t K = opt.target_count;
    // the target size: its errors (no cover with K balls, bad options) are the search's
    DeltaProbe best;
    st = probe_delta(set, opt, tc.connect, tc.fit, tc.evaluate, *surface, monitor, best);
    if (!st.ok()) return st;
    best.summary.passed = true;  // select_balls returns a fitting cover only
    out.probes.push_back(best.summary);
    uint32_t solves = best.selection.probes;

    const double d0 = best.selection.delta;
    const double unit = (d0 > 0 ? d0 : opt.delta) * tc.step;
    SelectOptions probe_opt = opt;
    probe_opt.target_count = 0;
    for (uint32_t i = 1; i < tc.max_probes; ++i) {
        probe_opt.delta = d0 + unit * i;
        DeltaProbe p;
        st = probe_delta(set, probe_opt, tc.connect, tc.fit, tc.evaluate, *surface, monitor, p);
        ++solves;
        if (st.code == Code::uncoverable) continue;  // cannot happen above a delta with a cover; harmless
        if (st.code == Code::time_limit) break;      // the best so far stands
        if (!st.ok()) return st;
        p.summary.passed = p.summary.balls <= K;
        out.probes.push_back(p.summary);
        if (p.summary.passed && better(p.summary, best.summary)) best = std::move(p);
    }
    out.selection = std::move(best.selection);
    out.selection.probes = solves;
    out.selection.time_total_s = seconds_since(t0);
    out.skeleton = std::move(best.skeleton);
    out.evaluation = best.evaluation;
    return Status::success();
}

}  // namespace ca
