// delta_search.cpp: the delta search (delta_search.h): bracket by doubling or halving, bisect,
// then probe the neighbourhood of the best probe, because HD(delta) is not monotone.
#include "delta_search.h"

#include <algorithm>
#include <cmath>

namespace ca {

bool better_probe(const TargetErrorProbe& a, const TargetErrorProbe& b) {
    if (a.passed != b.passed) return a.passed;
    if (a.passed) {
        if (a.balls != b.balls) return a.balls < b.balls;
        if (a.hd != b.hd) return a.hd < b.hd;
        return a.delta > b.delta;
    }
    if (a.hd != b.hd) return a.hd < b.hd;
    return a.balls < b.balls;
}

namespace {

struct Searcher {
    const DeltaSearchOptions& opt;
    const std::function<Status(double, TargetErrorProbe&)>& probe_fn;
    const std::function<void()>& keep;
    DeltaSearchResult& out;
    std::vector<double> tried;    // every delta probed, uncoverable ones included
    double last_hd = -1;          // the last probe's HD (-1: uncoverable)
    size_t last_balls = 0;

    // The next delta of the bracket from d, whose probe measured `hd`: scaled by E / hd (the HD
    // grows about in proportion to delta), up by 1.25 to 4 times, down by a half to a quarter
    // (a failing delta far from any passing one, when the HD is not monotone, is left quickly).
    double scaled(double d, double hd, bool up) const {
        const double ratio = hd > 0 ? opt.target_error / hd : 4.0;
        return up ? d * std::clamp(ratio, 1.25, 4.0) : d * std::clamp(ratio, 0.25, 0.5);
    }

    bool budget() const { return out.runs < opt.max_probes; }
    bool have_best() const { return !out.probes.empty(); }
    const TargetErrorProbe& best() const { return out.probes[out.best]; }

    // One probe at d. False with `st` set when the search must stop; `uncoverable` when d has
    // no cover.
    bool probe(double d, bool& passed, bool& uncoverable, Status& st) {
        uncoverable = passed = false;
        last_hd = -1;
        ++out.runs;
        tried.push_back(d);
        TargetErrorProbe p;
        st = probe_fn(d, p);
        if (st.code == Code::uncoverable) {
            uncoverable = true;
            st = Status::success();
            return true;
        }
        if (!st.ok()) return false;
        p.passed = p.hd <= opt.target_error;
        passed = p.passed;
        last_hd = p.hd;
        last_balls = p.balls;
        out.probes.push_back(p);
        if (out.probes.size() == 1 || better_probe(p, best())) {
            out.best = out.probes.size() - 1;
            keep();
        }
        return true;
    }

    bool probed(double d) const {
        for (double t : tried)
            if (std::abs(t - d) <= 1e-9 * std::max(t, d)) return true;
        return false;
    }

    // Phase 2's candidates for the probes so far, in order.
    std::vector<double> candidates() const {
        std::vector<double> c;
        std::vector<double> deltas;  // probed deltas with a result, ascending
        for (const TargetErrorProbe& p : out.probes) deltas.push_back(p.delta);
        std::sort(deltas.begin(), deltas.end());
        if (have_best() && best().passed) {
            const double lo = best().delta;
            double hi = 0;  // the nearest failing delta above lo
            for (const TargetErrorProbe& p : out.probes)
                if (!p.passed && p.delta > lo && (hi == 0 || p.delta < hi)) hi = p.delta;
            if (hi > 0) {
                // with count_down the caller probes the count just below lo's itself
                size_t hi_balls = 0;
                for (const TargetErrorProbe& p : out.probes)
                    if (p.delta == hi) hi_balls = p.balls;
                const bool adjacent = opt.count_down && best().balls <= hi_balls + 1;
                if (hi - lo > opt.tolerance && !adjacent) c.push_back(0.5 * (lo + hi));
                // upwards, far: the HD is not monotone (a feature caught or missed), so a much
                // larger delta can pass with far fewer balls
                for (double f : {1.1, 1.25, 1.5, 2.0, 3.0}) c.push_back(f * hi);
            } else {
                for (double f : {1.25, 1.5, 2.0}) c.push_back(f * lo);  // nothing above has failed yet
            }
            c.push_back(0.9 * lo);
        } else {
            c.push_back(1.25 * opt.start);
            c.push_back(1.5 * opt.start);
            // the widest gaps (by ratio) first, of equal ones the larger
            std::vector<std::pair<double, double>> gaps;  // (hi / lo, lo)
            for (size_t i = 1; i < deltas.size(); ++i)
                if (deltas[i] - deltas[i - 1] > opt.tolerance) gaps.emplace_back(deltas[i] / deltas[i - 1], deltas[i - 1]);
            std::sort(gaps.begin(), gaps.end(), [](const auto& a, const auto& b) {
                return a.first != b.first ? a.first > b.first : a.second > b.second;
            });
            for (const auto& [ratio, lo] : gaps) c.push_back(0.5 * lo * (1 + ratio));
        }
        return c;
    }

    Status run() {
        bool passed = false, uncoverable = false;
        Status st;
        // Phase 1. Bracket: lo passes, hi (> lo) fails; 0 = not found yet.
        double lo = 0, hi = 0;
        double hd_lo = 0, hd_hi = 0;    // their HDs
        size_t balls_lo = 0, balls_hi = 0;
        double d = opt.start;
        if (!probe(d, passed, uncoverable, st)) return st;
        // no cover at the start: double until there is one (lo and hi stay 0)
        if (!uncoverable) {
            (passed ? lo : hi) = d;
            (passed ? hd_lo : hd_hi) = last_hd;
            (passed ? balls_lo : balls_hi) = last_balls;
        }
        const double floor_delta = std::min(opt.start, opt.floor);
        while (budget()) {
            if (lo > 0 && hi > 0) break;
            if (hi == 0) {
                // passing (or uncoverable at the start): double until a probe fails
                if (d >= kLargestDelta) break;
                d = std::min(lo > 0 ? scaled(lo, hd_lo, true) : 2 * d, kLargestDelta);
                if (!probe(d, passed, uncoverable, st)) return st;
                if (uncoverable) continue;
                if (passed) {
                    lo = d, hd_lo = last_hd, balls_lo = last_balls;
                    if (best().balls <= 1) return st;  // one ball: nothing fewer to find
                } else if (lo > 0) {
                    hi = d, hd_hi = last_hd, balls_hi = last_balls;
                } else {
                    break;  // the first delta with a cover fails: phase 2 looks around it
                }
            } else {
                // failing: halve until a probe passes, not below the floor
                if (d <= floor_delta) break;
                d = std::max(scaled(d, last_hd, false), floor_delta);
                if (!probe(d, passed, uncoverable, st)) return st;
                if (uncoverable) break;
                if (passed) lo = d, hd_lo = last_hd, balls_lo = last_balls;
                else hi = d, hd_hi = last_hd, balls_hi = last_balls;
            }
        }
        // a third of the probes is kept for phase 2
        const uint32_t bisect_until = opt.max_probes - opt.max_probes / 3;
        while (lo > 0 && hi > 0 && out.runs < bisect_until && hi - lo > opt.tolerance) {
            // the caller's count-down probes hi's count itself: nothing else is left between
            if (opt.count_down && balls_lo <= balls_hi + 1) break;
            // where the HD, taken as linear between the ends, meets E; kept off the ends
            const double t = hd_hi > hd_lo ? (opt.target_error - hd_lo) / (hd_hi - hd_lo) : 0.5;
            const double mid = lo + std::clamp(t, 0.25, 0.75) * (hi - lo);
            if (!probe(mid, passed, uncoverable, st)) return st;
            if (uncoverable) break;
            if (passed) lo = mid, hd_lo = last_hd, balls_lo = last_balls;
            else hi = mid, hd_hi = last_hd, balls_hi = last_balls;
        }
        // Phase 2: the neighbourhood, while probes are left.
        while (budget() && have_best()) {
            if (best().passed && best().balls <= 1) break;
            double next = 0;
            for (double c : candidates())
                if (c >= floor_delta && c <= kLargestDelta && !probed(c)) {
                    next = c;
                    break;
                }
            if (next == 0) break;
            if (!probe(next, passed, uncoverable, st)) return st;
        }
        return Status::success();
    }
};

}  // namespace

Status search_delta(const DeltaSearchOptions& opt, const std::function<Status(double, TargetErrorProbe&)>& probe,
                    const std::function<void()>& keep, DeltaSearchResult& out) {
    out = DeltaSearchResult{};
    Searcher s{opt, probe, keep, out, {}};
    return s.run();
}

}  // namespace ca
