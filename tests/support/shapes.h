// shapes.h: procedural closed test meshes with known medial axes (sphere: its centre; capsule:
// its axis segment; torus: its core circle), outward-facing.
#pragma once
#include "common.h"

#include <cmath>

namespace shapes {

// Surface of revolution around the x axis: profile (x(t), rho(t)) for t in [0, 1], rho(0) =
// rho(1) = 0 (poles), `rings` x `segments` grid.
template <class Profile>
ca::Mesh revolve(Profile profile, int rings, int segments) {
    ca::Mesh m;
    const double pi = 3.14159265358979323846;
    auto [x0, r0] = profile(0.0);
    m.vertices.push_back({x0, 0, 0});
    for (int i = 1; i < rings; ++i) {
        auto [x, rho] = profile(double(i) / rings);
        for (int j = 0; j < segments; ++j) {
            const double a = 2 * pi * j / segments;
            m.vertices.push_back({x, rho * std::cos(a), rho * std::sin(a)});
        }
    }
    auto [x1, r1] = profile(1.0);
    m.vertices.push_back({x1, 0, 0});
    (void)r0; (void)r1;
    const uint32_t last = uint32_t(m.vertices.size() - 1);
    auto ring = [&](int i, int j) { return uint32_t(1 + (i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j) m.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            m.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
            m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
        }
    for (int j = 0; j < segments; ++j) m.triangles.push_back({last, ring(rings - 1, j), ring(rings - 1, j + 1)});
    return m;
}

inline ca::Mesh sphere(double radius, int rings = 48, int segments = 96) {
    const double pi = 3.14159265358979323846;
    return revolve([&](double t) { return std::pair<double, double>{-radius * std::cos(pi * t), radius * std::sin(pi * t)}; },
                   rings, segments);
}

// Capsule: axis from (-half_length, 0, 0) to (half_length, 0, 0), radius r.
inline ca::Mesh capsule(double half_length, double r, int rings = 96, int segments = 64) {
    const double pi = 3.14159265358979323846;
    const double total = pi * r + 2 * half_length;  // profile arc length
    return revolve([&](double t) {
        const double s = t * total;
        if (s < pi * r / 2) { const double a = s / r; return std::pair<double, double>{-half_length - r * std::cos(a), r * std::sin(a)}; }
        if (s < pi * r / 2 + 2 * half_length) return std::pair<double, double>{-half_length + (s - pi * r / 2), r};
        const double a = (s - pi * r / 2 - 2 * half_length) / r;
        return std::pair<double, double>{half_length + r * std::sin(a), r * std::cos(a)};
    }, rings, segments);
}

// Torus around the z axis: core circle radius R in the xy plane, tube radius r.
inline ca::Mesh torus(double R, double r, int major = 96, int minor = 32) {
    const double pi = 3.14159265358979323846;
    ca::Mesh m;
    for (int i = 0; i < major; ++i)
        for (int j = 0; j < minor; ++j) {
            const double u = 2 * pi * i / major, v = 2 * pi * j / minor;
            m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
        }
    auto id = [&](int i, int j) { return uint32_t((i % major) * minor + (j % minor)); };
    for (int i = 0; i < major; ++i)
        for (int j = 0; j < minor; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

}  // namespace shapes

namespace shapes {

// Two meshes as one (vertex indices of `b` shifted), `b` moved by `offset`.
inline ca::Mesh merged(const ca::Mesh& a, const ca::Mesh& b, const ca::Vec3& offset = ca::Vec3::Zero()) {
    ca::Mesh m = a;
    const uint32_t base = uint32_t(m.vertices.size());
    for (const ca::Vec3& v : b.vertices) m.vertices.push_back(v + offset);
    for (const ca::Tri& t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    return m;
}

// Axis-aligned box [0, sx] x [0, sy] x [0, sz], 12 outward-facing triangles.
inline ca::Mesh box(double sx, double sy, double sz) {
    ca::Mesh m;
    for (int i = 0; i < 8; ++i) m.vertices.push_back({(i & 1) ? sx : 0.0, (i & 2) ? sy : 0.0, (i & 4) ? sz : 0.0});
    m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return m;
}

}  // namespace shapes
