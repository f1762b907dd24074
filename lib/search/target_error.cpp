// target_error.cpp: the error-bounded selection (target_error.h): probes of select + connect +
// evaluate over the offset delta on one candidate set, bracketed by doubling or halving, then
// bisected; the best passing probe is returned.
#include "target_error.h"

#include <algorithm>
#include <cmath>

namespace ca {

namespace {

// The better of two probes: passing first, then (both passing) fewer balls, lower HD, larger
// delta; (both failing) lower HD, then fewer balls.
bool better(const TargetErrorProbe& a, const TargetErrorProbe& b) {
    if (a.passed != b.passed) return a.passed;
    if (a.passed) {
        if (a.balls != b.balls) return a.balls < b.balls;
        if (a.hd != b.hd) return a.hd < b.hd;
        return a.delta > b.delta;
    }
    if (a.hd != b.hd) return a.hd < b.hd;
    return a.balls < b.balls;
}

// A delta doubled at most this far: at 1 (the longest bbox side) every ball covers the shape.
constexpr double kLargestDelta = 1.0;

}  // namespace

Status select_target_error(const CandidateSet& set, const SelectOptions& opt, const TargetErrorOptions& te,
                           const Monitor& monitor, TargetErrorResult& out) {
    const auto t0 = Clock::now();
    out = TargetErrorResult{};
    if (!(std::isfinite(te.target_error) && te.target_error > 0))
        return fail(Code::invalid_argument, "target_error must be a finite number > 0");
    if (opt.dilation != Dilation::offset)
        return fail(Code::invalid_argument, "target_error searches the offset delta: it needs the offset dilation");
    if (opt.target_count > 0) return fail(Code::invalid_argument, "target_error and target_count cannot both be set");
    if (!(std::isfinite(opt.delta) && opt.delta > 0)) return fail(Code::invalid_argument, "delta must be a finite number > 0");
    if (!(std::isfinite(opt.target_tolerance) && opt.target_tolerance > 0))
        return fail(Code::invalid_argument, "target_tolerance must be a finite number > 0");
    if (set.surface.mesh.vertices.empty())
        return fail(Code::invalid_argument,
                    "target_error measures the skeleton against the surface: the candidate set has none (caller arrays)");
    if (te.max_probes == 0) return fail(Code::invalid_argument, "max_probes must be at least 1");

    SelectOptions probe_opt = opt;
    DeltaProbe best;
    bool have_best = false;
    uint32_t runs = 0;  // probes run, those without a cover included
    // Runs one probe at delta d. Returns false with `st` set when the search must stop: an error
    // (cancel, a failure) or, once some probe has finished, the time limit. `uncoverable` is set
    // when the cover does not exist at d (the descent then stops).
    auto probe = [&](double d, bool& passed, bool& uncoverable, Status& st) {
        uncoverable = false;
        ++runs;
        DeltaProbe p;
        probe_opt.delta = d;
        st = probe_delta(set, probe_opt, te.connect, te.fit, te.evaluate, monitor, p);
        if (st.code == Code::uncoverable) {
            uncoverable = true;
            st = Status::success();
            return true;
        }
        if (!st.ok()) return false;
        p.summary.passed = p.summary.hd <= te.target_error;
        out.probes.push_back(p.summary);
        passed = p.summary.passed;
        if (!have_best || better(p.summary, best.summary)) {
            best = std::move(p);
            have_best = true;
        }
        return true;
    };
    auto finish = [&](Status st) {
        const bool time_out = st.code == Code::time_limit;
        if (!st.ok() && !(time_out && have_best)) return st;
        if (!have_best) return fail(Code::uncoverable, "no delta tried gives a cover of every sample");
        out.selection = std::move(best.selection);
        out.selection.probes = runs;
        out.selection.time_total_s = seconds_since(t0);  // the whole search
        out.skeleton = std::move(best.skeleton);
        out.evaluation = best.evaluation;
        out.reached = best.summary.passed;
        return Status::success();
    };

    // Bracket: lo passes, hi (> lo) fails; 0 = not found yet.
    double lo = 0, hi = 0;
    bool passed = false, uncoverable = false;
    Status st;
    double d = opt.delta;
    if (!probe(d, passed, uncoverable, st)) return finish(st);
    // no cover at the start: double until there is one (lo and hi stay 0)
    if (!uncoverable) (passed ? lo : hi) = d;
    const double floor_delta = std::min(opt.delta, kFallbackReach);
    while (runs < te.max_probes) {
        if (lo > 0 && hi > 0) break;
        if (hi == 0) {
            // passing (or uncoverable at the start): double until a probe fails
            if (d >= kLargestDelta) break;
            d = std::min(2 * d, kLargestDelta);
            if (!probe(d, passed, uncoverable, st)) return finish(st);
            if (uncoverable) continue;
            if (passed) {
                lo = d;
                if (best.summary.balls <= 1) break;  // one ball: nothing fewer to find
            } else if (lo > 0) {
                hi = d;
            } else {
                break;  // the first delta with a cover fails: larger ones are coarser still
            }
        } else {
            // failing: halve until a probe passes, not below the fallback reach
            if (d <= floor_delta) break;
            d = std::max(d / 2, floor_delta);
            if (!probe(d, passed, uncoverable, st)) return finish(st);
            if (uncoverable) break;
            if (passed) lo = d;
            else hi = d;
        }
    }
    // Bisect towards the largest passing delta.
    while (lo > 0 && hi > 0 && runs < te.max_probes && hi - lo > opt.target_tolerance) {
        const double mid = 0.5 * (lo + hi);
        if (!probe(mid, passed, uncoverable, st)) return finish(st);
        if (uncoverable) break;
        if (passed) lo = mid;
        else hi = mid;
    }
    return finish(Status::success());
}

}  // namespace ca
