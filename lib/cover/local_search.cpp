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

// The search's state over one problem: the selection, each row's cover count and weight, each
// column's score (the weighted coverage it would gain when added, or lose when removed), the
// uncovered rows, and the configuration-checking stamps. add/remove keep all of it consistent.
class RowWeighting {
public:
    RowWeighting(const Problem& P, uint64_t seed)
        : R_(P.R), C_(P.C), rptr_(P.rptr.data()), rcol_(P.rcol.data()), cptr_(P.cptr.data()),
          crow_(P.crow.data()), w_(R_, 1), score_(C_, 0), cnt_(R_, 0), upos_(R_, UINT32_MAX),
          stamp_(C_, 0), row_change_(R_, 0), removed_at_(C_, kNever), owner_xor_(R_, 0),
          spos_(C_, UINT32_MAX), rng_{seed} {
        // empty selection: every row uncovered, a column's score is its size
        for (uint32_t r = 0; r < R_; ++r) uncover(r);
        for (uint32_t c = 0; c < C_; ++c) score_[c] = int64_t(cptr_[c + 1] - cptr_[c]);
    }

    const std::vector<uint32_t>& selection() const { return sel_; }
    bool covered() const { return uncovered_.empty(); }

    void add(uint32_t c, uint64_t step) {
        ++op_;
        int64_t sc = 0;
        for (uint32_t k = cptr_[c]; k < cptr_[c + 1]; ++k) {
            const uint32_t r = crow_[k];
            if (cnt_[r] == 0) {
                recover(r);
                // c's own score is set below, so it may take the update too (no branch)
                const int64_t wr = w_[r];
                for (uint32_t q = rptr_[r], qe = rptr_[r + 1]; q < qe; ++q) score_[rcol_[q]] -= wr;
                sc -= wr;
            } else if (cnt_[r] == 1) {
                score_[owner_xor_[r]] += w_[r];
            }
            cnt_[r]++;
            owner_xor_[r] ^= c;
            row_change_[r] = op_;  // configuration change: the columns around c may enter again
        }
        score_[c] = sc;
        spos_[c] = uint32_t(sel_.size());
        sel_.push_back(c);
        stamp_[c] = step;
    }

    void remove(uint32_t c, uint64_t step) {
        ++op_;
        const uint32_t p = spos_[c], last = sel_.back();
        sel_[p] = last;
        spos_[last] = p;
        sel_.pop_back();
        spos_[c] = UINT32_MAX;
        int64_t sc = 0;
        for (uint32_t k = cptr_[c]; k < cptr_[c + 1]; ++k) {
            const uint32_t r = crow_[k];
            cnt_[r]--;
            owner_xor_[r] ^= c;
            row_change_[r] = op_;
            if (cnt_[r] == 0) {
                uncover(r);
                const int64_t wr = w_[r];
                for (uint32_t q = rptr_[r], qe = rptr_[r + 1]; q < qe; ++q) score_[rcol_[q]] += wr;
                sc += wr;
            } else if (cnt_[r] == 1) {
                score_[owner_xor_[r]] -= w_[r];
            }
        }
        score_[c] = sc;
        removed_at_[c] = op_;
        stamp_[c] = step;
    }

    // the selected column to drop: largest score (smallest loss), ties to the oldest; not `tabu`
    uint32_t pick_drop(uint32_t tabu) const {
        uint32_t best = UINT32_MAX;
        for (uint32_t c : sel_) {
            if (c == tabu) continue;
            if (best == UINT32_MAX || better(c, best)) best = c;
        }
        return best;
    }

    // the column to add: the best allowed column of a random uncovered row (any of its columns
    // when every one has just left)
    uint32_t pick_add() {
        const uint32_t r = uncovered_[size_t(rng_.next() % uncovered_.size())];
        uint32_t a = UINT32_MAX;
        for (uint32_t q = rptr_[r]; q < rptr_[r + 1]; ++q) {
            const uint32_t c = rcol_[q];
            if (a == UINT32_MAX || better(c, a))
                if (allowed(c)) a = c;  // tested only when c would be the best so far
        }
        return a == UINT32_MAX ? rcol_[rptr_[r]] : a;
    }

    // rows still uncovered weigh more
    void raise_weights() {
        for (uint32_t u : uncovered_) {
            w_[u]++;
            for (uint32_t q = rptr_[u]; q < rptr_[u + 1]; ++q) score_[rcol_[q]]++;
        }
    }

private:
    // Configuration checking, kept lazily: a column removed at operation t may enter again once
    // a column sharing a row with it has been added or removed after t. row_change_[r] = the
    // last operation that added or removed a column of row r; removed_at_[c] = c's last removal
    // (kNever: never removed, allowed). Same rule as marking every neighbour on each change,
    // at |c| reads per tested candidate instead of sum over rows of their sizes per change.
    static constexpr uint64_t kNever = UINT64_MAX;

    bool better(uint32_t c, uint32_t than) const {
        return score_[c] > score_[than] || (score_[c] == score_[than] && stamp_[c] < stamp_[than]);
    }
    bool allowed(uint32_t c) const {
        const uint64_t t = removed_at_[c];
        if (t == kNever) return true;
        for (uint32_t k = cptr_[c]; k < cptr_[c + 1]; ++k)
            if (row_change_[crow_[k]] > t) return true;
        return false;
    }
    void uncover(uint32_t r) { upos_[r] = uint32_t(uncovered_.size()); uncovered_.push_back(r); }
    void recover(uint32_t r) {
        const uint32_t p = upos_[r], last = uncovered_.back();
        uncovered_[p] = last;
        upos_[last] = p;
        uncovered_.pop_back();
        upos_[r] = UINT32_MAX;
    }

    const uint32_t R_, C_;
    // the problem's arrays as raw pointers: read in every inner loop, never reloaded
    const uint32_t* const rptr_;
    const uint32_t* const rcol_;
    const uint32_t* const cptr_;
    const uint32_t* const crow_;
    std::vector<int64_t> w_, score_;
    std::vector<uint32_t> cnt_, upos_, uncovered_;
    std::vector<uint64_t> stamp_;
    std::vector<uint64_t> row_change_, removed_at_;
    uint64_t op_ = 0;
    std::vector<uint32_t> owner_xor_;  // XOR of the selected columns covering each row: the owner when one does
    std::vector<uint32_t> sel_;        // current columns (unordered)
    std::vector<uint32_t> spos_;
    SplitMix64 rng_;
};

// an optimal cover found at swap `at`: tell the other runs
void publish_optimal(SearchRace* race, uint64_t at) {
    if (!race) return;
    uint64_t cur = race->optimal_step.load();
    while (at < cur && !race->optimal_step.compare_exchange_weak(cur, at)) {
    }
}
}  // namespace

SearchResult local_search(const Problem& P, std::vector<uint32_t> start, const SearchSettings& settings) {
    const size_t lower_bound = settings.lower_bound;
    SearchResult result;
    std::sort(start.begin(), start.end());
    if (P.R == 0 || start.size() <= lower_bound || !covers_problem(P, start)) {
        if (P.R == 0 || start.size() <= lower_bound) publish_optimal(settings.race, 0);
        result.cover = std::move(start);
        return result;
    }
    RowWeighting search(P, settings.seed);
    for (uint32_t c : start) search.add(c, 0);
    std::vector<uint32_t> best = start;
    uint32_t last_added = UINT32_MAX;
    uint64_t last_improved = 0;
    auto finish = [&](uint64_t at) {  // best is optimal, found at swap `at`
        publish_optimal(settings.race, at);
        result.found_step = at;
        result.cover = std::move(best);
        return result;
    };
    const uint64_t patience = std::max<uint64_t>(kStallMin, kStallPerElement * (uint64_t(P.R) + P.C));
    uint64_t step_now = 0;
    for (uint64_t step = 1; step <= settings.max_steps; ++step) {
        step_now = step;
        result.steps = step;
        while (search.covered()) {
            if (search.selection().size() < best.size()) {
                best = search.selection();
                last_improved = step;
                std::sort(best.begin(), best.end());
                if (best.size() <= lower_bound) return finish(step);
            }
            search.remove(search.pick_drop(UINT32_MAX), step);
        }
        if ((step & 255) == 0) {
            if (settings.known_bound && best.size() <= settings.known_bound->load(std::memory_order_relaxed))
                return finish(last_improved);
            if (settings.race && step > settings.race->optimal_step.load(std::memory_order_relaxed)) break;  // cannot win
            if (settings.deadline.expired()) break;
        }
        if (step > 2 * last_improved + patience) break;  // no progress for a long while
        // swap: drop one, add the best allowed column for a random uncovered row
        const uint32_t d = search.pick_drop(last_added);
        if (d != UINT32_MAX) search.remove(d, step);
        last_added = search.pick_add();
        search.add(last_added, step);
        search.raise_weights();
    }
    if (search.covered() && search.selection().size() < best.size()) {
        best = search.selection();
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
