// normals.h: normals of a point cloud that has none, or whose normals are not consistently
// oriented. estimate_normals: per point, the direction of least variance of its k nearest
// neighbours (PCA). orient_normals: Hoppe et al. 1992: a minimum spanning tree of the symmetric
// k-nearest-neighbour graph weighted by 1 - |n_i . n_j| (nearly parallel neighbours first), the
// sign propagated from the root along the tree; each connected part of the graph is rooted at its
// highest point with a normal pointing up (+z). The global sign (outward) is fixed later by the
// winding number (point_cloud.cpp).
#pragma once
#include "common.h"

namespace ca {

// The least-squares plane of pts[idx[0..count)): its centroid and unit normal (direction of least
// variance, sign arbitrary); false if degenerate.
bool fit_plane(const std::vector<Vec3>& pts, const size_t* idx, size_t count, Vec3& mean, Vec3& normal);
std::vector<Vec3> estimate_normals(const std::vector<Vec3>& pts, size_t k = 16);
void orient_normals(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, size_t k = 16);

}  // namespace ca
