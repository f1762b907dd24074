// lp.cpp: the LP relaxation's duals (Clp; whole, by column generation, or by row and column
// generation) and the LP branching proof (no_cover_within). The Clp calls take no lock: each
// works on a ClpSimplex of its own, so contexts in several threads solve their LPs at once.
#include "setcover_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <memory>

#include <coin/ClpSimplex.hpp>

namespace ca {
namespace sc {

namespace {
using ClpModel = std::unique_ptr<ClpSimplex>;

// A silenced Clp model of min 1'x, A x >= 1 (no row upper bounds), 0 <= x <= 1, for the columns
// given column-major (colstart / rowidx). The time limit is
// wall-clock time: Clp's plain limit counts the CPU time of the whole process, which the local
// search's threads beside the LP use up faster than the clock.
ClpModel load_cover_lp(uint32_t rows, const std::vector<CoinBigIndex>& colstart, const std::vector<int>& rowidx,
                       double time_limit_s) {
    const size_t cols = colstart.size() - 1;
    std::vector<double> val(rowidx.size(), 1.0), lb(cols, 0.0), ub(cols, 1.0), obj(cols, 1.0), rlb(rows, 1.0);
    ClpModel model = std::make_unique<ClpSimplex>();
    model->setLogLevel(0);
    model->loadProblem(int(cols), int(rows), colstart.data(), rowidx.data(), val.data(), lb.data(), ub.data(),
                       obj.data(), rlb.data(), nullptr);
    if (time_limit_s > 0 && std::isfinite(time_limit_s)) model->setMaximumWallSeconds(time_limit_s);
    return model;
}
}  // namespace


std::vector<double> lp_duals(const Problem& P, double time_limit_s) {
    std::vector<CoinBigIndex> colstart(P.C + 1);
    std::vector<int> rowidx(P.crow.begin(), P.crow.end());
    for (uint32_t c = 0; c <= P.C; ++c) colstart[c] = CoinBigIndex(P.cptr[c]);
    const ClpModel model = load_cover_lp(P.R, colstart, rowidx, time_limit_s);
    ClpSimplex* m = model.get();
    m->dual(0);
    if (m->status() != 0) return {};  // not optimal (time limit, numerical trouble)
    const double* y = m->getRowPrice();
    if (!y) return {};
    std::vector<double> u(P.R);
    for (uint32_t r = 0; r < P.R; ++r) u[r] = std::isfinite(y[r]) ? std::max(0.0, y[r]) : 0.0;
    return u;
}

std::vector<double> lp_duals_core(const Problem& P, const std::vector<double>& cost, double time_limit_s) {
    if (cost.size() != P.C) return lp_duals(P, time_limit_s);
    // The core: reduced cost below 0.1, and the 5 cheapest columns of every row.
    constexpr double kCoreCost = 0.1;
    constexpr size_t kCorePerRow = 5;
    std::vector<uint8_t> in_core = core_columns(P, cost, kCoreCost, kCorePerRow, all_rows(P));
    // Column-major arrays of the columns to add (all of the core first).
    std::vector<CoinBigIndex> colstart(1, 0);
    std::vector<int> rowidx;
    auto add_column = [&](uint32_t c) {
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) rowidx.push_back(int(P.crow[k]));
        colstart.push_back(CoinBigIndex(rowidx.size()));
    };
    for (uint32_t c = 0; c < P.C; ++c)
        if (in_core[c]) add_column(c);
    std::vector<double> val(P.crow.size(), 1.0), lb(P.C, 0.0), ub(P.C, 1.0), obj(P.C, 1.0);  // for added columns

    const ClpModel model = load_cover_lp(P.R, colstart, rowidx, time_limit_s);
    ClpSimplex* m = model.get();
    // Primal simplex from the slack basis: on large covering LPs the dual simplex is slower,
    // on small ones the primal is at least as fast.
    m->primal(0);
    std::vector<double> u(P.R);
    // Every round adds at least one column, so at most P.C rounds; in practice 2-5.
    for (;;) {
        if (m->status() != 0) return {};  // infeasible core (cannot be: every row has a column), time, numerics
        const double* y = m->getRowPrice();
        if (!y) return {};
        for (uint32_t r = 0; r < P.R; ++r) u[r] = std::isfinite(y[r]) ? std::max(0.0, y[r]) : 0.0;
        colstart.assign(1, 0);
        rowidx.clear();
        for (uint32_t c = 0; c < P.C; ++c) {
            if (in_core[c]) continue;
            double rc = 1.0;
            for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) rc -= u[P.crow[k]];
            if (rc < -1e-9) {
                in_core[c] = 1;
                add_column(c);
            }
        }
        const int added = int(colstart.size()) - 1;
        if (added == 0) return u;
        m->addColumns(added, lb.data(), ub.data(), obj.data(), colstart.data(), rowidx.data(), val.data());
        m->primal(0);  // the basis stays primal feasible: continue from it
    }
}

std::vector<double> lp_duals_rows(const Problem& P, const std::vector<double>& u0, const std::vector<double>& cost,
                                  double time_limit_s) {
    if (u0.size() != P.R || cost.size() != P.C) return lp_duals(P, time_limit_s);
    constexpr double kStartDual = 1e-6;  // rows with a larger multiplier start in the LP
    constexpr double kCoreCost = 0.05;   // columns with a smaller reduced cost start in it,
    constexpr size_t kCorePerRow = 2;    // and the cheapest few of every starting row
    const Clock::time_point t0 = Clock::now();
    const bool limited = time_limit_s > 0 && std::isfinite(time_limit_s);
    std::vector<int> lp_row(P.R, -1), lp_col(P.C, -1);  // P index -> LP index, -1 = not in the LP
    std::vector<uint32_t> rows, cols;                    // LP index -> P index
    for (uint32_t r = 0; r < P.R; ++r)
        if (u0[r] > kStartDual) {
            lp_row[r] = int(rows.size());
            rows.push_back(r);
        }
    if (rows.empty())
        for (uint32_t r = 0; r < P.R; ++r) {
            lp_row[r] = int(r);
            rows.push_back(r);
        }
    const std::vector<uint8_t> in_core = core_columns(P, cost, kCoreCost, kCorePerRow, rows);
    // entries of the columns or rows to add, restricted to the rows or columns in the LP
    std::vector<CoinBigIndex> start(1, 0);
    std::vector<int> index;
    auto add_column = [&](uint32_t c) {
        lp_col[c] = int(cols.size());
        cols.push_back(c);
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k)
            if (lp_row[P.crow[k]] >= 0) index.push_back(lp_row[P.crow[k]]);
        start.push_back(CoinBigIndex(index.size()));
    };
    auto add_row = [&](uint32_t r) {
        lp_row[r] = int(rows.size());
        rows.push_back(r);
        for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q)
            if (lp_col[P.rcol[q]] >= 0) index.push_back(lp_col[P.rcol[q]]);
        start.push_back(CoinBigIndex(index.size()));
    };
    for (uint32_t c = 0; c < P.C; ++c)
        if (in_core[c]) add_column(c);
    const std::vector<double> ones(std::max<size_t>(P.crow.size(), std::max(P.R, P.C)), 1.0), zeros(P.C, 0.0),
        no_upper(P.R, COIN_DBL_MAX);

    const ClpModel model = load_cover_lp(uint32_t(rows.size()), start, index, time_limit_s);
    ClpSimplex* m = model.get();
    m->primal(0);
    std::vector<double> u(P.R), x(P.C);
    // Every round adds a column or a row, so it ends.
    for (;;) {
        if (m->status() != 0) return {};  // time limit or numerical trouble
        const double* y = m->getRowPrice();
        const double* xs = m->getColSolution();
        if (!y || !xs) return {};
        std::fill(u.begin(), u.end(), 0.0);
        for (size_t i = 0; i < rows.size(); ++i) u[rows[i]] = std::isfinite(y[i]) ? std::max(0.0, y[i]) : 0.0;
        double left = 0;
        if (limited) {
            left = time_limit_s - seconds_since(t0);
            if (left <= 0) return {};
        }
        // columns of negative reduced cost join; the basis stays primal feasible
        start.assign(1, 0);
        index.clear();
        const size_t cols_before = cols.size();
        for (uint32_t c = 0; c < P.C; ++c) {
            if (lp_col[c] >= 0) continue;
            double rc = 1.0;
            for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) rc -= u[P.crow[k]];
            if (rc < -1e-9) add_column(c);
        }
        if (cols.size() > cols_before) {
            const int added = int(cols.size() - cols_before);
            m->addColumns(added, zeros.data(), ones.data(), ones.data(), start.data(), index.data(), ones.data());
            if (limited) m->setMaximumWallSeconds(left);
            m->primal(0);
            continue;
        }
        // rows the LP solution leaves uncovered join; the basis stays dual feasible. A row none
        // of whose columns is in the LP first brings its cheapest one (priced >= 0: the basis
        // stays optimal), else the LP would be infeasible.
        std::fill(x.begin(), x.end(), 0.0);
        for (size_t i = 0; i < cols.size(); ++i) x[cols[i]] = xs[i];
        std::vector<uint32_t> uncovered;
        for (uint32_t r = 0; r < P.R; ++r) {
            if (lp_row[r] >= 0) continue;
            double covered = 0;
            bool any = false;
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) {
                covered += x[P.rcol[q]];
                any = any || lp_col[P.rcol[q]] >= 0;
            }
            if (covered >= 1.0 - 1e-7) continue;
            uncovered.push_back(r);
            if (!any) {
                uint32_t best = P.rcol[P.rptr[r]];
                for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q)
                    if (cost[P.rcol[q]] < cost[best]) best = P.rcol[q];
                add_column(best);
            }
        }
        if (uncovered.empty()) return u;  // feasible for P with dual-feasible duals: optimal
        if (cols.size() > cols_before) {
            const int added = int(cols.size() - cols_before);
            m->addColumns(added, zeros.data(), ones.data(), ones.data(), start.data(), index.data(), ones.data());
            start.assign(1, 0);
            index.clear();
        }
        for (uint32_t r : uncovered) add_row(r);
        m->addRows(int(uncovered.size()), ones.data(), no_upper.data(), start.data(), index.data(), ones.data());
        if (limited) m->setMaximumWallSeconds(left);
        m->dual(0);
    }
}

// The smallest simplex-iteration budget of the branches in no_cover_within.
constexpr int kMinBranchIterations = 50;
bool no_cover_within(const Problem& K, size_t size, int max_branches, const std::function<bool()>& stop) {
    if (K.R == 0) return false;  // the empty cover
    std::vector<CoinBigIndex> colstart(K.C + 1);
    std::vector<int> rowidx(K.crow.begin(), K.crow.end());
    for (uint32_t c = 0; c <= K.C; ++c) colstart[c] = CoinBigIndex(K.cptr[c]);
    const double limit = double(size) + 1e-6;  // an LP value above it rules out covers of `size`
    // L(u) from Clp's row prices (clamped to >= 0), over the rows not covered by column `fixed_in`
    // (plus 1 for it) and the columns other than `fixed_in` / `fixed_out` (-1: none): a valid
    // bound on the covers of that branch whatever the LP's tolerances.
    std::vector<double> u(K.R);
    std::vector<uint8_t> in_fixed(K.R, 0);
    auto bound = [&](const double* y, int fixed_in, int fixed_out) {
        std::fill(in_fixed.begin(), in_fixed.end(), 0);
        if (fixed_in >= 0)
            for (uint32_t k = K.cptr[fixed_in]; k < K.cptr[fixed_in + 1]; ++k) in_fixed[K.crow[k]] = 1;
        double z = fixed_in >= 0 ? 1.0 : 0.0;
        for (uint32_t r = 0; r < K.R; ++r) {
            u[r] = in_fixed[r] || !std::isfinite(y[r]) ? 0.0 : std::max(0.0, y[r]);
            z += u[r];
        }
        for (uint32_t c = 0; c < K.C; ++c) {
            if (int(c) == fixed_in || int(c) == fixed_out) continue;
            double cc = 1.0;
            for (uint32_t k = K.cptr[c]; k < K.cptr[c + 1]; ++k) cc -= u[K.crow[k]];
            z += std::min(0.0, cc);
        }
        return z;
    };
    const ClpModel root = load_cover_lp(K.R, colstart, rowidx, 0.0);
    root->dual(0);
    if (root->status() != 0 || !root->getRowPrice() || !root->getColSolution()) return false;
    if (bound(root->getRowPrice(), -1, -1) > limit) return true;
    // branching candidates: the most fractional columns of the LP solution (ties to the lower index)
    const double* x = root->getColSolution();
    std::vector<uint32_t> candidates;
    for (uint32_t c = 0; c < K.C; ++c)
        if (x[c] > 1e-6 && x[c] < 1 - 1e-6) candidates.push_back(c);
    std::sort(candidates.begin(), candidates.end(), [&](uint32_t a, uint32_t b) {
        const double fa = std::fabs(x[a] - 0.5), fb = std::fabs(x[b] - 0.5);
        return fa != fb ? fa < fb : a < b;
    });
    if (candidates.size() > size_t(std::max(0, max_branches))) candidates.resize(size_t(std::max(0, max_branches)));
    // The children together get at most as many simplex iterations as the root took (a
    // deterministic limit): children that prove take a fraction of the root's, while on
    // degenerate kernels children that prove nothing can take more than the root.
    int budget = std::max(kMinBranchIterations, root->numberIterations());
    for (uint32_t j : candidates) {
        bool both = true;
        for (int up = 0; up < 2 && both; ++up) {
            if ((stop && stop()) || budget <= 0) return false;
            ClpSimplex child(*root);  // warm start from the root's basis
            if (up) child.setColumnLower(int(j), 1.0);
            else child.setColumnUpper(int(j), 0.0);
            child.setDualObjectiveLimit(limit);  // the dual simplex may stop once past it
            child.setMaximumIterations(budget);
            child.dual(0);
            const double* y = child.getRowPrice();
            // whatever the status (optimal, stopped at the limit): L(u) holds for any u >= 0
            both = y && bound(y, up ? int(j) : -1, up ? -1 : int(j)) > limit;
            budget -= child.numberIterations();
        }
        if (both) return true;
    }
    return false;
}

}  // namespace sc
}  // namespace ca
