// setcover_problem.cpp: the compact set-cover problem's building blocks: redundancy removal,
// greedy and Coverage Axis++ covers, the disjoint-rows lower bound, connected components, and
// restrictions to column or row subsets.
#include "setcover_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>

namespace ca {
namespace sc {

// Drop selected columns whose required rows are all covered by the others, smallest columns
// first (ties: lower index); `locked` columns are never dropped. Result ascending.
void remove_redundant(const std::vector<uint32_t>& ptr, const std::vector<uint32_t>& idx, size_t R,
                      const std::vector<uint8_t>* required, const std::vector<uint8_t>* locked,
                      std::vector<uint32_t>& sel) {
    auto req = [&](uint32_t r) { return !required || (*required)[r]; };
    std::vector<uint32_t> cnt(R, 0), size(sel.size(), 0);
    for (size_t s = 0; s < sel.size(); ++s)
        for (uint32_t k = ptr[sel[s]]; k < ptr[sel[s] + 1]; ++k)
            if (req(idx[k])) { cnt[idx[k]]++; size[s]++; }
    std::vector<uint32_t> order(sel.size());
    for (uint32_t s = 0; s < order.size(); ++s) order[s] = s;
    std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) {
        return size[x] != size[y] ? size[x] < size[y] : sel[x] < sel[y];
    });
    std::vector<uint8_t> drop(sel.size(), 0);
    for (uint32_t s : order) {
        const uint32_t c = sel[s];
        if (locked && (*locked)[c]) continue;
        bool redundant = true;
        for (uint32_t k = ptr[c]; k < ptr[c + 1] && redundant; ++k)
            if (req(idx[k]) && cnt[idx[k]] < 2) redundant = false;
        if (!redundant) continue;
        drop[s] = 1;
        for (uint32_t k = ptr[c]; k < ptr[c + 1]; ++k)
            if (req(idx[k])) cnt[idx[k]]--;
    }
    std::vector<uint32_t> kept;
    for (size_t s = 0; s < sel.size(); ++s)
        if (!drop[s]) kept.push_back(sel[s]);
    std::sort(kept.begin(), kept.end());
    sel.swap(kept);
}

// Greedy: most newly covered rows, ties to the lower index (lazy max-heap), starting from the
// columns of `start` (kept). Ascending result.
std::vector<uint32_t> greedy_complete(const Problem& P, const std::vector<uint32_t>& start) {
    std::vector<uint32_t> cnt(P.C), sel = start;
    std::vector<uint8_t> covered(P.R, 0);
    uint32_t remaining = P.R;
    for (uint32_t c : start)
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k)
            if (!covered[P.crow[k]]) { covered[P.crow[k]] = 1; --remaining; }
    using Item = std::pair<uint32_t, uint32_t>;  // (count, C-1-col): larger = better
    std::priority_queue<Item> heap;
    for (uint32_t c = 0; c < P.C; ++c) {
        cnt[c] = 0;
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) cnt[c] += !covered[P.crow[k]];
        if (cnt[c]) heap.push({cnt[c], P.C - 1 - c});
    }
    while (remaining > 0 && !heap.empty()) {
        const Item top = heap.top();
        heap.pop();
        const uint32_t c = P.C - 1 - top.second;
        if (top.first != cnt[c]) {
            if (cnt[c]) heap.push({cnt[c], top.second});
            continue;
        }
        sel.push_back(c);
        remaining -= cover_column(P, c, covered, [&](uint32_t, uint32_t d) { cnt[d]--; });
    }
    std::sort(sel.begin(), sel.end());
    return sel;
}

std::vector<uint32_t> greedy_cover(const Problem& P) { return greedy_complete(P, {}); }

// Coverage Axis++ (Wang et al. 2024) selection on the kernel: each step maximises
// z(newly covered) + w_u z(distance to the nearest selected centre) - w_c z(0.1 r_max / r),
// z standardised over the still-eligible columns (unselected, covering something new).
std::vector<uint32_t> capp_cover(const Problem& P, const std::vector<Vec3>& centers,
                                 const std::vector<double>& radii, const std::vector<uint32_t>& preselected) {
    const double wu = 1.0, wc = 1.0;
    std::vector<uint32_t> cnt(P.C), sel;
    std::vector<uint8_t> covered(P.R, 0), taken(P.C, 0);
    std::vector<double> mind(P.C, std::numeric_limits<double>::infinity()), rterm(P.C, 0.1);
    double rmax = 0;
    for (uint32_t c = 0; c < P.C; ++c) rmax = std::max(rmax, radii[P.col_id[c]]);
    for (uint32_t c = 0; c < P.C; ++c) {
        cnt[c] = P.cptr[c + 1] - P.cptr[c];
        if (rmax > 0) rterm[c] = 0.1 * rmax / std::max(radii[P.col_id[c]], rmax * 1e-9);
        for (uint32_t f : preselected)
            mind[c] = std::min(mind[c], (centers[P.col_id[c]] - centers[f]).norm());
    }
    bool any_selected = !preselected.empty();
    uint32_t remaining = P.R;
    std::vector<uint32_t> elig;
    while (remaining > 0) {
        elig.clear();
        for (uint32_t c = 0; c < P.C; ++c)
            if (!taken[c] && cnt[c] > 0) elig.push_back(c);
        if (elig.empty()) break;
        auto stats = [&](auto&& f, double& mean, double& sd) {
            double s = 0, s2 = 0;
            for (uint32_t c : elig) s += f(c);
            mean = s / double(elig.size());
            for (uint32_t c : elig) { const double d = f(c) - mean; s2 += d * d; }
            sd = std::sqrt(s2 / double(elig.size()));
        };
        auto fc = [&](uint32_t c) { return double(cnt[c]); };
        auto fu = [&](uint32_t c) { return any_selected ? mind[c] : 0.0; };
        auto fr = [&](uint32_t c) { return rterm[c]; };
        double mc, sc, mu, su, mr, sr;
        stats(fc, mc, sc);
        stats(fu, mu, su);
        stats(fr, mr, sr);
        auto z = [](double x, double mean, double sd) { return sd > 1e-300 ? (x - mean) / sd : 0.0; };
        uint32_t best = elig[0];
        double best_score = -std::numeric_limits<double>::infinity();
        for (uint32_t c : elig) {
            const double s = z(fc(c), mc, sc) + wu * z(fu(c), mu, su) - wc * z(fr(c), mr, sr);
            if (s > best_score) { best_score = s; best = c; }  // ties: first = lower index
        }
        taken[best] = 1;
        sel.push_back(best);
        any_selected = true;
        remaining -= cover_column(P, best, covered, [&](uint32_t, uint32_t d) { cnt[d]--; });
        const Vec3& cb = centers[P.col_id[best]];
        for (uint32_t c = 0; c < P.C; ++c) mind[c] = std::min(mind[c], (centers[P.col_id[c]] - cb).norm());
    }
    std::sort(sel.begin(), sel.end());
    return sel;
}

std::vector<uint32_t> all_rows(const Problem& P) {
    std::vector<uint32_t> rows(P.R);
    std::iota(rows.begin(), rows.end(), 0u);
    return rows;
}

// Rows pairwise sharing no column need distinct columns: a valid lower bound.
uint32_t disjoint_bound(const Problem& P) {
    std::vector<uint32_t> rows;
    add_spread_rows(P, all_rows(P), P.R, rows);
    return uint32_t(rows.size());
}

bool covers_problem(const Problem& P, const std::vector<uint32_t>& sel) {
    std::vector<uint8_t> covered(P.R, 0);
    for (uint32_t c : sel) {
        if (c >= P.C) return false;
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) covered[P.crow[k]] = 1;
    }
    for (uint8_t v : covered)
        if (!v) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// Connected components: rows linked by a shared column. Components share neither rows nor
// columns, so their optima (and lower bounds) add up.
std::vector<Problem> split_components(const Problem& P) {
    std::vector<uint32_t> parent(P.R);
    for (uint32_t r = 0; r < P.R; ++r) parent[r] = r;
    auto find = [&](uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (uint32_t c = 0; c < P.C; ++c)
        for (uint32_t k = P.cptr[c] + 1; k < P.cptr[c + 1]; ++k) {
            const uint32_t a = find(P.crow[P.cptr[c]]), b = find(P.crow[k]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<uint32_t> comp_of(P.R), local(P.R);
    std::vector<Problem> out;
    std::vector<uint32_t> root_comp(P.R, UINT32_MAX);
    for (uint32_t r = 0; r < P.R; ++r) {
        const uint32_t root = find(r);
        if (root_comp[root] == UINT32_MAX) { root_comp[root] = uint32_t(out.size()); out.emplace_back(); }
        Problem& Q = out[root_comp[root]];
        comp_of[r] = root_comp[root];
        local[r] = Q.R++;
        Q.row_id.push_back(r);  // local ids into P for now
    }
    for (uint32_t c = 0; c < P.C; ++c) {
        if (P.cptr[c] == P.cptr[c + 1]) continue;
        Problem& Q = out[comp_of[P.crow[P.cptr[c]]]];
        if (Q.cptr.empty()) Q.cptr.push_back(0);
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) Q.crow.push_back(local[P.crow[k]]);
        Q.cptr.push_back(uint32_t(Q.crow.size()));
        Q.col_id.push_back(c);
    }
    for (Problem& Q : out) {
        Q.C = uint32_t(Q.col_id.size());
        if (Q.cptr.empty()) Q.cptr.push_back(0);
        fill_rows(Q);
    }
    // largest first: the time budget goes to the hard parts while it lasts
    std::stable_sort(out.begin(), out.end(), [](const Problem& a, const Problem& b) { return a.crow.size() > b.crow.size(); });
    return out;
}

// Columns restricted to `keep` (local ids of P), rows all kept; col_id = P-local column ids.
Problem restrict_columns(const Problem& P, const std::vector<uint8_t>& keep) {
    Problem Q;
    Q.R = P.R;
    Q.row_id.resize(P.R);
    for (uint32_t r = 0; r < P.R; ++r) Q.row_id[r] = r;
    Q.cptr.push_back(0);
    for (uint32_t c = 0; c < P.C; ++c) {
        if (!keep[c]) continue;
        Q.crow.insert(Q.crow.end(), P.crow.begin() + P.cptr[c], P.crow.begin() + P.cptr[c + 1]);
        Q.cptr.push_back(uint32_t(Q.crow.size()));
        Q.col_id.push_back(c);
    }
    Q.C = uint32_t(Q.col_id.size());
    fill_rows(Q);
    return Q;
}

// Fills the row -> column direction of Q from its column -> row direction.
void fill_rows(Problem& Q) {
    Q.rptr.assign(Q.R + 1, 0);
    for (uint32_t r : Q.crow) Q.rptr[r + 1]++;
    for (uint32_t r = 0; r < Q.R; ++r) Q.rptr[r + 1] += Q.rptr[r];
    Q.rcol.resize(Q.crow.size());
    std::vector<uint32_t> next(Q.rptr.begin(), Q.rptr.end() - 1);
    for (uint32_t c = 0; c < Q.C; ++c)
        for (uint32_t k = Q.cptr[c]; k < Q.cptr[c + 1]; ++k) Q.rcol[next[Q.crow[k]]++] = c;
}

// The rows `rows` of K (ascending) with the columns of K that meet them, restricted to them;
// row_id / col_id are K-local.
Problem restrict_rows(const Problem& K, const std::vector<uint32_t>& rows) {
    Problem S;
    S.R = uint32_t(rows.size());
    S.row_id = rows;
    std::vector<uint32_t> local(K.R, UINT32_MAX);
    for (uint32_t i = 0; i < S.R; ++i) local[rows[i]] = i;
    S.cptr.push_back(0);
    for (uint32_t c = 0; c < K.C; ++c) {
        const size_t before = S.crow.size();
        for (uint32_t k = K.cptr[c]; k < K.cptr[c + 1]; ++k)
            if (local[K.crow[k]] != UINT32_MAX) S.crow.push_back(local[K.crow[k]]);
        if (S.crow.size() == before) continue;
        S.cptr.push_back(uint32_t(S.crow.size()));
        S.col_id.push_back(c);
    }
    S.C = uint32_t(S.col_id.size());
    fill_rows(S);
    return S;
}

// Adds to `rows` (kept ascending) up to `cap` of the rows in `cand`, fewest columns first
// (ties: lower index), pairwise sharing no column: spread out over the surface, each one
// needing its own column.
void add_spread_rows(const Problem& K, std::vector<uint32_t> cand, size_t cap, std::vector<uint32_t>& rows) {
    std::sort(cand.begin(), cand.end(), [&](uint32_t x, uint32_t y) {
        const uint32_t dx = K.rptr[x + 1] - K.rptr[x], dy = K.rptr[y + 1] - K.rptr[y];
        return dx != dy ? dx < dy : x < y;
    });
    std::vector<uint8_t> used(K.C, 0);
    size_t added = 0;
    for (uint32_t r : cand) {
        if (added >= cap) break;
        bool free = true;
        for (uint32_t q = K.rptr[r]; q < K.rptr[r + 1] && free; ++q) free = !used[K.rcol[q]];
        if (!free) continue;
        for (uint32_t q = K.rptr[r]; q < K.rptr[r + 1]; ++q) used[K.rcol[q]] = 1;
        rows.push_back(r);
        ++added;
    }
    std::sort(rows.begin(), rows.end());
}

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

}  // namespace sc
}  // namespace ca
