// rig_writer.h: writes a mesh skinned to a rig as glTF 2.0 (.glb): the mesh with JOINTS_0 and
// WEIGHTS_0, one node per joint (translated from its parent), and a skin whose inverse bind
// matrices undo each joint's position, so the bind pose is the mesh as given.
#pragma once
#include "mesh_io.h"

#include <string>
#include <vector>

namespace caio {

struct RigData {
    std::vector<double> joints;            // x y z per joint
    std::vector<int32_t> parents;          // per joint: its parent (< its own index), -1 for the root (joint 0)
    std::vector<uint32_t> vertex_joints;   // 4 per vertex of the mesh
    std::vector<double> vertex_weights;    // 4 per vertex, sum 1
};

// The mesh (its triangles; a point cloud as points) skinned to the rig; engine proxies, when given,
// as static colliders under a root node "colliders" (gltf_physics.h). False with "path: what" on
// inconsistent arrays, a path not ending in .glb, a non-finite proxy, or a write error.
bool write_rig_glb(const std::string& path, const MeshData& mesh, const RigData& rig, std::string& error,
                   const std::vector<ProxyData>& proxies = {});

}  // namespace caio
