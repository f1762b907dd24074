// conversions.h: the C boundary's conversions between the caller's C structs and views (strided
// arrays, the caller's units) and the core's requests and results (lib/steps/steps.h). Only what
// the C types need is checked here (struct sizes, NULL pointers, strides, counts that could not be
// read); the values are checked by the core's steps.
#pragma once

#include "context.h"
#include "struct_size.h"

#include "steps.h"

#include <array>
#include <cstring>
#include <initializer_list>
#include <vector>

namespace capi {

ca::Status null_pointer(const char* what);

// A pointer argument and its name in the message when it is NULL.
struct Arg {
    const void* ptr;
    const char* name;
};
// The first check of every entry point: each pointer in `args` set (the first NULL one, in
// order, names the status).
ca::Status check_pointers(std::initializer_list<Arg> args);
// check_pointers, then the step's options (NULL: the defaults; read_input).
template <class O>
ca::Status read_arguments(std::initializer_list<Arg> args, const O* options, O& o) {
    ca::Status st = check_pointers(args);
    return st.ok() ? read_input(options, o) : st;
}

// A byte stride: 0 means packed (min); otherwise at least one element. Any byte count works:
// elements are read with memcpy (read_element), so a stride need not keep them aligned.
ca::Status check_stride(size_t stride, size_t min, const char* name, size_t& out);

// The i-th element (N values of T) of a strided array, copied byte-wise: no aligned load of an
// element a stride left misaligned.
template <class T, size_t N>
std::array<T, N> read_element(const T* base, size_t stride, size_t i) {
    std::array<T, N> v;
    std::memcpy(v.data(), reinterpret_cast<const char*>(base) + i * stride, sizeof v);
    return v;
}

// The entries of a borrowed array that has a count field (ABI 3): `count` as given, or, from a
// caller whose struct predates the field (has_count false), `implied`, the entries that caller's
// ABI defined. A set array with a count of 0 is refused (the count was not filled in), and so is a
// count without its array. Whether the count matches what the step needs is the step's check.
ca::Status array_count(const void* array, size_t count, bool has_count, size_t implied, const char* array_name,
                       const char* count_name, size_t& out);

// x y z per item from a strided array (values are not checked).
ca::Status read_points(const double* base, size_t count, size_t stride, const char* name, std::vector<ca::Vec3>& out);

// A surface view as the core's input, in the caller's units (struct size, pointers, counts and
// strides checked). Normals are read for point clouds when want_normals.
ca::Status read_surface(const ca_surface_view* surface, bool want_normals, ca::SurfaceInput& out);

// A skeleton view's arrays in the caller's units (pointers and counts checked; values are checked
// by the core's steps).
ca::Status read_skeleton(const ca_skeleton_view* in, ca::Skeleton& out);

// The surface (its normals not read) and a skeleton measured against it, as the steps that compare
// a skeleton with its surface take them (evaluation, correspondence, rig).
ca::Status read_surface_and_skeleton(const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                                     ca::SurfaceInput& input, ca::Skeleton& sk);

// The arguments of a per-vertex step (ca_correspond, ca_rig_build): the pointers checked (`out`
// last), the options read (NULL: the defaults), then the surface and the skeleton.
template <class O, class Out>
ca::Status read_per_vertex_arguments(const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                                     const O* options, Out** out, O& o, ca::SurfaceInput& input, ca::Skeleton& sk) {
    const ca::Status st = read_arguments({{surface, "surface"}, {skeleton, "skeleton"}, {out, "out"}}, options, o);
    return st.ok() ? read_surface_and_skeleton(surface, skeleton, input, sk) : st;
}

// Points in the caller's units, x y z per point, in memory from the result's allocator.
void fill(Array<double>& a, const Allocator& al, const std::vector<ca::Vec3>& pts, const ca::Normalization& n);
// Per-vertex influences, ca::kInfluences (index, weight) pairs per vertex, packed, in memory from
// the result's allocator.
void fill_influences(Array<uint32_t>& index, Array<double>& weight, const Allocator& al,
                     const std::vector<std::array<uint32_t, ca::kInfluences>>& in_index,
                     const std::vector<std::array<double, ca::kInfluences>>& in_weight);

// The C option structs as the core's options and requests (threads: the context's), and the core's
// defaults as the C structs (defaults.cpp: the C ABI's ca_*_defaults). The select options' masks
// are read by ca_select (they need the candidate set's sizes).
ca::CandidateOptions to_core(const ca_candidate_options& o, int32_t threads);
ca::SelectRequest to_core(const ca_select_options& o, int32_t threads);
ca::ConnectRequest to_core(const ca_connect_options& o, int32_t threads);
ca::EvaluateOptions to_core(const ca_evaluate_options& o, int32_t threads);
ca::ProxyOptions to_core(const ca_proxy_options& o, int32_t threads);
// the skip list is read by ca_bone_colliders_build (a borrowed array)
ca::BoneColliderOptions to_core(const ca_bone_collider_options& o, int32_t threads);
ca::CorrespondOptions to_core(const ca_correspondence_options& o, int32_t threads);
ca::RigOptions to_core(const ca_rig_options& o, int32_t threads);
ca_candidate_options to_c(const ca::CandidateOptions& o);
ca_select_options to_c(const ca::SelectRequest& o);
ca_connect_options to_c(const ca::ConnectRequest& o);
ca_evaluate_options to_c(const ca::EvaluateOptions& o);
ca_proxy_options to_c(const ca::ProxyOptions& o);
ca_bone_collider_options to_c(const ca::BoneColliderOptions& o);
// A primitive's placement as the C struct (full current size).
ca_proxy_placement to_c(const ca::ProxyPlacement& p);
ca_correspondence_options to_c(const ca::CorrespondOptions& o);
ca_rig_options to_c(const ca::RigOptions& o);

}  // namespace capi
