// ca_candidates.cpp: step 1 at the C boundary: the caller's surface view or arrays converted for
// the core's step (lib/steps/candidates_step.cpp), the candidate set's arrays in the caller's
// units, and its getters.
#include "conversions.h"
#include "results.h"

#include <cstring>

using ca::Status;
using ca::Vec3;
using namespace capi;

namespace {

// The set's arrays in the caller's units.
void publish(ca_candidate_set* set) {
    const ca::Normalization& n = set->core.surface.norm;
    std::vector<Vec3> c(set->core.balls.size());
    for (size_t i = 0; i < c.size(); ++i) c[i] = set->core.balls[i].center;
    fill(set->centers, set->allocator, c, n);
    set->radii.assign(set->allocator, c.size());
    for (size_t i = 0; i < c.size(); ++i) set->radii.data[i] = set->core.balls[i].radius * n.scale;
    fill(set->samples, set->allocator, set->core.cover_samples, n);
}

}  // namespace

extern "C" {

ca_status ca_candidates(ca_context* ctx, const ca_surface_view* surface, const ca_candidate_options* options,
                        ca_candidate_set** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        const ca::Monitor monitor = ctx->monitor();  // one budget for the whole call
        ca_candidate_options o;
        Status st = read_arguments({{out, "out"}, {surface, "surface"}}, options, o);
        if (!st.ok()) return st;
        ca::SurfaceInput input;
        st = read_surface(surface, true, input);
        if (!st.ok()) return st;
        capi::Pending<ca_candidate_set> res(capi::make_result<ca_candidate_set>(ctx));
        st = ca::candidates_step(std::move(input), to_core(o, ctx->desc.threads), monitor, res.obj->core);
        if (!st.ok()) return st;
        publish(res.obj);
        *out = res.release();
        return Status::success();
    });
}

ca_status ca_candidates_from_arrays(ca_context* ctx, const double* samples, size_t sample_count, size_t sample_stride,
                                    const double* centers, size_t center_stride, const double* radii,
                                    size_t radius_stride, size_t ball_count, double reference_length,
                                    ca_candidate_set** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        Status st = check_pointers({{out, "out"}, {samples, "samples"}, {centers, "centers"}, {radii, "radii"}});
        if (!st.ok()) return st;
        if (sample_count > UINT32_MAX || ball_count > UINT32_MAX)
            return ca::fail(ca::Code::invalid_argument, "more than 2^32 - 1 samples or balls");
        std::vector<Vec3> s, c;
        st = read_points(samples, sample_count, sample_stride, "sample_stride", s);
        if (!st.ok()) return st;
        st = read_points(centers, ball_count, center_stride, "center_stride", c);
        if (!st.ok()) return st;
        size_t rs;
        st = check_stride(radius_stride, sizeof(double), "radius_stride", rs);
        if (!st.ok()) return st;
        std::vector<double> r(ball_count);
        for (size_t i = 0; i < ball_count; ++i) r[i] = read_element<double, 1>(radii, rs, i)[0];
        capi::Pending<ca_candidate_set> res(capi::make_result<ca_candidate_set>(ctx));
        st = ca::candidates_from_arrays(s, c, r, reference_length, res.obj->core);
        if (!st.ok()) return st;
        publish(res.obj);
        *out = res.release();
        return Status::success();
    });
}

// The caller's reference; selections made from the set keep it alive until they go.
void ca_candidate_set_destroy(ca_candidate_set* set) { capi::release_set(set); }
size_t ca_candidate_set_count(const ca_candidate_set* s) { return s ? s->radii.size : 0; }
const double* ca_candidate_set_centers(const ca_candidate_set* s) { return s ? s->centers.data : nullptr; }
const double* ca_candidate_set_radii(const ca_candidate_set* s) { return s ? s->radii.data : nullptr; }
size_t ca_candidate_set_sample_count(const ca_candidate_set* s) { return s ? s->core.cover_samples.size() : 0; }
const double* ca_candidate_set_samples(const ca_candidate_set* s) { return s ? s->samples.data : nullptr; }
double ca_candidate_set_reference_length(const ca_candidate_set* s) { return s ? s->core.surface.norm.scale : 0; }
int32_t ca_candidate_set_flipped(const ca_candidate_set* s) { return s && s->core.surface.flipped ? 1 : 0; }
int32_t ca_candidate_set_normals(const ca_candidate_set* s) { return s ? int32_t(s->core.surface.normals_source) : 0; }
uint64_t ca_candidate_set_outlier_count(const ca_candidate_set* s) { return s ? uint64_t(s->core.report.outliers) : 0; }
uint64_t ca_candidate_set_normals_replaced(const ca_candidate_set* s) {
    return s ? uint64_t(s->core.surface.normals_replaced) : 0;
}

ca_status ca_candidate_set_copy(const ca_candidate_set* s, double* centers, double* radii, size_t capacity, size_t* count) {
    if (!s || !count) return CA_ERROR_NULL_POINTER;
    *count = s->radii.size;
    if (capacity < s->radii.size) return CA_ERROR_BUFFER_TOO_SMALL;
    if (centers && s->centers.size) std::memcpy(centers, s->centers.data, s->centers.size * sizeof(double));
    if (radii && s->radii.size) std::memcpy(radii, s->radii.data, s->radii.size * sizeof(double));
    return CA_OK;
}

}  // extern "C"
