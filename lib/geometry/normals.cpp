// normals.cpp: PCA normal estimation, minimum-spanning-tree orientation and the sign-disagreement
// check (normals.h).
#include "normals.h"

#include "kdtree.h"
#include "patch_signs.h"
#include "union_find.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <queue>

namespace ca {

bool fit_plane(const std::vector<Vec3>& pts, const size_t* idx, size_t count, Vec3& mean, Vec3& normal) {
    mean = Vec3::Zero();
    if (count == 0) return false;
    for (size_t j = 0; j < count; ++j) mean += pts[idx[j]];
    mean /= double(count);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (size_t j = 0; j < count; ++j) cov += (pts[idx[j]] - mean) * (pts[idx[j]] - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    const Vec3 n = es.eigenvectors().col(0);
    if (!(n.allFinite() && n.norm() > 0)) return false;
    normal = n.normalized();
    return true;
}

std::vector<Vec3> estimate_normals(const std::vector<Vec3>& pts, size_t k, int threads) {
    std::vector<Vec3> normals(pts.size(), Vec3(0, 0, 1));
    if (pts.size() < 3) return normals;
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double*, size_t found) {
        Vec3 mean, n;
        if (fit_plane(pts, idx, found, mean, n)) normals[i] = n;
    }, threads);
    return normals;
}

namespace {

// A pair facing across: the offset d = p_b - p_a well out of both tangent planes
// (|d . n| > 0.35 |d| for both normals: more than 20 degrees out), as across a thin part, a crease or a sharp edge. Other
// pairs lie side by side on a smooth part (|d . n| is about |d|^2 times the curvature).
constexpr double kFacing = 0.35;

bool facing(const Vec3& d, const Vec3& a, const Vec3& b) {
    const double len = d.norm();
    return std::abs(d.dot(a)) > kFacing * len && std::abs(d.dot(b)) > kFacing * len;
}

// Whether the signs of n_a and n_b agree (d = p_b - p_a): side by side, the normals point the same
// way; facing across, each point lies behind the other's tangent plane (outward normals) or each
// in front of it (inward ones), which flipping one normal of the pair breaks.
bool agrees(const Vec3& d, const Vec3& a, const Vec3& b) {
    return facing(d, a, b) ? d.dot(a) * d.dot(b) < 0 : a.dot(b) >= 0;
}

// Below the facing threshold but above this (|d . n| > |d| / 20 for both normals), a pair whose
// two rules disagree is uncertain: a concave part where the normals point the same way, or a
// sharp edge seen from the side where they face away.
constexpr double kUncertain = 0.05;

bool uncertain(const Vec3& d, const Vec3& a, const Vec3& b) {
    const double len = d.norm(), da = d.dot(a), db = d.dot(b);
    return !facing(d, a, b) && std::abs(da) > kUncertain * len && std::abs(db) > kUncertain * len &&
           (a.dot(b) >= 0) != (da * db < 0);
}

// Estimated normals: an uncertain pair counts as one only between normals within this |cosine|
// (about 18 degrees), the pair across a sheet thinner than PCA's neighbourhoods (both sides get
// the sheet's normal, and the offset is a few degrees out of it). Elsewhere PCA's normals tilt
// with the sampling on detailed parts, and the same rule would mark side-by-side pairs there.
constexpr double kEstimatedUncertainCos = 0.95;

// 1 - |n_u . n_v|; 2 more for an uncertain pair, so the tree takes one only where nothing else
// joins its two ends.
double edge_weight(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, uint32_t u, uint32_t v,
                   bool estimated) {
    const double c = std::abs(normals[u].dot(normals[v])), w = 1.0 - c;
    const bool counts = !estimated || c > kEstimatedUncertainCos;
    return counts && uncertain(pts[u] - pts[v], normals[u], normals[v]) ? w + 2.0 : w;
}

}  // namespace

namespace {

// A tree edge that propagation may have taken the wrong way round: between normals more than
// 60 degrees apart (weight 1 - |n_u . n_v| above this), a pair facing across (a thin part, a
// crease: the facing rule is only as good as the sampling there, and estimated normals average
// across creases), or an uncertain pair. Patches are cut there and each is signed as a whole
// by the winding-number vote instead (patch_signs.h), which sees the entire cloud.
constexpr double kCutWeight = 0.5;
// Patches below max(this, n / 200) points are joined to a neighbouring patch.
constexpr size_t kMinPatch = 32;

bool unreliable(const Vec3& d, const Vec3& a, const Vec3& b) {
    return 1.0 - std::abs(a.dot(b)) > kCutWeight || facing(d, a, b) || uncertain(d, a, b);
}

// Patches of the propagation tree (parent[v] == v: a root) cut at its unreliable edges; patches
// smaller than `min_size` points are joined back across their cut edges (lightest first), since
// too few points carry too little winding number to be signed on their own. Returns the count.
size_t tree_patches(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, const std::vector<uint32_t>& parent,
                    size_t min_size, std::vector<uint32_t>& label) {
    const size_t n = pts.size();
    UnionFind uf(n);
    std::vector<std::pair<double, uint32_t>> cut;   // (weight, child)
    for (uint32_t v = 0; v < n; ++v) {
        const uint32_t p = parent[v];
        if (p == v) continue;
        if (unreliable(pts[v] - pts[p], normals[p], normals[v]))
            cut.push_back({1.0 - std::abs(normals[p].dot(normals[v])), v});
        else
            uf.unite(v, p);
    }
    std::vector<size_t> size(n, 0);
    for (uint32_t v = 0; v < n; ++v) ++size[uf.find(v)];
    std::sort(cut.begin(), cut.end());
    for (bool joined = true; joined;) {
        joined = false;
        for (const auto& [w, v] : cut) {
            const uint32_t a = uf.find(v), b = uf.find(parent[v]);
            if (a == b || (size[a] >= min_size && size[b] >= min_size)) continue;
            uf.unite(a, b);
            size[uf.find(a)] = size[a] + size[b];
            joined = true;
        }
    }
    label.assign(n, 0);
    std::vector<uint32_t> id(n, UINT32_MAX);
    size_t count = 0;
    for (uint32_t v = 0; v < n; ++v) {
        const uint32_t r = uf.find(v);
        if (id[r] == UINT32_MAX) id[r] = uint32_t(count++);
        label[v] = id[r];
    }
    return count;
}

}  // namespace

void orient_normals(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, size_t k, bool estimated, int threads) {
    const size_t n = pts.size();
    if (n < 2 || normals.size() != n) return;
    // the searches in parallel (each point fills its own row), the symmetric graph in point order
    const size_t want = std::min(k + 1, n);
    std::vector<uint32_t> knn(n * want);
    std::vector<uint32_t> found_at(n, 0);
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double*, size_t found) {
        for (size_t j = 0; j < found; ++j) knn[i * want + j] = uint32_t(idx[j]);
        found_at[i] = uint32_t(found);
    }, threads);
    std::vector<std::vector<uint32_t>> adj(n);
    for (uint32_t i = 0; i < n; ++i)
        for (size_t j = 0; j < found_at[i]; ++j) {
            const uint32_t o = knn[i * want + j];
            if (o != i) adj[i].push_back(o), adj[o].push_back(i);
        }
    // roots: the highest unvisited point first
    std::vector<uint32_t> by_height(n);
    for (uint32_t i = 0; i < n; ++i) by_height[i] = i;
    std::sort(by_height.begin(), by_height.end(), [&](uint32_t a, uint32_t b) {
        return pts[a].z() != pts[b].z() ? pts[a].z() > pts[b].z() : a < b;
    });
    std::vector<uint8_t> done(n, 0);
    std::vector<uint32_t> parent(n);
    using Item = std::pair<double, std::pair<uint32_t, uint32_t>>;   // (weight, (point, parent))
    for (uint32_t root : by_height) {
        if (done[root]) continue;
        if (normals[root].z() < 0) normals[root] = -normals[root];
        // Prim's algorithm from root; a point's sign is fixed when it joins the tree
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
        heap.push({0.0, {root, root}});
        while (!heap.empty()) {
            const auto [w, e] = heap.top();
            heap.pop();
            const uint32_t v = e.first, p = e.second;
            if (done[v]) continue;
            done[v] = 1;
            parent[v] = p;
            if (v != p && !agrees(pts[v] - pts[p], normals[p], normals[v])) normals[v] = -normals[v];
            for (uint32_t u : adj[v])
                if (!done[u]) heap.push({edge_weight(pts, normals, u, v, estimated), {u, v}});
        }
    }
    // the global step: each patch of the tree signed by the winding-number vote
    std::vector<uint32_t> label;
    const size_t count = tree_patches(pts, normals, parent, std::max<size_t>(kMinPatch, n / 200), label);
    vote_patch_signs(pts, normals, label, count, threads);
}

double sign_disagreement(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, size_t k, int threads) {
    if (pts.size() < 2 || normals.size() != pts.size()) return 0;
    // per point (its own slot), summed afterwards
    std::vector<uint32_t> counted_at(pts.size(), 0), against_at(pts.size(), 0);
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double*, size_t found) {
        for (size_t j = 0; j < found; ++j) {
            if (idx[j] == i) continue;
            const Vec3 d = pts[idx[j]] - pts[i];
            if (!(d.squaredNorm() > 0)) continue;
            ++counted_at[i];
            against_at[i] += !agrees(d, normals[i], normals[idx[j]]);
        }
    }, threads);
    size_t counted = 0, against = 0;
    for (size_t i = 0; i < pts.size(); ++i) counted += counted_at[i], against += against_at[i];
    return counted ? double(against) / double(counted) : 0.0;
}

}  // namespace ca
