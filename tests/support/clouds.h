// clouds.h: oriented point clouds sampled from test meshes (area-uniform samples, each with the
// unit normal of its triangle), for the point-cloud tests; noisy_cloud adds scan noise and outliers.
#pragma once
#include "common.h"
#include "rng.h"
#include "sampling.h"
#include "surface.h"

#include <cmath>

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

// A scan-like copy of `clean`: every point moved by isotropic Gaussian noise of standard deviation
// `noise` x the bbox diagonal (normals kept), plus outlier_fraction x n far outliers: uniform in the
// bbox grown to twice its size, at least 0.1 diagonal away from every clean point (inside or
// outside the shape), with random unit normals. Deterministic for a seed (Box-Muller on ca::Rng).
inline Cloud noisy_cloud(const Cloud& clean, double noise, double outlier_fraction, uint64_t seed = 11) {
    auto [lo, hi] = ca::bounding_box(clean.points);
    const double diag = (hi - lo).norm();
    ca::Rng rng(seed);
    auto gauss = [&] {
        const double u = 1.0 - rng.uniform(), v = rng.uniform();
        return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
    };
    Cloud c = clean;
    for (ca::Vec3& p : c.points) p += noise * diag * ca::Vec3(gauss(), gauss(), gauss());
    const ca::Vec3 mid = 0.5 * (lo + hi), extent = hi - lo;
    const size_t want = size_t(std::lround(outlier_fraction * double(clean.points.size())));
    while (c.points.size() < clean.points.size() + want) {
        const ca::Vec3 p = mid + ca::Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5).cwiseProduct(2 * extent);
        double nearest = INFINITY;
        for (const ca::Vec3& q : clean.points) nearest = std::min(nearest, (p - q).norm());
        if (nearest < 0.1 * diag) continue;
        c.points.push_back(p);
        c.normals.push_back(ca::Vec3(gauss(), gauss(), gauss()).normalized());
    }
    return c;
}

}  // namespace shapes
