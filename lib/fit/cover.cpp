// cover.cpp: the covered fit (FitMode::covered): the fit, then a repair of the cover it breaks.
// The fit moves the balls the cover relies on, so some cover samples end up farther than the
// dilated radius from every ball. Those samples are covered again by candidate balls in their
// original (unfitted) place, which cover them by construction (a small greedy set cover of just
// those samples); the selection with the added balls is connected again, the fitted balls are put
// back in their fitted place, and a second fit moves them further with the added balls held and
// every trial pulled back until it keeps the cover (FitHold). So the returned balls cover every
// cover sample that the selected balls covered, at the price of the added balls.
#include "fit.h"

#include "connect.h"
#include "coverage.h"
#include "timing.h"

#include <algorithm>

namespace ca {

namespace {

double dilated(const Selection& sel, double radius) { return sel.delta > 0 ? radius + sel.delta : radius * sel.scale; }

// The fewest candidate balls (greedily: most samples first, ties to the lower index; then the
// redundant ones dropped, last chosen first) among those not in `exclude` that cover the samples
// `need` (indices into set.cover_samples) with their dilated radius. Samples that no such ball
// covers are returned in `left`.
std::vector<uint32_t> cover_again(const CandidateSet& set, const Selection& sel, const std::vector<uint32_t>& need,
                                  const std::vector<uint8_t>& exclude, std::vector<uint32_t>& left) {
    const size_t m = need.size();
    std::vector<std::vector<uint32_t>> reach;   // per useful ball: the positions in `need` it covers
    std::vector<uint32_t> ball;
    for (uint32_t j = 0; j < set.balls.size(); ++j) {
        if (exclude[j]) continue;
        const Ball& b = set.balls[j];
        const double rd = dilated(sel, b.radius);
        std::vector<uint32_t> got;
        for (uint32_t k = 0; k < m; ++k)
            if (covers(b.center, rd, set.cover_samples[need[k]])) got.push_back(k);
        if (got.empty()) continue;
        reach.push_back(std::move(got));
        ball.push_back(j);
    }
    std::vector<uint8_t> done(m, 0);
    for (size_t k = 0; k < m; ++k) {
        bool any = false;
        for (const auto& r : reach) any = any || std::binary_search(r.begin(), r.end(), uint32_t(k));
        if (!any) {
            done[k] = 1;
            left.push_back(need[k]);
        }
    }
    std::vector<size_t> chosen;
    for (;;) {
        size_t best = reach.size(), best_gain = 0;
        for (size_t c = 0; c < reach.size(); ++c) {
            size_t gain = 0;
            for (uint32_t k : reach[c]) gain += !done[k];
            if (gain > best_gain) { best_gain = gain; best = c; }
        }
        if (best == reach.size()) break;
        chosen.push_back(best);
        for (uint32_t k : reach[best]) done[k] = 1;
    }
    // a chosen ball is redundant when every sample it covers is covered by another chosen one
    std::vector<uint32_t> times(m, 0);
    for (size_t c : chosen)
        for (uint32_t k : reach[c]) ++times[k];
    std::vector<uint32_t> out;
    for (size_t i = chosen.size(); i-- > 0;) {
        const auto& r = reach[chosen[i]];
        if (std::all_of(r.begin(), r.end(), [&](uint32_t k) { return times[k] > 1; })) {
            for (uint32_t k : r) --times[k];
            continue;
        }
        out.push_back(ball[chosen[i]]);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

Status fit_covered(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const ConnectOptions& copt,
                   const Monitor& monitor, Skeleton& sk, FitStats& stats, ConnectReport* report) {
    const auto t0 = Clock::now();
    const std::vector<Ball> connected = sk.balls;
    const size_t n = sel.indices.size();
    if (connected.size() != n) return fail(Code::internal, "covered fit: the skeleton's balls are not the selection's");
    Status st = fit_skeleton(set, sel, opt, monitor, sk, stats);
    if (!st.ok() || stats.iterations == 0) return st;
    // the samples to cover again: those the fit uncovered that the connected balls covered (a
    // sample the selection left uncoverable stays so)
    const std::vector<uint32_t> lost = uncovered_samples(set, sel, sk.balls);
    stats.uncovered_first = lost.size();
    std::vector<uint32_t> need;
    {
        const std::vector<uint32_t> before = uncovered_samples(set, sel, connected);
        std::set_difference(lost.begin(), lost.end(), before.begin(), before.end(), std::back_inserter(need));
    }
    if (!need.empty()) {
        std::vector<uint8_t> selected(set.balls.size(), 0);
        for (uint32_t j : sel.indices) selected[j] = 1;
        std::vector<uint32_t> left;
        const std::vector<uint32_t> added = cover_again(set, sel, need, selected, left);
        Selection grown = sel;
        for (uint32_t j : added) {
            grown.indices.push_back(j);
            grown.dilated_radii.push_back(dilated(sel, set.balls[j].radius));
        }
        // the fitted balls, then the added ones in their original place, held
        std::vector<Ball> balls = sk.balls;
        for (uint32_t j : added) balls.push_back(set.balls[j]);
        FitHold hold;
        hold.fixed.assign(balls.size(), 1);
        std::fill(hold.fixed.begin(), hold.fixed.begin() + std::ptrdiff_t(n), 0);
        hold.keep_cover = true;
        // A sample that only selected balls cover in their original place: those balls go back
        // to it and are held there.
        for (uint32_t s : left)
            for (size_t i = 0; i < n; ++i)
                if (covers(connected[i].center, dilated(sel, connected[i].radius), set.cover_samples[s])) {
                    balls[i] = connected[i];
                    hold.fixed[i] = 1;
                }
        Skeleton joined;
        ConnectReport joined_report;
        st = connect_balls(set, grown, copt, monitor, joined, &joined_report);
        if (!st.ok()) return st;
        if (joined.balls.size() != balls.size())
            return fail(Code::internal, "covered fit: the skeleton's balls are not the selection's");
        joined.balls = balls;
        // the refit starts from balls that cover every sample and keeps that cover
        FitOptions refit = opt;
        refit.thorough = false;
        FitStats more;
        st = fit_once(set, grown, refit, monitor, joined, more, &hold);
        if (!st.ok()) return st;
        sk = std::move(joined);
        if (report) *report = joined_report;
        stats.iterations += more.iterations;
        stats.accepted += more.accepted;
        stats.error_after = more.error_after;
        stats.added = uint32_t(added.size());
    }
    stats.uncovered = uncovered_samples(set, sel, sk.balls).size();
    stats.time_s = seconds_since(t0);
    return Status::success();
}

}  // namespace ca
