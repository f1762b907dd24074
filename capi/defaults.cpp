// defaults.cpp: the one place the defaults of every input struct live. The C API reads them for
// fields past a caller's struct_size and for NULL options; the inline *_init of the header, the
// CLI and the bindings get them through the exported ca_*_defaults(pointer, struct_size).
#include "struct_size.h"

namespace capi {

template <class T>
static T zeroed() {
    T v;
    std::memset(&v, 0, sizeof v);
    v.struct_size = sizeof v;
    return v;
}

template <> ca_context_desc defaults<ca_context_desc>() {
    ca_context_desc d = zeroed<ca_context_desc>();
    d.threads = 0;                 // all cores
    d.progress_interval_s = 0;     // every update
    d.time_limit_s = 0;            // unlimited
    return d;
}

template <> ca_surface_view defaults<ca_surface_view>() { return zeroed<ca_surface_view>(); }
template <> ca_skeleton_view defaults<ca_skeleton_view>() { return zeroed<ca_skeleton_view>(); }

template <> ca_candidate_options defaults<ca_candidate_options>() {
    ca_candidate_options o = zeroed<ca_candidate_options>();
    o.generator = CA_CANDIDATES_VORONOI;
    o.cover_samples = 1500;
    o.voronoi_samples = 4000;
    o.random_candidates = 10000;
    o.seed = 1;
    o.connect_samples = 10000;
    return o;
}

template <> ca_select_options defaults<ca_select_options>() {
    ca_select_options o = zeroed<ca_select_options>();
    o.dilation = CA_DILATE_OFFSET;
    o.delta = 0.02;
    o.scale = 1.5;
    o.solver = CA_SOLVER_EXACT;
    o.time_limit_s = 60;
    o.skip_uncoverable = 0;
    o.target_count = 0;
    o.target_tolerance = 1e-4;
    o.divide_threshold = 100000;
    o.effort = CA_EFFORT_FAST;
    o.target_error = 0;
    o.probe_fit = 0;
    return o;
}

template <> ca_connect_options defaults<ca_connect_options>() {
    ca_connect_options o = zeroed<ca_connect_options>();
    o.method = CA_CONNECT_AUTO;
    o.remove_outside = 1;
    o.fill_holes = 1;
    o.reconnect = 1;
    o.fit = 0;
    o.fit_iterations = 10;
    return o;
}

template <> ca_evaluate_options defaults<ca_evaluate_options>() {
    ca_evaluate_options o = zeroed<ca_evaluate_options>();
    o.surface_samples = 30000;
    o.envelope_samples = 100000;
    o.seed = 1;
    return o;
}

namespace {
// Writes the defaults into the caller's first struct_size bytes (a published size only).
template <class T>
ca_status fill_defaults(T* out, uint32_t struct_size) {
    if (!out) return CA_ERROR_NULL_POINTER;
    if (!published_size<T>(struct_size)) return CA_ERROR_STRUCT_SIZE;
    const T d = defaults<T>();
    std::memcpy(out, &d, struct_size);
    out->struct_size = struct_size;
    return CA_OK;
}
}  // namespace

}  // namespace capi

extern "C" {
ca_status ca_context_desc_defaults(ca_context_desc* d, uint32_t size) { return capi::fill_defaults(d, size); }
ca_status ca_surface_view_defaults(ca_surface_view* v, uint32_t size) { return capi::fill_defaults(v, size); }
ca_status ca_candidate_options_defaults(ca_candidate_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
ca_status ca_select_options_defaults(ca_select_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
ca_status ca_connect_options_defaults(ca_connect_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
ca_status ca_skeleton_view_defaults(ca_skeleton_view* v, uint32_t size) { return capi::fill_defaults(v, size); }
ca_status ca_evaluate_options_defaults(ca_evaluate_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
}
