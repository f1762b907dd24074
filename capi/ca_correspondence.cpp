// ca_correspondence.cpp: the correspondence at the C boundary: the surface and skeleton views and
// the options converted for the core's step (lib/steps/correspondence_step.cpp), its per-vertex
// arrays copied into the result, the getters, and the options' defaults (from
// ca::CorrespondOptions; ca_correspondence_options_defaults is in defaults.cpp).
#include "conversions.h"

using ca::Status;
using namespace capi;

struct ca_correspondence {
    capi::Allocator allocator;
    capi::Array<uint32_t> balls, nearest_indices;
    capi::Array<double> weights;
    capi::Array<int32_t> nearest_kinds;
    size_t vertex_count = 0;
    void release_arrays() {
        balls.release(allocator); nearest_indices.release(allocator);
        weights.release(allocator); nearest_kinds.release(allocator);
    }
};

namespace capi {

template <> ca_correspondence_options defaults<ca_correspondence_options>() {
    ca_correspondence_options o = zeroed<ca_correspondence_options>();
    o.smoothing = ca::CorrespondOptions{}.smoothing;
    return o;
}

}  // namespace capi

extern "C" {

ca_status ca_correspond(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                        const ca_correspondence_options* options, ca_correspondence** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        ca_correspondence_options o;
        Status st = read_arguments({{surface, "surface"}, {skeleton, "skeleton"}, {out, "out"}}, options, o);
        if (!st.ok()) return st;
        const ca::Monitor monitor = ctx->monitor();
        ca::SurfaceInput input;
        ca::Skeleton sk;
        st = read_surface_and_skeleton(surface, skeleton, input, sk);
        if (!st.ok()) return st;
        ca::CorrespondOptions copt;
        copt.smoothing = o.smoothing;
        copt.threads = ctx->desc.threads;
        ca::Correspondence c;
        st = ca::correspondence_step(input, sk, copt, monitor, c);
        if (!st.ok()) return st;
        Pending<ca_correspondence> r(make_result<ca_correspondence>(ctx));
        const size_t n = c.balls.size();
        const size_t k = ca::kInfluences;
        r.obj->vertex_count = n;
        r.obj->balls.assign(r.obj->allocator, k * n);
        r.obj->weights.assign(r.obj->allocator, k * n);
        r.obj->nearest_kinds.assign(r.obj->allocator, n);
        r.obj->nearest_indices.assign(r.obj->allocator, n);
        for (size_t i = 0; i < n; ++i) {
            for (size_t j = 0; j < k; ++j) {
                r.obj->balls.data[k * i + j] = c.balls[i][j];
                r.obj->weights.data[k * i + j] = c.weights[i][j];
            }
            r.obj->nearest_kinds.data[i] = static_cast<int32_t>(c.nearest_kind[i]);
            r.obj->nearest_indices.data[i] = c.nearest_index[i];
        }
        *out = r.release();
        return Status::success();
    });
}

void ca_correspondence_destroy(ca_correspondence* c) { capi::destroy_result(c); }

size_t ca_correspondence_vertex_count(const ca_correspondence* c) { return c ? c->vertex_count : 0; }
const uint32_t* ca_correspondence_balls(const ca_correspondence* c) { return c ? c->balls.data : nullptr; }
const double* ca_correspondence_weights(const ca_correspondence* c) { return c ? c->weights.data : nullptr; }
const int32_t* ca_correspondence_nearest_kinds(const ca_correspondence* c) { return c ? c->nearest_kinds.data : nullptr; }
const uint32_t* ca_correspondence_nearest_indices(const ca_correspondence* c) { return c ? c->nearest_indices.data : nullptr; }

}  // extern "C"
