// weighted_cover.cpp: the weighted set cover with at most K columns (weighted_cover.h).
//  - Greedy with a price mu added to every column's cost: it picks the column of least
//    (cost + mu) / (rows it newly covers), then drops redundant columns, dearest first. A higher
//    price buys fewer, larger columns; the prices tried go up by doubling until the cover has at
//    most K columns, then bisection towards the cheapest price that still fits, keeping the
//    cheapest cover that fits.
//  - Local search: add one column and drop those it makes redundant (dearest first), and
//    re-cover one chosen column's own rows with cheaper columns while the budget allows; both
//    only when the total cost drops. This is where the budget is used: a loose column is split
//    into tighter ones while K allows.
//  - Lower bound: Lagrangian relaxation of the covering rows. For multipliers u >= 0,
//    L(u) = sum_i u_i + (sum of the at most K most negative reduced costs c_j - sum_{i in j} u_i)
//    is at most the optimum (the cardinality limit stays in the relaxed problem), subgradient
//    ascent on u with the incumbent's cost as target.
//  - The greedy again, priced by the reduced costs at the best multipliers (clamped at 0, plus a
//    thousandth of the cost): they charge a column for the rows other columns cover more cheaply,
//    which the plain greedy does not see; then the local search again.
//  - CBC (run_cbc with costs and the cardinality row) on a core: the chosen columns, every column
//    of negative reduced cost at the best multipliers and each row's cheapest few, with a node
//    limit; a cheaper cover it finds becomes the incumbent. Its bound counts only when the core
//    is the whole problem.
#include "weighted_cover.h"

#include "setcover_internal.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

namespace ca {

namespace {

// Price search: doublings from the smallest positive cost, then bisection steps.
constexpr int kPriceDoublings = 60;
constexpr int kPriceBisections = 10;
// Local search rounds (each tries every move once) and the add-and-drop columns verified per round.
constexpr int kSearchRounds = 40;
constexpr size_t kVerifiedAdds = 8;
// A move must lower the cost by this fraction of it (no moves on rounding).
constexpr double kMinImprovement = 1e-9;
// The core given to CBC: each row's cheapest columns by reduced cost.
constexpr size_t kCorePerRow = 3;

struct Columns {
    uint32_t R = 0, C = 0;
    const std::vector<uint32_t>& ptr;
    const std::vector<uint32_t>& idx;
    const std::vector<double>& cost;
    std::vector<uint32_t> rptr, rcol;  // row -> columns, ascending
    size_t K = 1;
};

double total(const Columns& P, const std::vector<uint32_t>& sel) {
    double s = 0;
    for (uint32_t j : sel) s += P.cost[j];
    return s;
}

bool covers(const Columns& P, const std::vector<uint32_t>& sel) {
    std::vector<uint8_t> covered(P.R, 0);
    for (uint32_t j : sel)
        for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) covered[P.idx[k]] = 1;
    return std::all_of(covered.begin(), covered.end(), [](uint8_t v) { return v != 0; });
}

// Drops columns whose rows are all covered by others, dearest first (ties: higher index first).
void drop_redundant(const Columns& P, std::vector<uint32_t>& sel) {
    std::vector<uint32_t> count(P.R, 0);
    for (uint32_t j : sel)
        for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) ++count[P.idx[k]];
    std::vector<uint32_t> order = sel;
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return P.cost[a] != P.cost[b] ? P.cost[a] > P.cost[b] : a > b;
    });
    std::vector<uint8_t> dropped(P.C, 0);
    for (uint32_t j : order) {
        bool needed = false;
        for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1] && !needed; ++k) needed = count[P.idx[k]] < 2;
        if (needed) continue;
        dropped[j] = 1;
        for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) --count[P.idx[k]];
    }
    sel.erase(std::remove_if(sel.begin(), sel.end(), [&](uint32_t j) { return dropped[j] != 0; }), sel.end());
    std::sort(sel.begin(), sel.end());
}

// Greedy on (cost + mu) / new rows over the rows not yet covered (`covered` on entry), among the
// columns of `allowed` (null: all), at most `limit` columns; returns the columns added (may leave
// rows uncovered when the limit ends it).
std::vector<uint32_t> greedy(const Columns& P, double mu, std::vector<uint8_t> covered, const std::vector<uint8_t>* allowed,
                             size_t limit, const std::vector<double>* prices = nullptr) {
    const std::vector<double>& cost = prices ? *prices : P.cost;
    std::vector<uint32_t> fresh(P.C, 0);
    size_t left = 0;
    for (uint32_t r = 0; r < P.R; ++r) left += !covered[r];
    using Entry = std::pair<double, uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    for (uint32_t j = 0; j < P.C; ++j) {
        if (allowed && !(*allowed)[j]) continue;
        for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) fresh[j] += !covered[P.idx[k]];
        if (fresh[j]) heap.push({(cost[j] + mu) / fresh[j], j});
    }
    std::vector<uint32_t> out;
    while (left > 0 && out.size() < limit && !heap.empty()) {
        const auto [score, j] = heap.top();
        heap.pop();
        if (fresh[j] == 0) continue;
        const double now = (cost[j] + mu) / fresh[j];
        if (now > score) {  // scores only grow as rows get covered: re-queue at the true score
            heap.push({now, j});
            continue;
        }
        out.push_back(j);
        for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) {
            const uint32_t r = P.idx[k];
            if (covered[r]) continue;
            covered[r] = 1;
            --left;
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) --fresh[P.rcol[q]];
        }
    }
    return out;
}

std::vector<uint32_t> greedy_cover(const Columns& P, double mu, const std::vector<double>* prices = nullptr) {
    std::vector<uint32_t> sel = greedy(P, mu, std::vector<uint8_t>(P.R, 0), nullptr, P.C, prices);
    drop_redundant(P, sel);
    return sel;
}

// Local search from a feasible `sel` (at most K columns); returns an equal or cheaper one.
void improve(const Columns& P, std::vector<uint32_t>& sel, const Monitor& monitor, const Deadline& deadline) {
    double value = total(P, sel);
    std::vector<uint32_t> count(P.R), owner(P.R), unique(P.C), hits(P.C);
    std::vector<uint8_t> in(P.C);
    for (int round = 0; round < kSearchRounds; ++round) {
        if (monitor.stopped() || deadline.expired()) return;
        bool improved = false;
        // a trial cover, less what it makes redundant, replaces the selection when it fits K and
        // lowers the cost
        auto accept = [&](std::vector<uint32_t>& trial) {
            drop_redundant(P, trial);
            const double v = total(P, trial);
            if (trial.size() > P.K || v >= value * (1 - kMinImprovement)) return false;
            sel = std::move(trial);
            value = v;
            improved = true;
            return true;
        };
        // ---- add one column, drop what it makes redundant ----
        std::fill(count.begin(), count.end(), 0);
        std::fill(in.begin(), in.end(), 0);
        std::fill(unique.begin(), unique.end(), 0);
        for (uint32_t j : sel) {
            in[j] = 1;
            for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) {
                ++count[P.idx[k]];
                owner[P.idx[k]] = j;
            }
        }
        for (uint32_t r = 0; r < P.R; ++r)
            if (count[r] == 1) ++unique[owner[r]];
        // estimated gain of adding j: the chosen columns all of whose unique rows j covers
        std::vector<std::pair<double, uint32_t>> gains;
        for (uint32_t j = 0; j < P.C; ++j) {
            if (in[j]) continue;
            double freed = 0;
            size_t dropped = 0;
            for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) {
                const uint32_t r = P.idx[k];
                if (count[r] != 1) continue;
                const uint32_t o = owner[r];
                if (++hits[o] == unique[o]) {
                    freed += P.cost[o];
                    ++dropped;
                }
            }
            for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k)
                if (count[P.idx[k]] == 1) hits[owner[P.idx[k]]] = 0;
            if (sel.size() + 1 - dropped > P.K) continue;
            const double gain = freed - P.cost[j];
            if (gain > kMinImprovement * value) gains.push_back({-gain, j});
        }
        std::sort(gains.begin(), gains.end());
        if (gains.size() > kVerifiedAdds) gains.resize(kVerifiedAdds);
        for (const auto& g : gains) {
            std::vector<uint32_t> trial = sel;
            trial.push_back(g.second);
            if (accept(trial)) break;
        }
        // ---- re-cover one chosen column's unique rows with cheaper columns ----
        std::vector<uint32_t> order = sel;
        std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            return P.cost[a] != P.cost[b] ? P.cost[a] > P.cost[b] : a < b;
        });
        for (uint32_t k : order) {
            if (monitor.stopped() || deadline.expired()) return;
            std::vector<uint8_t> covered(P.R, 0);
            for (uint32_t j : sel)
                if (j != k)
                    for (uint32_t q = P.ptr[j]; q < P.ptr[j + 1]; ++q) covered[P.idx[q]] = 1;
            // the columns that meet k's uncovered rows and cost less than k
            std::vector<uint8_t> allowed(P.C, 0);
            for (uint32_t q = P.ptr[k]; q < P.ptr[k + 1]; ++q) {
                const uint32_t r = P.idx[q];
                if (covered[r]) continue;
                for (uint32_t t = P.rptr[r]; t < P.rptr[r + 1]; ++t) {
                    const uint32_t j = P.rcol[t];
                    allowed[j] = j != k && P.cost[j] < P.cost[k];
                }
            }
            const size_t budget = P.K - (sel.size() - 1);
            std::vector<uint32_t> add = greedy(P, 0.0, covered, &allowed, budget);
            std::vector<uint32_t> trial;
            for (uint32_t j : sel)
                if (j != k) trial.push_back(j);
            trial.insert(trial.end(), add.begin(), add.end());
            std::sort(trial.begin(), trial.end());
            trial.erase(std::unique(trial.begin(), trial.end()), trial.end());
            if (covers(P, trial) && accept(trial)) break;  // the order is stale
        }
        if (!improved) return;
    }
}

struct Bound {
    double value = 0;
    std::vector<double> reduced;  // reduced costs at the best multipliers
};

// Subgradient ascent on L(u); `target` is the incumbent's cost.
Bound lagrangian(const Columns& P, double target, int iterations, const Monitor& monitor, const Deadline& deadline) {
    std::vector<double> u(P.R, std::numeric_limits<double>::infinity()), rc(P.C), g(P.R);
    for (uint32_t j = 0; j < P.C; ++j) {
        const uint32_t n = P.ptr[j + 1] - P.ptr[j];
        for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) u[P.idx[k]] = std::min(u[P.idx[k]], P.cost[j] / n);
    }
    Bound best;
    best.value = -std::numeric_limits<double>::infinity();
    double step = 2.0;
    int stall = 0;
    std::vector<std::pair<double, uint32_t>> neg;
    for (int it = 0; it < iterations; ++it) {
        if (monitor.stopped() || deadline.expired()) break;
        neg.clear();
        for (uint32_t j = 0; j < P.C; ++j) {
            double c = P.cost[j];
            for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) c -= u[P.idx[k]];
            rc[j] = c;
            if (c < 0) neg.push_back({c, j});
        }
        if (neg.size() > P.K) {
            std::nth_element(neg.begin(), neg.begin() + std::ptrdiff_t(P.K), neg.end());
            neg.resize(P.K);
        }
        double L = std::accumulate(u.begin(), u.end(), 0.0);
        for (const auto& n : neg) L += n.first;
        if (L > best.value) {
            best.value = L;
            best.reduced = rc;
            stall = 0;
        } else if (++stall >= 10) {
            step *= 0.5;
            stall = 0;
        }
        if (best.value >= target * (1 - 1e-9)) break;
        std::fill(g.begin(), g.end(), 1.0);
        for (const auto& n : neg)
            for (uint32_t k = P.ptr[n.second]; k < P.ptr[n.second + 1]; ++k) g[P.idx[k]] -= 1.0;
        double norm2 = 0;
        for (uint32_t r = 0; r < P.R; ++r) {
            if (u[r] <= 0 && g[r] < 0) g[r] = 0;
            norm2 += g[r] * g[r];
        }
        if (norm2 == 0) break;  // the relaxed solution covers every row exactly: optimal
        const double t = step * std::max(target - L, 1e-12 * std::max(1.0, target)) / norm2;
        for (uint32_t r = 0; r < P.R; ++r) u[r] = std::max(0.0, u[r] + t * g[r]);
    }
    best.value = std::max(0.0, best.value);  // costs are >= 0
    return best;
}

}  // namespace

Status solve_weighted_cover(const WeightedCoverProblem& problem, const WeightedCoverOptions& opt, const Monitor& monitor,
                            WeightedCoverResult& out) {
    out = WeightedCoverResult{};
    const size_t C = problem.cost.size();
    if (problem.max_columns == 0) return fail(Code::invalid_argument, "weighted cover: at most 0 columns");
    if (problem.ptr.size() != C + 1 || problem.ptr.front() != 0 || problem.ptr.back() != problem.idx.size())
        return fail(Code::invalid_argument, "weighted cover: column pointers do not match the costs");
    for (size_t j = 0; j < C; ++j) {
        if (!(std::isfinite(problem.cost[j]) && problem.cost[j] >= 0))
            return fail(Code::invalid_argument, "weighted cover: a cost is negative or not finite");
        if (problem.ptr[j] > problem.ptr[j + 1]) return fail(Code::invalid_argument, "weighted cover: column pointers decrease");
    }
    for (uint32_t r : problem.idx)
        if (r >= problem.rows) return fail(Code::invalid_argument, "weighted cover: a row index is out of range");
    Columns P{problem.rows, uint32_t(C), problem.ptr, problem.idx, problem.cost, {}, {}, problem.max_columns};
    P.rptr.assign(P.R + 1, 0);
    for (uint32_t r : P.idx) ++P.rptr[r + 1];
    for (uint32_t r = 0; r < P.R; ++r) P.rptr[r + 1] += P.rptr[r];
    P.rcol.resize(P.idx.size());
    {
        std::vector<uint32_t> at(P.rptr.begin(), P.rptr.end() - 1);
        for (uint32_t j = 0; j < P.C; ++j)
            for (uint32_t k = P.ptr[j]; k < P.ptr[j + 1]; ++k) P.rcol[at[P.idx[k]]++] = j;
    }
    for (uint32_t r = 0; r < P.R; ++r)
        if (P.rptr[r] == P.rptr[r + 1]) return fail(Code::uncoverable, "weighted cover: row " + std::to_string(r) + " is covered by no column");
    const Deadline deadline = Deadline::after(opt.time_limit_s).earliest(monitor.deadline);
    if (P.R == 0) return Status::success();

    const auto t0 = Clock::now();
    int greedy_runs = 0;
    // ---- greedy at rising prices ----
    double smallest = 0, largest = 0;
    for (double c : P.cost) {
        if (c > 0 && (smallest == 0 || c < smallest)) smallest = c;
        largest = std::max(largest, c);
    }
    std::vector<uint32_t> best;
    double best_value = std::numeric_limits<double>::infinity();
    auto consider = [&](const std::vector<uint32_t>& sel) {
        if (sel.size() > P.K) return false;
        const double v = total(P, sel);
        if (v < best_value) {
            best_value = v;
            best = sel;
        }
        return true;
    };
    double fits = -1, too_low = 0;
    if (consider(greedy_cover(P, 0.0))) fits = 0;
    double mu = smallest > 0 ? smallest : 1.0;
    for (int d = 0; d < kPriceDoublings && fits < 0; ++d, mu *= 2) {
        if (monitor.stopped()) return monitor.stop_status("weighted cover");
        ++greedy_runs;
        if (consider(greedy_cover(P, mu))) fits = mu;
        else too_low = mu;
    }
    if (fits < 0)
        return fail(Code::uncoverable, "weighted cover: no cover of at most " + std::to_string(P.K) + " columns was found");
    for (int b = 0; b < kPriceBisections && fits > 0; ++b) {
        if (monitor.stopped()) return monitor.stop_status("weighted cover");
        const double m = 0.5 * (too_low + fits);
        if (consider(greedy_cover(P, m))) fits = m;
        else too_low = m;
    }
    (void)largest;

    // ---- local search, bound, CBC on the core, local search again ----
    const double t_greedy = seconds_since(t0);
    const double v_greedy = best_value;
    improve(P, best, monitor, deadline);
    best_value = total(P, best);
    const double t_search = seconds_since(t0);
    const Bound bound = lagrangian(P, best_value, opt.lagrange_iterations, monitor, deadline);
    const double t_bound = seconds_since(t0);
    // ---- the greedy again on the reduced costs at the best multipliers (clamped at 0: a column
    // the relaxation wants is nearly free), which see what the rows' other columns cost ----
    if (!bound.reduced.empty() && bound.value < best_value * (1 - 1e-6)) {
        std::vector<double> prices(P.C);
        for (uint32_t j = 0; j < P.C; ++j) prices[j] = std::max(bound.reduced[j], 0.0) + 1e-3 * P.cost[j];
        double lo = 0, hi = -1;
        std::vector<uint32_t> sel = greedy_cover(P, 0.0, &prices);
        if (consider(sel)) hi = 0;
        double m = smallest > 0 ? smallest : 1.0;
        for (int d = 0; d < kPriceDoublings && hi < 0 && !monitor.stopped(); ++d, m *= 2) {
            if (consider(greedy_cover(P, m, &prices))) hi = m;
            else lo = m;
        }
        for (int b = 0; b < kPriceBisections && hi > 0 && !monitor.stopped(); ++b) {
            const double mid = 0.5 * (lo + hi);
            if (consider(greedy_cover(P, mid, &prices))) hi = mid;
            else lo = mid;
        }
        improve(P, best, monitor, deadline);
        best_value = total(P, best);
    }
    const double t_reduced = seconds_since(t0), v_reduced = best_value;
    out.lower_bound = std::min(bound.value, best_value);
    if (opt.cbc_nodes > 0 && !bound.reduced.empty() && bound.value < best_value * (1 - 1e-6) && !deadline.expired() &&
        !monitor.stopped()) {
        std::vector<uint8_t> core(P.C, 0);
        for (uint32_t j : best) core[j] = 1;
        for (uint32_t j = 0; j < P.C; ++j) core[j] |= bound.reduced[j] < 0;
        std::vector<uint32_t> cheapest;
        for (uint32_t r = 0; r < P.R; ++r) {
            cheapest.assign(P.rcol.begin() + P.rptr[r], P.rcol.begin() + P.rptr[r + 1]);
            const size_t k = std::min(kCorePerRow, cheapest.size());
            std::partial_sort(cheapest.begin(), cheapest.begin() + std::ptrdiff_t(k), cheapest.end(), [&](uint32_t a, uint32_t b) {
                return bound.reduced[a] != bound.reduced[b] ? bound.reduced[a] < bound.reduced[b] : a < b;
            });
            for (size_t i = 0; i < k; ++i) core[cheapest[i]] = 1;
        }
        std::vector<uint32_t> cols;
        for (uint32_t j = 0; j < P.C; ++j)
            if (core[j]) cols.push_back(j);
        size_t incidences = 0;
        for (uint32_t j : cols) incidences += P.ptr[j + 1] - P.ptr[j];
        if (incidences <= opt.cbc_max_incidences) {
            sc::Problem Q;
            Q.R = P.R;
            Q.C = uint32_t(cols.size());
            Q.cptr.push_back(0);
            std::vector<double> qcost;
            for (uint32_t j : cols) {
                Q.crow.insert(Q.crow.end(), P.idx.begin() + P.ptr[j], P.idx.begin() + P.ptr[j + 1]);
                Q.cptr.push_back(uint32_t(Q.crow.size()));
                Q.col_id.push_back(j);
                qcost.push_back(P.cost[j]);
            }
            Q.row_id.resize(P.R);
            std::iota(Q.row_id.begin(), Q.row_id.end(), 0u);
            sc::fill_rows(Q);
            sc::CbcSettings cs;
            cs.time_limit_s = std::min(deadline.limit_s() > 0 ? deadline.limit_s() : opt.cbc_time_limit_s, opt.cbc_time_limit_s);
            cs.threads = 1;
            cs.max_nodes = opt.cbc_nodes;
            cs.costs = &qcost;
            cs.max_columns = P.K;
            cs.cutoff = best_value * (1 - 1e-7);
            const sc::CbcOutcome cbc = sc::run_cbc(Q, 0, cs);
            if (cbc.ok && cbc.has_solution) {
                std::vector<uint32_t> sel;
                for (uint32_t c : cbc.solution) sel.push_back(Q.col_id[c]);
                std::sort(sel.begin(), sel.end());
                drop_redundant(P, sel);
                if (sel.size() <= P.K && covers(P, sel) && total(P, sel) < best_value) {
                    best = sel;
                    best_value = total(P, sel);
                    out.cbc_improved = true;
                    improve(P, best, monitor, deadline);
                    best_value = total(P, best);
                }
            }
            // the core's bound holds for the whole problem only when the core is all of it
            if (cbc.ok && cols.size() == P.C && std::isfinite(cbc.bound))
                out.lower_bound = std::max(out.lower_bound, std::min(cbc.bound, best_value));
        }
    }
    monitor.note(1, "weighted cover: greedy " + std::to_string(greedy_runs) + " runs " + std::to_string(t_greedy) + " s (" +
                        std::to_string(v_greedy) + "), search " + std::to_string(t_search - t_greedy) + " s (" +
                        std::to_string(total(P, best)) + "), bound " + std::to_string(t_bound - t_search) + " s (" +
                        std::to_string(bound.value) + "), reduced-cost greedy " + std::to_string(t_reduced - t_bound) + " s (" +
                        std::to_string(v_reduced) + "), CBC " + std::to_string(seconds_since(t0) - t_reduced) + " s");
    if (monitor.cancelled()) return monitor.stop_status("weighted cover");
    out.selected = best;
    out.objective = best_value;
    out.lower_bound = std::min(out.lower_bound, best_value);
    out.proven_optimal = out.lower_bound >= best_value * (1 - 1e-9);
    return Status::success();
}

}  // namespace ca
