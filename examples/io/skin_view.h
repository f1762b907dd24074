// skin_view.h: the C ABI's view of a skin read with a mesh (ca_skin_view over caio::SkinData's
// arrays), for the tool and the benchmarks that hand a file's skin to ca_bone_colliders_build.
#pragma once
#include <coverage_axis.h>

#include "mesh_io.h"

namespace caio {

// A ca_skin_view borrowing `mesh.skin`'s arrays (valid while the mesh lives and is not changed);
// the vertex count is the mesh's. A mesh without a skin gives a view of no joints, which the
// library refuses as it should refuse a missing skin.
inline ca_skin_view skin_view(const MeshData& mesh) {
    ca_skin_view v;
    ca_skin_view_defaults(&v, sizeof v);
    const SkinData& s = mesh.skin;
    v.joint_count = s.joint_names.size();
    v.parents = s.parents.empty() ? nullptr : s.parents.data();
    v.inverse_bind = s.inverse_bind.empty() ? nullptr : s.inverse_bind.data();
    v.vertex_count = mesh.positions.size() / 3;
    v.influences = s.influences;
    v.vertex_joints = s.vertex_joints.empty() ? nullptr : s.vertex_joints.data();
    v.vertex_weights = s.vertex_weights.empty() ? nullptr : s.vertex_weights.data();
    return v;
}

}  // namespace caio
