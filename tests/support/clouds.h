// clouds.h: oriented point clouds sampled from test meshes (area-uniform samples, each with the
// unit normal of its triangle), for the point-cloud tests.
#pragma once
#include "common.h"
#include "sampling.h"

namespace shapes {

struct Cloud {
    std::vector<ca::Vec3> points, normals;
};

inline Cloud sample_cloud(const ca::Mesh& mesh, size_t n, uint64_t seed = 7) {
    Cloud c;
    std::vector<uint32_t> tri;
    c.points = ca::sample_surface(mesh, n, seed, &tri);
    for (uint32_t t : tri) {
        const auto& f = mesh.triangles[t];
        const ca::Vec3& a = mesh.vertices[f[0]];
        c.normals.push_back((mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).normalized());
    }
    return c;
}

}  // namespace shapes
