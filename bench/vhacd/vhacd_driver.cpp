// vhacd_driver.cpp: V-HACD 4.1 (Mamou's convex decomposition, the one Unreal, Blender and Godot
// use) as bench_proxies runs it: one mesh in, its convex hulls out, at V-HACD's default parameters
// except the hull count. Built by bench/vhacd/setup.sh against the single header of the npm
// package vhacd-js (BSD-3-Clause, not part of this repository), never by the normal build.
// It uses the blocking interface (CreateVHACD): Compute returns when the hulls are made. At the
// defaults (m_asyncACD true) that call runs its work on a pool of 8 threads of its own.
// usage: vhacd_driver IN.bin OUT.bin MAX_HULLS
//   IN.bin:  uint32 vertex count, uint32 triangle count, float64 x y z per vertex, uint32 i j k per
//            triangle (little-endian, as bench_proxies writes it)
//   OUT.bin: float64 seconds of Compute, uint32 hull count, then per hull uint32 vertex count,
//            uint32 triangle count, float64 x y z per vertex, uint32 i j k per triangle
// Exit status 0 when the hulls were written, 1 otherwise (a message on stderr).
#define ENABLE_VHACD_IMPLEMENTATION 1
#include "VHACD.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

template <class T>
bool read_all(FILE* f, std::vector<T>& v, size_t n) {
    v.resize(n);
    return n == 0 || std::fread(v.data(), sizeof(T), n, f) == n;
}

template <class T>
bool write_all(FILE* f, const T* p, size_t n) {
    return n == 0 || std::fwrite(p, sizeof(T), n, f) == n;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: vhacd_driver IN.bin OUT.bin MAX_HULLS\n");
        return 1;
    }
    FILE* in = std::fopen(argv[1], "rb");
    uint32_t counts[2] = {0, 0};
    std::vector<double> points;
    std::vector<uint32_t> triangles;
    const bool read = in && std::fread(counts, sizeof counts, 1, in) == 1 && read_all(in, points, size_t(counts[0]) * 3) &&
                      read_all(in, triangles, size_t(counts[1]) * 3);
    if (in) std::fclose(in);
    if (!read) {
        std::fprintf(stderr, "vhacd_driver: cannot read %s\n", argv[1]);
        return 1;
    }
    VHACD::IVHACD::Parameters params;   // V-HACD's defaults but the hull count
    params.m_maxConvexHulls = uint32_t(std::strtoul(argv[3], nullptr, 10));
    VHACD::IVHACD* vhacd = VHACD::CreateVHACD();
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = vhacd->Compute(points.data(), counts[0], triangles.data(), counts[1], params);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!ok) {
        std::fprintf(stderr, "vhacd_driver: Compute failed\n");
        vhacd->Release();
        return 1;
    }
    FILE* out = std::fopen(argv[2], "wb");
    const uint32_t hulls = vhacd->GetNConvexHulls();
    bool wrote = out && write_all(out, &seconds, 1) && write_all(out, &hulls, 1);
    for (uint32_t h = 0; wrote && h < hulls; ++h) {
        VHACD::IVHACD::ConvexHull ch;
        vhacd->GetConvexHull(h, ch);
        const uint32_t n[2] = {uint32_t(ch.m_points.size()), uint32_t(ch.m_triangles.size())};
        wrote = write_all(out, n, 2);
        for (const VHACD::Vertex& v : ch.m_points) {
            const double xyz[3] = {v.mX, v.mY, v.mZ};
            wrote = wrote && write_all(out, xyz, 3);
        }
        for (const VHACD::Triangle& t : ch.m_triangles) {
            const uint32_t ijk[3] = {t.mI0, t.mI1, t.mI2};
            wrote = wrote && write_all(out, ijk, 3);
        }
    }
    vhacd->Release();
    if (out && std::fclose(out) != 0) wrote = false;
    if (!wrote) {
        std::fprintf(stderr, "vhacd_driver: cannot write %s\n", argv[2]);
        return 1;
    }
    return 0;
}
