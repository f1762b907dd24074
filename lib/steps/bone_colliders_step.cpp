// bone_colliders_step.cpp: bone colliders as one request: the set's surface (a triangle mesh),
// its queries and inner balls handed to the bone-collider step (bones.h), which maps its colliders
// to the caller's units and the joints' frames itself.
#include "steps.h"

namespace ca {

Status bone_colliders_step(const CandidateSet& set, const Skin& skin, const BoneColliderOptions& opt,
                           const Monitor& monitor, BoneColliderResult& out) {
    out = BoneColliderResult{};
    if (Status st = check_mesh_set(set, "bone colliders"); !st.ok()) return st;
    const size_t inner = set.balls.size() - std::min(set.surface_balls, set.balls.size());
    return make_bone_colliders(set.surface.mesh, set.queries, set.surface.norm, set.balls, inner, skin, opt, monitor, out);
}

}  // namespace ca
