// patch_signs.cpp: one sign per patch chosen by the winding-number vote (patch_signs.h). The
// winding number is summed directly (no tree): per patch, its contribution at each probe, so
// the quadratic form over the signs is exact; the probes are a subset of the points.
#include "patch_signs.h"

#include "kdtree.h"
#include "parallel.h"
#include "point_winding.h"

#include <algorithm>
#include <cmath>

namespace ca {
namespace {

constexpr double kFourPi = 4.0 * 3.14159265358979323846;
// At most this many probe points (every step-th point), so the direct sum costs at most
// 2 x this many dipoles per point.
constexpr size_t kMaxProbes = 2000;
// Probes sit this fraction of the point's 8th-neighbour distance to either side: a distance
// at which the points' dipoles act as a surface, yet inside thin parts sampled a few points across.
constexpr double kProbeDepth = 0.5;

// Greedy descent on E(s) = s'Gs - h's from `s`: negates the patch that lowers E most until none does.
double descend(const std::vector<double>& G, const std::vector<double>& h, size_t m, std::vector<int>& s) {
    std::vector<double> g(m, 0.0);   // g_q = sum over r != q of G_qr s_r
    for (size_t q = 0; q < m; ++q)
        for (size_t r = 0; r < m; ++r)
            if (r != q) g[q] += G[q * m + r] * s[r];
    for (size_t iter = 0; iter < 4 * m + 4; ++iter) {
        size_t best = m;
        double gain = -1e-12;
        for (size_t q = 0; q < m; ++q) {
            const double d = s[q] * (2.0 * h[q] - 4.0 * g[q]);   // E(s with s_q negated) - E(s)
            if (d < gain) gain = d, best = q;
        }
        if (best == m) break;
        s[best] = -s[best];
        for (size_t q = 0; q < m; ++q)
            if (q != best) g[q] += 2.0 * G[q * m + best] * s[best];
    }
    double e = 0;
    for (size_t q = 0; q < m; ++q) {
        e -= h[q] * s[q];
        for (size_t r = 0; r < m; ++r) e += G[q * m + r] * s[q] * s[r];
    }
    return e;
}


// M[q * probes + k]: patch q's mean winding number at probe k (just inside and just outside).
std::vector<double> patch_means(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals,
                                const std::vector<uint32_t>& patch, size_t m, size_t& np, int threads) {
    const size_t n = pts.size();
    const std::vector<double> areas = tangent_voronoi_areas(pts, normals, 20, threads);
    const size_t step = std::max<size_t>(1, (n + kMaxProbes - 1) / kMaxProbes);
    std::vector<double> depth(n, 0.0);
    for_each_neighbourhood(pts, 8, [&](size_t i, const size_t*, const double* d2, size_t found) {
        if (i % step == 0 && found) depth[i] = kProbeDepth * std::sqrt(d2[found - 1]);
    }, threads);
    std::vector<size_t> probes;
    for (size_t i = 0; i < n; i += step)
        if (depth[i] > 0) probes.push_back(i);
    np = probes.size();
    std::vector<double> M(m * np, 0.0);
    // each probe fills its own column of M
    parallel_for(np, threads, np, Monitor{}, "patch signs", [&](size_t begin, size_t end) {
        std::vector<double> acc(m);
        for (size_t k = begin; k < end; ++k) {
            const size_t i = probes[k];
            const Vec3 a = pts[i] + depth[i] * normals[i], b = pts[i] - depth[i] * normals[i];
            std::fill(acc.begin(), acc.end(), 0.0);
            for (size_t j = 0; j < n; ++j) {
                const Vec3 ra = pts[j] - a, rb = pts[j] - b;
                const double la = ra.squaredNorm(), lb = rb.squaredNorm();
                double v = 0;
                if (la > 0) v += ra.dot(normals[j]) / (la * std::sqrt(la));
                if (lb > 0) v += rb.dot(normals[j]) / (lb * std::sqrt(lb));
                acc[patch[j]] += areas[j] * v;
            }
            for (size_t q = 0; q < m; ++q) M[q * np + k] = acc[q] / (2.0 * kFourPi);
        }
    });
    return M;
}

}  // namespace

double winding_residual(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, int threads) {
    if (pts.size() < 3 || normals.size() != pts.size()) return 0;
    size_t np = 0;
    const std::vector<double> M = patch_means(pts, normals, std::vector<uint32_t>(pts.size(), 0), 1, np, threads);
    double outward = 0, inward = 0;
    for (double w : M) outward += (w - 0.5) * (w - 0.5), inward += (w + 0.5) * (w + 0.5);
    return np ? std::min(outward, inward) / double(np) : 0.0;
}

size_t vote_patch_signs(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, const std::vector<uint32_t>& patch,
                        size_t count, int threads) {
    const size_t n = pts.size();
    if (count < 2 || n < 3 || normals.size() != n || patch.size() != n) return 0;
    const size_t m = count;
    size_t np = 0;
    const std::vector<double> M = patch_means(pts, normals, patch, m, np, threads);
    // E(s) = sum_k (sum_q s_q M_qk - 1/2)^2 = s'Gs - h's + const; row q writes h_q and G_qr, G_rq
    // for r >= q only (rows interleaved across threads: later rows are shorter)
    std::vector<double> G(m * m, 0.0), h(m, 0.0);
    const size_t workers = std::min<size_t>(size_t(std::max(1, threads)), m);
    run_workers(workers, [&](size_t w) {
        for (size_t q = w; q < m; q += workers) {
            const double* mq = &M[q * np];
            for (size_t k = 0; k < np; ++k) h[q] += mq[k];
            for (size_t r = q; r < m; ++r) {
                const double* mr = &M[r * np];
                double dot = 0;
                for (size_t k = 0; k < np; ++k) dot += mq[k] * mr[k];
                G[q * m + r] = G[r * m + q] = dot;
            }
        }
    });
    // from the propagated signs, and from all of them negated (the whole cloud inward)
    std::vector<int> s(m, 1), t(m, -1);
    const double es = descend(G, h, m, s), et = descend(G, h, m, t);
    if (et < es) s = t;
    size_t negated = 0;
    for (size_t q = 0; q < m; ++q) negated += s[q] < 0;
    for (size_t i = 0; i < n; ++i)
        if (s[patch[i]] < 0) normals[i] = -normals[i];
    return negated;
}

}  // namespace ca
