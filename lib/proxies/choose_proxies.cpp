// choose_proxies.cpp: at most K candidates of least error. Each point takes its best chosen
// candidate; the error is the largest such cost over the points (clamped at 0), then the sum of
// their squares. Greedy on the sum of squares (the largest error alone seldom moves when one
// candidate is added), then swaps of one chosen candidate for another while (largest, sum) drops,
// then removal of the candidates the error can do without. Adding stops once the largest error is
// within `tolerance` of what all candidates together reach, or when the best candidate lowers
// neither the largest error nor the sum by `min_gain` of it; a chosen candidate is removed when,
// without it, the largest error stays within that reach or as it was and the sum grows by less
// than `min_gain` (over all removals together). More primitives would buy nothing worth an
// engine's time. Every score is one candidate's own sum in a fixed order, so the
// result does not depend on the thread count; ties go to the lower index.
#include "proxies.h"

#include "parallel.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace ca {

namespace {

// Swap passes over the chosen set (each tries every candidate in every slot).
constexpr int kSwapPasses = 2;
// A swap must lower the largest error by more than this (internal units), or keep it and lower the
// sum of squares by this fraction: no swaps back and forth on rounding.
constexpr double kMaxGain = 1e-7;
constexpr double kSumGain = 1e-9;

struct Score {
    double max = 0, sum = 0;
    bool better_than(const Score& o) const {
        if (max < o.max - kMaxGain) return true;
        return max <= o.max + kMaxGain && sum < o.sum * (1 - kSumGain);
    }
};

// The error of the points when each takes min(base[i], row[i]). It may stop early, with a partial
// score, once the largest error passes `max_cut` or the sum passes `sum_cut`: the candidate is then
// known to be worse than the one those cuts came from, and the full scores decide among the rest.
Score score(const float* row, const std::vector<float>& base, double max_cut = DBL_MAX, double sum_cut = DBL_MAX) {
    Score s;
    constexpr size_t kBlock = 256;
    for (size_t start = 0; start < base.size(); start += kBlock) {
        const size_t stop = std::min(base.size(), start + kBlock);
        float block_max = 0, block_sum = 0;
        for (size_t i = start; i < stop; ++i) {
            const float e = std::max(0.0f, std::min(base[i], row[i]));
            block_max = std::max(block_max, e);
            block_sum += e * e;
        }
        s.max = std::max(s.max, double(block_max));
        s.sum += double(block_sum);
        if (s.max > max_cut || s.sum > sum_cut) break;
    }
    return s;
}

// Per point: the best cost over `chosen` except slot `skip` (FLT_MAX when none).
std::vector<float> best_without(const std::vector<float>& cost, size_t points, const std::vector<uint32_t>& chosen,
                                 size_t skip) {
    std::vector<float> best(points, FLT_MAX);
    for (size_t k = 0; k < chosen.size(); ++k) {
        if (k == skip) continue;
        const float* row = cost.data() + size_t(chosen[k]) * points;
        for (size_t i = 0; i < points; ++i) best[i] = std::min(best[i], row[i]);
    }
    return best;
}

}  // namespace

std::vector<uint32_t> choose_proxies(const std::vector<float>& cost, size_t candidates, size_t points,
                                     size_t count, double tolerance, double min_gain, int threads) {
    std::vector<uint32_t> chosen;
    if (candidates == 0 || points == 0 || count == 0) return chosen;
    std::vector<uint32_t> all(candidates);
    for (size_t c = 0; c < candidates; ++c) all[c] = uint32_t(c);
    const std::vector<float> floor = best_without(cost, points, all, SIZE_MAX);
    const double goal = score(floor.data(), floor).max + tolerance;
    std::vector<uint8_t> taken(candidates, 0);
    std::vector<Score> scores(candidates);
    const Monitor quiet;
    // the best candidate for `base`: lowest score, lowest index among equals; SIZE_MAX if none.
    // by_sum: the cut is the lowest full sum this worker has seen; else the current largest error.
    auto best_for = [&](const std::vector<float>& base, bool by_sum, double max_cut) {
        parallel_for(candidates, threads, 64, quiet, "proxies", [&](size_t b, size_t e) {
            double sum_cut = DBL_MAX;
            for (size_t c = b; c < e; ++c) {
                if (taken[c]) continue;
                scores[c] = score(cost.data() + c * points, base, max_cut, by_sum ? sum_cut : DBL_MAX);
                if (scores[c].sum <= sum_cut && scores[c].max <= max_cut) sum_cut = scores[c].sum;
            }
        });
        size_t best = SIZE_MAX;
        for (size_t c = 0; c < candidates; ++c) {
            if (taken[c]) continue;
            if (best == SIZE_MAX) best = c;
            else if (by_sum ? scores[c].sum < scores[best].sum : scores[c].better_than(scores[best])) best = c;
        }
        return best;
    };

    // ---- greedy on the sum of squares ----
    std::vector<float> base(points, FLT_MAX);
    Score current{DBL_MAX, DBL_MAX};
    while (chosen.size() < count && current.max > goal) {
        const size_t c = best_for(base, true, DBL_MAX);
        if (c == SIZE_MAX) break;
        // (the lowest sum is never cut short: its score is whole)
        const Score& s = scores[c];
        if (!chosen.empty() && !(s.sum < current.sum * (1 - min_gain) || s.max < current.max * (1 - min_gain))) break;
        chosen.push_back(uint32_t(c));
        taken[c] = 1;
        const float* row = cost.data() + c * points;
        for (size_t i = 0; i < points; ++i) base[i] = std::min(base[i], row[i]);
        current = score(row, base);
    }

    // ---- swaps ----
    for (int pass = 0; pass < kSwapPasses && current.max > goal; ++pass) {
        bool changed = false;
        for (size_t k = 0; k < chosen.size(); ++k) {
            const std::vector<float> without = best_without(cost, points, chosen, k);
            const size_t c = best_for(without, false, current.max + kMaxGain);
            if (c == SIZE_MAX || !scores[c].better_than(current)) continue;
            taken[chosen[k]] = 0;
            chosen[k] = uint32_t(c);
            taken[c] = 1;
            current = scores[c];
            changed = true;
        }
        if (!changed) break;
    }

    // ---- removal of what the error does without ----
    const Score full = current;
    while (chosen.size() > 1) {
        size_t drop = SIZE_MAX;
        Score drop_score;
        for (size_t k = 0; k < chosen.size(); ++k) {
            const std::vector<float> without = best_without(cost, points, chosen, k);
            const Score s = score(without.data(), without);
            if (s.max > std::max(goal, full.max + kMaxGain) || s.sum > full.sum * (1 + min_gain)) continue;
            if (drop == SIZE_MAX || s.better_than(drop_score)) {
                drop = k;
                drop_score = s;
            }
        }
        if (drop == SIZE_MAX) break;
        chosen.erase(chosen.begin() + std::ptrdiff_t(drop));
        current = drop_score;
    }
    return chosen;
}

}  // namespace ca
