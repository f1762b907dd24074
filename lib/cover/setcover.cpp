// setcover.cpp: minimum set cover of the samples by the candidate balls (see setcover.h): the solve
// driver. Its steps are in their own files (setcover_internal.h): the input checks
// (setcover_checks.cpp), the reduction (reduction.cpp), the exact solve of one component
// (component_solve.cpp), building blocks (setcover_problem.cpp) and the exact machinery
// (lagrangian.cpp, lp.cpp, cbc.cpp, row_generation.cpp, local_search.cpp).
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
            const std::vector<Problem> components = split_components(P);
            // give_up_above: what a component's cover may have for the whole to stay within it,
            // the other components at their disjoint-rows bounds (a larger cover of this one
            // makes the whole larger than give_up_above whatever the others need)
            std::vector<double> others(components.size(), 0.0);
            if (opt.give_up_above > 0) {
                std::vector<double> own(components.size());
                double all = double(forced.size());
                for (size_t c = 0; c < components.size(); ++c) all += own[c] = double(disjoint_bound(components[c]));
                for (size_t c = 0; c < components.size(); ++c) others[c] = all - own[c];
            }
            for (size_t c = 0; c < components.size(); ++c) {
                const Problem& Q = components[c];
                if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");
                const double give_up = opt.give_up_above > 0 ? double(opt.give_up_above) - others[c] : kNoGiveUp;
                const ComponentResult cr =
                    solve_component(Q, deadline, opt.threads, opt.row_generation, opt.effort,
                                    opt.search_threads, monitor, give_up);
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
