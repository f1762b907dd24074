// defaults.cpp: the defaults of every input struct, converted from the core's option structs (the
// one place they are stated; lib/steps/steps.h). The C API reads them for fields past a caller's
// struct_size and for NULL options; the inline *_init of the header, the CLI and the bindings get
// them through the exported ca_*_defaults(pointer, struct_size).
#include "conversions.h"

namespace capi {

// No core struct: all cores, no callbacks, every progress update, no time limit (all zero).
template <> ca_context_desc defaults<ca_context_desc>() { return zeroed<ca_context_desc>(); }

template <> ca_surface_view defaults<ca_surface_view>() {
    ca_surface_view v = zeroed<ca_surface_view>();
    v.point_normals = static_cast<int32_t>(ca::SurfaceInput{}.point_normals);
    return v;
}
template <> ca_skeleton_view defaults<ca_skeleton_view>() { return zeroed<ca_skeleton_view>(); }
template <> ca_candidate_options defaults<ca_candidate_options>() { return to_c(ca::CandidateOptions{}); }
template <> ca_select_options defaults<ca_select_options>() { return to_c(ca::SelectRequest{}); }
template <> ca_connect_options defaults<ca_connect_options>() { return to_c(ca::ConnectRequest{}); }
template <> ca_evaluate_options defaults<ca_evaluate_options>() { return to_c(ca::EvaluateOptions{}); }
template <> ca_proxy_options defaults<ca_proxy_options>() { return to_c(ca::ProxyOptions{}); }
template <> ca_skin_view defaults<ca_skin_view>() { return zeroed<ca_skin_view>(); }
template <> ca_bone_collider_options defaults<ca_bone_collider_options>() { return to_c(ca::BoneColliderOptions{}); }
template <> ca_correspondence_options defaults<ca_correspondence_options>() { return to_c(ca::CorrespondOptions{}); }
template <> ca_rig_options defaults<ca_rig_options>() { return to_c(ca::RigOptions{}); }

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
ca_status ca_correspondence_options_defaults(ca_correspondence_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
ca_status ca_rig_options_defaults(ca_rig_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
ca_status ca_proxy_options_defaults(ca_proxy_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
ca_status ca_skin_view_defaults(ca_skin_view* v, uint32_t size) { return capi::fill_defaults(v, size); }
ca_status ca_bone_collider_options_defaults(ca_bone_collider_options* o, uint32_t size) { return capi::fill_defaults(o, size); }
}
