// normals.cpp: PCA normal estimation and minimum-spanning-tree orientation (normals.h).
#include "normals.h"

#include "kdtree.h"

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

std::vector<Vec3> estimate_normals(const std::vector<Vec3>& pts, size_t k) {
    std::vector<Vec3> normals(pts.size(), Vec3(0, 0, 1));
    if (pts.size() < 3) return normals;
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double*, size_t found) {
        Vec3 mean, n;
        if (fit_plane(pts, idx, found, mean, n)) normals[i] = n;
    });
    return normals;
}

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
                if (!done[u]) heap.push({1.0 - std::abs(normals[u].dot(normals[v])), {u, v}});
        }
    }
}

}  // namespace ca
