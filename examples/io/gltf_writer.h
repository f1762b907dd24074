// gltf_writer.h: writes a medial skeleton as glTF 2.0 for engines and DCC tools (Blender, ...):
// one node per ball (a shared unit-sphere mesh, translated to the centre and scaled by the
// radius), the edges as a LINES primitive and the faces as a TRIANGLES primitive of one
// "skeleton" mesh whose vertices carry the radius as the custom attribute _RADIUS. Engine proxies,
// when given, are the children of a "proxies" node: one node per primitive, placed and turned as
// an engine places it, carrying its collider as glTF physics (gltf_physics.h: KHR_implicit_shapes
// and KHR_physics_rigid_bodies, static) and its parameters in `extras` ({"kind": "sphere",
// "center", "radius"}, {"kind": "capsule", "a", "radius_a", "b", "radius_b"} or {"kind": "box",
// "center", "rotation", "half_extents"}, in the skeleton's units); a sphere's node has a child
// showing the ball mesh.
#pragma once
#include "mesh_io.h"

#include <string>

namespace caio {

// .glb: binary container (JSON chunk + BIN chunk). .gltf: JSON with the buffer embedded as a
// base64 data URI (one self-contained file). Positions and radii are stored as float32, as
// glTF requires for POSITION. Returns false with "path: what" on a bad skeleton, an unknown
// extension or a write error.
bool write_gltf(const std::string& path, const SkeletonData& s, std::string& error,
                const std::vector<ProxyData>& proxies = {});

}  // namespace caio
