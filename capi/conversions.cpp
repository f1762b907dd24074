// conversions.cpp: reading the caller's strided arrays and surface view, writing points back in
// the caller's units.
#include "conversions.h"
#include "struct_size.h"

namespace capi {

using ca::Code;
using ca::Status;
using ca::Vec3;

Status null_pointer(const char* what) { return ca::fail(Code::null_pointer, std::string(what) + " is NULL"); }

Status check_pointers(std::initializer_list<Arg> args) {
    for (const Arg& a : args)
        if (!a.ptr) return null_pointer(a.name);
    return Status::success();
}

Status check_stride(size_t stride, size_t min, const char* name, size_t& out) {
    if (stride != 0 && stride < min)
        return ca::fail(Code::invalid_argument, std::string(name) + " (" + std::to_string(stride) +
                                                    " bytes) is smaller than one element (" + std::to_string(min) + " bytes)");
    out = stride ? stride : min;
    return Status::success();
}

Status read_points(const double* base, size_t count, size_t stride, const char* name, std::vector<Vec3>& out) {
    size_t s;
    Status st = check_stride(stride, 3 * sizeof(double), name, s);
    if (!st.ok()) return st;
    out.clear();
    ca::reserve_large(out, count);
    for (size_t i = 0; i < count; ++i) {
        const std::array<double, 3> p = read_element<double, 3>(base, s, i);
        out.emplace_back(p[0], p[1], p[2]);
    }
    return Status::success();
}

Status read_surface(const ca_surface_view* in, bool want_normals, ca::Mesh& raw, std::vector<Vec3>& normals,
                    ca::PointNormals* trust) {
    ca_surface_view surface;
    Status st = read_input(in, surface);
    if (!st.ok()) return st;
    if (surface.point_normals < CA_POINT_NORMALS_TRUSTED || surface.point_normals > CA_POINT_NORMALS_ESTIMATE)
        return ca::fail(Code::invalid_argument, "surface->point_normals is " + std::to_string(surface.point_normals) +
                                                    "; expected CA_POINT_NORMALS_TRUSTED (0), UNORIENTED (1) or ESTIMATE (2)");
    if (trust) *trust = static_cast<ca::PointNormals>(surface.point_normals);
    if (surface.vertex_count > 0 && !surface.positions) return null_pointer("surface->positions");
    if (surface.triangle_count > 0 && !surface.triangles) return null_pointer("surface->triangles");
    if (surface.vertex_count > UINT32_MAX) return ca::fail(Code::invalid_argument, "more than 2^32 - 1 vertices");
    if (surface.triangle_count > UINT32_MAX) return ca::fail(Code::invalid_argument, "more than 2^32 - 1 triangles");
    st = read_points(surface.positions, surface.vertex_count, surface.position_stride, "surface->position_stride",
                     raw.vertices);
    if (!st.ok()) return st;
    size_t ts;
    st = check_stride(surface.triangle_stride, 3 * sizeof(uint32_t), "surface->triangle_stride", ts);
    if (!st.ok()) return st;
    raw.triangles.clear();
    ca::reserve_large(raw.triangles, surface.triangle_count);
    for (size_t t = 0; t < surface.triangle_count; ++t) raw.triangles.push_back(read_element<uint32_t, 3>(surface.triangles, ts, t));
    if (want_normals && surface.triangle_count == 0 && surface.normals)
        return read_points(surface.normals, surface.vertex_count, surface.normal_stride, "surface->normal_stride", normals);
    return Status::success();
}

void fill(Array<double>& a, const Allocator& al, const std::vector<Vec3>& pts, const ca::Normalization& n) {
    a.assign(al, 3 * pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        const Vec3 p = n.to_user(pts[i]);
        a.data[3 * i] = p.x(); a.data[3 * i + 1] = p.y(); a.data[3 * i + 2] = p.z();
    }
}

ca::ConnectOptions connect_options(const ca_connect_options& o, const ca::CandidateSet& set, int32_t threads) {
    ca::ConnectOptions co;
    // the medial route needs an inside test: a mesh's winding number or a clean point cloud's. On a
    // noisy cloud the power route stays: the medial route's inner Voronoi balls follow the noise out
    // of the shape (bench_pointcloud (d): h(recon->surface) up to 4.8x the clean cloud's)
    const bool has_mesh = !set.surface.point_cloud && !set.surface.mesh.triangles.empty();
    const bool has_inside = has_mesh || (set.cloud_winding != nullptr && !set.noisy_cloud);
    if (o.method == CA_CONNECT_AUTO) co.method = has_inside ? ca::ConnectMethod::medial : ca::ConnectMethod::power;
    else co.method = static_cast<ca::ConnectMethod>(o.method);
    co.remove_outside = o.remove_outside != 0;
    co.fill_holes = o.fill_holes != 0;
    co.reconnect = o.reconnect != 0;
    co.threads = threads;
    return co;
}

std::optional<ca::FitOptions> fit_options(const ca_connect_options& o, const ca::CandidateSet& set, int32_t threads) {
    const bool has_mesh = !set.surface.point_cloud && !set.surface.mesh.triangles.empty();
    if (!(o.fit != 0 && has_mesh && o.fit_iterations > 0)) return std::nullopt;
    ca::FitOptions fo;
    fo.iterations = uint32_t(o.fit_iterations);
    fo.thorough = o.fit == 2;
    fo.threads = threads;
    return fo;
}

}  // namespace capi
