// kdtree.h: a nanoflann k-d tree over a vector of 3-D points (radii and distances squared, as
// nanoflann 1.4 takes them). Built in the constructor; const queries are thread-safe.
#pragma once
#include "common.h"
#include "parallel.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

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
    // The squared distance of the nearest point if one is closer than sqrt(bound2) (the same value
    // nearest() gives), else bound2: a search that starts from the bound prunes more.
    double nearest_squared_below(const Vec3& q, double bound2) const {
        NearestResult result{bound2};
        if (!adaptor_.pts->empty()) tree_.findNeighbors(result, q.data(), nanoflann::SearchParams(32, 0, false));
        return result.best;
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
    // nanoflann result set of nearest_squared_below. A leaf compares its points with the bound it
    // read on entry, so addPoint keeps the smaller of the two.
    struct NearestResult {
        double best;
        double worstDist() const { return best; }
        bool full() const { return true; }
        bool addPoint(double dist, size_t) {
            best = std::min(best, dist);
            return true;
        }
    };
    PointSetAdaptor adaptor_;
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointSetAdaptor>, PointSetAdaptor, 3, size_t> tree_;
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
