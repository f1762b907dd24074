// surface_view.h: a mesh or point cloud read by these readers as the C ABI's borrowed surface
// view, and the name of the normals a candidate set used; shared by the tool and the benchmarks.
#pragma once
#include "coverage_axis.h"
#include "mesh_io.h"

namespace caio {

// A borrowed view of `mesh` (valid while it lives); a cloud's normals trusted as `point_normals`
// (CA_POINT_NORMALS_*) says.
inline ca_surface_view surface_view(const MeshData& mesh, int32_t point_normals = CA_POINT_NORMALS_TRUSTED) {
    ca_surface_view view;
    ca_surface_view_init(&view);
    view.positions = mesh.positions.data();
    view.vertex_count = mesh.positions.size() / 3;
    view.triangles = mesh.triangles.data();
    view.triangle_count = mesh.triangles.size() / 3;
    view.normals = mesh.normals.empty() ? nullptr : mesh.normals.data();
    view.normal_count = mesh.normals.size() / 3;
    view.point_normals = point_normals;
    return view;
}

// The name of ca_candidate_set_normals: none (a mesh), given, oriented or estimated.
inline const char* normals_name(int32_t normals) {
    switch (normals) {
        case CA_NORMALS_GIVEN: return "given";
        case CA_NORMALS_ORIENTED: return "oriented";
        case CA_NORMALS_ESTIMATED: return "estimated";
        default: return "none";
    }
}

}  // namespace caio
