// ca_rig.cpp: the rig at the C boundary: the surface and skeleton views and the options converted
// for the core's step (lib/steps/rig_step.cpp), its joints and per-vertex arrays copied into the
// result, and the getters (the conversions: conversions.cpp).
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

extern "C" {

ca_status ca_rig_build(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                       const ca_rig_options* options, ca_rig** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        const ca::Monitor monitor = ctx->monitor();  // one budget for the whole call
        ca_rig_options o;
        ca::SurfaceInput input;
        ca::Skeleton sk;
        Status st = read_per_vertex_arguments(surface, skeleton, options, out, o, input, sk);
        if (!st.ok()) return st;
        ca::Rig rig;
        st = ca::rig_step(input, sk, to_core(o, ctx->desc.threads), monitor, rig);
        if (!st.ok()) return st;
        Pending<ca_rig> r(make_result<ca_rig>(ctx));
        ca_rig& a = *r.obj;
        const size_t nj = rig.joints.size(), nv = rig.vertex_joints.size();
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
        fill_influences(a.joints, a.weights, a.allocator, rig.vertex_joints, rig.vertex_weights);
        a.vertex_branches.assign(a.allocator, nv);
        for (size_t i = 0; i < nv; ++i) a.vertex_branches.data[i] = rig.vertex_branch[i];
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
