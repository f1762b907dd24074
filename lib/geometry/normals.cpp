// normals.cpp: PCA normal estimation, minimum-spanning-tree orientation and the sign-disagreement
// check (normals.h).
#include "normals.h"

#include "kdtree.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <queue>

namespace ca {

std::vector<Vec3> estimate_normals(const std::vector<Vec3>& pts, size_t k) {
    std::vector<Vec3> normals(pts.size(), Vec3(0, 0, 1));
    if (pts.size() < 3) return normals;
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double*, size_t found) {
        Vec3 mean = Vec3::Zero();
        for (size_t j = 0; j < found; ++j) mean += pts[idx[j]];
        mean /= double(found);
        Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
        for (size_t j = 0; j < found; ++j) cov += (pts[idx[j]] - mean) * (pts[idx[j]] - mean).transpose();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
        const Vec3 n = es.eigenvectors().col(0);
        if (n.allFinite() && n.norm() > 0) normals[i] = n.normalized();
    });
    return normals;
}

namespace {

// Side by side on the surface: the offset within 30 degrees of both tangent planes,
// |d . n| <= sin(30 degrees) |d| (the rule sign_disagreement counts by).
constexpr double kMaxSine = 0.5;

bool side_by_side(const Vec3& d, const Vec3& a, const Vec3& b) {
    const double len = d.norm();
    return len > 0 && std::abs(d.dot(a)) <= kMaxSine * len && std::abs(d.dot(b)) <= kMaxSine * len;
}

// 1 - |n_u . n_v| for neighbours side by side; 2 more for a pair across a thin part (the offset
// along a normal, where the true normals are opposite while parallel up to sign), so the tree
// crosses a thin part only where nothing else joins its two sides.
double edge_weight(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, uint32_t u, uint32_t v) {
    const double w = 1.0 - std::abs(normals[u].dot(normals[v]));
    return side_by_side(pts[u] - pts[v], normals[u], normals[v]) ? w : w + 2.0;
}

}  // namespace

void orient_normals(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, size_t k) {
    const size_t n = pts.size();
    if (n < 2 || normals.size() != n) return;
    std::vector<std::vector<uint32_t>> adj(n);
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double*, size_t found) {
        for (size_t j = 0; j < found; ++j)
            if (idx[j] != i) adj[i].push_back(uint32_t(idx[j])), adj[idx[j]].push_back(uint32_t(i));
    });
    // roots: the highest unvisited point first
    std::vector<uint32_t> by_height(n);
    for (uint32_t i = 0; i < n; ++i) by_height[i] = i;
    std::sort(by_height.begin(), by_height.end(), [&](uint32_t a, uint32_t b) {
        return pts[a].z() != pts[b].z() ? pts[a].z() > pts[b].z() : a < b;
    });
    std::vector<uint8_t> done(n, 0);
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
            const uint32_t v = e.first, parent = e.second;
            if (done[v]) continue;
            done[v] = 1;
            if (v != parent && normals[v].dot(normals[parent]) < 0) normals[v] = -normals[v];
            for (uint32_t u : adj[v])
                if (!done[u]) heap.push({edge_weight(pts, normals, u, v), {u, v}});
        }
    }
}

double sign_disagreement(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, size_t k) {
    if (pts.size() < 2 || normals.size() != pts.size()) return 0;
    size_t counted = 0, against = 0;
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double*, size_t found) {
        for (size_t j = 0; j < found; ++j) {
            if (idx[j] == i) continue;
            const Vec3 d = pts[idx[j]] - pts[i];
            const double len = d.norm();
            if (!(len > 0) || std::abs(d.dot(normals[i])) > kMaxSine * len) continue;
            ++counted;
            against += normals[i].dot(normals[idx[j]]) < 0;
        }
    });
    return counted ? double(against) / double(counted) : 0.0;
}

}  // namespace ca
