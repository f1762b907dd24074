// row_generation.cpp: row generation (lazy covering constraints) for one component of the kernel:
// sub-problems on growing row subsets, solved by the Lagrangian heuristic or CBC, until a
// sub-problem proves the best cover optimal.
#include "setcover_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ca {
namespace sc {


constexpr size_t kRowsPerRound = 64;

RowGenOutcome row_generation(const Problem& K, size_t target, const Deadline& deadline,
                             int threads, const Monitor& monitor) {
    RowGenOutcome out;
    size_t best = target;
    std::vector<uint32_t> rows;
    add_spread_rows(K, all_rows(K), K.R, rows);  // a maximal set of rows pairwise sharing no column
    out.lb = double(rows.size());        // each needs its own column
    std::vector<uint8_t> covered(K.R);
    while (!monitor.cancelled()) {
        if (out.lb >= double(best)) { out.proven = true; break; }
        const double remaining = deadline.limit_s();  // 0 = no limit
        if (deadline.limited() && remaining <= 0) break;
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
                CbcSettings cs;
                cs.time_limit_s = remaining;
                cs.threads = threads;
                cs.first_solution = true;
                const CbcOutcome cbc = run_cbc(SK, best - sforced.size(), cs);
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

}  // namespace sc
}  // namespace ca
