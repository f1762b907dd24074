// point_signs.h: the last step of normal orientation, per point. After propagation and the patch
// vote (normals.h, patch_signs.h) most signs are right, but single points inside a patch can be
// wrong (PCA normals at creases and across sheets thinner than the neighbourhoods, where the pair
// rules of the propagation guess). The winding number of the rest of the cloud tells: just behind
// a rightly signed point it is higher than just in front of it.
#pragma once
#include "common.h"

namespace ca {

// Negates each normal for which the winding number of the cloud, the point's own dipole left out,
// is lower at depth t behind the point (along -n) than at t in front of it (t: half the point's
// 8th-neighbour distance). Repeated, with the winding number of the updated normals, until no
// point changes or `rounds` are done. Returns the number of normals negated in all. The points are
// split across `threads` threads; the result is the same for any count.
size_t refine_point_signs(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, int rounds = 3, int threads = 1);

}  // namespace ca
