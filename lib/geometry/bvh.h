// bvh.h: a small binary bounding-volume hierarchy over triangles, shared by winding.cpp and
// distance.cpp. Built top-down by a median split (of the triangle centroids) along the longest
// axis of the centroid box; leaves hold at most `leaf_size` triangles. Internal header.
#pragma once
#include "common.h"
#include <algorithm>
#include <limits>

namespace ca::detail {

struct BvhNode {
    Vec3 lo, hi;                     // bounding box of the node's triangles
    uint32_t begin = 0, end = 0;     // the node covers Bvh::order[begin, end)
    uint32_t left = 0, right = 0;    // children; 0 for a leaf (the root is never a child)
    bool leaf() const { return left == 0; }
};

struct Bvh {
    std::vector<BvhNode> nodes;      // nodes[0] is the root; empty when there is no triangle
    std::vector<uint32_t> order;     // indices into Mesh::triangles, grouped by node
};

// A triangle is used when its three vertex indices are valid and its corners finite.
inline bool triangle_ok(const Mesh& mesh, const Tri& f) {
    const size_t nv = mesh.vertices.size();
    return f[0] < nv && f[1] < nv && f[2] < nv && mesh.vertices[f[0]].allFinite() &&
           mesh.vertices[f[1]].allFinite() && mesh.vertices[f[2]].allFinite();
}

inline std::vector<uint32_t> valid_triangles(const Mesh& mesh) {
    std::vector<uint32_t> ids;
    ids.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        if (triangle_ok(mesh, mesh.triangles[t])) ids.push_back(uint32_t(t));
    return ids;
}

inline Bvh build_bvh(const Mesh& mesh, std::vector<uint32_t> ids, uint32_t leaf_size = 8) {
    Bvh bvh;
    bvh.order = std::move(ids);
    if (bvh.order.empty()) return bvh;
    const auto& V = mesh.vertices;
    const auto& T = mesh.triangles;
    auto centroid = [&](uint32_t t) { return Vec3((V[T[t][0]] + V[T[t][1]] + V[T[t][2]]) / 3.0); };
    bvh.nodes.reserve(2 * (bvh.order.size() / std::max<uint32_t>(leaf_size, 1)) + 1);

    // Recursion depth is about log2(F / leaf_size): the split is always at the median.
    auto build = [&](auto&& self, uint32_t begin, uint32_t end) -> uint32_t {
        const uint32_t id = uint32_t(bvh.nodes.size());
        bvh.nodes.emplace_back();
        const double inf = std::numeric_limits<double>::infinity();
        Vec3 lo = Vec3::Constant(inf), hi = Vec3::Constant(-inf);
        Vec3 clo = lo, chi = hi;
        for (uint32_t i = begin; i < end; ++i) {
            const Tri& f = T[bvh.order[i]];
            for (uint32_t k : f) { lo = lo.cwiseMin(V[k]); hi = hi.cwiseMax(V[k]); }
            const Vec3 c = centroid(bvh.order[i]);
            clo = clo.cwiseMin(c); chi = chi.cwiseMax(c);
        }
        BvhNode node;
        node.lo = lo; node.hi = hi; node.begin = begin; node.end = end;
        if (end - begin > std::max<uint32_t>(leaf_size, 1)) {
            int axis = 0;
            (chi - clo).maxCoeff(&axis);
            const uint32_t mid = begin + (end - begin) / 2;
            std::nth_element(bvh.order.begin() + begin, bvh.order.begin() + mid, bvh.order.begin() + end,
                             [&](uint32_t a, uint32_t b) { return centroid(a)[axis] < centroid(b)[axis]; });
            node.left = self(self, begin, mid);
            node.right = self(self, mid, end);
        }
        bvh.nodes[id] = node;
        return id;
    };
    build(build, 0, uint32_t(bvh.order.size()));
    return bvh;
}

}  // namespace ca::detail
