// kdtree.h: a nanoflann k-d tree over a vector of 3-D points (radii and distances squared, as
// nanoflann 1.4 takes them). Built in the constructor; const queries are thread-safe.
#pragma once
#include "common.h"

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
    // The nearest point when one lies at squared distance below bound2: the search prunes by that
    // bound from the start (fewer nodes visited), and the squared distance is nearest()'s; false
    // when no point is that close.
    bool nearest_below(const Vec3& q, double bound2, size_t* idx, double* dist2) const {
        if (adaptor_.pts->empty()) return false;
        nanoflann::KNNResultSet<double, size_t, size_t> found(1);
        found.init(idx, dist2);
        *dist2 = bound2;
        tree_.findNeighbors(found, q.data(), nanoflann::SearchParams());
        return found.size() == 1;
    }
    // Distance to the nearest point (+infinity for an empty set).
    double distance(const Vec3& q) const {
        size_t idx = 0;
        double d2 = std::numeric_limits<double>::infinity();
        if (adaptor_.pts->empty() || nearest(q, 1, &idx, &d2) == 0) return std::numeric_limits<double>::infinity();
        return std::sqrt(d2);
    }
private:
    PointSetAdaptor adaptor_;
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointSetAdaptor>, PointSetAdaptor, 3, size_t> tree_;
};

// Calls f(i, idx, d2, found) for every point i of pts with its `found` nearest points (at most
// k + 1, point i itself among them; indices and squared distances, nearest first), in index
// order from one tree: the neighbourhood loop of normal estimation, orientation and the
// tangent-plane areas.
template <class F>
void for_each_neighbourhood(const std::vector<Vec3>& pts, size_t k, F&& f) {
    if (pts.empty()) return;
    PointTree tree(pts);
    const size_t want = std::min(k + 1, pts.size());
    std::vector<size_t> idx(want);
    std::vector<double> d2(want);
    for (size_t i = 0; i < pts.size(); ++i) {
        const size_t found = tree.nearest(pts[i], want, idx.data(), d2.data());
        f(i, idx.data(), d2.data(), found);
    }
}

}  // namespace ca
