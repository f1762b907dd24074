// component_solve.cpp: the exact solve of one connected component of the kernel
// (setcover_internal.h, solve_component), step by step: bounds, heuristics, the search on the LP's
// optimal face, then reduced-cost fixing, reduction and CBC or row generation on what is left.
#include "setcover_internal.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

namespace ca {
namespace sc {

namespace {

// The columns a cover of at most `size` columns can contain: a column j is in none when
// L(u) + max(0, c_j(u)) > size (`bound` = L(u), `cost` = the reduced costs at u).
Problem drop_beyond(const Problem& P, double bound, const std::vector<double>& cost, double size) {
    std::vector<uint8_t> keep(P.C, 0);
    for (uint32_t c = 0; c < P.C; ++c) keep[c] = bound + std::max(0.0, cost[c]) <= size + 1e-6;
    return restrict_columns(P, keep);
}

// Whether P has no cover of `size` columns, shown after dropping the columns no such cover
// contains (at the multipliers of D) and reducing what is left: a row left without a column, more
// forced columns than `size`, or branching on the LP (no_cover_within).
constexpr int kBranchColumns = 8;
bool rules_out(const Problem& P, const Lagrange& D, size_t size, const Monitor& monitor,
               const std::function<bool()>& stop) {
    const Problem Q = drop_beyond(P, D.bound, D.cost, double(size));
    for (uint32_t r = 0; r < Q.R; ++r)
        if (Q.rptr[r] == Q.rptr[r + 1]) return true;
    std::vector<uint32_t> forced;
    Problem K;
    if (!reduce_problem(Q, monitor, forced, K).ok()) return false;
    if (forced.size() > size) return true;
    if (K.R == 0) return false;  // the forced columns are such a cover
    return no_cover_within(K, size - forced.size(), kBranchColumns, stop);
}

// Whether the fast effort's branching step (rules_out) is tried on component P, whose LP bound
// is lp (ceil: lp_bound): always on small components, and on larger ones when the LP lies
// within kFastBranchShortfall of lp_bound: branching on one column raises the LP by a tenth
// or so, so it can close only a small shortfall, and on large kernels a failed attempt is costly.
bool worth_branching(const Problem& P, double lp, size_t lp_bound) {
    return P.R <= kFastCbcMaxRows || double(lp_bound) - lp <= kFastBranchShortfall;
}

// Most swaps of the local search per component (it usually stops earlier, when it stalls), and
// its seed.
constexpr uint64_t kLocalSearchSteps = 1000000;
constexpr uint64_t kLocalSearchSeed = 3;
// Independent local-search runs (seeds kLocalSearchSeed, +1, ...): a single run's result
// depends on its seed, the best of several much less.
constexpr int kLocalSearchStarts = 4;
// Components of at most kSmallSearchRows rows get kSmallSearchStarts runs: on small kernels few
// runs already find the smallest covers, and more only cost search time. Components too large for CBC
// (below) get kSmallSearchStarts runs too: there a run is long, and the first runs already give
// the best covers.
constexpr uint32_t kSmallSearchRows = 400;
constexpr int kSmallSearchStarts = 2;

// Largest component CBC solves as a whole (its root LP cannot be interrupted). Larger ones also
// get the volume ascent, the LP by row and column generation, and kSmallSearchStarts search runs.
constexpr uint32_t kWholeCbcMaxRows = 4000;
// Subgradient steps around the LP duals (for the reduced-cost greedy).
constexpr int kDualSteps = 10;
// Subgradient steps before the LP on components up to kWholeCbcMaxRows rows.
constexpr int kSubgradientWarmup = 150;
// Volume steps before the LP on larger components.
constexpr int kVolumeSteps = 1000;

// The exact solve of one component, step by step; the steps share the state below. Each step
// returns false once the component is solved or the call cancelled.
class ComponentSolve {
public:
    ComponentSolve(const Problem& P, const Deadline& deadline, int threads, bool row_gen, Effort effort,
                   int search_threads, const Monitor& monitor, double give_up_above)
        : P_(P), deadline_(deadline), threads_(threads), row_gen_(row_gen), effort_(effort),
          search_threads_(search_threads), monitor_(monitor), large_(P.R > kWholeCbcMaxRows),
          give_up_above_(give_up_above) {}

    ComponentResult run() {
        if (bounds() && heuristics() && core_search()) exact();
        return std::move(out_);
    }

private:
    // What the LP phase found: the Lagrangian at the LP duals, and the bound branching proved.
    struct LpOutcome {
        Lagrange D;
        bool have_duals = false;
        size_t branched_bound = 0;  // > 0: every cover has at least this many columns
    };
    // The reduced problem the exact solve works on: the columns a cover smaller than the
    // incumbent can use (Q), the columns of Q every such cover contains, and the rest reduced (K).
    struct Kernel {
        Problem Q, K;
        std::vector<uint32_t> forced;  // Q-local
    };

    // The bound meets the cover: it is optimal.
    bool done() {
        if (out_.lb >= double(out_.sel.size())) {
            out_.lb = double(out_.sel.size());
            out_.proven = true;
        }
        return out_.proven;
    }
    // Solved, cancelled, or shown to need more columns than the caller can use (give_up_above_).
    bool stop() { return done() || monitor_.cancelled() || out_.lb > give_up_above_; }
    void prove_incumbent() {
        out_.lb = double(out_.sel.size());
        out_.proven = true;
    }

    // The greedy cover, the disjoint-rows bound, and a Lagrangian warm-up (volume ascent on
    // components too large for CBC).
    bool bounds() {
        out_.sel = greedy_cover(P_);
        remove_redundant(P_.cptr, P_.crow, P_.R, nullptr, nullptr, out_.sel);
        out_.lb = double(disjoint_bound(P_));
        if (stop()) return false;
        // The subgradient phase gets at most a quarter of what is left of the budget.
        const Deadline lag_deadline = deadline_.share(0.25);
        // Before the LP only a warm-up: its covers and reduced costs seed the core LP and the
        // local search, and the LP gives the bound; more steps cost time without changing
        // results once the local search runs from several seeds, far fewer give a poorer core.
        // Components too large for CBC get the volume ascent instead: its bound may have to
        // stand alone, and its sparse multipliers start the LP by row generation.
        L_ = large_ ? volume_ascent(P_, out_.sel, kVolumeSteps, lag_deadline)
                    : lagrangian(P_, out_.sel, kSubgradientWarmup, lag_deadline);
        if (L_.best.size() < out_.sel.size()) out_.sel = L_.best;
        out_.lb = std::max(out_.lb, std::ceil(L_.bound - 1e-6));
        return !stop();
    }

    // The LP relaxation (its duals: the best bound and reduced costs for fixing, and a
    // reduced-cost greedy around them) and the local search from the warm-up's cover (at most a
    // quarter of what is left: it usually reaches the optimum, so that CBC only has to prove it)
    // run side by side. Neither depends on the other's result, so the outcome is the same on one
    // thread or several; the LP's bound, once known, only lets the search stop earlier, and the
    // runs do not depend on which thread takes them or when (SearchRuns).
    bool heuristics() {
        const double lp_limit = deadline_.limited() ? std::max(1e-3, deadline_.remaining() / 4) : 0.0;
        const Deadline ls_deadline = deadline_.share(0.25);
        std::atomic<size_t> known_bound{size_t(out_.lb)};
        const std::vector<uint32_t> start = out_.sel;
        const int starts = (P_.R <= kSmallSearchRows || large_) ? kSmallSearchStarts : kLocalSearchStarts;
        SearchSettings search;
        search.lower_bound = size_t(out_.lb);
        search.max_steps = kLocalSearchSteps;
        search.seed = kLocalSearchSeed;
        search.deadline = ls_deadline;
        search.known_bound = &known_bound;
        SearchRuns runs(P_, start, search, starts);
        LpOutcome lp;
        const int search_workers = std::min(resolve_threads(search_threads_), starts);
        if (search_workers > 1) {
            // One search run per thread, and the LP's thread takes the runs still waiting once
            // its LP is solved, so the LP keeps a core of its own. Without a thread for the LP it
            // runs here first: the same result.
            Beside lp_thread([&]() {
                lp = lp_phase(start.size(), lp_limit, runs, known_bound);
                runs.work();
            });
            run_workers(size_t(search_workers), [&](size_t) { runs.work(); });
            lp_thread.wait();
        } else {
            lp = lp_phase(start.size(), lp_limit, runs, known_bound);
            runs.work();
        }
        const std::vector<uint32_t> searched = runs.best();
        lp_ok_ = lp.have_duals;  // else CBC does not get the whole component (its root LP)
        if (lp.have_duals) {
            if (lp.D.best.size() < L_.best.size()) L_.best = lp.D.best;
            if (lp.D.bound > L_.bound) {
                L_.bound = lp.D.bound;
                L_.u = std::move(lp.D.u);
                L_.cost = std::move(lp.D.cost);
            }
        }
        out_.sel = searched.size() <= L_.best.size() ? searched : L_.best;
        out_.lb = std::max({out_.lb, std::ceil(L_.bound - 1e-6), double(lp.branched_bound)});
        return !stop();
    }

    // The LP's duals, the Lagrangian at them, and the branching step; `start_size` is the size
    // of the cover the search starts from. Runs beside the search: it reads only L_ and P_.
    LpOutcome lp_phase(size_t start_size, double lp_limit, const SearchRuns& runs,
                       std::atomic<size_t>& known_bound) const {
        LpOutcome lp;
        const std::vector<double> duals =
            large_ ? lp_duals_rows(P_, L_.u, L_.cost, lp_limit) : lp_duals_core(P_, L_.cost, lp_limit);
        if (duals.empty()) return lp;
        // bound and costs at the duals, then a few small steps around them for the reduced-cost
        // greedy (near the LP optimum more steps find no better covers)
        lp.D = lagrangian(P_, L_.best, kDualSteps, deadline_, &duals, 0.05);
        lp.have_duals = true;
        const size_t lp_bound = size_t(std::max(0.0, std::ceil(lp.D.bound - 1e-6)));
        known_bound.store(std::max(known_bound.load(), lp_bound));
        // Both efforts (see worth_branching): try to show that no cover has lp_bound columns (one
        // more ball of bound, often the proof the search's cover needs, without CBC; in the prove
        // effort it keeps the bound when CBC's own stays below it). It gives up once a search run
        // finds a cover that small, which would make it fail anyway, so the outcome does not
        // depend on timing.
        if (worth_branching(P_, lp.D.bound, lp_bound) && lp_bound < start_size &&
            rules_out(P_, lp.D, lp_bound, monitor_, [&]() { return runs.reached_bound(); })) {
            lp.branched_bound = lp_bound + 1;
            known_bound.store(std::max(known_bound.load(), lp.branched_bound));
        }
        return lp;
    }

    // Prove effort: a short search on the LP optimal face first (core_cover): a smaller
    // incumbent there often equals the LP bound, which proves it at once. Not in the fast
    // effort: on most kernels it finds nothing, and its time would be spent for nothing.
    bool core_search() {
        if (effort_ != Effort::prove || !lp_ok_ || large_) return true;
        const double limit = deadline_.limit_s() / 4;
        if (deadline_.limited() && limit <= 0) return true;
        std::vector<uint32_t> smaller = core_cover(P_, L_.cost, out_.sel.size(), limit, threads_, monitor_);
        if (!smaller.empty()) out_.sel = std::move(smaller);
        return !stop();
    }

    // Reduced-cost fixing and reduction, then row generation and/or CBC on the kernel left.
    void exact() {
        // Covers smaller than the incumbent have at most target columns.
        const double target = double(out_.sel.size()) - 1.0;
        Kernel k;
        k.Q = drop_beyond(P_, L_.bound, L_.cost, target);
        for (uint32_t r = 0; r < k.Q.R; ++r)
            if (k.Q.rptr[r] == k.Q.rptr[r + 1]) return prove_incumbent();
        if (!reduce_problem(k.Q, monitor_, k.forced, k.K).ok()) return;
        const size_t inc = out_.sel.size();
        if (k.forced.size() >= inc) return prove_incumbent();
        if (k.K.R == 0) {  // the forced columns alone cover everything: smaller than the incumbent
            take(k, {});
            return prove_incumbent();
        }
        // Fast effort: CBC only for a one-ball gap on a small kernel, with a node limit.
        const bool fast = effort_ == Effort::fast;
        if (fast && (double(inc) - out_.lb > 1.0 || k.K.R > kFastCbcMaxRows)) return;
        double remaining = deadline_.limit_s();  // 0 = no limit
        if (deadline_.limited() && remaining <= 0) return;
        out_.used_cbc = true;
        // Covers of K smaller than kbest are sought; klb is a lower bound on K's optimum.
        size_t kbest = inc - k.forced.size();
        double klb = 0;
        // CBC's root LP ignores its time limit; on a component whose LP Clp could not solve
        // within its share, or one with more than kWholeCbcMaxRows rows, CBC never gets the
        // whole of it: row generation (small sub-problems) keeps the budget.
        const bool whole_cbc = lp_ok_ && k.K.R <= kWholeCbcMaxRows;
        if (!fast && (row_gen_ || !whole_cbc)) {
            // Row generation first, with part of the budget; if it does not finish, one CBC
            // solve of the whole of K takes over with its incumbent.
            const Deadline rg_deadline = whole_cbc ? deadline_.share(kRowGenShare) : deadline_;
            const RowGenOutcome rg = row_generation(k.K, kbest, rg_deadline, threads_, monitor_);
            out_.rowgen_rounds = rg.rounds;
            if (!rg.sel.empty()) kbest = take(k, rg.sel);
            klb = rg.lb;
            if (rg.proven) klb = double(kbest);
            if (klb >= double(kbest) || monitor_.cancelled() || !whole_cbc) return finish(k, klb);
            remaining = deadline_.limit_s();
            if (deadline_.limited() && remaining <= 0) return finish(k, klb);
        }
        // not ok: CBC failed, the incumbent stays
        CbcSettings cs;
        cs.time_limit_s = remaining;
        cs.threads = threads_;
        cs.heuristics = false;
        cs.max_nodes = fast ? kFastCbcNodes : 0;
        cs.lean = fast;
        const CbcOutcome cbc = run_cbc(k.K, kbest, cs);
        if (cbc.ok && cbc.has_solution) take(k, cbc.solution);
        if (cbc.ok && cbc.proven) return prove_incumbent();
        if (cbc.ok && std::isfinite(cbc.bound)) klb = std::max(klb, std::ceil(cbc.bound - 1e-6));
        finish(k, klb);
    }

    // The cover made of the forced columns and the K-local cover ksol; returns |ksol|.
    size_t take(const Kernel& k, const std::vector<uint32_t>& ksol) {
        out_.sel.clear();
        for (uint32_t c : k.forced) out_.sel.push_back(k.Q.col_id[c]);
        for (uint32_t c : ksol) out_.sel.push_back(k.Q.col_id[k.K.col_id[c]]);
        std::sort(out_.sel.begin(), out_.sel.end());
        return ksol.size();
    }
    // Every cover below the incumbent the kernel was made for lies in K (+ forced): the optimum
    // is at least min(|sel|, forced + klb).
    void finish(const Kernel& k, double klb) {
        out_.lb = std::max(out_.lb, std::min(double(out_.sel.size()), double(k.forced.size()) + klb));
        done();
    }

    const Problem& P_;
    const Deadline& deadline_;
    const int threads_;
    const bool row_gen_;
    const Effort effort_;
    const int search_threads_;
    const Monitor& monitor_;
    const bool large_;    // more than kWholeCbcMaxRows rows
    const double give_up_above_;  // kNoGiveUp: off
    ComponentResult out_;
    Lagrange L_;          // the best Lagrangian bound so far, its multipliers, costs and cover
    bool lp_ok_ = false;  // the LP relaxation was solved
};

}  // namespace

ComponentResult solve_component(const Problem& P, const Deadline& deadline, int threads,
                                bool row_gen, Effort effort, int search_threads, const Monitor& monitor,
                                double give_up_above) {
    return ComponentSolve(P, deadline, threads, row_gen, effort, search_threads, monitor, give_up_above).run();
}

}  // namespace sc
}  // namespace ca
