// setcover.cpp: minimum set cover of the samples by the candidate balls (see setcover.h).
//
// Pipeline: input checks -> reduction to a fixpoint (forced balls, degree-1 samples, dominated
// samples, dominated balls, empty balls) -> kernel solve -> redundancy removal -> verification.
// Exact kernel solve, per connected component of the kernel (components share no rows and no
// columns, so optima and bounds add): greedy cover -> Lagrangian subgradient (bound, and a
// reduced-cost greedy that improves the incumbent) -> done if ceil(bound) meets the incumbent;
// otherwise reduced-cost fixing (drop every column that no cover smaller than the incumbent can
// contain), reduction again, then row generation on what is left (exact ILPs on growing row
// subsets, see row_generation) with a quarter of the remaining budget, and if that does not
// finish, CBC on the whole of it with the best cover as cutoff.
// Heuristic kernel solve: greedy / Coverage Axis++.
// Reductions never change the optimum value, so forced + a kernel lower bound is a valid lower
// bound of the original problem.
#include "setcover.h"

#include <coin/Cbc_C_Interface.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <queue>
#include <string>

namespace ca {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// ---------------------------------------------------------------------------------------------
// Reduction on the original index space. Dead balls / samples keep empty lists.
class Reducer {
public:
    Reducer(size_t n_balls, size_t n_samples) : n_(n_balls), m_(n_samples) {}

    std::vector<uint8_t> s_alive, b_alive;  // sample still to be covered / ball still a candidate
    // Current lists: either views of the coverage itself (first round, when nothing is masked)
    // or the reducer's own compacted copies. Dead balls have empty lists once compacted.
    const uint32_t* bptr = nullptr;  // ball -> alive samples
    const uint32_t* bs = nullptr;
    const uint32_t* sptr = nullptr;  // sample -> alive balls (ascending)
    const uint32_t* sb = nullptr;
    std::vector<uint32_t> forced;    // selected by the reduction (forced_in + degree 1)

    uint32_t bsize(uint32_t a) const { return bptr[a + 1] - bptr[a]; }
    uint32_t sdeg(uint32_t j) const { return sptr[j + 1] - sptr[j]; }

    // Initial lists. With every sample required, every ball allowed and a consistent transpose
    // in `cov`, the coverage's own arrays are used as they are (no copy); otherwise the lists
    // are copied restricted to the alive sets.
    void init(const Coverage& cov, bool use_view) {
        if (use_view) {
            bptr = cov.ball_ptr.data();
            bs = cov.ball_samples.data();
            sptr = cov.sample_ptr.data();
            sb = cov.sample_balls.data();
            for (size_t a = 0; a < n_; ++a)
                if (bptr[a + 1] == bptr[a]) b_alive[a] = 0;
            return;
        }
        own_bptr.assign(n_ + 1, 0);
        own_bs.clear();
        for (size_t a = 0; a < n_; ++a) {
            if (b_alive[a])
                for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k)
                    if (s_alive[cov.ball_samples[k]]) own_bs.push_back(cov.ball_samples[k]);
            own_bptr[a + 1] = uint32_t(own_bs.size());
        }
        finish_rebuild();
    }

    // Drop dead samples/balls from the lists (cost: the current lists, not the original ones).
    void rebuild() {
        std::vector<uint32_t> nptr(n_ + 1, 0), ns;
        ns.reserve(bptr[n_]);
        for (size_t a = 0; a < n_; ++a) {
            if (b_alive[a])
                for (uint32_t k = bptr[a]; k < bptr[a + 1]; ++k)
                    if (s_alive[bs[k]]) ns.push_back(bs[k]);
            nptr[a + 1] = uint32_t(ns.size());
        }
        own_bptr.swap(nptr);
        own_bs.swap(ns);
        finish_rebuild();
    }

    void select(uint32_t b) {
        forced.push_back(b);
        b_alive[b] = 0;
        for (uint32_t k = bptr[b]; k < bptr[b + 1]; ++k) s_alive[bs[k]] = 0;
    }

    // Samples with exactly one candidate ball force that ball.
    bool force_degree_one() {
        bool any = false;
        for (uint32_t j = 0; j < m_; ++j)
            if (s_alive[j] && sdeg(j) == 1) {
                select(sb[sptr[j]]);
                any = true;
            }
        return any;
    }

    // Sample j is dropped if an alive sample k has balls(k) ⊆ balls(j) (equal sets: keep the
    // lower index): covering k covers j. Candidates k are grouped by their rarest ball, which
    // must be one of j's balls; the subset test uses a stamp of j's balls, first on a few
    // inline probes (k's next rarest balls, cache-friendly), then on k's whole list.
    bool sample_dominance() {
        std::vector<uint32_t> gptr(n_ + 1, 0);
        std::vector<Probe> pr(m_);
        for (uint32_t j = 0; j < m_; ++j) {
            if (!s_alive[j] || sdeg(j) == 0) continue;
            make_probe(&sb[sptr[j]], sdeg(j), [&](uint32_t b) { return bsize(b); }, pr[j]);
            gptr[pr[j].key + 1]++;
        }
        for (size_t b = 0; b < n_; ++b) gptr[b + 1] += gptr[b];
        std::vector<uint32_t> g(gptr[n_]), fill(gptr.begin(), gptr.end() - 1);
        for (uint32_t j = 0; j < m_; ++j)
            if (s_alive[j] && sdeg(j) > 0) g[fill[pr[j].key]++] = j;
        stamp_b_.assign(n_, 0);
        uint32_t stamp = 0;
        bool any = false;
        for (uint32_t j = 0; j < m_; ++j) {
            if (!s_alive[j]) continue;
            ++stamp;
            for (uint32_t k = sptr[j]; k < sptr[j + 1]; ++k) stamp_b_[sb[k]] = stamp;
            const uint32_t dj = sdeg(j);
            bool dominated = false;
            for (uint32_t q = sptr[j]; q < sptr[j + 1] && !dominated; ++q) {
                const uint32_t b = sb[q];
                for (uint32_t t = gptr[b]; t < gptr[b + 1]; ++t) {
                    const uint32_t k = g[t];
                    const Probe& P = pr[k];
                    if (k == j || P.size > dj || (P.size == dj && k > j) || !s_alive[k]) continue;
                    if (!probe_ok(P, stamp_b_, stamp)) continue;
                    bool subset = true;
                    for (uint32_t e = sptr[k]; e < sptr[k + 1]; ++e)
                        if (stamp_b_[sb[e]] != stamp) { subset = false; break; }
                    if (subset) { dominated = true; break; }
                }
            }
            if (dominated) {
                s_alive[j] = 0;
                any = true;
            }
        }
        return any;
    }

    // Ball a is dropped if an alive ball b has samples(a) ⊆ samples(b) (equal sets: keep the
    // lower index). Supersets b are visited largest first with their samples stamped; the
    // candidates a are grouped by their rarest sample (which b must contain); dead candidates
    // are removed from the groups as they are met. Same probe filter as above.
    bool ball_dominance() {
        std::vector<uint32_t> gptr(m_ + 1, 0), order;
        std::vector<Probe> pr(n_);
        order.reserve(n_);
        for (uint32_t a = 0; a < n_; ++a) {
            if (!b_alive[a]) continue;
            make_probe(&bs[bptr[a]], bsize(a), [&](uint32_t j) { return sdeg(j); }, pr[a]);
            gptr[pr[a].key + 1]++;
            order.push_back(a);
        }
        for (size_t j = 0; j < m_; ++j) gptr[j + 1] += gptr[j];
        std::vector<uint32_t> g(gptr[m_]), gend(gptr.begin(), gptr.end() - 1);
        for (uint32_t a : order) g[gend[pr[a].key]++] = a;
        std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) {
            const uint32_t sx = bsize(x), sy = bsize(y);
            return sx != sy ? sx > sy : x < y;
        });
        stamp_s_.assign(m_, 0);
        uint32_t stamp = 0;
        bool any = false;
        for (uint32_t b : order) {
            if (!b_alive[b]) continue;  // whatever dominates b also dominates b's subsets
            ++stamp;
            for (uint32_t k = bptr[b]; k < bptr[b + 1]; ++k) stamp_s_[bs[k]] = stamp;
            const uint32_t nb = bsize(b);
            for (uint32_t q = bptr[b]; q < bptr[b + 1]; ++q) {
                const uint32_t j = bs[q];
                uint32_t t = gptr[j];
                while (t < gend[j]) {
                    const uint32_t a = g[t];
                    if (!b_alive[a]) { g[t] = g[--gend[j]]; continue; }
                    const Probe& P = pr[a];
                    if (a == b || P.size > nb || (P.size == nb && a < b) || !probe_ok(P, stamp_s_, stamp)) {
                        ++t;
                        continue;
                    }
                    bool subset = true;
                    for (uint32_t e = bptr[a]; e < bptr[a + 1]; ++e)
                        if (stamp_s_[bs[e]] != stamp) { subset = false; break; }
                    if (subset) {
                        b_alive[a] = 0;
                        any = true;
                        g[t] = g[--gend[j]];
                    } else {
                        ++t;
                    }
                }
            }
        }
        return any;
    }

private:
    // Per element: list size, its rarest member (`key`, the group it is filed under) and the
    // next rarest members (`p`, padded with key), kept inline so most failing subset tests
    // never touch the element's list.
    static constexpr int kProbes = 3;
    struct Probe {
        uint32_t size = 0, key = 0;
        uint32_t p[kProbes] = {};
    };
    template <class Rarity>
    static void make_probe(const uint32_t* list, uint32_t len, Rarity rarity, Probe& out) {
        out.size = len;
        // the kProbes + 1 rarest members, ties to the lower index (lists are ascending)
        uint32_t best[kProbes + 1] = {}, rb[kProbes + 1] = {};
        int cnt = 0;
        for (uint32_t k = 0; k < len; ++k) {
            const uint32_t x = list[k], r = rarity(x);
            if (cnt == kProbes + 1 && r >= rb[kProbes]) continue;
            int pos = cnt < kProbes + 1 ? cnt++ : kProbes;
            while (pos > 0 && rb[pos - 1] > r) {
                best[pos] = best[pos - 1];
                rb[pos] = rb[pos - 1];
                --pos;
            }
            best[pos] = x;
            rb[pos] = r;
        }
        out.key = best[0];
        for (int i = 0; i < kProbes; ++i) out.p[i] = i + 1 < cnt ? best[i + 1] : best[0];
    }
    static bool probe_ok(const Probe& P, const std::vector<uint32_t>& stamp_arr, uint32_t stamp) {
        for (int i = 0; i < kProbes; ++i)
            if (stamp_arr[P.p[i]] != stamp) return false;
        return true;
    }

    // Transpose own_bs into own_sptr/own_sb and point the views at the own lists; a ball left
    // without samples dies.
    void finish_rebuild() {
        for (size_t a = 0; a < n_; ++a)
            if (b_alive[a] && own_bptr[a + 1] == own_bptr[a]) b_alive[a] = 0;
        own_sptr.assign(m_ + 1, 0);
        for (uint32_t j : own_bs) own_sptr[j + 1]++;
        for (size_t j = 0; j < m_; ++j) own_sptr[j + 1] += own_sptr[j];
        own_sb.resize(own_bs.size());
        std::vector<uint32_t> next(own_sptr.begin(), own_sptr.end() - 1);
        for (uint32_t a = 0; a < n_; ++a)
            for (uint32_t k = own_bptr[a]; k < own_bptr[a + 1]; ++k) own_sb[next[own_bs[k]]++] = a;
        bptr = own_bptr.data();
        bs = own_bs.data();
        sptr = own_sptr.data();
        sb = own_sb.data();
    }

    std::vector<uint32_t> own_bptr, own_bs, own_sptr, own_sb;
    size_t n_, m_;
    std::vector<uint32_t> stamp_b_, stamp_s_;
};

// ---------------------------------------------------------------------------------------------
// A compact set-cover problem: R rows (samples) x C columns (balls), every row coverable.
struct Problem {
    uint32_t R = 0, C = 0;
    std::vector<uint32_t> cptr, crow;  // column -> rows, ascending
    std::vector<uint32_t> rptr, rcol;  // row -> columns, ascending
    std::vector<uint32_t> col_id, row_id;  // original ball / sample index
};

Problem make_kernel(const Reducer& red, size_t n, size_t m) {
    Problem P;
    std::vector<uint32_t> row_of(m, UINT32_MAX);
    for (uint32_t j = 0; j < m; ++j)
        if (red.s_alive[j]) { row_of[j] = uint32_t(P.row_id.size()); P.row_id.push_back(j); }
    for (uint32_t a = 0; a < n; ++a)
        if (red.b_alive[a]) P.col_id.push_back(a);
    P.R = uint32_t(P.row_id.size());
    P.C = uint32_t(P.col_id.size());
    P.cptr.assign(P.C + 1, 0);
    for (uint32_t c = 0; c < P.C; ++c) {
        const uint32_t a = P.col_id[c];
        for (uint32_t k = red.bptr[a]; k < red.bptr[a + 1]; ++k) P.crow.push_back(row_of[red.bs[k]]);
        P.cptr[c + 1] = uint32_t(P.crow.size());
    }
    P.rptr.assign(P.R + 1, 0);
    for (uint32_t r : P.crow) P.rptr[r + 1]++;
    for (uint32_t r = 0; r < P.R; ++r) P.rptr[r + 1] += P.rptr[r];
    P.rcol.resize(P.crow.size());
    std::vector<uint32_t> next(P.rptr.begin(), P.rptr.end() - 1);
    for (uint32_t c = 0; c < P.C; ++c)
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) P.rcol[next[P.crow[k]]++] = c;
    return P;
}

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
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) {
            const uint32_t r = P.crow[k];
            if (covered[r]) continue;
            covered[r] = 1;
            --remaining;
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) cnt[P.rcol[q]]--;
        }
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
        for (uint32_t k = P.cptr[best]; k < P.cptr[best + 1]; ++k) {
            const uint32_t r = P.crow[k];
            if (covered[r]) continue;
            covered[r] = 1;
            --remaining;
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) cnt[P.rcol[q]]--;
        }
        const Vec3& cb = centers[P.col_id[best]];
        for (uint32_t c = 0; c < P.C; ++c) mind[c] = std::min(mind[c], (centers[P.col_id[c]] - cb).norm());
    }
    std::sort(sel.begin(), sel.end());
    return sel;
}

// Rows pairwise sharing no column need distinct columns: a valid lower bound.
uint32_t disjoint_bound(const Problem& P) {
    std::vector<uint32_t> order(P.R);
    for (uint32_t r = 0; r < P.R; ++r) order[r] = r;
    std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) {
        const uint32_t dx = P.rptr[x + 1] - P.rptr[x], dy = P.rptr[y + 1] - P.rptr[y];
        return dx != dy ? dx < dy : x < y;
    });
    std::vector<uint8_t> used(P.C, 0);
    uint32_t count = 0;
    for (uint32_t r : order) {
        bool free = true;
        for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1] && free; ++q)
            if (used[P.rcol[q]]) free = false;
        if (!free) continue;
        ++count;
        for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) used[P.rcol[q]] = 1;
    }
    return count;
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
        Q.rptr.assign(Q.R + 1, 0);
        for (uint32_t r : Q.crow) Q.rptr[r + 1]++;
        for (uint32_t r = 0; r < Q.R; ++r) Q.rptr[r + 1] += Q.rptr[r];
        Q.rcol.resize(Q.crow.size());
        std::vector<uint32_t> next(Q.rptr.begin(), Q.rptr.end() - 1);
        for (uint32_t c = 0; c < Q.C; ++c)
            for (uint32_t k = Q.cptr[c]; k < Q.cptr[c + 1]; ++k) Q.rcol[next[Q.crow[k]]++] = c;
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
    Q.rptr.assign(Q.R + 1, 0);
    for (uint32_t r : Q.crow) Q.rptr[r + 1]++;
    for (uint32_t r = 0; r < Q.R; ++r) Q.rptr[r + 1] += Q.rptr[r];
    Q.rcol.resize(Q.crow.size());
    std::vector<uint32_t> next(Q.rptr.begin(), Q.rptr.end() - 1);
    for (uint32_t c = 0; c < Q.C; ++c)
        for (uint32_t k = Q.cptr[c]; k < Q.cptr[c + 1]; ++k) Q.rcol[next[Q.crow[k]]++] = c;
    return Q;
}

// ---------------------------------------------------------------------------------------------
// Lagrangian relaxation of the covering rows (multipliers u >= 0):
//   L(u) = sum_i u_i + sum_j min(0, c_j(u)),  c_j(u) = 1 - sum_{i in j} u_i,
// a lower bound on the optimum for every u >= 0; L(u) + c_j(u) (c_j >= 0) bounds every cover
// that contains column j. Subgradient ascent (Held-Karp step, halving on stalls), with a
// primal heuristic on the reduced costs (Caprara-Fischetti-Toth score) every few steps.
struct Lagrange {
    double bound = 0;               // best L(u) found
    std::vector<double> u, cost;    // multipliers of the best bound and their reduced costs
    std::vector<uint32_t> best;     // best cover found (ascending), possibly improved on entry's
};

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
        for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) {
            const uint32_t r = P.crow[k];
            if (covered[r]) continue;
            covered[r] = 1;
            --remaining;
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) {
                const uint32_t d = P.rcol[q];
                mu[d]--;
                gamma[d] += u[r];
            }
        }
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

// `incumbent`: a cover of P (ascending). Stops early once ceil(bound) >= |best|.
Lagrange lagrangian(const Problem& P, std::vector<uint32_t> incumbent, int max_iter, Clock::time_point deadline) {
    Lagrange L;
    L.best = std::move(incumbent);
    std::vector<double> u(P.R), cost(P.C), g(P.R);
    std::vector<uint8_t> x(P.C);
    for (uint32_t r = 0; r < P.R; ++r) {
        double v = 1.0;
        for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) {
            const uint32_t c = P.rcol[q];
            v = std::min(v, 1.0 / double(P.cptr[c + 1] - P.cptr[c]));
        }
        u[r] = v;
    }
    L.bound = -1;
    double lambda = 2.0;
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
        if (std::ceil(L.bound - 1e-6) >= ub || lambda < 2e-3) break;
        if (it % 8 == 0) {
            std::vector<uint32_t> h = lagrange_greedy(P, u);
            if (h.size() < L.best.size()) L.best.swap(h);
            if (std::ceil(L.bound - 1e-6) >= double(L.best.size())) break;
        }
        if ((it & 15) == 15 && Clock::now() > deadline) break;
        // subgradient g_i = 1 - #selected columns covering i
        double norm = 0;
        for (uint32_t r = 0; r < P.R; ++r) {
            int cnt = 0;
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) cnt += x[P.rcol[q]];
            double gi = 1.0 - cnt;
            if (gi < 0 && u[r] <= 0) gi = 0;  // projected: u stays at 0
            g[r] = gi;
            norm += gi * gi;
        }
        if (norm == 0) break;  // x(u) is a cover with complementary slackness: L(u) is optimal
        const double step = lambda * (double(L.best.size()) - val) / norm;
        for (uint32_t r = 0; r < P.R; ++r) u[r] = std::max(0.0, u[r] + step * g[r]);
    }
    return L;
}

struct CbcOutcome {
    bool ok = false;            // CBC ran and returned without error
    bool has_solution = false;  // a cover better than the cutoff, verified
    bool proven = false;        // the search finished: `solution` optimal, or none below the cutoff
    double bound = -std::numeric_limits<double>::infinity();  // valid for solutions below the cutoff
    std::vector<uint32_t> solution;  // columns, ascending
};

// Solves the kernel with CBC, looking only for covers smaller than `incumbent` (the greedy
// cover): the cutoff incumbent - 0.5 prunes exactly as a MIP start would (objective values
// are integral). A MIP start (Cbc_setMIPStartI) is deliberately not used: in CBC 2.10 its
// processing ("Reduced search") ignored the time limit and took over a minute on a dense
// 1500 x 2000 kernel where the cutoff alone gives the same result in seconds.
// With `first_solution`, CBC stops at the first cover below the cutoff (not proven optimal).
CbcOutcome run_cbc(const Problem& P, size_t incumbent, double time_limit_s, int threads, bool first_solution = false) {
    // CBC parses its options through process-wide globals and is not thread-safe: every CBC
    // call sequence in the process goes through this one mutex. It is the library's only
    // process-wide state.
    static std::mutex cbc_mutex;
    CbcOutcome out;
    std::vector<CoinBigIndex> colstart(P.C + 1);
    std::vector<int> rowidx(P.crow.begin(), P.crow.end());
    for (uint32_t c = 0; c <= P.C; ++c) colstart[c] = CoinBigIndex(P.cptr[c]);
    std::vector<double> val(P.crow.size(), 1.0), lb(P.C, 0.0), ub(P.C, 1.0), obj(P.C, 1.0), rlb(P.R, 1.0);
    char buf[64];

    std::lock_guard<std::mutex> lock(cbc_mutex);
    struct Deleter { void operator()(Cbc_Model* m) const { Cbc_deleteModel(m); } };
    std::unique_ptr<Cbc_Model, Deleter> model(Cbc_newModel());
    if (!model) return out;
    Cbc_Model* m = model.get();
    Cbc_loadProblem(m, int(P.C), int(P.R), colstart.data(), rowidx.data(), val.data(), lb.data(), ub.data(),
                    obj.data(), rlb.data(), nullptr);
    for (uint32_t c = 0; c < P.C; ++c) Cbc_setInteger(m, int(c));
    Cbc_setParameter(m, "log", "0");  // otherwise CBC prints to stdout
    Cbc_setParameter(m, "slog", "0");
    Cbc_setParameter(m, "timeMode", "elapsed");
    if (time_limit_s > 0 && std::isfinite(time_limit_s)) {
        std::snprintf(buf, sizeof buf, "%.6f", time_limit_s);
        Cbc_setParameter(m, "sec", buf);
    }
    std::snprintf(buf, sizeof buf, "%d", std::max(1, threads));
    Cbc_setParameter(m, "threads", buf);
    std::snprintf(buf, sizeof buf, "%.1f", double(incumbent) - 0.5);
    Cbc_setParameter(m, "cutoff", buf);
    if (first_solution) Cbc_setParameter(m, "maxSolutions", "1");
    Cbc_solve(m);
    out.ok = true;
    const bool finished = Cbc_status(m) == 0;
    out.bound = Cbc_getBestPossibleObjValue(m);
    const double* x = Cbc_bestSolution(m) ? Cbc_getColSolution(m) : nullptr;
    if (x) {
        for (uint32_t c = 0; c < P.C; ++c)
            if (x[c] > 0.5) out.solution.push_back(c);
        out.has_solution = covers_problem(P, out.solution) && out.solution.size() < incumbent;
        if (!out.has_solution) out.solution.clear();
    }
    // Optimal below the cutoff, or proven that nothing beats the incumbent.
    if (out.has_solution)
        out.proven = Cbc_isProvenOptimal(m) != 0;
    else
        out.proven = finished && Cbc_isProvenInfeasible(m) != 0;
    return out;
}

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

Status check_coverage(const Coverage& cov) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (m >= UINT32_MAX || n >= UINT32_MAX) return fail(Code::invalid_input, "set cover: too many samples or balls");
    if (cov.ball_ptr.size() != n + 1 || cov.ball_ptr[0] != 0 || cov.ball_ptr[n] != cov.ball_samples.size())
        return fail(Code::invalid_input, "set cover: malformed coverage (ball_ptr)");
    for (size_t a = 0; a < n; ++a) {
        if (cov.ball_ptr[a + 1] < cov.ball_ptr[a]) return fail(Code::invalid_input, "set cover: malformed coverage (ball_ptr)");
        for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k) {
            if (cov.ball_samples[k] >= m) return fail(Code::invalid_input, "set cover: sample index out of range");
            if (k > cov.ball_ptr[a] && cov.ball_samples[k] <= cov.ball_samples[k - 1])
                return fail(Code::invalid_input, "set cover: ball sample list not strictly ascending");
        }
    }
    return Status::success();
}

// Cheap check that cov's sample -> ball direction can be trusted: right sizes, per-sample
// counts match the ball -> sample direction, lists ascending and in range.
bool transpose_consistent(const Coverage& cov) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (cov.sample_ptr.size() != m + 1 || cov.sample_ptr[0] != 0 || cov.sample_ptr[m] != cov.ball_samples.size() ||
        cov.sample_balls.size() != cov.ball_samples.size())
        return false;
    std::vector<uint32_t> cnt(m, 0);
    for (uint32_t j : cov.ball_samples) cnt[j]++;
    for (size_t j = 0; j < m; ++j) {
        if (cov.sample_ptr[j + 1] < cov.sample_ptr[j] || cov.sample_ptr[j + 1] - cov.sample_ptr[j] != cnt[j]) return false;
        for (uint32_t k = cov.sample_ptr[j]; k < cov.sample_ptr[j + 1]; ++k)
            if (cov.sample_balls[k] >= n || (k > cov.sample_ptr[j] && cov.sample_balls[k] <= cov.sample_balls[k - 1]))
                return false;
    }
    return true;
}

// Shared front part: checks, masks, uncoverable samples, reduction.
struct Prepared {
    std::vector<uint8_t> required, allowed, locked;
    std::vector<uint32_t> uncovered;
    size_t rows_before = 0, cols_before = 0;
};

Status prepare(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, Prepared& pr) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    Status st = check_coverage(cov);
    if (!st.ok()) return st;
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
    std::vector<uint8_t> reachable(m, 0);
    for (size_t a = 0; a < n; ++a)
        if (pr.allowed[a])
            for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k) reachable[cov.ball_samples[k]] = 1;
    for (uint32_t j = 0; j < m; ++j)
        if (pr.required[j] && !reachable[j]) pr.uncovered.push_back(j);
    if (!pr.uncovered.empty()) {
        if (!skip_uncoverable) return fail(Code::uncoverable, uncoverable_message(pr.uncovered, m));
        for (uint32_t j : pr.uncovered) pr.required[j] = 0;
    }
    for (uint8_t v : pr.required) pr.rows_before += v;
    for (uint8_t v : pr.allowed) pr.cols_before += v;
    return Status::success();
}

// Reduce to the fixpoint from the reducer's current state.
Status reduce_fixpoint(Reducer& red, const Monitor& monitor) {
    // Ball dominance only changes when sample sets change and vice versa: rerun a phase only
    // when the other one (or forcing) changed something. Ball dominance first: it usually
    // removes most columns, which makes every later phase cheap.
    bool need_balls = true, need_samples = true;
    for (;;) {
        if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");
        if (red.force_degree_one()) {
            red.rebuild();
            need_balls = need_samples = true;
            continue;
        }
        if (need_balls) {
            need_balls = false;
            if (red.ball_dominance()) {
                red.rebuild();
                need_samples = true;
            }
            continue;
        }
        if (need_samples) {
            need_samples = false;
            if (red.sample_dominance()) {
                red.rebuild();
                need_balls = true;
            }
            continue;
        }
        break;
    }
    return Status::success();
}

// Reduce to the fixpoint. On success `red` holds the forced balls and the kernel.
Status reduce(const Coverage& cov, const Prepared& pr, const Monitor& monitor, Reducer& red) {
    const size_t n = cov.n_balls;
    red.s_alive = pr.required;
    red.b_alive = pr.allowed;
    bool plain = cov.sample_ptr.size() == cov.n_samples + 1 && transpose_consistent(cov);
    for (size_t j = 0; j < cov.n_samples && plain; ++j) plain = pr.required[j] != 0;
    for (size_t a = 0; a < n && plain; ++a) plain = pr.allowed[a] && !pr.locked[a];
    red.init(cov, plain);
    bool any_forced_in = false;
    for (uint32_t a = 0; a < n; ++a)
        if (pr.locked[a]) {
            // select even if it covers nothing required (it was asked for)
            red.forced.push_back(a);
            red.b_alive[a] = 0;
            for (uint32_t k = red.bptr[a]; k < red.bptr[a + 1]; ++k) red.s_alive[red.bs[k]] = 0;
            any_forced_in = true;
        }
    if (any_forced_in) red.rebuild();
    return reduce_fixpoint(red, monitor);
}

// The reduction on a compact problem (every row required, every column allowed). `forced` gets
// P-local columns; the kernel's col_id / row_id are P-local too.
Status reduce_problem(const Problem& P, const Monitor& monitor, std::vector<uint32_t>& forced, Problem& kernel) {
    Coverage cov;
    cov.n_samples = P.R;
    cov.n_balls = P.C;
    cov.ball_ptr = P.cptr;
    cov.ball_samples = P.crow;
    cov.sample_ptr = P.rptr;
    cov.sample_balls = P.rcol;
    Reducer red(P.C, P.R);
    red.s_alive.assign(P.R, 1);
    red.b_alive.assign(P.C, 1);
    red.init(cov, true);
    Status st = reduce_fixpoint(red, monitor);
    if (!st.ok()) return st;
    forced = red.forced;
    kernel = make_kernel(red, P.C, P.R);
    return Status::success();
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

// Row generation (lazy covering constraints) on a reduced component K, looking for covers
// smaller than `target` (the incumbent's size; `best` below, lowered as better covers appear).
// Loop: take the sub-problem on a row subset R (start: a maximal set of rows pairwise sharing
// no column); reduce it; look for a cover of R smaller than `best`, first with the Lagrangian
// heuristic, else with CBC stopped at its first solution below the cutoff best - 0.5. A
// solution that covers all of K becomes the incumbent; otherwise it is repaired into a cover
// of K (greedy + redundancy removal) and up to kRowsPerRound spread-out rows it leaves
// uncovered join R. Stops when R has no cover smaller than `best`.
// Why the bounds are valid: a cover of K, restricted to the columns meeting R, covers R, so
// every lower bound on the optimum over R (Lagrangian, CBC bound, a finished CBC search that
// finds nothing below the cutoff) is one on K. Each round adds rows or lowers `best`, so the
// loop ends, and when it ends with "nothing below `best` on R", `best` is optimal for K.
struct RowGenOutcome {
    std::vector<uint32_t> sel;  // K-local cover smaller than `target` (ascending), or empty
    double lb = 0;              // lower bound on the optimum of K (at most the best size)
    bool proven = false;        // the best cover (sel, or if empty the incumbent) is optimal
    size_t rounds = 0;          // sub-problems solved
};

// Share of the remaining budget given to row generation before CBC takes the whole component.
constexpr double kRowGenShare = 0.25;
constexpr size_t kRowsPerRound = 64;

RowGenOutcome row_generation(const Problem& K, size_t target, Clock::time_point deadline, bool has_deadline,
                             int threads, const Monitor& monitor) {
    RowGenOutcome out;
    size_t best = target;
    std::vector<uint32_t> rows, all(K.R);
    for (uint32_t r = 0; r < K.R; ++r) all[r] = r;
    add_spread_rows(K, all, K.R, rows);  // a maximal set of rows pairwise sharing no column
    out.lb = double(rows.size());        // each needs its own column
    std::vector<uint8_t> covered(K.R);
    while (!monitor.cancelled()) {
        if (out.lb >= double(best)) { out.proven = true; break; }
        double remaining = 0;
        if (has_deadline) {
            remaining = std::chrono::duration<double>(deadline - Clock::now()).count();
            if (remaining <= 0) break;
        }
        ++out.rounds;
        const Problem S = restrict_rows(K, rows);
        std::vector<uint32_t> sforced;  // S-local
        Problem SK;                     // col_id / row_id S-local
        if (!reduce_problem(S, monitor, sforced, SK).ok()) break;
        if (sforced.size() >= best) { out.proven = true; break; }
        std::vector<uint32_t> x;  // K-local cover of R smaller than best
        for (uint32_t c : sforced) x.push_back(S.col_id[c]);
        if (SK.R > 0) {
            std::vector<uint32_t> g = greedy_cover(SK);
            remove_redundant(SK.cptr, SK.crow, SK.R, nullptr, nullptr, g);
            const Lagrange L = lagrangian(SK, g, 300, deadline);
            const double sub_lb = double(sforced.size()) + std::ceil(L.bound - 1e-6);
            out.lb = std::max(out.lb, std::min(double(best), sub_lb));
            if (sub_lb >= double(best)) { out.proven = true; break; }
            std::vector<uint32_t> sub;  // SK-local
            if (L.best.size() + sforced.size() < best) {
                sub = L.best;
            } else {
                CbcOutcome cbc;
                try {
                    cbc = run_cbc(SK, best - sforced.size(), has_deadline ? remaining : 0.0, threads, true);
                } catch (const std::bad_alloc&) {
                    throw;
                } catch (...) {
                    cbc = CbcOutcome{};
                }
                if (!cbc.ok) break;
                if (std::isfinite(cbc.bound))
                    out.lb = std::max(out.lb, std::min(double(best), double(sforced.size()) + std::ceil(cbc.bound - 1e-6)));
                if (!cbc.has_solution) {
                    if (cbc.proven) out.proven = true;  // nothing below the cutoff on R
                    break;                              // else: out of time
                }
                sub = cbc.solution;
            }
            for (uint32_t c : sub) x.push_back(S.col_id[SK.col_id[c]]);
        }
        std::sort(x.begin(), x.end());
        std::fill(covered.begin(), covered.end(), 0);
        for (uint32_t c : x)
            for (uint32_t k = K.cptr[c]; k < K.cptr[c + 1]; ++k) covered[K.crow[k]] = 1;
        std::vector<uint32_t> violated;
        for (uint32_t r = 0; r < K.R; ++r)
            if (!covered[r]) violated.push_back(r);
        if (violated.empty()) {
            best = x.size();
            out.sel = x;
            continue;
        }
        std::vector<uint32_t> full = greedy_complete(K, x);
        remove_redundant(K.cptr, K.crow, K.R, nullptr, nullptr, full);
        if (full.size() < best) {
            best = full.size();
            out.sel = full;
        }
        add_spread_rows(K, violated, kRowsPerRound, rows);
    }
    if (out.proven) out.lb = double(best);
    out.lb = std::min(out.lb, double(best));
    return out;
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

ComponentResult solve_component(const Problem& P, Clock::time_point deadline, bool has_deadline, int threads,
                                bool row_gen, const Monitor& monitor) {
    ComponentResult out;
    out.sel = greedy_cover(P);
    remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, out.sel);
    out.lb = double(disjoint_bound(P));
    auto done = [&]() {
        if (out.lb >= double(out.sel.size())) { out.lb = double(out.sel.size()); out.proven = true; }
        return out.proven;
    };
    if (done()) return out;
    // The subgradient phase gets at most a quarter of what is left of the budget.
    Clock::time_point lag_deadline = deadline;
    if (has_deadline) lag_deadline = Clock::now() + (deadline - Clock::now()) / 4;
    const Lagrange L = lagrangian(P, out.sel, 1000, lag_deadline);
    if (L.best.size() < out.sel.size()) out.sel = L.best;
    out.lb = std::max(out.lb, std::ceil(L.bound - 1e-6));
    if (done() || monitor.cancelled()) return out;

    // Covers smaller than the incumbent have value <= target; a column j with
    // L(u) + c_j(u) > target is in none of them.
    const double target = double(out.sel.size()) - 1.0;
    std::vector<uint8_t> keep(P.C, 0);
    for (uint32_t c = 0; c < P.C; ++c) keep[c] = L.bound + std::max(0.0, L.cost[c]) <= target + 1e-6;
    const Problem Q = restrict_columns(P, keep);
    for (uint32_t r = 0; r < Q.R; ++r)
        if (Q.rptr[r] == Q.rptr[r + 1]) { out.lb = double(out.sel.size()); out.proven = true; return out; }
    std::vector<uint32_t> qforced;
    Problem K;
    if (!reduce_problem(Q, monitor, qforced, K).ok()) return out;
    auto to_p = [&](uint32_t kcol) { return Q.col_id[K.col_id[kcol]]; };
    const size_t inc = out.sel.size();
    if (qforced.size() >= inc) { out.lb = double(inc); out.proven = true; return out; }
    if (K.R == 0) {  // the forced columns alone cover everything: smaller than the incumbent
        out.sel.clear();
        for (uint32_t c : qforced) out.sel.push_back(Q.col_id[c]);
        std::sort(out.sel.begin(), out.sel.end());
        out.lb = double(out.sel.size());
        out.proven = true;
        return out;
    }
    double remaining = 0;
    if (has_deadline) {
        remaining = std::chrono::duration<double>(deadline - Clock::now()).count();
        if (remaining <= 0) return out;
    }
    out.used_cbc = true;
    // Covers of K smaller than kbest are sought; klb is a lower bound on K's optimum.
    size_t kbest = inc - qforced.size();
    double klb = 0;
    auto take = [&](const std::vector<uint32_t>& ksol) {
        out.sel.clear();
        for (uint32_t c : qforced) out.sel.push_back(Q.col_id[c]);
        for (uint32_t c : ksol) out.sel.push_back(to_p(c));
        std::sort(out.sel.begin(), out.sel.end());
        kbest = ksol.size();
    };
    if (row_gen) {
        // Row generation first, with part of the budget; if it does not finish, one CBC solve
        // of the whole of K takes over with its incumbent.
        Clock::time_point rg_deadline = deadline;
        if (has_deadline)
            rg_deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>((deadline - Clock::now()) * kRowGenShare);
        const RowGenOutcome rg = row_generation(K, kbest, rg_deadline, has_deadline, threads, monitor);
        out.rowgen_rounds = rg.rounds;
        if (!rg.sel.empty()) take(rg.sel);
        klb = rg.lb;
        if (rg.proven) klb = double(kbest);
        if (klb >= double(kbest) || monitor.cancelled()) {
            // every cover below the old incumbent lies in K (+ forced)
            out.lb = std::max(out.lb, std::min(double(out.sel.size()), double(qforced.size()) + klb));
            done();
            return out;
        }
        if (has_deadline) {
            remaining = std::chrono::duration<double>(deadline - Clock::now()).count();
            if (remaining <= 0) {
                out.lb = std::max(out.lb, std::min(double(out.sel.size()), double(qforced.size()) + klb));
                done();
                return out;
            }
        }
    }
    CbcOutcome cbc;
    try {
        cbc = run_cbc(K, kbest, has_deadline ? remaining : 0.0, threads);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (...) {
        cbc = CbcOutcome{};  // CBC failure: keep the incumbent
    }
    if (cbc.ok && cbc.has_solution) take(cbc.solution);
    const double obj = double(out.sel.size());
    if (cbc.ok && cbc.proven) {
        out.lb = obj;
        out.proven = true;
    } else {
        if (cbc.ok && std::isfinite(cbc.bound)) klb = std::max(klb, std::ceil(cbc.bound - 1e-6));
        // every cover below the old incumbent lies in K (+ forced): optimum >= min(obj, forced + klb)
        out.lb = std::max(out.lb, std::min(obj, double(qforced.size()) + klb));
    }
    done();
    return out;
}

Status solve_impl(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, const Monitor& monitor,
                  CoverResult& result) {
    const auto t0 = Clock::now();
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (opt.solver != Solver::exact && opt.solver != Solver::greedy && opt.solver != Solver::capp)
        return fail(Code::invalid_argument, "set cover: unknown solver");
    if (std::isnan(opt.time_limit_s)) return fail(Code::invalid_argument, "set cover: time limit is NaN");
    if (opt.solver == Solver::capp) {
        if (!opt.centers || !opt.radii || opt.centers->size() != n || opt.radii->size() != n)
            return fail(Code::invalid_argument, "set cover: the capp solver needs centers and radii for every ball");
        for (size_t a = 0; a < n; ++a) {
            const Vec3& c = (*opt.centers)[a];
            if (!std::isfinite(c.x()) || !std::isfinite(c.y()) || !std::isfinite(c.z()) ||
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
    if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");

    Reducer red(n, m);
    st = reduce(cov, pr, monitor, red);
    if (!st.ok()) return st;
    const Problem P = make_kernel(red, n, m);
    result.rows_after = P.R;
    result.cols_after = P.C;
    result.forced = red.forced.size();
    result.time_reduce_s = seconds_since(t0);
    if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");

    // Kernel solve.
    const auto t1 = Clock::now();
    std::vector<uint32_t> ksel;
    double klb = P.R > 0 ? double(disjoint_bound(P)) : 0.0;
    bool proven = false;
    if (opt.solver == Solver::capp) {
        ksel = capp_cover(P, *opt.centers, *opt.radii, red.forced);
        remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, ksel);
    } else {
        if (opt.solver == Solver::exact) {
            const bool has_deadline = opt.time_limit_s > 0 && std::isfinite(opt.time_limit_s);
            const auto deadline = has_deadline ? t0 + std::chrono::duration_cast<Clock::duration>(
                                                          std::chrono::duration<double>(opt.time_limit_s))
                                               : Clock::time_point::max();
            proven = true;
            klb = 0;
            for (const Problem& Q : split_components(P)) {
                if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");
                const ComponentResult cr = solve_component(Q, deadline, has_deadline, opt.threads, opt.row_generation, monitor);
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
    std::vector<uint32_t> sel = red.forced;
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
    result.lower_bound = std::min(result.objective, double(red.forced.size()) + klb);
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
    try {
        Prepared pr;
        Status st = prepare(cov, opt, skip_uncoverable, pr);
        if (!st.ok()) return st;
        Reducer red(cov.n_balls, cov.n_samples);
        st = reduce(cov, pr, monitor, red);
        if (!st.ok()) return st;
        const Problem P = make_kernel(red, cov.n_balls, cov.n_samples);
        forced = red.forced;
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
    } catch (const std::bad_alloc&) {
        return fail(Code::out_of_memory, "set cover: out of memory");
    } catch (...) {
        return fail(Code::internal, "set cover: unexpected exception");
    }
}
}  // namespace detail

Status solve_set_cover(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, const Monitor& monitor,
                       CoverResult& result) {
    result = CoverResult{};
    try {
        return solve_impl(cov, opt, skip_uncoverable, monitor, result);
    } catch (const std::bad_alloc&) {
        return fail(Code::out_of_memory, "set cover: out of memory");
    } catch (...) {
        return fail(Code::internal, "set cover: unexpected exception");
    }
}

}  // namespace ca
