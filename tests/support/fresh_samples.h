// fresh_samples.h: area-uniform points on a mesh's triangles from a generator of the tests' own
// (not the library's sampler), so checks on them are independent of the samples the pipeline used.
#pragma once
#include "common.h"

#include <algorithm>
#include <random>
#include <vector>

// `where`, when given, receives each sample's triangle and its barycentric weights of the
// triangle's corners (to interpolate per-vertex data such as skin weights).
struct FreshSampleSite {
    size_t triangle;
    double corner[3];
};
inline std::vector<ca::Vec3> fresh_surface_samples(const ca::Mesh& m, size_t n, uint64_t seed,
                                                   std::vector<FreshSampleSite>* where = nullptr) {
    std::mt19937_64 rng(seed);
    std::vector<double> cumulative;
    double total = 0;
    for (const ca::Tri& t : m.triangles) {
        total += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
        cumulative.push_back(total);
    }
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<ca::Vec3> out;
    for (size_t i = 0; i < n; ++i) {
        const size_t k = size_t(std::lower_bound(cumulative.begin(), cumulative.end(), u(rng) * total) - cumulative.begin());
        const ca::Tri& t = m.triangles[std::min(k, m.triangles.size() - 1)];
        double a = u(rng), b = u(rng);
        if (a + b > 1) { a = 1 - a; b = 1 - b; }
        out.push_back(m.vertices[t[0]] + a * (m.vertices[t[1]] - m.vertices[t[0]]) + b * (m.vertices[t[2]] - m.vertices[t[0]]));
        if (where) where->push_back({std::min(k, m.triangles.size() - 1), {1 - a - b, a, b}});
    }
    return out;
}
