// ca_bone_colliders.cpp: bone colliders at the C boundary: the skin view and options read into the
// core's request (struct sizes, NULL arrays and counts checked here; values by the core's step,
// lib/bones/skin.cpp), the colliders (in their joints' frames) and stats copied out, and their
// getters. The result holds nothing of the set.
#include "conversions.h"
#include "results.h"

using ca::Status;
using namespace capi;

namespace {

Status read_skin(const ca_skin_view* in, ca::Skin& out) {
    ca_skin_view v;
    Status st = read_input(in, v);
    if (!st.ok()) return st;
    if (v.joint_count == 0) return ca::fail(ca::Code::invalid_input, "skin: joint_count must be at least 1");
    if (!v.parents) return null_pointer("skin->parents");
    if (v.vertex_count && !v.vertex_joints) return null_pointer("skin->vertex_joints");
    if (v.vertex_count && !v.vertex_weights) return null_pointer("skin->vertex_weights");
    if (v.influences < 1 || v.influences > 8)
        return ca::fail(ca::Code::invalid_input,
                        "skin: influences must be 1 to 8 joints per vertex (got " + std::to_string(v.influences) + ")");
    if (v.joint_count > UINT32_MAX || v.vertex_count > UINT32_MAX)
        return ca::fail(ca::Code::invalid_input, "skin: more than 2^32 - 1 joints or vertices");
    out.parents.assign(v.parents, v.parents + v.joint_count);
    if (v.inverse_bind) {
        out.inverse_bind.resize(v.joint_count);
        for (size_t j = 0; j < v.joint_count; ++j)
            out.inverse_bind[j] = Eigen::Map<const Eigen::Matrix4d>(v.inverse_bind + 16 * j);   // column-major
    }
    out.influences = v.influences;
    const size_t n = v.vertex_count * v.influences;
    out.vertex_joints.assign(v.vertex_joints, v.vertex_joints + n);
    out.vertex_weights.assign(v.vertex_weights, v.vertex_weights + n);
    return Status::success();
}

void publish(ca_bone_colliders& r, const ca::BoneColliderResult& res) {
    const size_t n = res.colliders.size();
    r.joints.assign(r.allocator, n);
    r.kinds.assign(r.allocator, n);
    r.centers.assign(r.allocator, 6 * n);
    r.radii.assign(r.allocator, 2 * n);
    r.contained.assign(r.allocator, n);
    r.overlap.assign(r.allocator, n);
    for (size_t i = 0; i < n; ++i) {
        const ca::BoneCollider& c = res.colliders[i];
        r.joints.data[i] = c.joint;
        r.kinds.data[i] = static_cast<int32_t>(c.shape.kind);
        for (int k = 0; k < 3; ++k) {
            r.centers.data[6 * i + size_t(k)] = c.shape.a.center[k];
            r.centers.data[6 * i + 3 + size_t(k)] = c.shape.b.center[k];
        }
        r.radii.data[2 * i] = c.shape.a.radius;
        r.radii.data[2 * i + 1] = c.shape.b.radius;
        r.contained.data[i] = c.contained;
        r.overlap.data[i] = c.overlap;
    }
    const ca::BoneColliderStats& s = res.stats;
    ca_bone_collider_stats& o = r.stats;
    o = zeroed<ca_bone_collider_stats>();
    o.contained_fraction = s.contained_fraction;
    o.union_volume = s.union_volume;
    o.outside_volume = s.outside_volume;
    o.neighbour_overlap = s.neighbour_overlap;
    o.joints_with_collider = s.joints_with_collider;
    o.joints_skipped = s.joints_skipped;
    o.time_s = s.time_s;
}

}  // namespace

extern "C" {

ca_status ca_bone_colliders_build(ca_context* ctx, const ca_candidate_set* set, const ca_skeleton_view* skeleton,
                                  const ca_skin_view* skin, const ca_bone_collider_options* options,
                                  ca_bone_colliders** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        ca_bone_collider_options o;
        Status st = read_arguments({{out, "out"}, {set, "set"}, {skin, "skin"}}, options, o);
        if (!st.ok()) return st;
        if (skeleton) {   // not used yet; a view given must still be readable
            ca::Skeleton sk;
            st = read_skeleton(skeleton, sk);
            if (!st.ok()) return st;
        }
        ca::Skin sk;
        st = read_skin(skin, sk);
        if (!st.ok()) return st;
        if (o.skip_count && !o.skip_joints) return null_pointer("options->skip_joints");
        ca::BoneColliderOptions bo = to_core(o, ctx->desc.threads);
        if (o.skip_count) bo.skip_joints.assign(o.skip_joints, o.skip_joints + o.skip_count);
        ca::BoneColliderResult result;
        st = ca::bone_colliders_step(set->core, sk, bo, ctx->monitor(), result);
        if (!st.ok()) return st;
        capi::Pending<ca_bone_colliders> res(capi::make_result<ca_bone_colliders>(ctx));
        publish(*res.obj, result);
        *out = res.release();
        return Status::success();
    });
}

void ca_bone_colliders_destroy(ca_bone_colliders* c) { destroy_result(c); }
size_t ca_bone_colliders_count(const ca_bone_colliders* c) { return c ? c->joints.size : 0; }
const uint32_t* ca_bone_colliders_joints(const ca_bone_colliders* c) { return c ? c->joints.data : nullptr; }
const double* ca_bone_colliders_contained(const ca_bone_colliders* c) { return c ? c->contained.data : nullptr; }
const double* ca_bone_colliders_overlap(const ca_bone_colliders* c) { return c ? c->overlap.data : nullptr; }

ca_status ca_bone_colliders_stats(const ca_bone_colliders* c, ca_bone_collider_stats* stats) {
    if (!c || !stats) return CA_ERROR_NULL_POINTER;
    return guarded_status([&] { return write_output(c->stats, stats); });
}

ca_status ca_bone_colliders_placement(const ca_bone_colliders* c, size_t index, ca_proxy_placement* placement) {
    if (!c || !placement) return CA_ERROR_NULL_POINTER;
    return guarded_status([&]() -> Status {
        if (index >= c->joints.size)
            return ca::fail(ca::Code::invalid_argument, "bone collider index " + std::to_string(index) +
                                                            " out of range (" + std::to_string(c->joints.size) +
                                                            " colliders)");
        ca::Proxy q;
        q.kind = static_cast<ca::ProxyKind>(c->kinds.data[index]);
        for (int k = 0; k < 3; ++k) {
            q.a.center[k] = c->centers.data[6 * index + size_t(k)];
            q.b.center[k] = c->centers.data[6 * index + 3 + size_t(k)];
        }
        q.a.radius = c->radii.data[2 * index];
        q.b.radius = c->radii.data[2 * index + 1];
        return write_output(to_c(ca::proxy_placement(q)), placement);
    });
}

}  // extern "C"
