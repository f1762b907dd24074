// normals.h: normals of a point cloud that has none, or whose normals are not consistently
// oriented. estimate_normals: per point, the direction of least variance of its k nearest
// neighbours (PCA). orient_normals: after Hoppe et al. 1992: a minimum spanning tree of the
// symmetric k-nearest-neighbour graph weighted by 1 - |n_i . n_j| (nearly parallel neighbours
// first; pairs facing across a thin part or a crease last), the sign propagated from the root
// along the tree (side by side: the same way; facing across: away from each other); each connected
// part of the graph is rooted at its highest point with a normal pointing up (+z). The tree is
// then cut at its unreliable edges and each patch signed as a whole by the winding-number vote
// (patch_signs.h). The global sign (outward) is fixed later by the winding number
// (point_cloud.cpp). sign_disagreement: the
// fraction of neighbouring pairs whose signs disagree by the same rule, a cheap check that normals
// given as oriented really are. `threads`: the per-point loops are split across that many
// threads; every result is the same for any count (each point writes only its own slot, sums
// are taken in point order).
#pragma once
#include "common.h"

namespace ca {

// The least-squares plane of pts[idx[0..count)): its centroid and unit normal (direction of least
// variance, sign arbitrary); false if degenerate.
bool fit_plane(const std::vector<Vec3>& pts, const size_t* idx, size_t count, Vec3& mean, Vec3& normal);
std::vector<Vec3> estimate_normals(const std::vector<Vec3>& pts, size_t k = 16, int threads = 1);
// `estimated`: PCA normals. Across a sheet thinner than their neighbourhoods both sides get the
// sheet's normal, so only the facing rule tells the two sides apart there; at creases they average,
// and on detailed parts they tilt with the sampling, so an uncertain pair is avoided only between
// nearly parallel normals (the pair across a thin sheet).
void orient_normals(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, size_t k = 16, bool estimated = false,
                    int threads = 1);

// The fraction of neighbouring pairs (j among i's k nearest) whose signs disagree: side by side
// on a smooth part, normals pointing against each other; facing across a thin part, a crease or
// a sharp edge (the offset well out of both tangent planes), not each point behind the other's
// tangent plane (nor each in front of it). Consistent normals of a sampled surface give few such
// pairs (across concave creases), random per-point signs about half.
double sign_disagreement(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, size_t k = 8,
                         int threads = 1);
// Above this sign_disagreement normals given as oriented are not trusted (re-oriented), and
// oriented or estimated normals are refused: clean sampled clouds stay far below it, clouds with
// random per-point signs far above (bench_normals in docs/benchmarks.md).
constexpr double kMaxSignDisagreement = 0.1;
// Re-oriented trusted normals replace the caller's only when their disagreement is below this
// fraction of the given one (random signs: about 0.5 before, near 0 after).
constexpr double kSignCheckGain = 0.5;

}  // namespace ca
