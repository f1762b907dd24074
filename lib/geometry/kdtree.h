// kdtree.h: two k-d trees over a vector of 3-D points (radii and distances squared). PointTree
// wraps nanoflann 1.4 (neighbour lists, counts, radius searches); PackedPointTree is this
// project's own, for two searches whose answer is one number or one bit, where tight node boxes
// prune more than nanoflann's split distances: the nearest squared distance below a bound, and
// whether any of a set of balls reaches a point. Both are built in the constructor; const queries
// are thread-safe.
#pragma once
#include "common.h"
#include "parallel.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ca {

struct PointSetAdaptor {
    const std::vector<Vec3>* pts;
    size_t kdtree_get_point_count() const { return pts->size(); }
    double kdtree_get_pt(size_t i, size_t d) const { return (*pts)[i][int(d)]; }
    template <class B> bool kdtree_get_bbox(B&) const { return false; }
};

class PointTree {
public:
    explicit PointTree(const std::vector<Vec3>& pts)
        : adaptor_{&pts}, tree_(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
    // (index, squared distance) of the points within `radius` of q.
    void within(const Vec3& q, double radius, std::vector<std::pair<size_t, double>>& hits) const {
        within_squared(q, radius * radius, hits);
    }
    // (index, squared distance) of the points with squared distance below radius2 (unsorted).
    void within_squared(const Vec3& q, double radius2, std::vector<std::pair<size_t, double>>& hits) const {
        hits.clear();
        tree_.radiusSearch(q.data(), radius2, hits, nanoflann::SearchParams(32, 0, false));
    }
    // f(index) for the points with squared distance below radius2, in the order within_squared
    // lists them (no list built); returns how many.
    template <class F>
    size_t for_each_within_squared(const Vec3& q, double radius2, F&& f) const {
        struct Visit {   // a nanoflann result set that hands each hit to f
            double radius;
            F& f;
            size_t count = 0;
            void init() {}
            size_t size() const { return count; }
            bool full() const { return true; }
            bool addPoint(double dist, size_t index) {
                if (dist < radius) { f(index); ++count; }
                return true;
            }
            double worstDist() const { return radius; }
        } visit{radius2, f};
        tree_.findNeighbors(visit, q.data(), nanoflann::SearchParams(32, 0, false));
        return visit.count;
    }
    // k nearest points; returns how many were found.
    size_t nearest(const Vec3& q, size_t k, size_t* idx, double* dist2) const {
        return tree_.knnSearch(q.data(), k, idx, dist2);
    }
    // How many points lie within squared distance radius2 of q (inclusive), counting up to `cap`
    // (the search stops there): at least cap points within the radius <=> the cap-th nearest
    // point is within it, answered without sorting or listing the neighbours.
    size_t count_within_squared(const Vec3& q, double radius2, size_t cap) const {
        CountResult result{radius2, std::nextafter(radius2, std::numeric_limits<double>::infinity()), cap, 0};
        if (cap > 0 && !adaptor_.pts->empty()) tree_.findNeighbors(result, q.data(), nanoflann::SearchParams(32, 0, false));
        return result.count;
    }
    // Distance to the nearest point (+infinity for an empty set).
    double distance(const Vec3& q) const {
        size_t idx = 0;
        double d2 = std::numeric_limits<double>::infinity();
        if (adaptor_.pts->empty() || nearest(q, 1, &idx, &d2) == 0) return std::numeric_limits<double>::infinity();
        return std::sqrt(d2);
    }
private:
    // nanoflann result set of count_within_squared: the leaf test admits dist < worst (the next
    // double above radius2, so dist == radius2 is counted); false stops the search at the cap.
    struct CountResult {
        double radius2, worst;
        size_t cap, count;
        double worstDist() const { return worst; }
        bool full() const { return count >= cap; }
        bool addPoint(double dist, size_t) {
            if (dist <= radius2) ++count;
            return count < cap;
        }
    };
    PointSetAdaptor adaptor_;
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointSetAdaptor>, PointSetAdaptor, 3, size_t> tree_;
};

// A k-d tree over a copy of the points stored in leaf order, every node with the tight box of its
// points (median splits on the box's longest side, at most kLeaf points a leaf). Its answers are
// exact and the same as a scan of all points: a point's squared distance is computed as
// nanoflann's (((0 + dx^2) + dy^2) + dz^2, d = q - p), and a node is skipped only on a bound built
// from its box's sides in the same order; rounding is monotonic, so that bound is <= every point's
// computed distance. Points must be finite (a set with a non-finite coordinate becomes one leaf:
// scanned, still exact), fewer than 2^32. Points may carry a squared reach each (balls):
// reaches(q) asks whether q is strictly within one of them.
class PackedPointTree {
public:
    explicit PackedPointTree(const std::vector<Vec3>& pts) : PackedPointTree(pts, {}) {}
    // reach2: empty, or one squared reach per point (for reaches())
    PackedPointTree(const std::vector<Vec3>& pts, const std::vector<double>& reach2) {
        if (pts.empty()) return;
        std::vector<uint32_t> order(pts.size());
        std::iota(order.begin(), order.end(), 0u);
        const bool finite = std::all_of(pts.begin(), pts.end(), [](const Vec3& p) { return p.allFinite(); });
        nodes_.reserve(4 * (pts.size() / kLeaf + 1));
        nodes_.emplace_back();
        build(pts, order, 0, 0, uint32_t(pts.size()), finite);
        xyz_.resize(3 * pts.size());
        for (size_t i = 0; i < order.size(); ++i)
            for (int d = 0; d < 3; ++d) xyz_[3 * i + size_t(d)] = pts[order[i]][d];
        if (reach2.size() == pts.size()) {
            reach2_.resize(pts.size());
            for (size_t i = 0; i < order.size(); ++i) reach2_[i] = reach2[order[i]];
            // children come after their parent: one backward pass gives each node its largest reach
            for (size_t k = nodes_.size(); k-- > 0;) {
                Node& n = nodes_[k];
                n.reach2 = -std::numeric_limits<double>::infinity();
                if (n.leaf())
                    for (uint32_t i = n.begin; i < n.end; ++i) n.reach2 = std::max(n.reach2, reach2_[i]);
                else
                    n.reach2 = std::max(nodes_[n.left].reach2, nodes_[n.left + 1].reach2);
            }
        }
    }

    // Whether some point i has distance2(q, i) < reach2[i] (the reaches given to the constructor;
    // false without them). Stops at the first such point.
    bool reaches(const Vec3& q) const {
        if (reach2_.empty()) return false;
        uint32_t stack[kStack];
        size_t top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (!(lower_bound(node, q) < node.reach2)) continue;
            if (node.leaf()) {
                for (uint32_t i = node.begin; i < node.end; ++i)
                    if (distance2(q, i) < reach2_[i]) return true;
                continue;
            }
            stack[top++] = node.left + 1;
            stack[top++] = node.left;
        }
        return false;
    }

    // min(bound2, the smallest squared distance from q to a point): the value of
    // PointTree::nearest()'s squared distance when a point is closer than sqrt(bound2).
    double nearest_squared_below(const Vec3& q, double bound2) const {
        double best = bound2;
        if (nodes_.empty()) return best;
        Pending stack[kStack];
        size_t top = 0;
        stack[top++] = {0, lower_bound(nodes_[0], q)};
        while (top > 0) {
            const Pending item = stack[--top];
            if (item.lower >= best) continue;
            const Node& node = nodes_[item.node];
            if (node.leaf()) {
                for (uint32_t i = node.begin; i < node.end; ++i) best = std::min(best, distance2(q, i));
                continue;
            }
            const double a = lower_bound(nodes_[node.left], q), b = lower_bound(nodes_[node.left + 1], q);
            // the nearer child is searched first (pushed last)
            if (a <= b) {
                stack[top++] = {node.left + 1, b};
                stack[top++] = {node.left, a};
            } else {
                stack[top++] = {node.left, a};
                stack[top++] = {node.left + 1, b};
            }
        }
        return best;
    }

private:
    static constexpr uint32_t kLeaf = 16;
    // median splits: depth <= log2(n) + 1 < 34 for n < 2^32, and a search holds at most two
    // pending nodes a level
    static constexpr size_t kStack = 80;
    struct Node {
        double lo[3], hi[3];
        uint32_t begin, end;   // its points: xyz_ entries [begin, end)
        uint32_t left;         // children left and left + 1; 0 for a leaf
        double reach2;         // the largest squared reach of its points (with reaches only)
        bool leaf() const { return left == 0; }
    };
    struct Pending {
        uint32_t node;
        double lower;
    };

    // Fills node `id` with the points order[begin, end) and splits it (its two children made
    // next to each other, then filled).
    void build(const std::vector<Vec3>& pts, std::vector<uint32_t>& order, uint32_t id, uint32_t begin,
               uint32_t end, bool finite) {
        Node node{};
        node.begin = begin;
        node.end = end;
        for (int d = 0; d < 3; ++d) node.lo[d] = node.hi[d] = pts[order[begin]][d];
        for (uint32_t i = begin + 1; i < end; ++i)
            for (int d = 0; d < 3; ++d) {
                node.lo[d] = std::min(node.lo[d], pts[order[i]][d]);
                node.hi[d] = std::max(node.hi[d], pts[order[i]][d]);
            }
        int axis = 0;
        for (int d = 1; d < 3; ++d)
            if (node.hi[d] - node.lo[d] > node.hi[axis] - node.lo[axis]) axis = d;
        const bool split = end - begin > kLeaf && finite && node.hi[axis] > node.lo[axis];
        if (split) {
            node.left = uint32_t(nodes_.size());
            nodes_.emplace_back();
            nodes_.emplace_back();
        }
        nodes_[id] = node;
        if (!split) return;
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](uint32_t a, uint32_t b) { return pts[a][axis] < pts[b][axis]; });
        build(pts, order, node.left, begin, mid, finite);
        build(pts, order, node.left + 1, mid, end, finite);
    }

    double distance2(const Vec3& q, uint32_t i) const {
        const double* p = &xyz_[3 * size_t(i)];
        const double dx = q.x() - p[0], dy = q.y() - p[1], dz = q.z() - p[2];
        return dx * dx + dy * dy + dz * dz;
    }
    // <= distance2 of every point of the node: the gap to the box, side by side
    static double lower_bound(const Node& n, const Vec3& q) {
        double s = 0;
        for (int d = 0; d < 3; ++d) {
            const double g = q[d] < n.lo[d] ? n.lo[d] - q[d] : (q[d] > n.hi[d] ? q[d] - n.hi[d] : 0.0);
            s += g * g;
        }
        return s;
    }
    std::vector<Node> nodes_;
    std::vector<double> xyz_;       // the points in leaf order
    std::vector<double> reach2_;    // their squared reaches (or none)
};

// Calls f(i, idx, d2, found) for every point i of pts with its `found` nearest points (at most
// k + 1, point i itself among them; indices and squared distances, nearest first) from one tree:
// the neighbourhood loop of normal estimation, orientation and the tangent-plane areas. With
// threads <= 1 in index order; otherwise the index range is split into `threads` contiguous
// parts run at once (run_workers), so f must only write what belongs to point i. A query's
// answer does not depend on the thread that asks, so the results are the same either way.
template <class F>
void for_each_neighbourhood(const std::vector<Vec3>& pts, size_t k, F&& f, int threads = 1) {
    if (pts.empty()) return;
    const PointTree tree(pts);
    const size_t want = std::min(k + 1, pts.size());
    const size_t workers = std::min(pts.size(), size_t(std::max(1, threads)));
    const size_t chunk = (pts.size() + workers - 1) / workers;
    auto part = [&](size_t w) {
        std::vector<size_t> idx(want);
        std::vector<double> d2(want);
        for (size_t i = w * chunk; i < std::min(pts.size(), (w + 1) * chunk); ++i) {
            const size_t found = tree.nearest(pts[i], want, idx.data(), d2.data());
            f(i, idx.data(), d2.data(), found);
        }
    };
    if (workers <= 1) part(0);
    else run_workers(workers, part);
}

}  // namespace ca
