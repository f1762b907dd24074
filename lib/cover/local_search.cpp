// local_search.cpp: the anytime primal heuristic of the exact solver: row-weighting local
// search for unicost set cover (RWLS, Gao, Weise & Li 2015). Starting from a cover, it looks
// for covers one column smaller: drop a column, then swap columns (remove the one whose loss of
// weighted coverage is smallest, add the best column for a random uncovered row), raising the
// weight of rows that stay uncovered so that the search leaves local minima. Stops at a step
// limit, at the lower bound, or when it stalls. Deterministic for a seed (rng.h's portable splitmix64;
// the deadline is only a safety stop). SearchRuns: several seeded runs as a pool that threads
// work through.
#include "setcover_internal.h"

#include "rng.h"

#include <algorithm>
#include <cstdint>

namespace ca {
namespace sc {

namespace {
// Stall rule: stop once the steps since the last improvement exceed as many steps as the last
// improvement needed plus a patience proportional to the problem, kStallPerElement swaps per
// row and column but at least kStallMin. Improvements come sooner the longer a run has gone,
// so the patience grows with the problem and with the run's own progress rather than being a
// fixed count that small kernels would spend in full; several seeded runs share the work, so
// each can be short. Smaller factors lose balls.
constexpr uint64_t kStallPerElement = 5;
constexpr uint64_t kStallMin = 2000;
}  // namespace

SearchResult local_search(const Problem& P, std::vector<uint32_t> start, const SearchSettings& settings) {
    const size_t lower_bound = settings.lower_bound;
    const uint64_t max_steps = settings.max_steps, seed = settings.seed;
    const Deadline& deadline = settings.deadline;
    const std::atomic<size_t>* known_bound = settings.known_bound;
    SearchRace* race = settings.race;
    SearchResult result;
    std::sort(start.begin(), start.end());
    // an optimal cover found at swap `at`: tell the other runs
    auto publish = [&](uint64_t at) {
        if (!race) return;
        uint64_t cur = race->optimal_step.load();
        while (at < cur && !race->optimal_step.compare_exchange_weak(cur, at)) {
        }
    };
    if (P.R == 0 || start.size() <= lower_bound || !covers_problem(P, start)) {
        if (P.R == 0 || start.size() <= lower_bound) publish(0);
        result.cover = std::move(start);
        return result;
    }
    const uint32_t R = P.R, C = P.C;
    // raw pointers: the byte stores into `in` may alias anything, and would otherwise make the
    // compiler reload the vectors' data pointers in every inner loop
    const uint32_t* const rptr = P.rptr.data();
    const uint32_t* const rcol = P.rcol.data();
    const uint32_t* const cptr = P.cptr.data();
    const uint32_t* const crow = P.crow.data();
    std::vector<int64_t> w(R, 1), score(C, 0);
    std::vector<uint32_t> cnt(R, 0), upos(R, UINT32_MAX), uncovered;
    std::vector<uint64_t> stamp(C, 0);
    std::vector<uint8_t> in(C, 0);
    // Configuration checking, kept lazily: a column removed at operation t may enter again once
    // a column sharing a row with it has been added or removed after t. row_change[r] = the last
    // operation that added or removed a column of row r; removed_at[c] = c's last removal
    // (kNever: never removed, allowed). Same rule as marking every neighbour on each change,
    // at |c| reads per tested candidate instead of sum over rows of their sizes per change.
    constexpr uint64_t kNever = UINT64_MAX;
    std::vector<uint64_t> row_change(R, 0), removed_at(C, kNever);
    uint64_t op = 0;
    // XOR of the selected columns covering each row: the owner when exactly one covers it.
    std::vector<uint32_t> owner_xor(R, 0);
    std::vector<uint32_t> sel;  // current columns (unordered)
    std::vector<uint32_t> spos(C, UINT32_MAX);
    SplitMix64 rng{seed};

    auto uncover = [&](uint32_t r) { upos[r] = uint32_t(uncovered.size()); uncovered.push_back(r); };
    auto recover = [&](uint32_t r) {
        const uint32_t p = upos[r], last = uncovered.back();
        uncovered[p] = last;
        upos[last] = p;
        uncovered.pop_back();
        upos[r] = UINT32_MAX;
    };
    // the one selected column covering r (cnt[r] == 1)
    auto owner = [&](uint32_t r) { return owner_xor[r]; };
    auto allowed = [&](uint32_t c) {
        const uint64_t t = removed_at[c];
        if (t == kNever) return true;
        for (uint32_t k = cptr[c]; k < cptr[c + 1]; ++k)
            if (row_change[crow[k]] > t) return true;
        return false;
    };
    auto add = [&](uint32_t c) {
        ++op;
        int64_t sc = 0;
        for (uint32_t k = cptr[c]; k < cptr[c + 1]; ++k) {
            const uint32_t r = crow[k];
            if (cnt[r] == 0) {
                recover(r);
                // c's own score is set below, so it may take the update too (no branch)
                const int64_t wr = w[r];
                for (uint32_t q = rptr[r], qe = rptr[r + 1]; q < qe; ++q) score[rcol[q]] -= wr;
                sc -= wr;
            } else if (cnt[r] == 1) {
                score[owner(r)] += w[r];
            }
            cnt[r]++;
            owner_xor[r] ^= c;
            row_change[r] = op;  // configuration change: the columns around c may enter again
        }
        in[c] = 1;
        score[c] = sc;
        spos[c] = uint32_t(sel.size());
        sel.push_back(c);
    };
    auto remove = [&](uint32_t c) {
        ++op;
        in[c] = 0;
        const uint32_t p = spos[c], last = sel.back();
        sel[p] = last;
        spos[last] = p;
        sel.pop_back();
        spos[c] = UINT32_MAX;
        int64_t sc = 0;
        for (uint32_t k = cptr[c]; k < cptr[c + 1]; ++k) {
            const uint32_t r = crow[k];
            cnt[r]--;
            owner_xor[r] ^= c;
            row_change[r] = op;
            if (cnt[r] == 0) {
                uncover(r);
                const int64_t wr = w[r];
                for (uint32_t q = rptr[r], qe = rptr[r + 1]; q < qe; ++q) score[rcol[q]] += wr;
                sc += wr;
            } else if (cnt[r] == 1) {
                score[owner(r)] -= w[r];
            }
        }
        score[c] = sc;
        removed_at[c] = op;
    };
    // best selected column to drop: largest score (smallest loss), ties to the oldest
    auto pick_drop = [&](uint32_t tabu) {
        uint32_t best = UINT32_MAX;
        for (uint32_t c : sel) {
            if (c == tabu) continue;
            if (best == UINT32_MAX || score[c] > score[best] || (score[c] == score[best] && stamp[c] < stamp[best]))
                best = c;
        }
        return best;
    };

    // empty selection: every row uncovered, a column's score is its size; then add the start
    for (uint32_t r = 0; r < R; ++r) uncover(r);
    for (uint32_t c = 0; c < C; ++c) score[c] = int64_t(cptr[c + 1] - cptr[c]);
    for (uint32_t c : start) add(c);
    std::vector<uint32_t> best = start;
    uint32_t last_added = UINT32_MAX;
    uint64_t last_improved = 0;
    auto finish = [&](uint64_t at) {  // best is optimal, found at swap `at`
        publish(at);
        result.found_step = at;
        result.cover = std::move(best);
        return result;
    };
    const uint64_t patience = std::max<uint64_t>(kStallMin, kStallPerElement * (uint64_t(R) + C));
    uint64_t step_now = 0;
    for (uint64_t step = 1; step <= max_steps; ++step) {
        step_now = step;
        result.steps = step;
        while (uncovered.empty()) {
            if (sel.size() < best.size()) {
                best = sel;
                last_improved = step;
                std::sort(best.begin(), best.end());
                if (best.size() <= lower_bound) return finish(step);
            }
            const uint32_t c = pick_drop(UINT32_MAX);
            remove(c);
            stamp[c] = step;
        }
        if ((step & 255) == 0) {
            if (known_bound && best.size() <= known_bound->load(std::memory_order_relaxed)) return finish(last_improved);
            if (race && step > race->optimal_step.load(std::memory_order_relaxed)) break;  // cannot win
            if (deadline.expired()) break;
        }
        if (step > 2 * last_improved + patience) break;  // no progress for a long while
        // swap: drop one, add the best column (configuration allowed) for a random uncovered row
        const uint32_t d = pick_drop(last_added);
        if (d != UINT32_MAX) {
            remove(d);
            stamp[d] = step;
        }
        const uint32_t r = uncovered[size_t(rng.next() % uncovered.size())];
        uint32_t a = UINT32_MAX;
        for (uint32_t q = rptr[r]; q < rptr[r + 1]; ++q) {
            const uint32_t c = rcol[q];
            if (a == UINT32_MAX || score[c] > score[a] || (score[c] == score[a] && stamp[c] < stamp[a]))
                if (allowed(c)) a = c;  // tested only when c would be the best so far
        }
        if (a == UINT32_MAX) a = rcol[rptr[r]];  // every candidate just left: take one anyway
        add(a);
        stamp[a] = step;
        last_added = a;
        // rows still uncovered weigh more
        for (uint32_t u : uncovered) {
            w[u]++;
            for (uint32_t q = rptr[u]; q < rptr[u + 1]; ++q) score[rcol[q]]++;
        }
    }
    if (uncovered.empty() && sel.size() < best.size()) {
        best = sel;
        last_improved = step_now;
        std::sort(best.begin(), best.end());
    }
    remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, best);
    result.found_step = last_improved;
    result.cover = std::move(best);
    return result;
}

SearchRuns::SearchRuns(const Problem& P, const std::vector<uint32_t>& start, const SearchSettings& settings, int starts)
    : P_(P), start_(start), settings_(settings), found_(size_t(std::max(1, starts))), found_at_(found_.size(), 0) {
    settings_.race = &race_;
}

void SearchRuns::work() {
    for (size_t i = next_++; i < found_.size(); i = next_++) {
        SearchSettings run = settings_;
        run.seed = settings_.seed + i;
        SearchResult r = local_search(P_, start_, run);
        found_[i] = std::move(r.cover);
        found_at_[i] = r.found_step;
    }
}

std::vector<uint32_t> SearchRuns::best() const {
    size_t best = 0;
    for (size_t i = 1; i < found_.size(); ++i)
        if (found_[i].size() < found_[best].size() ||
            (found_[i].size() == found_[best].size() && found_at_[i] < found_at_[best]))
            best = i;
    return found_[best];
}

}  // namespace sc
}  // namespace ca
