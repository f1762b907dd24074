// point_winding.h: the generalised winding number of an oriented point cloud (Barill et al. 2018):
// w(q) = sum_i a_i (p_i - q).n_i / (4 pi |p_i - q|^3), a_i the area of point i's Voronoi cell in
// its tangent plane among its k nearest neighbours. Hierarchical like the mesh winding number
// (winding.h): the same BVH over the points, far clusters replaced by their dipole expansion
// (to second order), exact near the query, so a query costs O(log n). About 1 inside a closed, outward-
// oriented cloud and 0 outside. Queries are const and safe from several threads at once.
#pragma once
#include "common.h"
#include <memory>

namespace ca {

// Per-point areas: the area of each point's Voronoi cell in the plane through it orthogonal to its
// normal, among the projections of its k nearest neighbours (bounded by a square of half-side
// the k-th neighbour distance, so boundary points of open clouds get finite areas). The points are
// split across `threads` threads; the areas do not depend on it.
std::vector<double> tangent_voronoi_areas(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals,
                                          size_t k = 20, int threads = 1);

class PointCloudWinding {
public:
    // `normals` unit, one per point; `beta` as in WindingNumber; the areas are computed on
    // `threads` threads (the result does not depend on it).
    PointCloudWinding(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, double beta = 2.0,
                      int threads = 1);
    ~PointCloudWinding();
    PointCloudWinding(PointCloudWinding&&) noexcept;
    PointCloudWinding& operator=(PointCloudWinding&&) noexcept;

    double operator()(const Vec3& q) const;                 // hierarchical approximation
    bool inside(const Vec3& q) const { return (*this)(q) > 0.5; }
    const std::vector<double>& areas() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Exact O(n) sum with the given areas; for tests.
double point_winding_brute_force(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals,
                                 const std::vector<double>& areas, const Vec3& q);

}  // namespace ca
