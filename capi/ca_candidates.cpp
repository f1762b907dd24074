// ca_candidates.cpp: step 1 at the C boundary: candidates from a surface view or from the
// caller's arrays, and the candidate set's getters.
#include "conversions.h"
#include "parallel.h"
#include "results.h"
#include "struct_size.h"

#include <cmath>
#include <cstring>

using ca::Code;
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
        if (o.generator != CA_CANDIDATES_VORONOI && o.generator != CA_CANDIDATES_RANDOM)
            return ca::fail(Code::invalid_argument, "unknown candidate generator " + std::to_string(o.generator));
        ca::Mesh raw;
        std::vector<Vec3> normals;
        ca::PointNormals trust = ca::PointNormals::trusted;
        st = read_surface(surface, true, raw, normals, &trust);
        if (!st.ok()) return st;
        if (monitor.stopped()) return monitor.stop_status("surface");
        ca::Surface surf;
        st = ca::prepare_surface(std::move(raw), std::move(normals), surf, true, trust, monitor,
                                 ca::resolve_threads(ctx->desc.threads));
        if (!st.ok()) return st;
        if (trust == ca::PointNormals::trusted && surf.normals_source == ca::NormalSource::oriented)
            ctx->log(2, "the point normals point against each other at " +
                            std::to_string(int(std::lround(100 * surf.disagreement_given))) +
                            "% of neighbouring pairs; they were re-oriented");
        if (monitor.stopped()) return monitor.stop_status("surface");
        if (surf.flipped) ctx->log(2, "the mesh faces inward (negative signed volume); it was flipped");
        if (surf.dropped_triangles)
            ctx->log(1, std::to_string(surf.dropped_triangles) + " zero-area triangles were ignored");
        if (surf.duplicate_triangles)
            ctx->log(1, std::to_string(surf.duplicate_triangles) + " repeated triangles were merged");

        ca::CandidateOptions co;
        co.generator = static_cast<ca::Generator>(o.generator);
        co.cover_samples = o.cover_samples;
        co.voronoi_samples = o.voronoi_samples;
        co.random_candidates = o.random_candidates;
        co.seed = o.seed;
        co.connect_samples = o.connect_samples;
        co.volumetric_only = o.volumetric_only != 0;
        co.threads = ctx->desc.threads;
        capi::Pending<ca_candidate_set> res(capi::make_result<ca_candidate_set>(ctx));
        st = ca::generate_candidates(std::move(surf), co, monitor, res.obj->core);
        if (!st.ok()) return st;
        publish(res.obj);
        ctx->log(1, std::to_string(res.obj->core.cover_samples.size()) + " surface samples, " +
                        std::to_string(res.obj->core.balls.size()) + " candidate balls");
        if (res.obj->core.surface_balls)
            ctx->log(1, std::to_string(res.obj->core.surface_balls) +
                            " surface balls for samples no inner ball reaches (open sheets or thin parts)");
        if (res.obj->core.delaunay_failed)
            ctx->log(2, "the Delaunay step failed (Qhull, after its retries); the candidates are fallback and surface balls");
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
        if (sample_count == 0) return ca::fail(Code::degenerate_input, "no surface samples");
        if (ball_count == 0) return ca::fail(Code::no_candidates, "no candidate balls");
        if (sample_count > UINT32_MAX || ball_count > UINT32_MAX)
            return ca::fail(Code::invalid_argument, "more than 2^32 - 1 samples or balls");
        if (!(std::isfinite(reference_length) && reference_length >= 0))
            return ca::fail(Code::invalid_argument, "reference_length must be finite and >= 0");
        std::vector<Vec3> s, c;
        st = read_points(samples, sample_count, sample_stride, "sample_stride", s);
        if (!st.ok()) return st;
        st = read_points(centers, ball_count, center_stride, "center_stride", c);
        if (!st.ok()) return st;
        size_t rs;
        st = check_stride(radius_stride, sizeof(double), "radius_stride", rs);
        if (!st.ok()) return st;
        for (size_t i = 0; i < s.size(); ++i)
            if (!s[i].allFinite()) return ca::fail(Code::invalid_input, "sample " + std::to_string(i) + " has a NaN or infinite coordinate");
        for (size_t i = 0; i < c.size(); ++i)
            if (!c[i].allFinite()) return ca::fail(Code::invalid_input, "ball " + std::to_string(i) + " has a NaN or infinite centre");
        capi::Pending<ca_candidate_set> res(capi::make_result<ca_candidate_set>(ctx));
        ca::CandidateSet& core = res.obj->core;
        auto [lo, hi] = ca::bounding_box(s);
        double length = reference_length > 0 ? reference_length : (hi - lo).maxCoeff();
        if (!(length > 0)) return ca::fail(Code::degenerate_input, "all samples coincide; give reference_length");
        core.surface.norm.origin = lo;
        core.surface.norm.scale = length;
        for (const Vec3& p : s) core.cover_samples.push_back(core.surface.norm.to_internal(p));
        for (size_t i = 0; i < c.size(); ++i) {
            const double r = read_element<double, 1>(radii, rs, i)[0];
            if (!(std::isfinite(r) && r >= 0))
                return ca::fail(Code::invalid_input, "ball " + std::to_string(i) + " has a negative, NaN or infinite radius");
            core.balls.push_back({core.surface.norm.to_internal(c[i]), r / length});
        }
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
uint64_t ca_candidate_set_outlier_count(const ca_candidate_set* s) { return s ? uint64_t(s->core.outliers) : 0; }

ca_status ca_candidate_set_copy(const ca_candidate_set* s, double* centers, double* radii, size_t capacity, size_t* count) {
    if (!s || !count) return CA_ERROR_NULL_POINTER;
    *count = s->radii.size;
    if (capacity < s->radii.size) return CA_ERROR_BUFFER_TOO_SMALL;
    if (centers && s->centers.size) std::memcpy(centers, s->centers.data, s->centers.size * sizeof(double));
    if (radii && s->radii.size) std::memcpy(radii, s->radii.data, s->radii.size * sizeof(double));
    return CA_OK;
}

}  // extern "C"
