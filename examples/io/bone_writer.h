// bone_writer.h: colliders per bone (--bone-colliders, docs/bone_colliders.md) written where
// engines load them: on the joint nodes of a skinned glTF as glTF physics (KHR_implicit_shapes,
// KHR_physics_rigid_bodies with kinematic motion, OMI_physics_* where the shapes allow), and, for
// a VRM 1.0 input, as VRMC_springBone colliders on the same nodes.
//
// Each collider is given in its joint's bind frame: the frame the joint's inverse bind matrix
// takes the mesh to. Skinning moves a mesh point v dominated by joint j to W_j * IBM_j * v, W_j the
// joint node's current world matrix; a child node of the joint whose local transform is the
// collider's placement in the bind frame lands at W_j * placement, so it follows that part of the
// mesh in every pose, whether or not the joint's rest world matrix equals inverse(IBM_j). The
// collider node's local transform is therefore the placement itself, never corrected by the rest
// pose.
#pragma once
#include "mesh_io.h"

#include <string>
#include <vector>

namespace caio {

// One collider: its joint (an index into SkinData's joints) and its placement in the joint's bind
// frame (ColliderShape: a sphere, kind 0, or a capsule, kind 1, along the placement's +Y).
struct BoneCollider {
    uint32_t joint = 0;
    ColliderShape placed;
};

// What the writer made, for the JSON report: per collider, its node and its joint's node.
struct BoneCollidersWritten {
    std::vector<int> collider_nodes, joint_nodes;
    bool rewritten = false;   // the input glTF's own document was written back
    bool vrm = false;         // VRMC_springBone colliders were added
};

// Writes the colliders to `path` (.glb, or .gltf with the buffer embedded).
//  - `input` a glTF (.glb/.gltf) whose skin `mesh.skin` was read from (skin.gltf_nodes filled):
//    the input's own document (meshes, skins, animations, materials, extensions) with one collider
//    node added under each collider's joint node. Its buffers are merged into one; a buffer in an
//    external file is read from the input's folder (a relative path inside it only). When the
//    document carries VRMC_vrm, VRMC_springBone (specVersion 1.0) colliders are added too: one per
//    collider on the joint's node (a sphere {offset, radius} or a capsule {offset, radius, tail}
//    with ONE radius: the larger of the two when `conservative`, so the shape still holds the
//    tapered one, else the smaller, so it stays inside), one colliderGroup per joint; existing
//    springs, colliders and groups are kept.
//  - otherwise (FBX and other formats, the --rig skin): a new .glb holding the mesh (bind pose),
//    the skin (one node per joint, in its hierarchy, placed by skin.joint_world, or by
//    inverse(inverse_bind) when that is empty; the inverse bind matrices; JOINTS_n/WEIGHTS_n) and
//    the colliders on the joint nodes.
// False with "path: what" on inconsistent arrays, a non-finite value, an unreadable input or a
// write error; nothing is written then.
bool write_bone_colliders(const std::string& path, const std::string& input, const MeshData& mesh,
                          const std::vector<BoneCollider>& colliders, bool conservative, BoneCollidersWritten& written,
                          std::string& error);

// Whether `input` is a glTF file whose document the writer rewrites (a .glb or .gltf with a skin
// read from it).
bool rewrites_input(const std::string& input, const MeshData& mesh);

}  // namespace caio
