// lp_cbc.cpp: the LP relaxation's duals (Clp; whole, by column generation, or by row and column
// generation), the LP branching proof (no_cover_within), CBC (the C interface, silenced, with a
// cutoff and a time limit, behind the library's only process-wide mutex) and the search for a
// cover on the LP optimal face (core_cover). The Clp calls take no lock: each works on a
// ClpSimplex of its own, so contexts in several threads solve their LPs at once.
#include "setcover_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <memory>
#include <mutex>
#include <new>

#include <coin/Cbc_C_Interface.h>
#include <coin/ClpSimplex.hpp>


namespace ca {
namespace sc {

namespace {
// CBC 2.10's Cbc_newModel and Cbc_solve run CbcMain0 / CbcMain1, which parse the options through
// process-wide globals (CbcOrClpRead_mode, the signal handler's current model): two at once can
// misread each other's options. Every CBC model's life (create, solve, read, delete) in the
// process therefore goes through this one mutex, the library's only process-wide state. Clp
// needs none: a ClpSimplex keeps all of its state (factorization, pricing, random numbers) in
// the object, Clp 1.17's function-level statics are all in debugging code compiled out of the
// library, and CBC's own parallel search runs one ClpSimplex per thread the same way.
std::mutex& cbc_mutex() {
    static std::mutex m;
    return m;
}
}  // namespace

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

namespace {
// The columns of reduced cost below max_cost, and the per_row cheapest columns of each of `rows`
// (ties to the lower index), as a mask over P's columns.
std::vector<uint8_t> core_columns(const Problem& P, const std::vector<double>& cost, double max_cost, size_t per_row,
                                  const std::vector<uint32_t>& rows) {
    std::vector<uint8_t> in_core(P.C, 0);
    for (uint32_t c = 0; c < P.C; ++c) in_core[c] = cost[c] < max_cost;
    std::vector<uint32_t> cheapest;
    for (uint32_t r : rows) {
        cheapest.assign(P.rcol.begin() + P.rptr[r], P.rcol.begin() + P.rptr[r + 1]);
        const size_t k = std::min(per_row, cheapest.size());
        std::partial_sort(cheapest.begin(), cheapest.begin() + k, cheapest.end(),
                          [&](uint32_t a, uint32_t b) { return cost[a] != cost[b] ? cost[a] < cost[b] : a < b; });
        for (size_t i = 0; i < k; ++i) in_core[cheapest[i]] = 1;
    }
    return in_core;
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

// Solves the kernel with CBC, looking only for covers smaller than `incumbent` (the best known
// cover): the cutoff incumbent - 1 + kCutoffSlack prunes at least as much as a MIP start would.
// A MIP start (Cbc_setMIPStartI) is deliberately not used: in CBC 2.10 its processing ("Reduced
// search") ignores the time limit and can take far longer than the cutoff alone.
// With `first_solution`, CBC stops at the first cover below the cutoff (not proven optimal).
namespace {
CbcOutcome run_cbc_unguarded(const Problem& P, size_t incumbent, const CbcSettings& settings) {
    const double time_limit_s = settings.time_limit_s;
    const int threads = settings.threads, max_nodes = settings.max_nodes;
    const bool first_solution = settings.first_solution, heuristics = settings.heuristics, lean = settings.lean,
               strong_branching = settings.strong_branching;
    CbcOutcome out;
    std::vector<CoinBigIndex> colstart(P.C + 1);
    std::vector<int> rowidx(P.crow.begin(), P.crow.end());
    for (uint32_t c = 0; c <= P.C; ++c) colstart[c] = CoinBigIndex(P.cptr[c]);
    std::vector<double> val(P.crow.size(), 1.0), lb(P.C, 0.0), ub(P.C, 1.0), obj(P.C, 1.0), rlb(P.R, 1.0);
    const bool weighted = settings.costs != nullptr;
    if (weighted) obj = *settings.costs;
    char buf[64];

    std::lock_guard<std::mutex> lock(cbc_mutex());
    struct Deleter { void operator()(Cbc_Model* m) const { Cbc_deleteModel(m); } };
    std::unique_ptr<Cbc_Model, Deleter> model(Cbc_newModel());
    if (!model) return out;
    Cbc_Model* m = model.get();
    Cbc_loadProblem(m, int(P.C), int(P.R), colstart.data(), rowidx.data(), val.data(), lb.data(), ub.data(),
                    obj.data(), rlb.data(), nullptr);
    for (uint32_t c = 0; c < P.C; ++c) Cbc_setInteger(m, int(c));
    if (settings.max_columns > 0) {  // sum x <= max_columns
        std::vector<int> all(P.C);
        std::iota(all.begin(), all.end(), 0);
        Cbc_addRow(m, "columns", int(P.C), all.data(), ub.data(), 'L', double(settings.max_columns));
    }
    Cbc_setParameter(m, "log", "0");  // otherwise CBC prints to stdout
    Cbc_setParameter(m, "slog", "0");
    Cbc_setParameter(m, "timeMode", "elapsed");
    if (time_limit_s > 0 && std::isfinite(time_limit_s)) {
        std::snprintf(buf, sizeof buf, "%.6f", time_limit_s);
        Cbc_setParameter(m, "sec", buf);
    }
    std::snprintf(buf, sizeof buf, "%d", std::max(1, threads));
    Cbc_setParameter(m, "threads", buf);
    // Objective values are integral: a cover smaller than the incumbent has value <= incumbent - 1,
    // so every node whose LP bound exceeds that is pruned (a looser cutoff such as
    // incumbent - 0.5 would keep exploring nodes with bounds in (incumbent - 1, incumbent - 0.5)).
    if (weighted) std::snprintf(buf, sizeof buf, "%.17g", settings.cutoff);
    else std::snprintf(buf, sizeof buf, "%.4f", double(incumbent) - 1.0 + kCutoffSlack);
    Cbc_setParameter(m, "cutoff", buf);
    // CBC's root heuristics (feasibility pump, mini branch and bound) are costly on large
    // kernels and rarely beat a local-search incumbent.
    if (!heuristics) Cbc_setParameter(m, "heuristicsOnOff", "off");
    if (first_solution) Cbc_setParameter(m, "maxSolutions", "1");
    // On small kernels with a one-ball gap, preprocessing and cuts cost more than they save and
    // do not change the outcome.
    if (lean) {
        Cbc_setParameter(m, "preprocess", "off");
        Cbc_setParameter(m, "cuts", "off");
    }
    if (!strong_branching) {
        Cbc_setParameter(m, "strong", "0");
        Cbc_setParameter(m, "trust", "0");
    }
    if (max_nodes > 0) {
        std::snprintf(buf, sizeof buf, "%d", max_nodes);
        Cbc_setParameter(m, "maxNodes", buf);
    }
    const Clock::time_point t0 = Clock::now();
    Cbc_solve(m);
    const double elapsed = seconds_since(t0);
    out.ok = true;
    const bool finished = Cbc_status(m) == 0;
    const double bp = Cbc_getBestPossibleObjValue(m);
    const double* x = Cbc_bestSolution(m) ? Cbc_getColSolution(m) : nullptr;
    if (x) {
        for (uint32_t c = 0; c < P.C; ++c)
            if (x[c] > 0.5) out.solution.push_back(c);
        if (weighted) {
            double value = 0;
            for (uint32_t c : out.solution) value += obj[c];
            out.has_solution = covers_problem(P, out.solution) && value < settings.cutoff &&
                               (settings.max_columns == 0 || out.solution.size() <= settings.max_columns);
        } else {
            out.has_solution = covers_problem(P, out.solution) && out.solution.size() < incumbent;
        }
        if (!out.has_solution) out.solution.clear();
    }
    // CBC 2.10 reports "finished, linear relaxation infeasible or worse than the cutoff"
    // (status 0, secondary status 1) also when its time limit interrupts the root LP, with the
    // interrupted LP value (below the cutoff) as bound, which would falsely "prove" the
    // incumbent optimal on a sub-problem with little time left. When CBC
    // used half its time limit or more, such a claim is trusted only with a bound at or above
    // the cutoff (a genuine one can come from preprocessing with a lower LP bound), and its
    // bound is not used.
    const double cutoff = weighted            ? settings.cutoff
                          : out.has_solution ? double(out.solution.size()) - 1.0 + kCutoffSlack
                                             : double(incumbent) - 1.0 + kCutoffSlack;
    const bool near_limit = time_limit_s > 0 && std::isfinite(time_limit_s) && elapsed >= 0.5 * time_limit_s;
    const bool trusted = Cbc_secondaryStatus(m) != 1 || bp >= cutoff - 1e-9 || !near_limit;
    if (trusted && std::isfinite(bp) && bp < 1e40) out.bound = bp;
    // Optimal below the cutoff, or proven that nothing beats the incumbent.
    if (out.has_solution)
        out.proven = finished && trusted && Cbc_isProvenOptimal(m) != 0;
    else
        out.proven = finished && trusted && Cbc_isProvenInfeasible(m) != 0;
    return out;
}
}  // namespace

// Any exception from CBC other than bad_alloc is a failed solve (ok = false): the callers keep
// their incumbent.
CbcOutcome run_cbc(const Problem& P, size_t incumbent, const CbcSettings& settings) {
    try {
        return run_cbc_unguarded(P, incumbent, settings);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (...) {
        return CbcOutcome{};
    }
}


// Why: the local search's covers can contain a few columns of positive reduced cost at the LP
// duals while an optimum uses only columns of reduced cost 0 (the LP optimal face). Restricted
// to those, CBC without strong branching finds such a cover within a few nodes, where the whole
// kernel or strong branching would take far longer; a small node limit keeps the attempt cheap
// when there is none.
std::vector<uint32_t> core_cover(const Problem& P, const std::vector<double>& cost, size_t incumbent,
                                 double time_limit_s, int threads, const Monitor& monitor) {
    // every row keeps a column: its cheapest
    const Problem Q = restrict_columns(P, core_columns(P, cost, kCoreMaxCost, 1, all_rows(P)));
    std::vector<uint32_t> forced;  // Q-local
    Problem K;                     // col_id Q-local
    if (!reduce_problem(Q, monitor, forced, K).ok()) return {};
    std::vector<uint32_t> sel;
    for (uint32_t c : forced) sel.push_back(Q.col_id[c]);
    if (K.R > 0) {
        if (forced.size() + 1 >= incumbent) return {};  // K needs a column too
        CbcSettings cs;
        cs.time_limit_s = time_limit_s;
        cs.threads = threads;
        cs.heuristics = false;
        cs.max_nodes = kCoreCbcNodes;
        cs.lean = true;
        cs.strong_branching = false;
        const CbcOutcome cbc = run_cbc(K, incumbent - forced.size(), cs);
        if (!cbc.ok || !cbc.has_solution) return {};
        for (uint32_t c : cbc.solution) sel.push_back(Q.col_id[K.col_id[c]]);
    }
    std::sort(sel.begin(), sel.end());
    if (sel.size() >= incumbent || !covers_problem(P, sel)) return {};
    return sel;
}

}  // namespace sc
}  // namespace ca
