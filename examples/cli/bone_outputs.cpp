// bone_outputs.cpp: --bone-colliders OUT.glb and --bone-colliders-json FILE.json: one collider per
// bone of the input's skin (or of the rig of the skeleton, for an input without one) through
// ca_bone_colliders_build, written on the joints' nodes (bone_writer.h) and as JSON: per collider
// its joint, its node, its placement in the joint's bind frame and its containment and overlap,
// then the stats.
#include "bone_writer.h"
#include "cli.h"
#include "output_file.h"
#include "skin_view.h"

#include <memory>

namespace cli {
namespace {

Failure usage_failure(const std::string& message) { return Failure{"USAGE_ERROR", -1, message, 2}; }

// The rig of the skeleton as a skin: joint j at p_j, its bind frame the mesh frame moved to p_j
// (inverse bind: a translation by -p_j), 4 weights per vertex.
bool rig_skin(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton* sk, const RunOptions& o, caio::SkinData& skin,
              Failure& failure) {
    const RigPtr rig = build_rig(ctx, mesh, sk, o, failure);
    if (!rig) return false;
    const size_t nj = ca_rig_joint_count(rig.get()), nv = ca_rig_vertex_count(rig.get());
    const double* p = ca_rig_joint_positions(rig.get());
    skin = caio::SkinData{};
    skin.parents.assign(ca_rig_joint_parents(rig.get()), ca_rig_joint_parents(rig.get()) + nj);
    for (size_t j = 0; j < nj; ++j) {
        skin.joint_names.push_back("joint_" + std::to_string(j));
        for (int sign : {-1, 1}) {
            std::vector<double>& m = sign < 0 ? skin.inverse_bind : skin.joint_world;
            const size_t at = m.size();
            m.resize(at + 16, 0.0);
            m[at] = m[at + 5] = m[at + 10] = m[at + 15] = 1;
            for (int c = 0; c < 3; ++c) m[at + 12 + size_t(c)] = sign * p[3 * j + size_t(c)];
        }
    }
    skin.influences = CA_INFLUENCES;
    skin.vertex_joints.assign(ca_rig_vertex_joints(rig.get()), ca_rig_vertex_joints(rig.get()) + CA_INFLUENCES * nv);
    skin.vertex_weights.assign(ca_rig_vertex_weights(rig.get()), ca_rig_vertex_weights(rig.get()) + CA_INFLUENCES * nv);
    return true;
}

// --skip-bones: each name to its joint; an unknown name is a usage error.
bool skipped_joints(const std::string& names, const caio::SkinData& skin, std::vector<uint32_t>& out, Failure& failure) {
    size_t b = 0;
    while (b < names.size()) {
        const size_t e = std::min(names.find(',', b), names.size());
        const std::string name = names.substr(b, e - b);
        b = e + 1;
        if (name.empty()) continue;
        size_t j = 0;
        while (j < skin.joint_names.size() && skin.joint_names[j] != name) ++j;
        if (j == skin.joint_names.size()) return failure = usage_failure("--skip-bones: the skin has no joint named '" + name + "'"), false;
        out.push_back(uint32_t(j));
    }
    return true;
}

const char* kind_name(int kind) { return kind == CA_PROXY_CAPSULE ? "capsule" : "sphere"; }

}  // namespace

Failure bone_skin_missing(const std::string& input) {
    return usage_failure(input + " has no skin: --bone-colliders needs a skinned input (a glTF skin, FBX bones) or --rig "
                                 "to skin it to the skeleton's rig");
}

bool write_bone_outputs(ca_context* ctx, const std::string& input, const caio::MeshData& mesh, const ca_candidate_set* set,
                        const ca_skeleton* sk, const RunOptions& o, const Outputs& out, Json& report, Failure& failure) {
    if (out.bone_colliders.empty() && out.bone_colliders_json.empty()) return true;
    // the input's skin, else the rig's (asked for with --rig)
    caio::MeshData rigged;
    const caio::MeshData* skinned = &mesh;
    const bool from_rig = mesh.skin.empty();
    if (from_rig) {
        if (out.rig.empty()) return failure = bone_skin_missing(input), false;
        rigged.positions = mesh.positions;
        rigged.triangles = mesh.triangles;
        if (!rig_skin(ctx, mesh, sk, o, rigged.skin, failure)) return false;
        skinned = &rigged;
    }
    const caio::SkinData& skin = skinned->skin;
    std::vector<uint32_t> skip;
    if (!skipped_joints(o.skip_bones, skin, skip, failure)) return false;

    const ca_skin_view view = caio::skin_view(*skinned);
    ca_bone_collider_options bo = o.bone;
    bo.skip_joints = skip.empty() ? nullptr : skip.data();
    bo.skip_count = skip.size();
    const ca_skeleton_view skv = skeleton_view(sk);
    ca_bone_colliders* raw = nullptr;
    const ca_status st = ca_bone_colliders_build(ctx, set, &skv, &view, &bo, &raw);
    std::unique_ptr<ca_bone_colliders, void (*)(ca_bone_colliders*)> bones(raw, ca_bone_colliders_destroy);
    if (st != CA_OK) return failure = library_failure(ctx, st, "bone colliders"), false;

    const size_t n = ca_bone_colliders_count(bones.get());
    const uint32_t* joints = ca_bone_colliders_joints(bones.get());
    std::vector<caio::BoneCollider> colliders(n);
    for (size_t i = 0; i < n; ++i) {
        ca_proxy_placement pl;
        pl.struct_size = sizeof pl;
        ca_bone_colliders_placement(bones.get(), i, &pl);   // i < count: cannot fail
        caio::BoneCollider& c = colliders[i];
        c.joint = joints[i];
        c.placed.kind = pl.kind;
        for (int k = 0; k < 3; ++k) c.placed.translation[k] = pl.center[k];
        for (int k = 0; k < 4; ++k) c.placed.rotation[k] = pl.rotation[k];
        c.placed.radius_top = pl.radius_top;
        c.placed.radius_bottom = pl.radius_bottom;
        c.placed.height = pl.height;
    }
    ca_bone_collider_stats s;
    s.struct_size = sizeof s;
    ca_bone_colliders_stats(bones.get(), &s);
    const bool conservative = o.bone.mode == CA_PROXY_CONSERVATIVE;
    std::string err;
    caio::BoneCollidersWritten written;
    if (!out.bone_colliders.empty() &&
        !caio::write_bone_colliders(out.bone_colliders, input, *skinned, colliders, conservative, written, err))
        return failure = file_failure(err), false;

    const Json stats = {{"skin", from_rig ? "rig" : "input"},
                        {"mode", o.bone_mode},
                        {"joints", skin.joint_names.size()},
                        {"count", n},
                        {"joints_with_collider", s.joints_with_collider},
                        {"joints_skipped", s.joints_skipped},
                        {"contained_fraction", s.contained_fraction},
                        {"union_volume", s.union_volume},
                        {"outside_volume", s.outside_volume},
                        {"neighbour_overlap", s.neighbour_overlap},
                        {"input_rewritten", written.rewritten},
                        {"vrm_spring_bone", written.vrm},
                        {"time_s", s.time_s}};
    report["bone_colliders"] = stats;
    if (!out.bone_colliders_json.empty()) {
        const double* contained = ca_bone_colliders_contained(bones.get());
        const double* overlap = ca_bone_colliders_overlap(bones.get());
        Json list = Json::array();
        for (size_t i = 0; i < n; ++i) {
            const caio::ColliderShape& c = colliders[i].placed;
            Json item = {{"joint", colliders[i].joint},
                         {"joint_name", skin.joint_names[colliders[i].joint]},
                         {"kind", kind_name(c.kind)},
                         {"translation", {c.translation[0], c.translation[1], c.translation[2]}},
                         {"rotation", {c.rotation[0], c.rotation[1], c.rotation[2], c.rotation[3]}},
                         {"radius_top", c.radius_top},
                         {"radius_bottom", c.radius_bottom},
                         {"height", c.height},
                         {"contained", contained[i]},
                         {"overlap", overlap[i]}};
            item["joint_node"] = written.joint_nodes.empty() ? Json(nullptr) : Json(written.joint_nodes[i]);
            item["node"] = written.collider_nodes.empty() ? Json(nullptr) : Json(written.collider_nodes[i]);
            list.push_back(item);
        }
        Json doc = {{"format_version", kFormatVersion}, {"joint_names", skin.joint_names}, {"parents", skin.parents},
                    {"colliders", list}};
        for (const auto& [key, value] : stats.items()) doc[key] = value;
        if (!caio::write_bytes(out.bone_colliders_json, doc.dump(1) + "\n", err)) return failure = file_failure(err), false;
    }
    return true;
}

}  // namespace cli
