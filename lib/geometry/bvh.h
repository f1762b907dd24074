// bvh.h: a small binary bounding-volume hierarchy over triangles, shared by winding.cpp and
// distance.cpp (one TriangleTree can serve both). Built top-down by a median split (of the triangle centroids) along the longest
// axis of the centroid box; leaves hold at most `leaf_size` triangles. The builds take an optional
// stop request, tested every few thousand triangles so that a cancel takes effect at once; a
// stopped build returns an empty tree, which the caller must not use. Internal header.
#pragma once
#include "common.h"
#include "parallel.h"
#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <limits>
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

// Each node's box is the union of its children's (leaves: of their triangles' corners), and
// the split compares precomputed centroids, so a build costs O(F log F) comparisons of doubles.
// With threads > 1 the top levels are split first (to the least power of two >= threads
// subtrees, at most 2^kMaxParallelLevels; a node of at most kParallelItemsPerLeaf leaves' worth
// of triangles is not split there) and the subtrees below them are built at once, each into a
// vector of its own, renumbered on appending: the same nodes in the same order as one thread
// builds.
// `stop` is tested at every node of more than kStopCheckItems triangles and every
// kStopCheckItems centroids, so at most O(kStopCheckItems log kStopCheckItems) work separates two
// tests; it may be called from every thread. A stopped build returns an empty tree.
constexpr uint32_t kStopCheckItems = 4096;
// Below this many leaves' worth of triangles a subtree is not split further for the threads.
constexpr uint32_t kParallelItemsPerLeaf = 64;
constexpr int kMaxParallelLevels = 6;
inline Bvh build_bvh(const Mesh& mesh, std::vector<uint32_t> ids, uint32_t leaf_size = 8, int threads = 1,
                     const std::function<bool()>& stop = {}) {
    Bvh bvh;
    if (ids.empty()) return bvh;
    const auto& V = mesh.vertices;
    const auto& T = mesh.triangles;
    struct Item {
        Vec3 centroid;
        uint32_t id;
    };
    std::atomic<bool> stopped{false};
    auto stop_now = [&] {
        if (stopped.load(std::memory_order_relaxed)) return true;
        if (stop && stop()) stopped.store(true, std::memory_order_relaxed);
        return stopped.load(std::memory_order_relaxed);
    };
    // reserved, then appended: a zero-filled vector would touch every page before the first stop test
    std::vector<Item> items;
    reserve_large(items, ids.size());
    for (size_t i = 0; i < ids.size(); ++i) {
        if (i % kStopCheckItems == 0 && stop_now()) return Bvh{};
        const Tri& f = T[ids[i]];
        items.push_back({Vec3((V[f[0]] + V[f[1]] + V[f[2]]) / 3.0), ids[i]});
    }
    ids = std::vector<uint32_t>();
    const uint32_t leaf = std::max<uint32_t>(leaf_size, 1);
    // a split node has more than `leaf` items, so each half, and every leaf, at least
    // (leaf + 1) / 2: a tree over m items has at most 2 m / that - 1 nodes
    const uint32_t least = std::max<uint32_t>((leaf + 1) / 2, 1);
    reserve_large(bvh.nodes, 2 * (items.size() / least) + 1);
    const double inf = std::numeric_limits<double>::infinity();

    // The median split of items[begin, end) along the longest axis of its centroid box.
    auto split = [&](uint32_t begin, uint32_t end) {
        Vec3 clo = Vec3::Constant(inf), chi = Vec3::Constant(-inf);
        for (uint32_t i = begin; i < end; ++i) {
            clo = clo.cwiseMin(items[i].centroid); chi = chi.cwiseMax(items[i].centroid);
        }
        int axis = 0;
        (chi - clo).maxCoeff(&axis);
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                         [axis](const Item& a, const Item& b) { return a.centroid[axis] < b.centroid[axis]; });
        return mid;
    };
    auto join = [](BvhNode& node, const std::vector<BvhNode>& nodes) {
        for (uint32_t c : {node.left, node.right}) {
            node.lo = node.lo.cwiseMin(nodes[c].lo); node.hi = node.hi.cwiseMax(nodes[c].hi);
        }
    };
    // Recursion depth is about log2(F / leaf_size): the split is always at the median. Node ids
    // are positions in `nodes` (a parent before its children, the left subtree first).
    auto build = [&](auto&& self, std::vector<BvhNode>& nodes, uint32_t begin, uint32_t end) -> uint32_t {
        const uint32_t id = uint32_t(nodes.size());
        nodes.emplace_back();
        BvhNode node;
        node.begin = begin; node.end = end;
        node.lo = Vec3::Constant(inf); node.hi = Vec3::Constant(-inf);
        if (end - begin > kStopCheckItems && stop_now()) {
            nodes[id] = node;   // a leaf over its range: the tree is discarded anyway
            return id;
        }
        if (end - begin > leaf) {
            const uint32_t mid = split(begin, end);
            node.left = self(self, nodes, begin, mid);
            node.right = self(self, nodes, mid, end);
            join(node, nodes);
        } else {
            for (uint32_t i = begin; i < end; ++i)
                for (uint32_t k : T[items[i].id]) { node.lo = node.lo.cwiseMin(V[k]); node.hi = node.hi.cwiseMax(V[k]); }
        }
        nodes[id] = node;
        return id;
    };
    const uint32_t n = uint32_t(items.size());
    if (threads > 1 && n > kParallelItemsPerLeaf * leaf) {
        // The top levels are split here, in the order one thread splits them (each split reads
        // and permutes only its own range, so the ranges below are the same): `plan` lists the
        // top in preorder, a node to split or a subtree for the workers. Each subtree is built
        // into a vector of its own and appended where one thread would have built it, its ids
        // renumbered.
        int levels = 0;
        while ((1 << levels) < threads && levels < kMaxParallelLevels) ++levels;
        struct Step {
            uint32_t begin, end;
            int subtree;   // -1: a node split here; else the index of its range in `ranges`
        };
        std::vector<Step> plan;
        std::vector<std::pair<uint32_t, uint32_t>> ranges;
        auto top = [&](auto&& self, uint32_t begin, uint32_t end, int depth) -> void {
            if (depth < levels && end - begin > kParallelItemsPerLeaf * leaf) {
                plan.push_back({begin, end, -1});
                const uint32_t mid = split(begin, end);
                self(self, begin, mid, depth + 1);
                self(self, mid, end, depth + 1);
            } else {
                plan.push_back({begin, end, int(ranges.size())});
                ranges.emplace_back(begin, end);
            }
        };
        top(top, 0, n, 0);
        std::vector<std::vector<BvhNode>> built(ranges.size());
        const size_t workers = std::min(ranges.size(), size_t(threads));
        run_workers(workers, [&](size_t w) {
            for (size_t r = w; r < ranges.size(); r += workers) {
                reserve_large(built[r], 2 * ((ranges[r].second - ranges[r].first) / least) + 1);
                build(build, built[r], ranges[r].first, ranges[r].second);
            }
        });
        size_t at = 0;
        auto assemble = [&](auto&& self) -> uint32_t {
            const Step& step = plan[at++];
            const uint32_t id = uint32_t(bvh.nodes.size());
            if (step.subtree >= 0) {
                for (BvhNode b : built[size_t(step.subtree)]) {
                    if (!b.leaf()) b.left += id, b.right += id;
                    bvh.nodes.push_back(b);
                }
                std::vector<BvhNode>().swap(built[size_t(step.subtree)]);
                return id;
            }
            bvh.nodes.emplace_back();
            BvhNode node;
            node.begin = step.begin; node.end = step.end;
            node.lo = Vec3::Constant(inf); node.hi = Vec3::Constant(-inf);
            node.left = self(self);
            node.right = self(self);
            join(node, bvh.nodes);
            bvh.nodes[id] = node;
            return id;
        };
        assemble(assemble);
    } else {
        build(build, bvh.nodes, 0, n);
    }
    if (stopped) return Bvh{};
    reserve_large(bvh.order, items.size());
    for (const Item& item : items) bvh.order.push_back(item.id);
    return bvh;
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
