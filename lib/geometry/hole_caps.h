// hole_caps.h: the caps that close the holes of an open mesh (hole_caps.cpp). Used for the
// orientation of an open mesh (surface.cpp: the signed volume of an open mesh depends on the
// origin, that of the mesh closed by its caps does not) and to keep candidate balls from reaching
// out through a hole (candidates/hole_caps.cpp).
#pragma once
#include "common.h"
#include "mesh_topology.h"

namespace ca {

// Every closed boundary loop of `mesh` (edges used by one triangle, vertices welded by position,
// every loop vertex on exactly two boundary edges) gets a fan of triangles from the loop's
// centroid, one per boundary edge, oriented like the mesh: a boundary edge a -> b of its triangle
// gives the cap triangle (centroid, b, a), so mesh + caps is consistently oriented and closed
// where the mesh is. Closed meshes give no caps; open boundary curves that are not loops get none.
// No caps when `monitor` stopped the welding: the caller tests monitor.stopped().
Mesh hole_caps(const Mesh& mesh, const Monitor& monitor = Monitor{});
// The same from the half-edge buckets of the mesh's welded corners (mesh_topology.h; built with
// no vertex map when the triangles already refer to welded vertices). No caps for empty buckets.
Mesh hole_caps(const Mesh& mesh, const HalfEdgeBuckets& edges);

}  // namespace ca
