// setcover.cpp: minimum set cover of the samples by the candidate balls (see setcover.h): input
// checks and the solve driver. The reduction is in reduction.cpp, building blocks in
// setcover_problem.cpp, the exact machinery in lagrangian.cpp, lp_cbc.cpp and row_generation.cpp (setcover_internal.h).
//
// Pipeline: input checks -> reduction to a fixpoint (forced balls, degree-1 samples, dominated
// samples, dominated balls, empty balls; after one complete pass of each dominance test only
// the balls / samples whose lists shrank are tested again) -> kernel solve -> redundancy
// removal -> verification.
// Exact kernel solve, per connected component of the kernel (components share no rows and no
// columns, so optima and bounds add): greedy cover -> Lagrangian subgradient (bound, and a
// reduced-cost greedy that improves the incumbent; the volume algorithm on components too large
// for CBC) -> if that leaves a gap, the LP relaxation's duals (Clp) as multipliers, with small
// subgradient steps around them for the greedy ->
// done if ceil(bound) meets the incumbent; otherwise row-weighting local search
// (local_search.cpp, a quarter of the remaining budget) for a better incumbent, then
// reduced-cost fixing (drop every column that no cover smaller than the incumbent can
// contain), reduction again, and CBC on what is left with the incumbent as cutoff and CBC's
// own heuristics off (it only has to prove). Both efforts first try, beside the search and
// on small components or LPs close to the next integer, to raise the LP bound by one ball by
// branching on the LP (rules_out).
// With the fast effort (the default) CBC runs only
// when one ball separates incumbent and bound on a small kernel, with a node limit and no
// preprocessing or cuts (see Effort);
// otherwise the local-search cover is returned with its bound. Row generation (exact ILPs on growing row subsets,
// see row_generation) runs first only on request (CoverOptions::row_generation) or when the
// component is too large for one CBC solve.
// Heuristic kernel solve: greedy / Coverage Axis++.
// Reductions never change the optimum value, so forced + a kernel lower bound is a valid lower
// bound of the original problem.
#include "setcover_internal.h"
#include "parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <queue>
#include <string>

namespace ca {

namespace {

using namespace sc;

std::string uncoverable_message(const std::vector<uint32_t>& unc, size_t m) {
    std::string msg = std::to_string(unc.size()) + " of " + std::to_string(m) +
                      " samples are covered by no candidate ball (first: ";
    for (size_t i = 0; i < unc.size() && i < 10; ++i) {
        if (i) msg += ", ";
        msg += std::to_string(unc[i]);
    }
    if (unc.size() > 10) msg += ", ...";
    msg += ")";
    return msg;
}

// Ascending (strictly) list check, branch-free over the list.
bool strictly_ascending(const uint32_t* l, uint32_t len) {
    uint32_t bad = 0;
    for (uint32_t k = 1; k < len; ++k) bad |= uint32_t(l[k] <= l[k - 1]);
    return bad == 0;
}

// Checks the ball -> sample lists; `count[j]` gets the number of balls covering sample j.
Status check_coverage(const Coverage& cov, std::vector<uint32_t>& count) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (m >= UINT32_MAX || n >= UINT32_MAX) return fail(Code::invalid_input, "set cover: too many samples or balls");
    if (cov.ball_ptr.size() != n + 1 || cov.ball_ptr[0] != 0 || cov.ball_ptr[n] != cov.ball_samples.size())
        return fail(Code::invalid_input, "set cover: malformed coverage (ball_ptr)");
    for (size_t a = 0; a < n; ++a) {
        const uint32_t b = cov.ball_ptr[a], e = cov.ball_ptr[a + 1];
        if (e < b) return fail(Code::invalid_input, "set cover: malformed coverage (ball_ptr)");
        if (!strictly_ascending(cov.ball_samples.data() + b, e - b))
            return fail(Code::invalid_input, "set cover: ball sample list not strictly ascending");
        if (e > b && cov.ball_samples[e - 1] >= m) return fail(Code::invalid_input, "set cover: sample index out of range");
    }
    count.assign(m, 0);
    for (uint32_t j : cov.ball_samples) count[j]++;
    return Status::success();
}

// Cheap check that cov's sample -> ball direction can be trusted: right sizes, per-sample
// counts match the ball -> sample direction (`count`), lists ascending and in range.
bool transpose_consistent(const Coverage& cov, const std::vector<uint32_t>& count) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (cov.sample_ptr.size() != m + 1 || cov.sample_ptr[0] != 0 || cov.sample_ptr[m] != cov.ball_samples.size() ||
        cov.sample_balls.size() != cov.ball_samples.size())
        return false;
    for (size_t j = 0; j < m; ++j) {
        const uint32_t b = cov.sample_ptr[j], e = cov.sample_ptr[j + 1];
        if (e < b || e - b != count[j] || !strictly_ascending(cov.sample_balls.data() + b, e - b)) return false;
        if (e > b && cov.sample_balls[e - 1] >= n) return false;
    }
    return true;
}

// Shared front part: checks, masks, uncoverable samples.
struct Prepared {
    std::vector<uint8_t> required, allowed, locked;
    bool transpose_ok = false;  // cov's sample -> ball lists can be used as they are
    std::vector<uint32_t> uncovered;
    size_t rows_before = 0, cols_before = 0;
};

Status prepare(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, Prepared& pr) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    std::vector<uint32_t> count;
    Status st = check_coverage(cov, count);
    if (!st.ok()) return st;
    pr.transpose_ok = transpose_consistent(cov, count);
    if (!opt.ignorable_samples.empty() && opt.ignorable_samples.size() != m)
        return fail(Code::invalid_argument, "set cover: ignorable_samples must have 0 or n_samples entries");
    if (!opt.forced_in.empty() && opt.forced_in.size() != n)
        return fail(Code::invalid_argument, "set cover: forced_in must have 0 or n_balls entries");
    if (!opt.forced_out.empty() && opt.forced_out.size() != n)
        return fail(Code::invalid_argument, "set cover: forced_out must have 0 or n_balls entries");
    pr.required.assign(m, 1);
    pr.allowed.assign(n, 1);
    pr.locked.assign(n, 0);
    for (size_t j = 0; j < opt.ignorable_samples.size(); ++j)
        if (opt.ignorable_samples[j]) pr.required[j] = 0;
    for (size_t a = 0; a < opt.forced_out.size(); ++a)
        if (opt.forced_out[a]) pr.allowed[a] = 0;
    for (size_t a = 0; a < opt.forced_in.size(); ++a)
        if (opt.forced_in[a]) {
            if (!pr.allowed[a]) return fail(Code::invalid_argument, "set cover: a ball is both forced in and forced out");
            pr.locked[a] = 1;
        }
    // count[j] becomes the number of allowed balls covering j
    for (size_t a = 0; a < n; ++a)
        if (!pr.allowed[a])
            for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k) count[cov.ball_samples[k]]--;
    for (uint32_t j = 0; j < m; ++j)
        if (pr.required[j] && count[j] == 0) pr.uncovered.push_back(j);
    if (!pr.uncovered.empty()) {
        if (!skip_uncoverable) return fail(Code::uncoverable, uncoverable_message(pr.uncovered, m));
        for (uint32_t j : pr.uncovered) pr.required[j] = 0;
    }
    for (uint8_t v : pr.required) pr.rows_before += v;
    for (uint8_t v : pr.allowed) pr.cols_before += v;
    return Status::success();
}

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

// Exact solve of one connected component: greedy -> Lagrangian bound and heuristic ->
// reduced-cost fixing (drop every column that no cover smaller than the incumbent can use) ->
// reduction of what is left -> CBC on that, with the incumbent as cutoff.
struct ComponentResult {
    std::vector<uint32_t> sel;  // P-local columns, ascending
    double lb = 0;
    bool proven = false;
    bool used_cbc = false;
    size_t rowgen_rounds = 0;
};

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
                   int search_threads, const Monitor& monitor)
        : P_(P), deadline_(deadline), threads_(threads), row_gen_(row_gen), effort_(effort),
          search_threads_(search_threads), monitor_(monitor), large_(P.R > kWholeCbcMaxRows) {}

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
    bool stop() { return done() || monitor_.cancelled(); }
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
        if (done()) return false;
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
    ComponentResult out_;
    Lagrange L_;          // the best Lagrangian bound so far, its multipliers, costs and cover
    bool lp_ok_ = false;  // the LP relaxation was solved
};

ComponentResult solve_component(const Problem& P, const Deadline& deadline, int threads,
                                bool row_gen, Effort effort, int search_threads, const Monitor& monitor) {
    return ComponentSolve(P, deadline, threads, row_gen, effort, search_threads, monitor).run();
}

Status solve_impl(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, const Monitor& monitor,
                  CoverResult& result) {
    const auto t0 = Clock::now();
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (opt.solver != Solver::exact && opt.solver != Solver::greedy && opt.solver != Solver::capp)
        return fail(Code::invalid_argument, "set cover: unknown solver");
    if (std::isnan(opt.time_limit_s)) return fail(Code::invalid_argument, "set cover: time limit is NaN");
    if (opt.effort != Effort::fast && opt.effort != Effort::prove)
        return fail(Code::invalid_argument, "set cover: unknown effort");
    if (opt.solver == Solver::capp) {
        if (!opt.centers || !opt.radii || opt.centers->size() != n || opt.radii->size() != n)
            return fail(Code::invalid_argument, "set cover: the capp solver needs centers and radii for every ball");
        for (size_t a = 0; a < n; ++a) {
            const Vec3& c = (*opt.centers)[a];
            if (!c.allFinite() ||
                !std::isfinite((*opt.radii)[a]))
                return fail(Code::invalid_input, "set cover: non-finite ball centre or radius");
        }
    }
    Prepared pr;
    Status st = prepare(cov, opt, skip_uncoverable, pr);
    if (!st.ok()) return st;
    result.uncovered = pr.uncovered;
    result.rows_before = pr.rows_before;
    result.cols_before = pr.cols_before;
    if (monitor.stopped()) return monitor.stop_status("reduction");

    std::vector<uint32_t> forced;
    Problem P;
    st = reduce_coverage(cov, pr.transpose_ok, pr.required, pr.allowed, pr.locked, monitor, forced, P);
    if (!st.ok()) return st;
    result.rows_after = P.R;
    result.cols_after = P.C;
    result.forced = forced.size();
    result.time_reduce_s = seconds_since(t0);
    if (monitor.stopped()) return monitor.stop_status("reduction");

    // Kernel solve.
    const auto t1 = Clock::now();
    std::vector<uint32_t> ksel;
    double klb = P.R > 0 ? double(disjoint_bound(P)) : 0.0;
    bool proven = false;
    if (opt.solver == Solver::capp) {
        ksel = capp_cover(P, *opt.centers, *opt.radii, forced);
        remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, ksel);
    } else {
        if (opt.solver == Solver::exact) {
            // The solver's own limit or the call's budget, whichever ends first: either way
            // the best cover found so far is the result, not proven.
            const Deadline deadline = Deadline::after(opt.time_limit_s, t0).earliest(monitor.deadline);
            proven = true;
            klb = 0;
            for (const Problem& Q : split_components(P)) {
                if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");
                const ComponentResult cr =
                    solve_component(Q, deadline, opt.threads, opt.row_generation, opt.effort,
                                    opt.search_threads, monitor);
                for (uint32_t c : cr.sel) ksel.push_back(Q.col_id[c]);
                klb += cr.lb;
                proven = proven && cr.proven;
                result.components++;
                result.cbc_components += cr.used_cbc;
                result.rowgen_rounds += cr.rowgen_rounds;
            }
            std::sort(ksel.begin(), ksel.end());
        } else {
            ksel = greedy_cover(P);
            remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, ksel);
        }
    }
    if (!covers_problem(P, ksel)) return fail(Code::internal, "set cover: kernel selection does not cover the kernel");

    // Combine, drop redundant balls on the full problem (never forced-in ones), verify.
    std::vector<uint32_t> sel = forced;
    for (uint32_t c : ksel) sel.push_back(P.col_id[c]);
    std::sort(sel.begin(), sel.end());
    remove_redundant(cov.ball_ptr, cov.ball_samples, m, &pr.required, &pr.locked, sel);
    {
        std::vector<uint8_t> covered(m, 0), chosen(n, 0);
        for (uint32_t a : sel) {
            if (!pr.allowed[a]) return fail(Code::internal, "set cover: a forced-out ball was selected");
            chosen[a] = 1;
            for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k) covered[cov.ball_samples[k]] = 1;
        }
        for (size_t a = 0; a < n; ++a)
            if (pr.locked[a] && !chosen[a]) return fail(Code::internal, "set cover: a forced-in ball was dropped");
        for (size_t j = 0; j < m; ++j)
            if (pr.required[j] && !covered[j])
                return fail(Code::internal, "set cover: the selection leaves sample " + std::to_string(j) + " uncovered");
    }
    result.selected = sel;
    result.objective = double(sel.size());
    result.lower_bound = std::min(result.objective, double(forced.size()) + klb);
    result.proven_optimal = (opt.solver == Solver::exact && proven) ? 1 : 0;
    if (result.proven_optimal) result.lower_bound = result.objective;
    result.gap = result.objective > 0 ? (result.objective - result.lower_bound) / result.objective : 0.0;
    result.time_solve_s = seconds_since(t1);
    return Status::success();
}

}  // namespace

void remove_redundant_balls(const Coverage& cov, const std::vector<uint8_t>& required,
                            const std::vector<uint8_t>& locked, std::vector<uint32_t>& selected) {
    std::sort(selected.begin(), selected.end());
    selected.erase(std::unique(selected.begin(), selected.end()), selected.end());
    remove_redundant(cov.ball_ptr, cov.ball_samples, cov.n_samples, required.empty() ? nullptr : &required,
                     locked.empty() ? nullptr : &locked, selected);
}

namespace detail {
Status reduce_set_cover(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, const Monitor& monitor,
                        std::vector<uint32_t>& forced, Coverage& kernel, std::vector<uint32_t>& kernel_balls,
                        std::vector<uint32_t>& kernel_samples) {
    Prepared pr;
    Status st = prepare(cov, opt, skip_uncoverable, pr);
    if (!st.ok()) return st;
    Problem P;
    st = reduce_coverage(cov, pr.transpose_ok, pr.required, pr.allowed, pr.locked, monitor, forced, P);
    if (!st.ok()) return st;
    std::sort(forced.begin(), forced.end());
    kernel = Coverage{};
    kernel.n_samples = P.R;
    kernel.n_balls = P.C;
    kernel.ball_ptr = P.cptr;
    kernel.ball_samples = P.crow;
    kernel.sample_ptr = P.rptr;
    kernel.sample_balls = P.rcol;
    kernel_balls = P.col_id;
    kernel_samples = P.row_id;
    return Status::success();
}
}  // namespace detail

Status solve_set_cover(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, const Monitor& monitor,
                       CoverResult& result) {
    result = CoverResult{};
    return solve_impl(cov, opt, skip_uncoverable, monitor, result);
}

}  // namespace ca
