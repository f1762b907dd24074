// ca_correspondence.cpp: the correspondence at the C boundary: the surface and skeleton views and
// the options converted for the core's step (lib/steps/correspondence_step.cpp), its per-vertex
// arrays copied into the result, and the getters (the conversions: conversions.cpp).
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

extern "C" {

ca_status ca_correspond(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                        const ca_correspondence_options* options, ca_correspondence** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        const ca::Monitor monitor = ctx->monitor();  // one budget for the whole call
        ca_correspondence_options o;
        ca::SurfaceInput input;
        ca::Skeleton sk;
        Status st = read_per_vertex_arguments(surface, skeleton, options, out, o, input, sk);
        if (!st.ok()) return st;
        ca::Correspondence c;
        st = ca::correspondence_step(input, sk, to_core(o, ctx->desc.threads), monitor, c);
        if (!st.ok()) return st;
        Pending<ca_correspondence> r(make_result<ca_correspondence>(ctx));
        ca_correspondence& a = *r.obj;
        const size_t n = c.balls.size();
        a.vertex_count = n;
        fill_influences(a.balls, a.weights, a.allocator, c.balls, c.weights);
        a.nearest_kinds.assign(a.allocator, n);
        a.nearest_indices.assign(a.allocator, n);
        for (size_t i = 0; i < n; ++i) {
            a.nearest_kinds.data[i] = static_cast<int32_t>(c.nearest_kind[i]);
            a.nearest_indices.data[i] = c.nearest_index[i];
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
