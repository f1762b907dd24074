// bvh.cpp: builds the bounding-volume hierarchy of bvh.h in named steps: the triangles'
// centroids (make_items), the median split of a range (split), a subtree built by recursion
// (build_subtree), and, with threads, the top levels split in one thread's order (plan_top), the
// subtrees below built at once and appended where one thread would have built them (assemble).
#include "bvh.h"
#include "parallel.h"
#include <algorithm>
#include <atomic>
#include <limits>

namespace ca::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Item {
    Vec3 centroid;
    uint32_t id;
};

// A node over items[begin, end) with an empty box, its children not yet set.
BvhNode empty_node(uint32_t begin, uint32_t end) {
    BvhNode node;
    node.begin = begin; node.end = end;
    node.lo = Vec3::Constant(kInf); node.hi = Vec3::Constant(-kInf);
    return node;
}

// A node's box from its children's boxes.
void join(BvhNode& node, const std::vector<BvhNode>& nodes) {
    for (uint32_t c : {node.left, node.right}) {
        node.lo = node.lo.cwiseMin(nodes[c].lo); node.hi = node.hi.cwiseMax(nodes[c].hi);
    }
}

class BvhBuilder {
public:
    BvhBuilder(const Mesh& mesh, uint32_t leaf_size, const std::function<bool()>& stop)
        : V_(mesh.vertices), T_(mesh.triangles), stop_(stop), leaf_(std::max<uint32_t>(leaf_size, 1)),
          // a split node has more than `leaf` items, so each half, and every leaf, at least
          // (leaf + 1) / 2: a tree over m items has at most 2 m / that - 1 nodes
          least_(std::max<uint32_t>((leaf_ + 1) / 2, 1)) {}

    // The centroid of every triangle of `ids`; false when stopped. Reserved, then appended: a
    // zero-filled vector would touch every page before the first stop test.
    bool make_items(const std::vector<uint32_t>& ids) {
        reserve_large(items_, ids.size());
        for (size_t i = 0; i < ids.size(); ++i) {
            if (i % kStopCheckItems == 0 && stop_now()) return false;
            const Tri& f = T_[ids[i]];
            items_.push_back({Vec3((V_[f[0]] + V_[f[1]] + V_[f[2]]) / 3.0), ids[i]});
        }
        return true;
    }

    Bvh build(int threads) {
        Bvh bvh;
        reserve_large(bvh.nodes, node_bound(uint32_t(items_.size())));
        const uint32_t n = uint32_t(items_.size());
        if (threads > 1 && n > kParallelItemsPerLeaf * leaf_) build_parallel(bvh.nodes, n, threads);
        else build_subtree(bvh.nodes, 0, n);
        if (stopped_) return Bvh{};
        reserve_large(bvh.order, items_.size());
        for (const Item& item : items_) bvh.order.push_back(item.id);
        return bvh;
    }

private:
    // One top-level step, in preorder: a node split here, or a subtree for the workers.
    struct Step {
        uint32_t begin, end;
        int subtree;   // -1: a node split here; else the index of its range in `ranges`
    };

    size_t node_bound(uint32_t items) const { return 2 * (items / least_) + 1; }

    bool stop_now() {
        if (stopped_.load(std::memory_order_relaxed)) return true;
        if (stop_ && stop_()) stopped_.store(true, std::memory_order_relaxed);
        return stopped_.load(std::memory_order_relaxed);
    }

    // The median split of items[begin, end) along the longest axis of its centroid box.
    uint32_t split(uint32_t begin, uint32_t end) {
        Vec3 clo = Vec3::Constant(kInf), chi = Vec3::Constant(-kInf);
        for (uint32_t i = begin; i < end; ++i) {
            clo = clo.cwiseMin(items_[i].centroid); chi = chi.cwiseMax(items_[i].centroid);
        }
        int axis = 0;
        (chi - clo).maxCoeff(&axis);
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                         [axis](const Item& a, const Item& b) { return a.centroid[axis] < b.centroid[axis]; });
        return mid;
    }

    // The subtree over items[begin, end), appended to `nodes`; its root's id. Recursion depth is
    // about log2(F / leaf_size): the split is always at the median. Node ids are positions in
    // `nodes` (a parent before its children, the left subtree first).
    uint32_t build_subtree(std::vector<BvhNode>& nodes, uint32_t begin, uint32_t end) {
        const uint32_t id = uint32_t(nodes.size());
        nodes.emplace_back();
        BvhNode node = empty_node(begin, end);
        if (end - begin > kStopCheckItems && stop_now()) {
            nodes[id] = node;   // a leaf over its range: the tree is discarded anyway
            return id;
        }
        if (end - begin > leaf_) {
            const uint32_t mid = split(begin, end);
            node.left = build_subtree(nodes, begin, mid);
            node.right = build_subtree(nodes, mid, end);
            join(node, nodes);
        } else {
            for (uint32_t i = begin; i < end; ++i)
                for (uint32_t k : T_[items_[i].id]) { node.lo = node.lo.cwiseMin(V_[k]); node.hi = node.hi.cwiseMax(V_[k]); }
        }
        nodes[id] = node;
        return id;
    }

    // The top levels, split here in the order one thread splits them (each split reads and
    // permutes only its own range, so the ranges below are the same): `plan_` lists the top in
    // preorder, a node to split or a subtree for the workers.
    void plan_top(uint32_t begin, uint32_t end, int depth, int levels) {
        if (depth < levels && end - begin > kParallelItemsPerLeaf * leaf_) {
            plan_.push_back({begin, end, -1});
            const uint32_t mid = split(begin, end);
            plan_top(begin, mid, depth + 1, levels);
            plan_top(mid, end, depth + 1, levels);
        } else {
            plan_.push_back({begin, end, int(ranges_.size())});
            ranges_.emplace_back(begin, end);
        }
    }

    // The nodes of plan_[at_...] appended to `nodes`: a subtree built by a worker is copied where
    // one thread would have built it, its ids renumbered; its root's id.
    uint32_t assemble(std::vector<BvhNode>& nodes) {
        const Step& step = plan_[at_++];
        const uint32_t id = uint32_t(nodes.size());
        if (step.subtree >= 0) {
            for (BvhNode b : built_[size_t(step.subtree)]) {
                if (!b.leaf()) b.left += id, b.right += id;
                nodes.push_back(b);
            }
            std::vector<BvhNode>().swap(built_[size_t(step.subtree)]);
            return id;
        }
        nodes.emplace_back();
        BvhNode node = empty_node(step.begin, step.end);
        node.left = assemble(nodes);
        node.right = assemble(nodes);
        join(node, nodes);
        nodes[id] = node;
        return id;
    }

    void build_parallel(std::vector<BvhNode>& nodes, uint32_t n, int threads) {
        plan_top(0, n, 0, parallel_top_levels(threads));
        built_.resize(ranges_.size());
        const size_t workers = std::min(ranges_.size(), size_t(threads));
        run_workers(workers, [&](size_t w) {
            for (size_t r = w; r < ranges_.size(); r += workers) {
                reserve_large(built_[r], node_bound(ranges_[r].second - ranges_[r].first));
                build_subtree(built_[r], ranges_[r].first, ranges_[r].second);
            }
        });
        assemble(nodes);
    }

    const std::vector<Vec3>& V_;
    const std::vector<Tri>& T_;
    const std::function<bool()>& stop_;
    const uint32_t leaf_, least_;
    std::atomic<bool> stopped_{false};
    std::vector<Item> items_;
    std::vector<Step> plan_;
    std::vector<std::pair<uint32_t, uint32_t>> ranges_;
    std::vector<std::vector<BvhNode>> built_;
    size_t at_ = 0;
};

}  // namespace

Bvh build_bvh(const Mesh& mesh, std::vector<uint32_t> ids, uint32_t leaf_size, int threads,
              const std::function<bool()>& stop) {
    if (ids.empty()) return Bvh{};
    BvhBuilder builder(mesh, leaf_size, stop);
    if (!builder.make_items(ids)) return Bvh{};
    ids = std::vector<uint32_t>();
    return builder.build(threads);
}

}  // namespace ca::detail
