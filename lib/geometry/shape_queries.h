// shape_queries.h: the queries every stage after the candidates asks of the input shape, built
// once by the candidate step and shared read-only (connect, fit, search, proxies): the inside
// test and the distance (meshes: the winding number and the exact distance, on one tree of the
// triangles; open meshes also the distance to the hole caps; point clouds: the cloud's winding
// number and its reach rule). What the input is says Surface::kind() (surface.h). No step builds
// these again: a set whose surface changes after the candidate step must be given new ones.
#pragma once
#include "common.h"

#include <functional>
#include <memory>

namespace ca {

class WindingNumber;
class MeshDistance;
class PointCloudWinding;
class CloudReach;   // candidates.h: the point clouds' reach rule, built by the candidate step

struct ShapeQueries {
    // Meshes: inside by the winding number (> 1/2), and the exact distance to the surface.
    std::shared_ptr<const WindingNumber> winding;
    std::shared_ptr<const MeshDistance> distance;
    // Open meshes: the distance to the hole caps (hole_caps.h); null when the mesh is closed. It
    // bounds balls and skeleton elements as the surface does, so nothing reaches out through a hole.
    std::shared_ptr<const MeshDistance> cap_distance;
    // Point clouds: the winding number of the (de-duplicated, oriented) points, and the reach rule.
    std::shared_ptr<const PointCloudWinding> cloud_winding;
    std::shared_ptr<const CloudReach> cloud_reach;

    double depth(const Vec3& x) const;  // meshes: distance to the surface, negative outside
};

// Meshes: the winding number and the distance of `mesh`, on one tree of its triangles built on
// `threads` threads (the same tree for any count). `stop` is tested during the build; false (and
// neither set) when it said stop.
bool build_mesh_queries(const Mesh& mesh, int threads, const std::function<bool()>& stop, ShapeQueries& out);

// Open meshes: the distance to the hole caps `caps` (none set when it has no triangles).
void build_cap_queries(const Mesh& caps, ShapeQueries& out);

}  // namespace ca
