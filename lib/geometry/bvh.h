// bvh.h: a small binary bounding-volume hierarchy over triangles, shared by winding.cpp and
// distance.cpp (one TriangleTree can serve both). Built top-down by a median split (of the triangle centroids) along the longest
// axis of the centroid box; leaves hold at most `leaf_size` triangles. The builds take an optional
// stop request, tested every few thousand triangles so that a cancel takes effect at once; a
// stopped build returns an empty tree, which the caller must not use. Internal header.
#pragma once
#include "common.h"
#include <array>
#include <functional>
#include <memory>

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
    reserve_large(ids, mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        if (triangle_ok(mesh, mesh.triangles[t])) ids.push_back(uint32_t(t));
    return ids;
}

// Built in bvh.cpp. Each node's box is the union of its children's (leaves: of their triangles'
// corners), and the split compares precomputed centroids, so a build costs O(F log F)
// comparisons of doubles. With threads > 1 the top levels are split first (to the least power
// of two >= threads subtrees, at most 2^kMaxParallelLevels; a node of at most
// kParallelItemsPerLeaf leaves' worth of triangles is not split there) and the subtrees below
// them are built at once, each into a vector of its own, renumbered on appending: the same nodes
// in the same order as one thread builds.
// `stop` is tested at every node of more than kStopCheckItems triangles and every
// kStopCheckItems centroids, so at most O(kStopCheckItems log kStopCheckItems) work separates two
// tests; it may be called from every thread. A stopped build returns an empty tree.
constexpr uint32_t kStopCheckItems = 4096;
// Below this many leaves' worth of triangles a subtree is not split further for the threads.
constexpr uint32_t kParallelItemsPerLeaf = 64;
constexpr int kMaxParallelLevels = 6;
Bvh build_bvh(const Mesh& mesh, std::vector<uint32_t> ids, uint32_t leaf_size = 8, int threads = 1,
              const std::function<bool()>& stop = {});

// The top levels a build over `threads` threads splits before the workers take the subtrees
// below: the least L with 2^L >= threads, at most kMaxParallelLevels (the BVH build and the
// winding number's expansions split the same tree the same way).
inline int parallel_top_levels(int threads) {
    int levels = 0;
    while ((1 << levels) < threads && levels < kMaxParallelLevels) ++levels;
    return levels;
}

// The BVH over a mesh's valid triangles and their corners in BVH order: what the winding
// number and the distance queries both walk, built once for both. The corner copy tests `stop`
// every kStopCheckItems triangles too (it writes as much memory as the build); a stopped build
// returns an empty tree.
struct TriangleTree {
    Bvh bvh;
    std::vector<std::array<Vec3, 3>> tris;   // triangle corners, in bvh.order
};

inline std::shared_ptr<const TriangleTree> build_triangle_tree(const Mesh& mesh, int threads = 1,
                                                             const std::function<bool()>& stop = {}) {
    auto tree = std::make_shared<TriangleTree>();
    tree->bvh = build_bvh(mesh, valid_triangles(mesh), 8, threads, stop);
    reserve_large(tree->tris, tree->bvh.order.size());
    for (uint32_t t : tree->bvh.order) {
        if (stop && tree->tris.size() % kStopCheckItems == 0 && stop()) return std::make_shared<TriangleTree>();
        const Tri& f = mesh.triangles[t];
        tree->tris.push_back({mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]});
    }
    return tree;
}

}  // namespace ca::detail
