// setcover.cpp: minimum set cover of the samples by the candidate balls (see setcover.h): the
// reduction (on the input and on compact problems) and the solve driver. Building blocks are in
// setcover_problem.cpp, the exact machinery in setcover_exact.cpp (setcover_internal.h).
//
// Pipeline: input checks -> reduction to a fixpoint (forced balls, degree-1 samples, dominated
// samples, dominated balls, empty balls; after one complete pass of each dominance test only
// the balls / samples whose lists shrank are tested again) -> kernel solve -> redundancy
// removal -> verification.
// Exact kernel solve, per connected component of the kernel (components share no rows and no
// columns, so optima and bounds add): greedy cover -> Lagrangian subgradient (bound, and a
// reduced-cost greedy that improves the incumbent) -> if that leaves a gap, the LP relaxation's
// duals (Clp) as multipliers, with small subgradient steps around them for the greedy ->
// done if ceil(bound) meets the incumbent; otherwise row-weighting local search
// (setcover_local.cpp, a quarter of the remaining budget) for a better incumbent, then
// reduced-cost fixing (drop every column that no cover smaller than the incumbent can
// contain), reduction again, and CBC on what is left with the incumbent as cutoff and CBC's
// own heuristics off (it only has to prove). With the fast effort (the default) CBC runs only
// when one ball separates incumbent and bound on a small kernel, with a node limit (see Effort);
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
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <queue>
#include <string>

namespace ca {

namespace sc {

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
    // Records what changed for the incremental dominance passes: an alive ball that lost a
    // sample is dirty for ball dominance, an alive sample that lost a ball (a ball of its list
    // died) is dirty for sample dominance.
    void rebuild() {
        dirty_b_.resize(n_, 0);
        dirty_s_.resize(m_, 0);
        std::vector<uint32_t> nptr(n_ + 1, 0), ns;
        ns.reserve(bptr[n_]);
        for (size_t a = 0; a < n_; ++a) {
            if (b_alive[a]) {
                for (uint32_t k = bptr[a]; k < bptr[a + 1]; ++k)
                    if (s_alive[bs[k]]) ns.push_back(bs[k]);
                if (balls_full_ && ns.size() - nptr[a] < bsize(uint32_t(a))) dirty_b_[a] = 1;
            } else if (samples_full_) {  // before the first complete pass nothing is tracked
                for (uint32_t k = bptr[a]; k < bptr[a + 1]; ++k) dirty_s_[bs[k]] = 1;
            }
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
        if (samples_full_) return sample_dominance_dirty();
        samples_full_ = true;
        dirty_s_.assign(m_, 0);
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
        if (balls_full_) return ball_dominance_dirty();
        balls_full_ = true;
        dirty_b_.assign(n_, 0);
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

    // After a complete pass no alive sample dominates another. A pair (k, j) can only become
    // one (balls(k) ⊆ balls(j)) when k loses a ball, so the later passes test only the dirty
    // samples k as dominators, against the samples j of k's rarest ball (j must contain it).
    bool sample_dominance_dirty() {
        bool any = false;
        for (uint32_t k = 0; k < m_; ++k) {
            if (!dirty_s_[k]) continue;
            dirty_s_[k] = 0;
            if (!s_alive[k] || sdeg(k) == 0) continue;
            const uint32_t* lk = &sb[sptr[k]];
            const uint32_t dk = sdeg(k);
            uint32_t rare = lk[0];
            for (uint32_t e = 1; e < dk; ++e)
                if (bsize(lk[e]) < bsize(rare)) rare = lk[e];
            for (uint32_t q = bptr[rare]; q < bptr[rare + 1]; ++q) {
                const uint32_t j = bs[q];
                if (j == k || !s_alive[j] || sdeg(j) < dk) continue;
                if (!sorted_subset(lk, dk, &sb[sptr[j]], sdeg(j))) continue;
                any = true;
                if (sdeg(j) > dk || k < j) {
                    s_alive[j] = 0;  // k dominates j
                } else {
                    s_alive[k] = 0;  // equal sets: the lower index j stays
                    break;
                }
            }
        }
        return any;
    }

    // Same for balls: a pair (a, b) can only become one (samples(a) ⊆ samples(b)) when a loses
    // a sample, so the later passes test only the dirty balls a, against the balls b of a's
    // rarest sample.
    bool ball_dominance_dirty() {
        bool any = false;
        for (uint32_t a = 0; a < n_; ++a) {
            if (!dirty_b_[a]) continue;
            dirty_b_[a] = 0;
            if (!b_alive[a] || bsize(a) == 0) continue;
            const uint32_t* la = &bs[bptr[a]];
            const uint32_t na = bsize(a);
            uint32_t rare = la[0];
            for (uint32_t e = 1; e < na; ++e)
                if (sdeg(la[e]) < sdeg(rare)) rare = la[e];
            for (uint32_t q = sptr[rare]; q < sptr[rare + 1]; ++q) {
                const uint32_t b = sb[q];
                if (b == a || !b_alive[b] || bsize(b) < na) continue;
                if (bsize(b) == na && b > a) continue;  // equal sets: the lower index stays
                if (!sorted_subset(la, na, &bs[bptr[b]], bsize(b))) continue;
                b_alive[a] = 0;
                any = true;
                break;
            }
        }
        return any;
    }

private:
    // x[0..nx) ⊆ y[0..ny), both ascending: galloping merge.
    static bool sorted_subset(const uint32_t* x, uint32_t nx, const uint32_t* y, uint32_t ny) {
        if (nx > ny) return false;
        const uint32_t* yi = y;
        const uint32_t* ye = y + ny;
        for (uint32_t i = 0; i < nx; ++i) {
            yi = std::lower_bound(yi, ye, x[i]);
            if (yi == ye || *yi != x[i]) return false;
            ++yi;
            if (uint32_t(ye - yi) < nx - i - 1) return false;
        }
        return true;
    }

    bool balls_full_ = false, samples_full_ = false;
    std::vector<uint8_t> dirty_b_, dirty_s_;

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

}  // namespace sc

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
}  // namespace

namespace sc {

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

}  // namespace sc

namespace {

using namespace sc;

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
// Independent local-search runs (seeds kLocalSearchSeed, +1, ...): on the paper kernels the
// best of 4 is 1-2 balls smaller than one run on cup, desk_table and bird_penguin.
constexpr int kLocalSearchStarts = 4;

// Largest component CBC solves as a whole (its root LP cannot be interrupted).
constexpr uint32_t kWholeCbcMaxRows = 4000;
// Subgradient steps before the LP on components up to kWholeCbcMaxRows rows.
constexpr int kSubgradientWarmup = 50;

ComponentResult solve_component(const Problem& P, Clock::time_point deadline, bool has_deadline, int threads,
                                bool row_gen, Effort effort, int search_threads, const Monitor& monitor) {
    ComponentResult out;
    out.sel = greedy_cover(P);
    remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, out.sel);
    out.lb = double(disjoint_bound(P));
    auto done = [&]() {
        if (out.lb >= double(out.sel.size())) { out.lb = double(out.sel.size()); out.proven = true; }
        return out.proven;
    };
    if (done()) return out;
    // The subgradient phase gets at most a quarter of what is left of the budget, then the LP
    // relaxation's duals (the best Lagrangian multipliers) tighten the bound and the reduced
    // costs for fixing when the subgradient bound did not close the gap.
    Clock::time_point lag_deadline = deadline;
    if (has_deadline) lag_deadline = Clock::now() + (deadline - Clock::now()) / 4;
    // Before the LP only a short warm-up (its covers and reduced costs seed the core LP and the
    // local search: 1000 steps instead cost 0.1-0.3 s and changed no result on the paper models
    // once the local search runs from several seeds); components too large for a sure LP get
    // the long ascent, whose bound may have to stand alone.
    const int subgradient_steps = P.R <= kWholeCbcMaxRows ? kSubgradientWarmup : 1000;
    Lagrange L = lagrangian(P, out.sel, subgradient_steps, lag_deadline);
    bool lp_ok = P.R <= kWholeCbcMaxRows;  // the LP is not needed when the subgradient closes the gap
    if (std::ceil(L.bound - 1e-6) < double(L.best.size()) && !monitor.cancelled()) {
        double lp_limit = 0;
        if (has_deadline) lp_limit = std::max(1e-3, std::chrono::duration<double>(deadline - Clock::now()).count() / 4);
        const std::vector<double> duals = lp_duals_core(P, L.cost, lp_limit);
        lp_ok = !duals.empty();
        if (!duals.empty()) {
            // bound and costs at the duals, then small steps around them for the reduced-cost greedy
            Lagrange D = lagrangian(P, L.best, 200, deadline, &duals, 0.05);
            std::vector<uint32_t> best = D.best.size() < L.best.size() ? D.best : L.best;
            if (D.bound > L.bound) L = std::move(D);
            L.best = std::move(best);
        }
    }
    if (L.best.size() < out.sel.size()) out.sel = L.best;
    out.lb = std::max(out.lb, std::ceil(L.bound - 1e-6));
    if (done() || monitor.cancelled()) return out;
    // Row-weighting local search from the best cover, with at most a quarter of what is left:
    // usually reaches the optimum, so that CBC only has to prove it.
    {
        Clock::time_point ls_deadline = deadline;
        if (has_deadline) ls_deadline = Clock::now() + (deadline - Clock::now()) / 4;
        out.sel = local_search_multi(P, out.sel, size_t(out.lb), kLocalSearchSteps, kLocalSearchSeed, kLocalSearchStarts,
                                     resolve_threads(search_threads), ls_deadline);
        if (done() || monitor.cancelled()) return out;
    }

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
    // Fast effort: CBC only for a one-ball gap on a small kernel, with a node limit.
    const bool fast = effort == Effort::fast;
    if (fast && (double(inc) - out.lb > 1.0 || K.R > kFastCbcMaxRows)) return out;
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
    // CBC's root LP ignores its time limit; on a component whose LP Clp could not solve within
    // its share, or one with more than kWholeCbcMaxRows rows, CBC never gets the whole of it:
    // row generation (small sub-problems) keeps the budget.
    const bool whole_cbc = lp_ok && K.R <= kWholeCbcMaxRows;
    if (!fast && (row_gen || !whole_cbc)) {
        // Row generation first, with part of the budget; if it does not finish, one CBC solve
        // of the whole of K takes over with its incumbent.
        Clock::time_point rg_deadline = deadline;
        if (has_deadline && whole_cbc)
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
        if (!whole_cbc) {
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
        cbc = run_cbc(K, kbest, has_deadline ? remaining : 0.0, threads, false, false, fast ? kFastCbcNodes : 0);
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
    if (opt.effort != Effort::fast && opt.effort != Effort::prove)
        return fail(Code::invalid_argument, "set cover: unknown effort");
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
                const ComponentResult cr =
                    solve_component(Q, deadline, has_deadline, opt.threads, opt.row_generation, opt.effort,
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
