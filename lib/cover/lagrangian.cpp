// lagrangian.cpp: the Lagrangian lower bound of a compact set-cover problem: subgradient ascent
// and the volume algorithm, with the greedy completion on reduced costs as their primal heuristic.
#include "setcover_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>

namespace ca {
namespace sc {

// Greedy completion scored on reduced costs: gamma_j = c_j - sum of u over uncovered rows,
// mu_j = newly covered rows; score gamma/mu if gamma > 0 else gamma*mu (smaller is better).
// Scores only grow as rows get covered, so a lazy min-heap is exact.
std::vector<uint32_t> lagrange_greedy(const Problem& P, const std::vector<double>& u) {
    std::vector<uint32_t> mu(P.C), sel;
    std::vector<double> gamma(P.C);
    std::vector<uint8_t> covered(P.R, 0), taken(P.C, 0);
    auto score = [&](uint32_t c) { return gamma[c] > 0 ? gamma[c] / mu[c] : gamma[c] * mu[c]; };
    using Item = std::pair<double, uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    for (uint32_t c = 0; c < P.C; ++c) {
        mu[c] = P.cptr[c + 1] - P.cptr[c];
        double g = 1.0;
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) g -= u[P.crow[k]];
        gamma[c] = g;
        if (mu[c]) heap.push({score(c), c});
    }
    uint32_t remaining = P.R;
    while (remaining > 0 && !heap.empty()) {
        const Item top = heap.top();
        heap.pop();
        const uint32_t c = top.second;
        if (taken[c] || mu[c] == 0) continue;
        const double s = score(c);
        if (s > top.first + 1e-12) { heap.push({s, c}); continue; }
        taken[c] = 1;
        sel.push_back(c);
        remaining -= cover_column(P, c, covered, [&](uint32_t r, uint32_t d) {
            mu[d]--;
            gamma[d] += u[r];
        });
    }
    // redundancy: drop the columns of largest reduced cost first
    std::vector<uint32_t> cnt(P.R, 0);
    for (uint32_t c : sel)
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) cnt[P.crow[k]]++;
    std::vector<double> cj(P.C, 1.0);
    for (uint32_t c : sel)
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) cj[c] -= u[P.crow[k]];
    std::sort(sel.begin(), sel.end(), [&](uint32_t a, uint32_t b) { return cj[a] != cj[b] ? cj[a] > cj[b] : a < b; });
    std::vector<uint32_t> kept;
    for (uint32_t c : sel) {
        bool redundant = true;
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1] && redundant; ++k)
            if (cnt[P.crow[k]] < 2) redundant = false;
        if (redundant) {
            for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) cnt[P.crow[k]]--;
        } else {
            kept.push_back(c);
        }
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

namespace {
// The usual first multipliers: u_r = 1 / (the size of the largest column covering r).
std::vector<double> first_multipliers(const Problem& P) {
    std::vector<double> u(P.R);
    for (uint32_t r = 0; r < P.R; ++r) {
        double v = 1.0;
        for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) {
            const uint32_t c = P.rcol[q];
            v = std::min(v, 1.0 / double(P.cptr[c + 1] - P.cptr[c]));
        }
        u[r] = v;
    }
    return u;
}
}  // namespace

// `incumbent`: a cover of P (ascending). Stops early once ceil(bound) >= |best|.
Lagrange lagrangian(const Problem& P, std::vector<uint32_t> incumbent, int max_iter, const Deadline& deadline,
                    const std::vector<double>* start, double step) {
    Lagrange L;
    L.best = std::move(incumbent);
    std::vector<double> u = start && start->size() == P.R ? *start : first_multipliers(P), cost(P.C), g(P.R);
    std::vector<uint8_t> x(P.C);
    L.bound = -1;
    double lambda = step;
    const int stall_max = 20;
    int stall = 0;
    for (int it = 0; it < max_iter; ++it) {
        double val = 0;
        for (uint32_t r = 0; r < P.R; ++r) val += u[r];
        for (uint32_t c = 0; c < P.C; ++c) {
            double cc = 1.0;
            for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) cc -= u[P.crow[k]];
            cost[c] = cc;
            x[c] = cc < 0;
            if (cc < 0) val += cc;
        }
        if (val > L.bound + 1e-9) {
            L.bound = val;
            L.u = u;
            L.cost = cost;
            stall = 0;
        } else if (++stall >= stall_max) {
            lambda *= 0.5;
            stall = 0;
        }
        const double ub = double(L.best.size());
        if (std::ceil(L.bound - 1e-6) >= ub || lambda < 1e-3 * step) break;
        if (it % 8 == 0) {
            std::vector<uint32_t> h = lagrange_greedy(P, u);
            if (h.size() < L.best.size()) L.best.swap(h);
            if (std::ceil(L.bound - 1e-6) >= double(L.best.size())) break;
        }
        if ((it & 15) == 15 && deadline.expired()) break;
        // subgradient g_i = 1 - #selected columns covering i (from the few selected columns)
        std::fill(g.begin(), g.end(), 1.0);
        for (uint32_t c = 0; c < P.C; ++c)
            if (x[c])
                for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) g[P.crow[k]] -= 1.0;
        double norm = 0;
        for (uint32_t r = 0; r < P.R; ++r) {
            if (g[r] < 0 && u[r] <= 0) g[r] = 0;  // projected: u stays at 0
            norm += g[r] * g[r];
        }
        if (norm == 0) break;  // x(u) is a cover with complementary slackness: L(u) is optimal
        const double step = lambda * (double(L.best.size()) - val) / norm;
        for (uint32_t r = 0; r < P.R; ++r) u[r] = std::max(0.0, u[r] + step * g[r]);
    }
    return L;
}


// Volume algorithm (Barahona & Anbil 2000): like the subgradient method, but the direction is
// the subgradient of a running average of the Lagrangian solutions (xbar, an approximate LP
// solution; v = 1 - A xbar), the step factor grows after improving steps whose new subgradient
// agrees with the direction and shrinks after runs without improvement, and the averaging
// weight's upper limit halves whenever 100 steps raise the bound by less than 1 %.
Lagrange volume_ascent(const Problem& P, std::vector<uint32_t> incumbent, int max_iter, const Deadline& deadline) {
    Lagrange L;
    L.best = std::move(incumbent);
    std::vector<double> ubar = first_multipliers(P), u(P.R), cost(P.C), xbar(P.C), v(P.R), w(P.R), g(P.R);
    std::vector<uint8_t> x(P.C);
    // L(y), the reduced costs, x = x(y) (c_j(y) < 0) and w = 1 - A x
    auto evaluate = [&](const std::vector<double>& y) {
        double z = 0;
        for (uint32_t r = 0; r < P.R; ++r) z += y[r];
        std::fill(w.begin(), w.end(), 1.0);
        for (uint32_t c = 0; c < P.C; ++c) {
            double cc = 1.0;
            for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) cc -= y[P.crow[k]];
            cost[c] = cc;
            x[c] = cc < 0;
            if (cc < 0) {
                z += cc;
                for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) w[P.crow[k]] -= 1.0;
            }
        }
        return z;
    };
    double zbar = evaluate(ubar);
    for (uint32_t c = 0; c < P.C; ++c) xbar[c] = x[c];
    v = w;
    L.bound = zbar;
    L.u = ubar;
    L.cost = cost;
    double lambda = 0.1, alpha_max = 0.1, z_checked = zbar;
    int red = 0;  // steps since the last improvement
    for (int it = 0; it < max_iter; ++it) {
        if (std::ceil(L.bound - 1e-6) >= double(L.best.size())) break;
        if ((it & 15) == 15 && deadline.expired()) break;
        double norm = 0;
        for (uint32_t r = 0; r < P.R; ++r) {
            g[r] = (v[r] < 0 && ubar[r] <= 0) ? 0.0 : v[r];  // projected: u stays >= 0
            norm += g[r] * g[r];
        }
        if (norm < 1e-12) break;  // xbar covers every row exactly where u > 0
        const double step = lambda * (double(L.best.size()) - zbar) / norm;
        for (uint32_t r = 0; r < P.R; ++r) u[r] = std::max(0.0, ubar[r] + step * g[r]);
        const double z = evaluate(u);
        // averaging weight: the one minimising |alpha w + (1 - alpha) v|, within [alpha_max / 10, alpha_max]
        double a = 0, b = 0;
        for (uint32_t r = 0; r < P.R; ++r) {
            const double d = w[r] - v[r];
            a += v[r] * d;
            b += d * d;
        }
        const double alpha = std::min(alpha_max, std::max(alpha_max / 10, b > 0 ? -a / b : alpha_max));
        for (uint32_t c = 0; c < P.C; ++c) xbar[c] = alpha * x[c] + (1 - alpha) * xbar[c];
        for (uint32_t r = 0; r < P.R; ++r) v[r] = alpha * w[r] + (1 - alpha) * v[r];
        if (z > zbar) {
            double agree = 0;
            for (uint32_t r = 0; r < P.R; ++r) agree += g[r] * w[r];
            if (agree >= 0) lambda = std::min(2.0, lambda * 1.1);
            ubar = u;
            zbar = z;
            red = 0;
            L.bound = z;
            L.u = u;
            L.cost = cost;
        } else if (++red >= 20) {
            lambda *= 0.67;
            red = 0;
        }
        if ((it + 1) % 100 == 0) {
            if (zbar - z_checked < 0.01 * std::fabs(zbar) && alpha_max > 1e-5) alpha_max /= 2;
            z_checked = zbar;
        }
        if (it % 8 == 0) {
            std::vector<uint32_t> h = lagrange_greedy(P, u);
            if (h.size() < L.best.size()) L.best.swap(h);
        }
    }
    return L;
}

}  // namespace sc
}  // namespace ca
