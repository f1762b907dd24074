// delaunay.h: Qhull (reentrant API, one qhT per call) behind two functions: the 3-D Delaunay
// tetrahedra of a point set, and the regular triangulation of weighted points (the dual of the
// power diagram) as the lower hull of the points lifted to 4-D. Every Qhull failure becomes a
// Status carrying Qhull's own first error line; nothing is printed and exit() is never reached
// (Qhull traps its errors inside qh_new_qhull; no other Qhull call that can fail is made). Both
// stop when the monitor says so, also inside Qhull's build (see qhull_stream.h), and then return
// the monitor's stop status for the given stage with no cells.
#pragma once
#include "common.h"

namespace ca {

using Tet = std::array<uint32_t, 4>;

// Delaunay tetrahedra (indices into pts). Tries "d QJ Qbb", then "d Qbb Qt", then "d Qbb Qt Qz".
// Zero-volume tetrahedra (possible with Qt) are dropped. Needs >= 5 points not all coplanar;
// remove duplicates first.
Status delaunay_tetrahedra(const std::vector<Vec3>& pts, std::vector<Tet>& tets, const Monitor& monitor,
                           const char* stage);

// Cells of the regular triangulation of points with weights w (power distance |x-p|^2 - w):
// lower facets of the lifted points (x, y, z, |p|^2 - w). Tries "Qt", then "QJ".
Status regular_triangulation(const std::vector<Vec3>& pts, const std::vector<double>& weights,
                             std::vector<Tet>& cells, const Monitor& monitor, const char* stage);

// Circumcentre of a tetrahedron; false if it is (numerically) flat.
bool circumcenter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Vec3& center);

}  // namespace ca
