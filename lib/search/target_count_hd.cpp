// target_count_hd.cpp: the lowest two-sided HD with at most K balls (target_count_hd.h): the
// target size's probe, then probes at growing deltas, each measured coarsely; the most promising
// are measured exactly, and the best exact one with at most K balls is kept.
#include "target_count_hd.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ca {

namespace {

// The better of two exactly measured probes that both have at most K balls: lower HD, then fewer
// balls, then the smaller delta (the order they ran in, so the choice is deterministic).
bool better(const TargetErrorProbe& a, const TargetErrorProbe& b) {
    if (a.hd != b.hd) return a.hd < b.hd;
    if (a.balls != b.balls) return a.balls < b.balls;
    return a.delta < b.delta;
}

}  // namespace

EvaluateOptions coarse_evaluation(const EvaluateOptions& exact, uint32_t envelope_samples) {
    EvaluateOptions o = exact;
    o.envelope_samples = std::max<uint32_t>(1, std::min(exact.envelope_samples, envelope_samples));
    return o;
}

Status select_target_count_hd(const CandidateSet& set, const SelectOptions& opt, const TargetCountHdOptions& tc,
                              const Monitor& monitor, TargetCountHdResult& out) {
    const auto t0 = Clock::now();
    out = TargetCountHdResult{};
    if (opt.target_count == 0) return fail(Code::invalid_argument, "the lowest-HD search needs target_count > 0");
    if (opt.dilation != Dilation::offset)
        return fail(Code::invalid_argument, "the lowest-HD search for target_count varies delta: it needs the offset dilation");
    if (!set.surface.kind().has_surface())
        return fail(Code::invalid_argument,
                    "the lowest-HD search measures the skeleton against the surface: the candidate set has none (caller arrays)");
    if (tc.max_probes == 0) return fail(Code::invalid_argument, "max_probes must be at least 1");
    if (!(std::isfinite(tc.step) && tc.step > 0)) return fail(Code::invalid_argument, "step must be a finite number > 0");

    // the surface's samples and distance structure, once for every probe
    std::shared_ptr<const EvaluationSurface> surface;
    Status st = prepare_evaluation(set.surface.mesh, tc.evaluate, surface, &set.queries);
    if (!st.ok()) return st;
    const EvaluateOptions coarse = coarse_evaluation(tc.evaluate, tc.coarse_envelope_samples);
    const size_t K = opt.target_count;
    std::vector<DeltaProbe> probes;
    // the target size: its errors (no cover with K balls, bad options) are the search's
    probes.emplace_back();
    st = probe_delta(set, opt, tc.connect, tc.fit, coarse, *surface, monitor, probes[0]);
    if (!st.ok()) return st;
    probes[0].summary.passed = true;  // select_balls returns a fitting cover only
    probes[0].summary.exact = false;
    uint32_t solves = probes[0].selection.probes;
    auto report = [&](uint32_t k) {
        return monitor.report("target count: probes", double(k) / double(tc.max_probes + 2));
    };

    const double d0 = probes[0].selection.delta;
    const double unit = (d0 > 0 ? d0 : opt.delta) * tc.step;
    SelectOptions probe_opt = opt;
    probe_opt.target_count = 0;
    bool stopped = false;  // the time limit: the probes so far stand
    for (uint32_t i = 1; i < tc.max_probes; ++i) {
        if (!report(i)) {
            if (!monitor.deadline.expired()) return monitor.stop_status("target count");  // a cancel
            stopped = true;
            break;
        }
        probe_opt.delta = d0 + unit * i;
        DeltaProbe p;
        st = probe_delta(set, probe_opt, tc.connect, tc.fit, coarse, *surface, monitor, p);
        ++solves;
        if (st.code == Code::uncoverable) continue;  // cannot happen above a delta with a cover; harmless
        if (st.code == Code::time_limit) {
            stopped = true;
            break;
        }
        if (!st.ok()) return st;
        p.summary.passed = p.summary.balls <= K;
        p.summary.exact = false;
        probes.push_back(std::move(p));
    }
    // Coarse to fine: the probes with at most K balls in the order of their coarse HD; each is
    // measured exactly while its coarse HD is below the best exact HD so far (a coarse HD is the
    // maximum over fewer samples of E's boundary, so it is about a lower bound of the exact one).
    // The target size (the first probe) is always measured, so the result is never above it.
    std::vector<size_t> order(probes.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (a == 0 || b == 0) return a == 0 && b != 0;
        return probes[a].summary.hd < probes[b].summary.hd;
    });
    size_t best = 0;
    bool have_exact = false;
    for (size_t k : order) {
        DeltaProbe& p = probes[k];
        if (!p.summary.passed) continue;
        if (have_exact) {
            if (p.summary.hd >= probes[best].summary.hd) continue;
            if (stopped || monitor.stopped()) {
                if (!monitor.deadline.expired()) return monitor.stop_status("target count");  // a cancel
                stopped = true;
                break;  // the time limit: the best exact probe so far stands
            }
        }
        st = evaluate(*surface, p.skeleton, tc.evaluate, monitor, p.evaluation, true);
        if (!st.ok()) {
            if (st.code != Code::time_limit) return st;
            stopped = true;
            if (!have_exact) {
                // the time limit before any exact measurement: the lowest coarse HD with at most
                // K balls stands, measured coarsely (a failed evaluate leaves its result as it was)
                for (size_t j = 0; j < probes.size(); ++j)
                    if (probes[j].summary.passed && probes[j].summary.hd < probes[best].summary.hd) best = j;
            }
            break;
        }
        p.summary.hd = p.evaluation.hd_two_sided;
        p.summary.exact = true;
        if (!have_exact || better(p.summary, probes[best].summary)) best = k;
        have_exact = true;
    }
    for (const DeltaProbe& p : probes) out.probes.push_back(p.summary);
    out.stopped = stopped;
    out.selection = std::move(probes[best].selection);
    out.selection.probes = solves;
    out.selection.time_total_s = seconds_since(t0);
    out.skeleton = std::move(probes[best].skeleton);
    out.evaluation = probes[best].evaluation;
    return Status::success();
}

}  // namespace ca
