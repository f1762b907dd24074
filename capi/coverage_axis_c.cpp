// coverage_axis_c.cpp: the extern "C" layer over the C++ core. It checks arguments and
// struct sizes, reads the caller's strided arrays, converts between the caller's units and the
// core's unit-cube units, owns the opaque results, and is the exception firewall: no C++
// exception crosses this file's functions, every failure becomes a ca_status plus a message.
#include "coverage_axis.h"

#include "candidates.h"
#include "connect.h"
#include "evaluate.h"
#include "selection.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

using ca::Code;
using ca::Status;
using ca::Vec3;

// ---- context ---------------------------------------------------------------------------------

struct ca_context {
    ca_context_desc desc{};
    std::atomic<int> cancel{0};
    std::string last_error;

    void* allocate(size_t bytes) const {
        if (bytes == 0) bytes = 1;
        return desc.alloc ? desc.alloc(desc.alloc_user, bytes) : std::malloc(bytes);
    }
    void release(void* p) const {
        if (!p) return;
        if (desc.free) desc.free(desc.alloc_user, p);
        else std::free(p);
    }
    void log(int32_t level, const std::string& msg) const {
        if (desc.log) desc.log(desc.log_user, level, msg.c_str());
    }
    ca::Monitor monitor() const {
        ca::Monitor m;
        m.cancel_flag = &cancel;
        if (desc.progress) {
            ca_progress_fn fn = desc.progress;
            void* user = desc.progress_user;
            m.progress = [fn, user](const char* stage, double f) { return fn(user, stage, f) == 0; };
        }
        return m;
    }
};

namespace {

// Result arrays live in memory from the context's allocator; the allocator travels with the
// result so destroy works after the context is gone.
struct Allocator {
    ca_alloc_fn alloc = nullptr;
    ca_free_fn free = nullptr;
    void* user = nullptr;
    void* get(size_t bytes) const {
        if (bytes == 0) bytes = 1;
        void* p = alloc ? alloc(user, bytes) : std::malloc(bytes);
        if (!p) throw std::bad_alloc();
        return p;
    }
    void put(void* p) const {
        if (!p) return;
        if (free) free(user, p);
        else std::free(p);
    }
};

template <class T>
struct Array {
    T* data = nullptr;
    size_t size = 0;
    void assign(const Allocator& a, size_t n) {
        data = static_cast<T*>(a.get(n * sizeof(T)));
        size = n;
    }
    void release(const Allocator& a) { a.put(data); data = nullptr; size = 0; }
};

Allocator allocator_of(const ca_context* ctx) { return {ctx->desc.alloc, ctx->desc.free, ctx->desc.alloc_user}; }

// Allocates a result object with the context's allocator and constructs it in place.
template <class T>
T* make_result(const ca_context* ctx) {
    Allocator a = allocator_of(ctx);
    void* mem = a.get(sizeof(T));
    T* obj = new (mem) T();
    obj->allocator = a;
    return obj;
}
template <class T>
void destroy_result(T* obj) {
    if (!obj) return;
    Allocator a = obj->allocator;
    obj->release_arrays();
    obj->~T();
    a.put(obj);
}

ca_status to_status(Code c) { return static_cast<ca_status>(c); }

// The exception firewall: runs f (returning ca::Status), records the message, never throws.
template <class F>
ca_status guarded(ca_context* ctx, F&& f) noexcept {
    if (!ctx) return CA_ERROR_NULL_POINTER;
    try {
        ctx->last_error.clear();
        Status st = f();
        if (!st.ok()) ctx->last_error = st.message;
        return to_status(st.code);
    } catch (const std::bad_alloc&) {
        try { ctx->last_error = "out of memory"; } catch (...) {}
        return CA_ERROR_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        try { ctx->last_error = std::string("internal error: ") + e.what(); } catch (...) {}
        return CA_ERROR_INTERNAL;
    } catch (...) {
        try { ctx->last_error = "internal error: unknown exception"; } catch (...) {}
        return CA_ERROR_INTERNAL;
    }
}

Status null_pointer(const char* what) { return ca::fail(Code::null_pointer, std::string(what) + " is NULL"); }

// Option structs: NULL means defaults; otherwise struct_size must be one this library knows.
template <class T>
Status read_options(const T* in, T& out, void (*init)(T*), const char* name) {
    init(&out);
    if (!in) return Status::success();
    if (in->struct_size != sizeof(T))
        return ca::fail(Code::struct_size, std::string(name) + ".struct_size is " + std::to_string(in->struct_size) +
                                               ", this library expects " + std::to_string(sizeof(T)) +
                                               " (fill it with " + name + "_init)");
    std::memcpy(&out, in, sizeof(T));
    return Status::success();
}

Status check_stride(size_t stride, size_t min, const char* name, size_t& out) {
    if (stride != 0 && stride < min)
        return ca::fail(Code::invalid_argument, std::string(name) + " (" + std::to_string(stride) +
                                                    " bytes) is smaller than one element (" + std::to_string(min) + " bytes)");
    out = stride ? stride : min;
    return Status::success();
}

const double* at(const double* base, size_t stride, size_t i) {
    return reinterpret_cast<const double*>(reinterpret_cast<const char*>(base) + i * stride);
}

Status read_points(const double* base, size_t count, size_t stride, const char* name, std::vector<Vec3>& out) {
    size_t s;
    Status st = check_stride(stride, 3 * sizeof(double), name, s);
    if (!st.ok()) return st;
    out.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const double* p = at(base, s, i);
        out[i] = Vec3(p[0], p[1], p[2]);
    }
    return Status::success();
}

// Reads a surface view into raw arrays (no validation of values: prepare_surface does that).
Status read_surface(const ca_surface_view* surface, bool want_normals, ca::Mesh& raw, std::vector<Vec3>& normals) {
    if (surface->struct_size != sizeof(ca_surface_view))
        return ca::fail(Code::struct_size, "ca_surface_view.struct_size is " + std::to_string(surface->struct_size) +
                                               ", this library expects " + std::to_string(sizeof(ca_surface_view)) +
                                               " (fill it with ca_surface_view_init)");
    if (surface->vertex_count > 0 && !surface->positions) return null_pointer("surface->positions");
    if (surface->triangle_count > 0 && !surface->triangles) return null_pointer("surface->triangles");
    if (surface->vertex_count > UINT32_MAX) return ca::fail(Code::invalid_argument, "more than 2^32 - 1 vertices");
    Status st = read_points(surface->positions, surface->vertex_count, surface->position_stride,
                            "surface->position_stride", raw.vertices);
    if (!st.ok()) return st;
    size_t ts;
    st = check_stride(surface->triangle_stride, 3 * sizeof(uint32_t), "surface->triangle_stride", ts);
    if (!st.ok()) return st;
    raw.triangles.resize(surface->triangle_count);
    for (size_t t = 0; t < surface->triangle_count; ++t) {
        const uint32_t* f = reinterpret_cast<const uint32_t*>(reinterpret_cast<const char*>(surface->triangles) + t * ts);
        raw.triangles[t] = {f[0], f[1], f[2]};
    }
    if (want_normals && surface->triangle_count == 0 && surface->normals)
        return read_points(surface->normals, surface->vertex_count, surface->normal_stride, "surface->normal_stride", normals);
    return Status::success();
}

void fill(Array<double>& a, const Allocator& al, const std::vector<Vec3>& pts, const ca::Normalization& n) {
    a.assign(al, 3 * pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        const Vec3 p = n.to_user(pts[i]);
        a.data[3 * i] = p.x(); a.data[3 * i + 1] = p.y(); a.data[3 * i + 2] = p.z();
    }
}

}  // namespace

// ---- results ------------------------------------------------------------------------------------

struct ca_candidate_set {
    Allocator allocator;
    ca::CandidateSet core;
    Array<double> centers, radii, samples;
    void release_arrays() { centers.release(allocator); radii.release(allocator); samples.release(allocator); }
};

struct ca_selection {
    Allocator allocator;
    const ca_candidate_set* set = nullptr;
    ca::Selection core;
    Array<uint32_t> indices, uncovered;
    Array<double> centers, radii, dilated;
    ca_select_stats stats{};
    void release_arrays() {
        indices.release(allocator); uncovered.release(allocator);
        centers.release(allocator); radii.release(allocator); dilated.release(allocator);
    }
};

struct ca_skeleton {
    Allocator allocator;
    Array<double> centers, radii;
    Array<uint32_t> edges, faces;
    ca_skeleton_stats stats{};
    void release_arrays() {
        centers.release(allocator); radii.release(allocator); edges.release(allocator); faces.release(allocator);
    }
};

namespace {

void publish(ca_candidate_set* set) {
    const ca::Normalization& n = set->core.surface.norm;
    std::vector<Vec3> c(set->core.balls.size());
    for (size_t i = 0; i < c.size(); ++i) c[i] = set->core.balls[i].center;
    fill(set->centers, set->allocator, c, n);
    set->radii.assign(set->allocator, c.size());
    for (size_t i = 0; i < c.size(); ++i) set->radii.data[i] = set->core.balls[i].radius * n.scale;
    fill(set->samples, set->allocator, set->core.cover_samples, n);
}

// Owns a freshly made result until it is handed to the caller.
template <class T>
struct Pending {
    T* obj;
    explicit Pending(T* o) : obj(o) {}
    ~Pending() { destroy_result(obj); }
    T* release() { T* o = obj; obj = nullptr; return o; }
};

}  // namespace

// ---- versions and status ------------------------------------------------------------------------

extern "C" {

uint32_t ca_version(void) { return CA_VERSION_NUMBER; }
uint32_t ca_abi_version(void) { return CA_ABI_VERSION; }

const char* ca_status_string(ca_status s) {
    switch (s) {
        case CA_OK: return "CA_OK: success";
        case CA_ERROR_INVALID_ARGUMENT: return "CA_ERROR_INVALID_ARGUMENT: an option is out of range";
        case CA_ERROR_NULL_POINTER: return "CA_ERROR_NULL_POINTER: a required pointer is NULL";
        case CA_ERROR_STRUCT_SIZE: return "CA_ERROR_STRUCT_SIZE: struct_size is not one this library knows";
        case CA_ERROR_INVALID_INPUT: return "CA_ERROR_INVALID_INPUT: NaN/Inf coordinate, out-of-range index or bad normal";
        case CA_ERROR_DEGENERATE_INPUT: return "CA_ERROR_DEGENERATE_INPUT: empty, flat or too few distinct points";
        case CA_ERROR_UNCOVERABLE: return "CA_ERROR_UNCOVERABLE: some samples are covered by no candidate ball";
        case CA_ERROR_GEOMETRY: return "CA_ERROR_GEOMETRY: the Delaunay or power diagram computation failed";
        case CA_ERROR_SOLVER: return "CA_ERROR_SOLVER: the set-cover solver failed";
        case CA_ERROR_CANCELLED: return "CA_ERROR_CANCELLED: cancelled by the caller";
        case CA_ERROR_OUT_OF_MEMORY: return "CA_ERROR_OUT_OF_MEMORY: out of memory";
        case CA_ERROR_BUFFER_TOO_SMALL: return "CA_ERROR_BUFFER_TOO_SMALL: the output buffer is too small";
        case CA_ERROR_INTERNAL: return "CA_ERROR_INTERNAL: internal error";
        case CA_ERROR_NO_CANDIDATES: return "CA_ERROR_NO_CANDIDATES: no inner candidate ball was found";
        default: return "unknown ca_status";
    }
}

// ---- context --------------------------------------------------------------------------------------

void ca_context_desc_init(ca_context_desc* d) {
    if (!d) return;
    std::memset(d, 0, sizeof *d);
    d->struct_size = sizeof *d;
    d->threads = 0;
}

ca_status ca_context_create(const ca_context_desc* desc, ca_context** out) {
    if (!out) return CA_ERROR_NULL_POINTER;
    *out = nullptr;
    ca_context_desc d;
    ca_context_desc_init(&d);
    if (desc) {
        if (desc->struct_size != sizeof(ca_context_desc)) return CA_ERROR_STRUCT_SIZE;
        d = *desc;
        if ((d.alloc == nullptr) != (d.free == nullptr)) return CA_ERROR_INVALID_ARGUMENT;
        if (d.threads < 0) return CA_ERROR_INVALID_ARGUMENT;
    }
    ca_context* ctx = new (std::nothrow) ca_context();
    if (!ctx) return CA_ERROR_OUT_OF_MEMORY;
    ctx->desc = d;
    *out = ctx;
    return CA_OK;
}

void ca_context_destroy(ca_context* ctx) { delete ctx; }
void ca_context_request_cancel(ca_context* ctx) { if (ctx) ctx->cancel.store(1); }
void ca_context_clear_cancel(ca_context* ctx) { if (ctx) ctx->cancel.store(0); }
const char* ca_context_last_error(const ca_context* ctx) { return ctx ? ctx->last_error.c_str() : "ctx is NULL"; }

// ---- step 1 ---------------------------------------------------------------------------------------

void ca_surface_view_init(ca_surface_view* v) {
    if (!v) return;
    std::memset(v, 0, sizeof *v);
    v->struct_size = sizeof *v;
}

void ca_candidate_options_init(ca_candidate_options* o) {
    if (!o) return;
    std::memset(o, 0, sizeof *o);
    o->struct_size = sizeof *o;
    o->generator = CA_CANDIDATES_VORONOI;
    o->cover_samples = 1500;
    o->voronoi_samples = 4000;
    o->random_candidates = 10000;
    o->seed = 1;
    o->connect_samples = 10000;
}

ca_status ca_candidates(ca_context* ctx, const ca_surface_view* surface, const ca_candidate_options* options,
                        ca_candidate_set** out) {
    if (out) *out = nullptr;
    return guarded(ctx, [&]() -> Status {
        if (!out) return null_pointer("out");
        if (!surface) return null_pointer("surface");
        ca_candidate_options o;
        Status st = read_options(options, o, ca_candidate_options_init, "ca_candidate_options");
        if (!st.ok()) return st;
        if (o.generator != CA_CANDIDATES_VORONOI && o.generator != CA_CANDIDATES_RANDOM)
            return ca::fail(Code::invalid_argument, "unknown candidate generator " + std::to_string(o.generator));
        ca::Mesh raw;
        std::vector<Vec3> normals;
        st = read_surface(surface, true, raw, normals);
        if (!st.ok()) return st;
        ca::Surface surf;
        st = ca::prepare_surface(std::move(raw), std::move(normals), surf);
        if (!st.ok()) return st;
        if (surf.flipped) ctx->log(2, "the mesh faces inward (negative signed volume); it was flipped");
        if (surf.dropped_triangles)
            ctx->log(1, std::to_string(surf.dropped_triangles) + " zero-area triangles were ignored");

        ca::CandidateOptions co;
        co.generator = static_cast<ca::Generator>(o.generator);
        co.cover_samples = o.cover_samples;
        co.voronoi_samples = o.voronoi_samples;
        co.random_candidates = o.random_candidates;
        co.seed = o.seed;
        co.connect_samples = o.connect_samples;
        co.threads = ctx->desc.threads;
        Pending<ca_candidate_set> res(make_result<ca_candidate_set>(ctx));
        st = ca::generate_candidates(std::move(surf), co, ctx->monitor(), res.obj->core);
        if (!st.ok()) return st;
        publish(res.obj);
        ctx->log(1, std::to_string(res.obj->core.cover_samples.size()) + " surface samples, " +
                        std::to_string(res.obj->core.balls.size()) + " candidate balls");
        *out = res.release();
        return Status::success();
    });
}

ca_status ca_candidates_from_arrays(ca_context* ctx, const double* samples, size_t sample_count, size_t sample_stride,
                                    const double* centers, size_t center_stride, const double* radii,
                                    size_t radius_stride, size_t ball_count, double reference_length,
                                    ca_candidate_set** out) {
    if (out) *out = nullptr;
    return guarded(ctx, [&]() -> Status {
        if (!out) return null_pointer("out");
        if (!samples) return null_pointer("samples");
        if (!centers) return null_pointer("centers");
        if (!radii) return null_pointer("radii");
        if (sample_count == 0) return ca::fail(Code::degenerate_input, "no surface samples");
        if (ball_count == 0) return ca::fail(Code::no_candidates, "no candidate balls");
        if (sample_count > UINT32_MAX || ball_count > UINT32_MAX)
            return ca::fail(Code::invalid_argument, "more than 2^32 - 1 samples or balls");
        if (!(std::isfinite(reference_length) && reference_length >= 0))
            return ca::fail(Code::invalid_argument, "reference_length must be finite and >= 0");
        std::vector<Vec3> s, c;
        Status st = read_points(samples, sample_count, sample_stride, "sample_stride", s);
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
        Pending<ca_candidate_set> res(make_result<ca_candidate_set>(ctx));
        ca::CandidateSet& core = res.obj->core;
        auto [lo, hi] = ca::bounding_box(s);
        double length = reference_length > 0 ? reference_length : (hi - lo).maxCoeff();
        if (!(length > 0)) return ca::fail(Code::degenerate_input, "all samples coincide; give reference_length");
        core.surface.norm.origin = lo;
        core.surface.norm.scale = length;
        for (const Vec3& p : s) core.cover_samples.push_back(core.surface.norm.to_internal(p));
        for (size_t i = 0; i < c.size(); ++i) {
            const double r = *at(radii, rs, i);
            if (!(std::isfinite(r) && r >= 0))
                return ca::fail(Code::invalid_input, "ball " + std::to_string(i) + " has a negative, NaN or infinite radius");
            core.balls.push_back({core.surface.norm.to_internal(c[i]), r / length});
        }
        publish(res.obj);
        *out = res.release();
        return Status::success();
    });
}

void ca_candidate_set_destroy(ca_candidate_set* set) { destroy_result(set); }
size_t ca_candidate_set_count(const ca_candidate_set* s) { return s ? s->radii.size : 0; }
const double* ca_candidate_set_centers(const ca_candidate_set* s) { return s ? s->centers.data : nullptr; }
const double* ca_candidate_set_radii(const ca_candidate_set* s) { return s ? s->radii.data : nullptr; }
size_t ca_candidate_set_sample_count(const ca_candidate_set* s) { return s ? s->core.cover_samples.size() : 0; }
const double* ca_candidate_set_samples(const ca_candidate_set* s) { return s ? s->samples.data : nullptr; }
double ca_candidate_set_reference_length(const ca_candidate_set* s) { return s ? s->core.surface.norm.scale : 0; }
int32_t ca_candidate_set_flipped(const ca_candidate_set* s) { return s && s->core.surface.flipped ? 1 : 0; }

ca_status ca_candidate_set_copy(const ca_candidate_set* s, double* centers, double* radii, size_t capacity, size_t* count) {
    if (!s || !count) return CA_ERROR_NULL_POINTER;
    *count = s->radii.size;
    if (capacity < s->radii.size) return CA_ERROR_BUFFER_TOO_SMALL;
    if (centers && s->centers.size) std::memcpy(centers, s->centers.data, s->centers.size * sizeof(double));
    if (radii && s->radii.size) std::memcpy(radii, s->radii.data, s->radii.size * sizeof(double));
    return CA_OK;
}

// ---- step 2 ---------------------------------------------------------------------------------------

void ca_select_options_init(ca_select_options* o) {
    if (!o) return;
    std::memset(o, 0, sizeof *o);
    o->struct_size = sizeof *o;
    o->dilation = CA_DILATE_OFFSET;
    o->delta = 0.02;
    o->scale = 1.5;
    o->solver = CA_SOLVER_EXACT;
    o->time_limit_s = 60;
    o->target_tolerance = 1e-4;
    o->divide_threshold = 100000;
    o->effort = CA_EFFORT_FAST;
}

ca_status ca_select(ca_context* ctx, const ca_candidate_set* set, const ca_select_options* options, ca_selection** out) {
    if (out) *out = nullptr;
    return guarded(ctx, [&]() -> Status {
        if (!out) return null_pointer("out");
        if (!set) return null_pointer("set");
        ca_select_options o;
        Status st = read_options(options, o, ca_select_options_init, "ca_select_options");
        if (!st.ok()) return st;
        if (o.dilation != CA_DILATE_OFFSET && o.dilation != CA_DILATE_SCALE)
            return ca::fail(Code::invalid_argument, "unknown dilation " + std::to_string(o.dilation));
        if (o.solver < CA_SOLVER_EXACT || o.solver > CA_SOLVER_CAPP)
            return ca::fail(Code::invalid_argument, "unknown solver " + std::to_string(o.solver));
        if (std::isnan(o.time_limit_s)) return ca::fail(Code::invalid_argument, "time_limit_s is NaN");
        if (o.effort != CA_EFFORT_FAST && o.effort != CA_EFFORT_PROVE)
            return ca::fail(Code::invalid_argument, "unknown effort " + std::to_string(o.effort));
        if (o.target_count && !(std::isfinite(o.target_tolerance) && o.target_tolerance > 0))
            return ca::fail(Code::invalid_argument, "target_tolerance must be a finite number > 0");
        ca::SelectOptions so;
        so.dilation = static_cast<ca::Dilation>(o.dilation);
        so.delta = o.delta;
        so.scale = o.scale;
        so.skip_uncoverable = o.skip_uncoverable != 0;
        so.cover.solver = static_cast<ca::Solver>(o.solver);
        so.cover.time_limit_s = o.time_limit_s;
        so.cover.effort = static_cast<ca::Effort>(o.effort);
        so.target_count = o.target_count;
        so.target_tolerance = o.target_tolerance;
        so.dc_threshold = o.divide_threshold;
        so.threads = ctx->desc.threads;
        const size_t ns = set->core.cover_samples.size(), nb = set->core.balls.size();
        if (o.ignorable_samples) so.cover.ignorable_samples.assign(o.ignorable_samples, o.ignorable_samples + ns);
        if (o.forced_in) so.cover.forced_in.assign(o.forced_in, o.forced_in + nb);
        if (o.forced_out) so.cover.forced_out.assign(o.forced_out, o.forced_out + nb);

        Pending<ca_selection> res(make_result<ca_selection>(ctx));
        ca_selection& r = *res.obj;
        r.set = set;
        st = ca::select_balls(set->core, so, ctx->monitor(), r.core);
        if (!st.ok()) return st;
        const ca::Normalization& n = set->core.surface.norm;
        const size_t k = r.core.indices.size();
        r.indices.assign(r.allocator, k);
        r.radii.assign(r.allocator, k);
        r.dilated.assign(r.allocator, k);
        std::vector<Vec3> c(k);
        for (size_t i = 0; i < k; ++i) {
            const ca::Ball& b = set->core.balls[r.core.indices[i]];
            r.indices.data[i] = r.core.indices[i];
            c[i] = b.center;
            r.radii.data[i] = b.radius * n.scale;
            r.dilated.data[i] = r.core.dilated_radii[i] * n.scale;
        }
        fill(r.centers, r.allocator, c, n);
        r.uncovered.assign(r.allocator, r.core.cover.uncovered.size());
        for (size_t i = 0; i < r.uncovered.size; ++i) r.uncovered.data[i] = r.core.cover.uncovered[i];
        const ca::CoverResult& cr = r.core.cover;
        ca_select_stats& s = r.stats;
        s.struct_size = sizeof s;
        s.proven_optimal = cr.proven_optimal;
        s.solver = o.solver;
        s.objective = cr.objective;
        s.lower_bound = cr.lower_bound;
        s.gap = cr.gap;
        s.delta_absolute = r.core.delta * n.scale;
        s.time_reduce_s = cr.time_reduce_s;
        s.time_solve_s = cr.time_solve_s;
        s.time_total_s = r.core.time_total_s;
        s.rows_before = cr.rows_before; s.cols_before = cr.cols_before;
        s.rows_after = cr.rows_after; s.cols_after = cr.cols_after; s.forced = cr.forced;
        s.components = cr.components;
        s.probes = r.core.probes;
        s.parts = r.core.parts;
        s.scale_used = r.core.scale;
        if (!cr.uncovered.empty())
            ctx->log(2, std::to_string(cr.uncovered.size()) + " samples are covered by no ball and were skipped");
        *out = res.release();
        return Status::success();
    });
}

void ca_selection_destroy(ca_selection* s) { destroy_result(s); }
size_t ca_selection_count(const ca_selection* s) { return s ? s->indices.size : 0; }
const uint32_t* ca_selection_indices(const ca_selection* s) { return s ? s->indices.data : nullptr; }
const double* ca_selection_centers(const ca_selection* s) { return s ? s->centers.data : nullptr; }
const double* ca_selection_radii(const ca_selection* s) { return s ? s->radii.data : nullptr; }
const double* ca_selection_dilated_radii(const ca_selection* s) { return s ? s->dilated.data : nullptr; }
size_t ca_selection_uncovered_count(const ca_selection* s) { return s ? s->uncovered.size : 0; }
const uint32_t* ca_selection_uncovered(const ca_selection* s) { return s ? s->uncovered.data : nullptr; }

ca_status ca_selection_stats(const ca_selection* sel, ca_select_stats* stats) {
    if (!sel || !stats) return CA_ERROR_NULL_POINTER;
    if (stats->struct_size != sizeof(ca_select_stats)) return CA_ERROR_STRUCT_SIZE;
    *stats = sel->stats;
    return CA_OK;
}

// ---- step 3 ---------------------------------------------------------------------------------------

void ca_connect_options_init(ca_connect_options* o) {
    if (!o) return;
    std::memset(o, 0, sizeof *o);
    o->struct_size = sizeof *o;
    o->method = CA_CONNECT_AUTO;
    o->remove_outside = 1;
    o->fill_holes = 1;
    o->reconnect = 1;
}

ca_status ca_connect(ca_context* ctx, const ca_candidate_set* set, const ca_selection* selection,
                     const ca_connect_options* options, ca_skeleton** out) {
    if (out) *out = nullptr;
    return guarded(ctx, [&]() -> Status {
        if (!out) return null_pointer("out");
        if (!set) return null_pointer("set");
        if (!selection) return null_pointer("selection");
        if (selection->set != set)
            return ca::fail(Code::invalid_argument, "the selection was made from another candidate set");
        ca_connect_options o;
        Status st = read_options(options, o, ca_connect_options_init, "ca_connect_options");
        if (!st.ok()) return st;
        if (o.method != CA_CONNECT_POWER && o.method != CA_CONNECT_MEDIAL && o.method != CA_CONNECT_AUTO)
            return ca::fail(Code::invalid_argument, "unknown connection method " + std::to_string(o.method));
        const auto t0 = std::chrono::steady_clock::now();
        ca::ConnectOptions co;
        const bool has_mesh = !set->core.surface.point_cloud && !set->core.surface.mesh.triangles.empty();
        if (o.method == CA_CONNECT_AUTO) co.method = has_mesh ? ca::ConnectMethod::medial : ca::ConnectMethod::power;
        else co.method = static_cast<ca::ConnectMethod>(o.method);
        co.remove_outside = o.remove_outside != 0;
        co.fill_holes = o.fill_holes != 0;
        co.reconnect = o.reconnect != 0;
        co.threads = ctx->desc.threads;
        ca::Skeleton sk;
        st = ca::connect_balls(set->core, selection->core, co, ctx->monitor(), sk);
        if (!st.ok()) return st;
        const ca::TopologyStats topo = ca::topology(sk);
        Pending<ca_skeleton> res(make_result<ca_skeleton>(ctx));
        ca_skeleton& r = *res.obj;
        const ca::Normalization& n = set->core.surface.norm;
        std::vector<Vec3> c(sk.balls.size());
        for (size_t i = 0; i < c.size(); ++i) c[i] = sk.balls[i].center;
        fill(r.centers, r.allocator, c, n);
        r.radii.assign(r.allocator, c.size());
        for (size_t i = 0; i < c.size(); ++i) r.radii.data[i] = sk.balls[i].radius * n.scale;
        r.edges.assign(r.allocator, 2 * sk.edges.size());
        for (size_t i = 0; i < sk.edges.size(); ++i) { r.edges.data[2 * i] = sk.edges[i][0]; r.edges.data[2 * i + 1] = sk.edges[i][1]; }
        r.faces.assign(r.allocator, 3 * sk.faces.size());
        for (size_t i = 0; i < sk.faces.size(); ++i)
            for (int k = 0; k < 3; ++k) r.faces.data[3 * i + size_t(k)] = sk.faces[i][size_t(k)];
        ca_skeleton_stats& s = r.stats;
        s.struct_size = sizeof s;
        s.vertices = sk.balls.size();
        s.edges = sk.edges.size();
        s.faces = sk.faces.size();
        s.components = topo.components;
        s.isolated = topo.isolated;
        s.betti1 = topo.betti1;
        s.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        s.method = static_cast<int32_t>(co.method);
        *out = res.release();
        return Status::success();
    });
}

void ca_skeleton_destroy(ca_skeleton* s) { destroy_result(s); }
size_t ca_skeleton_vertex_count(const ca_skeleton* s) { return s ? s->radii.size : 0; }
const double* ca_skeleton_centers(const ca_skeleton* s) { return s ? s->centers.data : nullptr; }
const double* ca_skeleton_radii(const ca_skeleton* s) { return s ? s->radii.data : nullptr; }
size_t ca_skeleton_edge_count(const ca_skeleton* s) { return s ? s->edges.size / 2 : 0; }
const uint32_t* ca_skeleton_edges(const ca_skeleton* s) { return s ? s->edges.data : nullptr; }
size_t ca_skeleton_face_count(const ca_skeleton* s) { return s ? s->faces.size / 3 : 0; }
const uint32_t* ca_skeleton_faces(const ca_skeleton* s) { return s ? s->faces.data : nullptr; }

ca_status ca_skeleton_stats_get(const ca_skeleton* sk, ca_skeleton_stats* stats) {
    if (!sk || !stats) return CA_ERROR_NULL_POINTER;
    if (stats->struct_size != sizeof(ca_skeleton_stats)) return CA_ERROR_STRUCT_SIZE;
    *stats = sk->stats;
    return CA_OK;
}

// ---- evaluation ----------------------------------------------------------------------------------

void ca_skeleton_view_init(ca_skeleton_view* v) {
    if (!v) return;
    std::memset(v, 0, sizeof *v);
    v->struct_size = sizeof *v;
}

ca_status ca_skeleton_get_view(const ca_skeleton* sk, ca_skeleton_view* v) {
    if (!sk || !v) return CA_ERROR_NULL_POINTER;
    if (v->struct_size != sizeof(ca_skeleton_view)) return CA_ERROR_STRUCT_SIZE;
    v->centers = sk->centers.data;
    v->radii = sk->radii.data;
    v->vertex_count = sk->radii.size;
    v->edges = sk->edges.data;
    v->edge_count = sk->edges.size / 2;
    v->faces = sk->faces.data;
    v->face_count = sk->faces.size / 3;
    return CA_OK;
}

void ca_evaluate_options_init(ca_evaluate_options* o) {
    if (!o) return;
    std::memset(o, 0, sizeof *o);
    o->struct_size = sizeof *o;
    o->surface_samples = 30000;
    o->envelope_samples = 100000;
    o->seed = 1;
}

ca_status ca_evaluate(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                      const ca_evaluate_options* options, ca_evaluation* result) {
    return guarded(ctx, [&]() -> Status {
        if (!surface) return null_pointer("surface");
        if (!skeleton) return null_pointer("skeleton");
        if (!result) return null_pointer("result");
        if (result->struct_size != sizeof(ca_evaluation))
            return ca::fail(Code::struct_size, "ca_evaluation.struct_size is " + std::to_string(result->struct_size) +
                                                   ", this library expects " + std::to_string(sizeof(ca_evaluation)));
        if (skeleton->struct_size != sizeof(ca_skeleton_view))
            return ca::fail(Code::struct_size, "ca_skeleton_view.struct_size is " + std::to_string(skeleton->struct_size) +
                                                   ", this library expects " + std::to_string(sizeof(ca_skeleton_view)) +
                                                   " (fill it with ca_skeleton_view_init)");
        ca_evaluate_options o;
        Status st = read_options(options, o, ca_evaluate_options_init, "ca_evaluate_options");
        if (!st.ok()) return st;
        if (o.surface_samples == 0 || o.envelope_samples == 0)
            return ca::fail(Code::invalid_argument, "surface_samples and envelope_samples must be at least 1");
        ca::Mesh raw;
        std::vector<Vec3> normals;
        st = read_surface(surface, false, raw, normals);
        if (!st.ok()) return st;
        ca::Surface surf;
        st = ca::prepare_surface(std::move(raw), {}, surf, false);
        if (!st.ok()) return st;

        const size_t nv = skeleton->vertex_count;
        if (nv == 0) return ca::fail(Code::degenerate_input, "the skeleton has no vertices");
        if (!skeleton->centers) return null_pointer("skeleton->centers");
        if (!skeleton->radii) return null_pointer("skeleton->radii");
        if (skeleton->edge_count && !skeleton->edges) return null_pointer("skeleton->edges");
        if (skeleton->face_count && !skeleton->faces) return null_pointer("skeleton->faces");
        ca::Skeleton sk;
        const ca::Normalization& n = surf.norm;
        for (size_t i = 0; i < nv; ++i) {
            const Vec3 c(skeleton->centers[3 * i], skeleton->centers[3 * i + 1], skeleton->centers[3 * i + 2]);
            const double r = skeleton->radii[i];
            if (!c.allFinite() || !(std::isfinite(r) && r >= 0))
                return ca::fail(Code::invalid_input, "skeleton ball " + std::to_string(i) + " has a NaN, infinite or negative value");
            sk.balls.push_back({n.to_internal(c), r / n.scale});
        }
        for (size_t e = 0; e < skeleton->edge_count; ++e) {
            const uint32_t a = skeleton->edges[2 * e], b = skeleton->edges[2 * e + 1];
            if (a >= nv || b >= nv)
                return ca::fail(Code::invalid_input, "skeleton edge " + std::to_string(e) + " references vertex " +
                                                         std::to_string(std::max(a, b)) + " of " + std::to_string(nv));
            sk.edges.push_back({a, b});
        }
        for (size_t f = 0; f < skeleton->face_count; ++f) {
            ca::Tri t{skeleton->faces[3 * f], skeleton->faces[3 * f + 1], skeleton->faces[3 * f + 2]};
            for (uint32_t v : t)
                if (v >= nv)
                    return ca::fail(Code::invalid_input, "skeleton face " + std::to_string(f) + " references vertex " +
                                                             std::to_string(v) + " of " + std::to_string(nv));
            sk.faces.push_back(t);
        }
        ca::EvaluateOptions eo;
        eo.surface_samples = o.surface_samples;
        eo.envelope_samples = o.envelope_samples;
        eo.seed = o.seed;
        eo.threads = ctx->desc.threads;
        const auto t0 = std::chrono::steady_clock::now();
        ca::EvaluateResult er;
        st = ca::evaluate(surf.mesh, sk, eo, ctx->monitor(), er);
        if (!st.ok()) return st;
        ca_evaluation out{};
        out.struct_size = sizeof out;
        out.hd_surface_to_recon = er.hd_surface_to_recon;
        out.mean_surface_to_recon = er.mean_surface_to_recon;
        out.hd_recon_to_surface = er.hd_recon_to_surface;
        out.mean_recon_to_surface = er.mean_recon_to_surface;
        out.hd_two_sided = er.hd_two_sided;
        out.diagonal = er.diagonal * n.scale;
        out.surface_samples_used = er.surface_samples_used;
        out.envelope_samples_used = er.envelope_samples_used;
        out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        *result = out;
        return Status::success();
    });
}

}  // extern "C"
