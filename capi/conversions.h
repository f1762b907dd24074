// conversions.h: checks and conversions between the caller's C views (strided arrays, the caller's
// units) and the core's types (Vec3 arrays in unit-cube units).
#pragma once

#include "context.h"
#include "struct_size.h"

#include "connect.h"
#include "fit.h"
#include "surface.h"

#include <optional>

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

// x y z per item from a strided array (values are not checked).
ca::Status read_points(const double* base, size_t count, size_t stride, const char* name, std::vector<ca::Vec3>& out);

// A surface view into raw arrays (struct size, pointers, strides and point_normals checked; values
// are checked by prepare_surface). Normals are read for point clouds when want_normals; `trust`
// (if set) receives point_normals.
ca::Status read_surface(const ca_surface_view* surface, bool want_normals, ca::Mesh& raw, std::vector<ca::Vec3>& normals,
                        ca::PointNormals* trust = nullptr);

// Points in the caller's units, x y z per point, in memory from the result's allocator.
void fill(Array<double>& a, const Allocator& al, const std::vector<ca::Vec3>& pts, const ca::Normalization& n);

// The core's connect options from the caller's (method already checked): AUTO is the medial
// route for a mesh, the power route for point clouds and caller arrays.
ca::ConnectOptions connect_options(const ca_connect_options& o, const ca::CandidateSet& set, int32_t threads);

// The core's fit options when ca_connect with `o` fits (fit on, fit_iterations > 0, a triangle
// mesh: the fit needs one), else none. fit_iterations must already be checked (>= 0).
std::optional<ca::FitOptions> fit_options(const ca_connect_options& o, const ca::CandidateSet& set, int32_t threads);

}  // namespace capi
