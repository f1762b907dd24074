// shape_queries.cpp: the mesh queries of shape_queries.h built on one tree of the triangles, and
// the signed depth they answer together.
#include "shape_queries.h"

#include "bvh.h"
#include "distance.h"
#include "winding.h"

namespace ca {

double ShapeQueries::depth(const Vec3& x) const {
    const double d = distance->distance(x);
    return winding->inside(x) ? d : -d;
}

bool build_mesh_queries(const Mesh& mesh, int threads, const std::function<bool()>& stop, ShapeQueries& out) {
    const auto tree = detail::build_triangle_tree(mesh, threads, stop);   // one tree for both
    if (stop && stop()) return false;
    auto winding = std::make_shared<const WindingNumber>(tree, 2.0, threads, stop);
    if (stop && stop()) return false;
    out.winding = std::move(winding);
    out.distance = std::make_shared<const MeshDistance>(tree);
    return true;
}

void build_cap_queries(const Mesh& caps, ShapeQueries& out) {
    if (!caps.triangles.empty()) out.cap_distance = std::make_shared<const MeshDistance>(caps);
}

}  // namespace ca
