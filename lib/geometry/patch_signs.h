// patch_signs.h: the global step of normal orientation. Propagation along a neighbour graph
// (normals.h) makes signs consistent within patches but may join two patches the wrong way
// round; here each patch's sign is chosen by the winding number of the whole cloud (Barill et
// al. 2018, point_winding.h): on a closed, consistently oriented surface the mean of w just
// inside and just outside every point is 1/2, and a wrongly signed patch moves it at every point
// that sees the patch (most of all across a thin part). w is linear in the signs, so the choice
// is a small quadratic problem over one sign per patch.
#pragma once
#include "common.h"

namespace ca {

// `patch[i]` in [0, count) labels point i's patch (signs consistent within it). Negates whole
// patches of `normals` to minimise sum over probe points of (mean w - 1/2)^2; a patch is
// negated only if that lowers the sum. Returns the number of patches negated (0 when count < 2).
// The probes (and the patch pairs of the quadratic form) are split across `threads` threads;
// each probe's sum runs over the points in order, so the result is the same for any count.
size_t vote_patch_signs(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, const std::vector<uint32_t>& patch,
                        size_t count, int threads = 1);

// The mean over probe points (as the vote's) of (m - 1/2)^2, m the mean winding number just inside
// and just outside the point, for the better of the two global signs: near 0 for consistent
// normals of a closed surface, near 1/4 where signs cancel (random per-point signs give m near 0).
// Unlike the pair rule of sign_disagreement it does not depend on the points' offsets, so noise
// moves it little.
double winding_residual(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, int threads = 1);
// Below this residual, halfway between consistent (0) and cancelling (1/4) signs, normals are
// consistent by the winding number (bench_normals in docs/benchmarks.md).
constexpr double kMaxWindingResidual = 0.125;

}  // namespace ca
