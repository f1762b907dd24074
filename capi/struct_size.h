// struct_size.h: the rule that lets the ABI grow. Every public struct starts with struct_size;
// a call accepts any size this library has published for the struct (sizeof of its layout in
// ABI 1, 2, ...: fields are only ever appended). Inputs are read up to the caller's size and the
// rest takes the defaults; outputs are written up to the caller's size only.
// The layouts of earlier ABI versions are frozen here, so their sizes are what the caller's
// compiler computed for them on this platform.
#pragma once

#include "coverage_axis.h"

#include "common.h"

#include <cstddef>
#include <cstring>
#include <string>

namespace capi {

// ---- layouts published in ABI 1 (only structs that grew since) ----
namespace abi1 {
struct ca_context_desc {
    uint32_t struct_size;
    ca_alloc_fn alloc;
    ca_free_fn free;
    void* alloc_user;
    ca_log_fn log;
    void* log_user;
    ca_progress_fn progress;
    void* progress_user;
    int32_t threads;
};
struct ca_select_stats {
    uint32_t struct_size;
    int32_t proven_optimal;
    int32_t solver;
    double objective, lower_bound, gap, delta_absolute, time_reduce_s, time_solve_s, time_total_s;
    uint64_t rows_before, cols_before, rows_after, cols_after, forced, components, probes, parts;
    double scale_used;
};
struct ca_select_options {
    uint32_t struct_size;
    int32_t dilation;
    double delta, scale;
    int32_t solver;
    double time_limit_s;
    int32_t skip_uncoverable;
    const uint8_t *ignorable_samples, *forced_in, *forced_out;
    uint32_t target_count;
    double target_tolerance;
    uint32_t divide_threshold;
    int32_t effort;
};
struct ca_connect_options {
    uint32_t struct_size;
    int32_t method, remove_outside, fill_holes, reconnect;
};
struct ca_surface_view {
    uint32_t struct_size;
    const double* positions;
    size_t vertex_count, position_stride;
    const uint32_t* triangles;
    size_t triangle_count, triangle_stride;
    const double* normals;
    size_t normal_stride;
};
struct ca_skeleton_stats {
    uint32_t struct_size;
    uint64_t vertices, edges, faces, components, isolated;
    int64_t betti1;
    double time_s;
    int32_t method;
};
}  // namespace abi1

// ---- as first published in ABI 2: ca_context_desc before time_limit_s, ca_select_stats before
// hd_reached, ca_select_options before probe_fit, ca_skeleton_stats before genus were appended ----
namespace abi2_first {
struct ca_context_desc {
    abi1::ca_context_desc abi1_fields;
    double progress_interval_s;
};
struct ca_select_stats {
    abi1::ca_select_stats abi1_fields;
    double time_coverage_s;
    uint64_t cbc_components, rowgen_rounds;
};
struct ca_skeleton_stats {
    abi1::ca_skeleton_stats abi1_fields;
    double fit_time_s, fit_error_before, fit_error_after;
    uint64_t fit_uncovered;
    int32_t fitted;
};
struct ca_select_options {
    abi1::ca_select_options abi1_fields;
    double target_error;
};
}  // namespace abi2_first

// ---- as last published in ABI 2 (before ABI 3 appended to them) ----
namespace abi2 {
struct ca_surface_view {
    abi1::ca_surface_view abi1_fields;
    int32_t point_normals;
};
struct ca_candidate_options {
    uint32_t struct_size;
    int32_t generator;
    uint32_t cover_samples, voronoi_samples, random_candidates;
    uint64_t seed;
    uint32_t connect_samples;
};
struct ca_select_options {
    abi2_first::ca_select_options abi2_first_fields;
    int32_t probe_fit;
};
struct ca_skeleton_stats {
    abi2_first::ca_skeleton_stats abi2_first_fields;
    int64_t genus;
    uint64_t thin_handles;
};
}  // namespace abi2

// Published sizes of each struct, first to current, each with the ABI version that published it
// (a struct that did not change in a later version keeps its size). A new ABI version appends its
// size; appended fields must start at or after the previous size (checked below), so a caller's
// struct_size tells exactly which fields it has.
struct PublishedSize {
    uint32_t abi;   // CA_ABI_VERSION that published it
    uint32_t size;  // sizeof the struct's layout in that version
};
template <class T> struct Published;
#define CA_PUBLISHED(T, ...)                                          \
    template <> struct Published<T> {                                 \
        static constexpr const char* name = #T;                       \
        static constexpr PublishedSize sizes[] = {__VA_ARGS__};       \
    };
CA_PUBLISHED(ca_context_desc, {1, sizeof(abi1::ca_context_desc)}, {2, sizeof(abi2_first::ca_context_desc)},
             {2, sizeof(ca_context_desc)})
CA_PUBLISHED(ca_surface_view, {1, sizeof(abi1::ca_surface_view)}, {2, sizeof(abi2::ca_surface_view)},
             {3, sizeof(ca_surface_view)})
CA_PUBLISHED(ca_candidate_options, {1, sizeof(abi2::ca_candidate_options)}, {3, sizeof(ca_candidate_options)})
CA_PUBLISHED(ca_select_options, {1, sizeof(abi1::ca_select_options)}, {2, sizeof(abi2_first::ca_select_options)},
             {2, sizeof(abi2::ca_select_options)}, {3, sizeof(ca_select_options)})
CA_PUBLISHED(ca_select_stats, {1, sizeof(abi1::ca_select_stats)}, {2, sizeof(abi2_first::ca_select_stats)},
             {2, sizeof(ca_select_stats)})
CA_PUBLISHED(ca_connect_options, {1, sizeof(abi1::ca_connect_options)}, {2, sizeof(ca_connect_options)})
CA_PUBLISHED(ca_skeleton_stats, {1, sizeof(abi1::ca_skeleton_stats)}, {2, sizeof(abi2_first::ca_skeleton_stats)},
             {2, sizeof(abi2::ca_skeleton_stats)}, {3, sizeof(ca_skeleton_stats)})
CA_PUBLISHED(ca_skeleton_view, {1, sizeof(ca_skeleton_view)})
CA_PUBLISHED(ca_evaluate_options, {1, sizeof(ca_evaluate_options)})
CA_PUBLISHED(ca_evaluation, {1, sizeof(ca_evaluation)})
// correspondence and rig
CA_PUBLISHED(ca_correspondence_options, {3, sizeof(ca_correspondence_options)})
CA_PUBLISHED(ca_rig_options, {3, sizeof(ca_rig_options)})
CA_PUBLISHED(ca_proxy_options, {3, sizeof(ca_proxy_options)})
CA_PUBLISHED(ca_proxy_stats, {3, sizeof(ca_proxy_stats)})
CA_PUBLISHED(ca_proxy_placement, {3, sizeof(ca_proxy_placement)})
// bone colliders
CA_PUBLISHED(ca_skin_view, {3, sizeof(ca_skin_view)})
CA_PUBLISHED(ca_bone_collider_options, {3, sizeof(ca_bone_collider_options)})
CA_PUBLISHED(ca_bone_collider_stats, {3, sizeof(ca_bone_collider_stats)})
#undef CA_PUBLISHED

static_assert(offsetof(ca_context_desc, threads) == offsetof(abi1::ca_context_desc, threads) &&
                  offsetof(ca_context_desc, progress_interval_s) >= sizeof(abi1::ca_context_desc),
              "ca_context_desc: ABI 1 is a prefix of ABI 2");
static_assert(offsetof(ca_context_desc, progress_interval_s) ==
                      offsetof(abi2_first::ca_context_desc, progress_interval_s) &&
                  offsetof(ca_context_desc, time_limit_s) >= sizeof(abi2_first::ca_context_desc),
              "ca_context_desc: its first ABI 2 layout is a prefix of the current one");
static_assert(offsetof(ca_surface_view, normal_stride) == offsetof(abi1::ca_surface_view, normal_stride) &&
                  offsetof(ca_surface_view, point_normals) >= sizeof(abi1::ca_surface_view),
              "ca_surface_view: ABI 1 is a prefix of ABI 2");
static_assert(offsetof(ca_surface_view, point_normals) == offsetof(abi2::ca_surface_view, point_normals) &&
                  offsetof(ca_surface_view, normal_count) >= sizeof(abi2::ca_surface_view),
              "ca_surface_view: ABI 2 is a prefix of ABI 3");
static_assert(offsetof(ca_select_stats, scale_used) == offsetof(abi1::ca_select_stats, scale_used) &&
                  offsetof(ca_select_stats, time_coverage_s) >= sizeof(abi1::ca_select_stats),
              "ca_select_stats: ABI 1 is a prefix of ABI 2");
static_assert(offsetof(ca_select_stats, rowgen_rounds) == offsetof(abi2_first::ca_select_stats, rowgen_rounds) &&
                  offsetof(ca_select_stats, hd_reached) >= sizeof(abi2_first::ca_select_stats),
              "ca_select_stats: its first ABI 2 layout is a prefix of the current one");
static_assert(offsetof(ca_select_options, effort) == offsetof(abi1::ca_select_options, effort) &&
                  offsetof(ca_select_options, target_error) >= sizeof(abi1::ca_select_options),
              "ca_select_options: ABI 1 is a prefix of ABI 2");
static_assert(offsetof(ca_select_options, target_error) == offsetof(abi2_first::ca_select_options, target_error) &&
                  offsetof(ca_select_options, probe_fit) >= sizeof(abi2_first::ca_select_options),
              "ca_select_options: its first ABI 2 layout is a prefix of the current one");
static_assert(offsetof(ca_select_options, probe_fit) == offsetof(abi2::ca_select_options, probe_fit) &&
                  offsetof(ca_select_options, ignorable_samples_count) >= sizeof(abi2::ca_select_options),
              "ca_select_options: ABI 2 is a prefix of ABI 3");

static_assert(offsetof(ca_connect_options, reconnect) == offsetof(abi1::ca_connect_options, reconnect) &&
                  offsetof(ca_connect_options, fit) >= sizeof(abi1::ca_connect_options),
              "ca_connect_options: ABI 1 is a prefix of ABI 2");
static_assert(offsetof(ca_skeleton_stats, method) == offsetof(abi1::ca_skeleton_stats, method) &&
                  offsetof(ca_skeleton_stats, fit_time_s) >= sizeof(abi1::ca_skeleton_stats),
              "ca_skeleton_stats: ABI 1 is a prefix of ABI 2");
static_assert(offsetof(ca_skeleton_stats, fitted) == offsetof(abi2_first::ca_skeleton_stats, fitted) &&
                  offsetof(ca_skeleton_stats, genus) >= sizeof(abi2_first::ca_skeleton_stats),
              "ca_skeleton_stats: its first ABI 2 layout is a prefix of the current one");

static_assert(offsetof(ca_candidate_options, connect_samples) == offsetof(abi2::ca_candidate_options, connect_samples) &&
                  offsetof(ca_candidate_options, volumetric_only) >= sizeof(abi2::ca_candidate_options),
              "ca_candidate_options: ABI 2 is a prefix of ABI 3");
static_assert(offsetof(ca_skeleton_stats, thin_handles) == offsetof(abi2::ca_skeleton_stats, thin_handles) &&
                  offsetof(ca_skeleton_stats, medial_balls) >= sizeof(abi2::ca_skeleton_stats),
              "ca_skeleton_stats: ABI 2 is a prefix of ABI 3");

template <class T>
bool published_size(uint32_t size) {
    for (const PublishedSize& s : Published<T>::sizes)
        if (s.size == size) return true;
    return false;
}

// "ca_select_stats.struct_size is 12; this library (ABI 3) accepts 136 (ABI 1), 160 (ABI 2) or 168 (ABI 2)"
std::string struct_size_message(const char* name, uint32_t size, const PublishedSize* sizes, size_t count);

template <class T>
ca::Status check_struct_size(uint32_t size) {
    if (published_size<T>(size)) return ca::Status::success();
    constexpr size_t n = sizeof(Published<T>::sizes) / sizeof(PublishedSize);
    return ca::fail(ca::Code::struct_size, struct_size_message(Published<T>::name, size, Published<T>::sizes, n));
}

// The defaults of T (full current size); defined in defaults.cpp, converted from the core's option
// structs (the one place they live).
template <class T> T defaults();
template <> ca_context_desc defaults<ca_context_desc>();
template <> ca_surface_view defaults<ca_surface_view>();
template <> ca_candidate_options defaults<ca_candidate_options>();
template <> ca_select_options defaults<ca_select_options>();
template <> ca_connect_options defaults<ca_connect_options>();
template <> ca_skeleton_view defaults<ca_skeleton_view>();
template <> ca_evaluate_options defaults<ca_evaluate_options>();
template <> ca_correspondence_options defaults<ca_correspondence_options>();  // ca_correspondence.cpp
template <> ca_rig_options defaults<ca_rig_options>();                        // ca_rig.cpp
template <> ca_proxy_options defaults<ca_proxy_options>();
template <> ca_skin_view defaults<ca_skin_view>();
template <> ca_bone_collider_options defaults<ca_bone_collider_options>();

// A struct of all zero bytes but its struct_size (sizeof T): the start of every default and result.
template <class T>
T zeroed() {
    T v;
    std::memset(&v, 0, sizeof v);
    v.struct_size = sizeof v;
    return v;
}

// An input struct: NULL means all defaults; otherwise the caller's fields up to its struct_size,
// the defaults after.
template <class T>
ca::Status read_input(const T* in, T& out) {
    out = defaults<T>();
    if (!in) return ca::Status::success();
    ca::Status st = check_struct_size<T>(in->struct_size);
    if (!st.ok()) return st;
    std::memcpy(&out, in, in->struct_size);
    out.struct_size = sizeof(T);
    return ca::Status::success();
}

// Whether a caller's struct of `struct_size` bytes (a published size) has the field at `offset`:
// fields appended after the caller's ABI are not in it and take their defaults.
inline bool has_field(uint32_t struct_size, size_t offset) { return struct_size > offset; }

// An output struct: writes value's first out->struct_size bytes, keeping the caller's size.
template <class T>
ca::Status write_output(const T& value, T* out) {
    ca::Status st = check_struct_size<T>(out->struct_size);
    if (!st.ok()) return st;
    const uint32_t size = out->struct_size;
    std::memcpy(out, &value, size);
    out->struct_size = size;
    return ca::Status::success();
}

}  // namespace capi
