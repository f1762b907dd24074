// bench_inputs.h: inputs the benchmarks generate instead of storing big files: a finely
// tessellated torus (any triangle count), repeated and coincident geometry, one huge polygon,
// duplicated vertices, and writers for binary PLY and OBJ files made of them.
#pragma once
#include "mesh_io.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace bench {

// Torus of major radius 1, minor radius 0.35: `around` x `tube` quads, 2 * around * tube triangles.
inline caio::MeshData torus(uint32_t around, uint32_t tube) {
    caio::MeshData m;
    const double pi = 3.14159265358979323846;
    m.positions.reserve(size_t(3) * around * tube);
    for (uint32_t i = 0; i < around; ++i)
        for (uint32_t j = 0; j < tube; ++j) {
            const double u = 2 * pi * i / around, v = 2 * pi * j / tube;
            const double r = 1 + 0.35 * std::cos(v);
            m.positions.insert(m.positions.end(), {r * std::cos(u), r * std::sin(u), 0.35 * std::sin(v)});
        }
    m.triangles.reserve(size_t(6) * around * tube);
    auto id = [&](uint32_t i, uint32_t j) { return (i % around) * tube + (j % tube); };
    for (uint32_t i = 0; i < around; ++i)
        for (uint32_t j = 0; j < tube; ++j) {
            const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
        }
    return m;
}

// `copies` copies of one outward tetrahedron (4 triangles each), every copy with its own vertices.
inline caio::MeshData tetrahedron_copies(uint32_t copies) {
    caio::MeshData m;
    const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (uint32_t c = 0; c < copies; ++c) {
        for (const auto& v : p) m.positions.insert(m.positions.end(), {v[0], v[1], v[2]});
        for (const auto& t : f) m.triangles.insert(m.triangles.end(), {4 * c + t[0], 4 * c + t[1], 4 * c + t[2]});
    }
    return m;
}

// `count` triangles whose corners are drawn (fixed LCG) from the 8 corners of a cube.
inline caio::MeshData soup_on_cube_corners(uint32_t count) {
    caio::MeshData m;
    for (int k = 0; k < 8; ++k) m.positions.insert(m.positions.end(), {double(k & 1), double((k >> 1) & 1), double(k >> 2)});
    uint64_t s = 12345;
    auto next = [&] { s = s * 6364136223846793005ull + 1442695040888963407ull; return uint32_t(s >> 61); };
    for (uint32_t t = 0; t < count; ++t) m.triangles.insert(m.triangles.end(), {next(), next(), next()});
    return m;
}

// The torus with every vertex stored `repeat` times; each triangle uses its own copies.
inline caio::MeshData duplicated_vertices(const caio::MeshData& base, uint32_t repeat) {
    caio::MeshData m;
    const size_t nv = base.positions.size() / 3;
    for (uint32_t r = 0; r < repeat; ++r) m.positions.insert(m.positions.end(), base.positions.begin(), base.positions.end());
    for (size_t i = 0; i < base.triangles.size(); ++i)
        m.triangles.push_back(uint32_t(base.triangles[i] + nv * ((i / 3) % repeat)));
    return m;
}

// OBJ text of `n` vertices on a closed non-planar curve (a wavy circle) and one face using all
// of them in order: the reader fan-triangulates it.
inline std::string polygon_obj(uint32_t n) {
    std::string s;
    const double pi = 3.14159265358979323846;
    char line[96];
    for (uint32_t i = 0; i < n; ++i) {
        const double u = 2 * pi * i / n;
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", std::cos(u), std::sin(u), 0.3 * std::sin(3 * u));
        s += line;
    }
    s += "f";
    for (uint32_t i = 1; i <= n; ++i) s += " " + std::to_string(i);
    return s + "\n";
}

// OBJ text of a cube's 8 corners and one face line of about `bytes` bytes cycling through them.
inline std::string single_line_obj(size_t bytes) {
    std::string s;
    for (int k = 0; k < 8; ++k)
        s += "v " + std::to_string(k & 1) + " " + std::to_string((k >> 1) & 1) + " " + std::to_string(k >> 2) + "\n";
    s.reserve(bytes + 16);
    s += "f";
    for (size_t i = 0; s.size() < bytes; ++i) s += " " + std::to_string(1 + i % 8);
    return s + "\n";
}

inline bool write_text(const std::string& path, const std::string& text) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    return std::fclose(f) == 0 && ok;
}

// Binary little-endian PLY (float coordinates, uchar/int face lists); assumes a little-endian host.
inline bool write_binary_ply(const std::string& path, const caio::MeshData& m) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const size_t nv = m.positions.size() / 3, nt = m.triangles.size() / 3;
    std::fprintf(f, "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\nproperty float y\n"
                    "property float z\nelement face %zu\nproperty list uchar int vertex_indices\nend_header\n", nv, nt);
    bool ok = true;
    for (size_t i = 0; i < nv && ok; ++i) {
        const float p[3] = {float(m.positions[3 * i]), float(m.positions[3 * i + 1]), float(m.positions[3 * i + 2])};
        ok = std::fwrite(p, sizeof p, 1, f) == 1;
    }
    for (size_t t = 0; t < nt && ok; ++t) {
        const unsigned char three = 3;
        const int32_t v[3] = {int32_t(m.triangles[3 * t]), int32_t(m.triangles[3 * t + 1]), int32_t(m.triangles[3 * t + 2])};
        ok = std::fwrite(&three, 1, 1, f) == 1 && std::fwrite(v, sizeof v, 1, f) == 1;
    }
    return std::fclose(f) == 0 && ok;
}

}  // namespace bench
