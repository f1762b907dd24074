// shapes.h: procedural closed test meshes, one copy for every test, with known medial axes
// (sphere and icosphere: the centre; capsule: its axis segment; torus: its core circle), outward-facing.
#pragma once
#include "common.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

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

// The same torus with its centre moved to `centre`.
inline ca::Mesh torus(double R, double r, int major, int minor, const ca::Vec3& centre) {
    ca::Mesh m = torus(R, r, major, minor);
    for (ca::Vec3& v : m.vertices) v = centre + v;
    return m;
}

// Icosphere of radius `radius` around `centre`: the icosahedron subdivided `levels` times (20 *
// 4^levels triangles), each new vertex the normalised midpoint of an edge.
inline ca::Mesh icosphere(double radius, int levels, const ca::Vec3& centre = ca::Vec3::Zero()) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    ca::Mesh m;
    m.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto& v : m.vertices) v.normalize();
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
            return mid[key] = uint32_t(m.vertices.size() - 1);
        };
        std::vector<ca::Tri> next;
        for (const ca::Tri& f : m.triangles) {
            const uint32_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
            next.insert(next.end(), {ca::Tri{f[0], a, c}, ca::Tri{f[1], b, a}, ca::Tri{f[2], c, b}, ca::Tri{a, b, c}});
        }
        m.triangles = next;
    }
    for (auto& v : m.vertices) v = centre + radius * v;
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
