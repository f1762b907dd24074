// ca_rig.cpp: the rig at the C boundary: the surface and skeleton views and the options converted
// for the core's step (lib/steps/rig_step.cpp), its joints and per-vertex arrays copied into the
// result, the getters, and the options' defaults (from ca::RigOptions; ca_rig_options_defaults is
// in defaults.cpp).
#include "conversions.h"

using ca::Status;
using namespace capi;

struct ca_rig {
    capi::Allocator allocator;
    capi::Array<double> positions, weights;
    capi::Array<int32_t> parents;
    capi::Array<uint32_t> joint_balls, joint_branches, joints, vertex_branches;
    size_t joint_count = 0, vertex_count = 0, branch_count = 0;
    void release_arrays() {
        positions.release(allocator); weights.release(allocator); parents.release(allocator);
        joint_balls.release(allocator); joint_branches.release(allocator); joints.release(allocator);
        vertex_branches.release(allocator);
    }
};

namespace capi {

template <> ca_rig_options defaults<ca_rig_options>() {
    const ca::RigOptions d;
    ca_rig_options o = zeroed<ca_rig_options>();
    o.root = d.root;
    o.max_joints = d.max_joints;
    o.joint_spacing = d.joint_spacing;
    o.min_branch = d.min_branch;
    o.smoothing = d.correspond.smoothing;
    return o;
}

}  // namespace capi

extern "C" {

ca_status ca_rig_build(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                       const ca_rig_options* options, ca_rig** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        ca_rig_options o;
        Status st = read_arguments({{surface, "surface"}, {skeleton, "skeleton"}, {out, "out"}}, options, o);
        if (!st.ok()) return st;
        const ca::Monitor monitor = ctx->monitor();
        ca::SurfaceInput input;
        ca::Skeleton sk;
        st = read_surface_and_skeleton(surface, skeleton, input, sk);
        if (!st.ok()) return st;
        ca::RigOptions ropt;
        ropt.root = o.root;
        ropt.max_joints = o.max_joints;
        ropt.joint_spacing = o.joint_spacing;
        ropt.min_branch = o.min_branch;
        ropt.correspond.smoothing = o.smoothing;
        ropt.correspond.threads = ctx->desc.threads;
        ca::Rig rig;
        st = ca::rig_step(input, sk, ropt, monitor, rig);
        if (!st.ok()) return st;
        Pending<ca_rig> r(make_result<ca_rig>(ctx));
        ca_rig& a = *r.obj;
        const size_t nj = rig.joints.size(), nv = rig.vertex_joints.size(), k = ca::kInfluences;
        a.joint_count = nj;
        a.vertex_count = nv;
        a.branch_count = rig.branch_count;
        a.positions.assign(a.allocator, 3 * nj);
        a.parents.assign(a.allocator, nj);
        a.joint_balls.assign(a.allocator, nj);
        a.joint_branches.assign(a.allocator, nj);
        for (size_t j = 0; j < nj; ++j) {
            for (int c = 0; c < 3; ++c) a.positions.data[3 * j + size_t(c)] = rig.joints[j][c];
            a.parents.data[j] = rig.parent[j];
            a.joint_balls.data[j] = rig.joint_ball[j];
            a.joint_branches.data[j] = rig.joint_branch[j];
        }
        a.joints.assign(a.allocator, k * nv);
        a.weights.assign(a.allocator, k * nv);
        a.vertex_branches.assign(a.allocator, nv);
        for (size_t i = 0; i < nv; ++i) {
            for (size_t j = 0; j < k; ++j) {
                a.joints.data[k * i + j] = rig.vertex_joints[i][j];
                a.weights.data[k * i + j] = rig.vertex_weights[i][j];
            }
            a.vertex_branches.data[i] = rig.vertex_branch[i];
        }
        *out = r.release();
        return Status::success();
    });
}

void ca_rig_destroy(ca_rig* rig) { capi::destroy_result(rig); }

size_t ca_rig_joint_count(const ca_rig* r) { return r ? r->joint_count : 0; }
const double* ca_rig_joint_positions(const ca_rig* r) { return r ? r->positions.data : nullptr; }
const int32_t* ca_rig_joint_parents(const ca_rig* r) { return r ? r->parents.data : nullptr; }
const uint32_t* ca_rig_joint_balls(const ca_rig* r) { return r ? r->joint_balls.data : nullptr; }
const uint32_t* ca_rig_joint_branches(const ca_rig* r) { return r ? r->joint_branches.data : nullptr; }
size_t ca_rig_branch_count(const ca_rig* r) { return r ? r->branch_count : 0; }
size_t ca_rig_vertex_count(const ca_rig* r) { return r ? r->vertex_count : 0; }
const uint32_t* ca_rig_vertex_joints(const ca_rig* r) { return r ? r->joints.data : nullptr; }
const double* ca_rig_vertex_weights(const ca_rig* r) { return r ? r->weights.data : nullptr; }
const uint32_t* ca_rig_vertex_branches(const ca_rig* r) { return r ? r->vertex_branches.data : nullptr; }

}  // extern "C"
