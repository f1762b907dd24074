// gltf_physics.h: engine proxies as glTF physics, the colliders engines load (docs/proxies.md):
// each primitive a node placed and turned as ColliderShape says, carrying
// KHR_physics_rigid_bodies {collider: {geometry: {shape: i}}} with shape i of the document's
// KHR_implicit_shapes (sphere {radius}; capsule {height, radiusTop, radiusBottom} along the node's
// +Y; box {size}). Without `motion` a collider is static; `kinematic` gives each node
// motion {isKinematic: true}, a body that follows its parent (a bone) instead of the simulation.
// Where every shape of a call has a twin in Godot's OMI_physics_shape (spheres, boxes, capsules of
// equal radii: OMI has no tapered capsule), the nodes also carry OMI_physics_body {collider: {shape}}.
// Used by the skeleton's glTF (--gltf), the rig (--rig) and the colliders file (--colliders).
#pragma once
#include "gltf_builder.h"
#include "mesh_io.h"

#include <string>
#include <vector>

namespace caio {
namespace gltf {

struct ColliderOptions {
    // The node the colliders hang under; -1: a new root node of scene 0 named `group`.
    int parent = -1;
    std::string group = "colliders";
    // The parent's world placement (translation, rotation x y z w): the colliders' nodes are
    // written in its frame, so that they land where ColliderShape (world) says.
    double parent_translation[3] = {0, 0, 0};
    double parent_rotation[4] = {0, 0, 0, 1};
    bool kinematic = false;
    bool omi = true;
    std::string name = "collider";   // nodes are named name_0, name_1, ...
};

// Adds `name` to doc["extensionsUsed"] (made an array if it is not one) unless it is there.
void use_extension(json& doc, const char* name);

// Whether a shape has volume: the glTF physics extensions forbid a zero radius, a zero box side
// and a capsule whose radii are both zero (and non-finite numbers are refused before writing).
bool collider_has_volume(const ColliderShape& c);

// Appends one node per shape to doc["nodes"] as children of the parent, and its collider when the
// shape has volume (a shape without gets its node, placed, with no collider); adds the shapes to
// the document's extensions and the extensions to extensionsUsed. Returns the nodes' indices, in
// order. `doc` must have "nodes" and "scenes"[0].
std::vector<size_t> add_colliders(json& doc, const std::vector<ColliderShape>& shapes, const ColliderOptions& options);

}  // namespace gltf

// --colliders: the mesh (its triangles, in the caller's units) as a node named "mesh" and the
// proxies as static colliders under a root node named "colliders". .glb or .gltf by the path's
// extension; false with "path: what" on bad arrays, a non-finite value or a write error.
bool write_colliders(const std::string& path, const MeshData& mesh, const std::vector<ProxyData>& proxies,
                     std::string& error);

// Whether every number of the proxies and their placements is finite ("" if so, else what is not).
std::string proxies_finite(const std::vector<ProxyData>& proxies);

}  // namespace caio
