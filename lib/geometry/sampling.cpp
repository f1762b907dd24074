// sampling.cpp: area-uniform surface sampling, seeded subsets, near-duplicate removal.
#include "sampling.h"

#include "kdtree.h"
#include "rng.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ca {

std::vector<Vec3> sample_surface(const Mesh& mesh, size_t n, uint64_t seed,
                                 std::vector<uint32_t>* triangle_of_sample) {
    std::vector<Vec3> out;
    sample_surface(mesh, n, seed, out, Monitor{}, triangle_of_sample);
    return out;
}

bool sample_surface(const Mesh& mesh, size_t n, uint64_t seed, std::vector<Vec3>& out, const Monitor& monitor,
                    std::vector<uint32_t>* triangle_of_sample) {
    out.clear();
    if (triangle_of_sample) triangle_of_sample->clear();
    const size_t nt = mesh.triangles.size();
    if (nt == 0 || n == 0) return true;
    std::vector<double> cumulative;
    reserve_large(cumulative, nt);
    double total = 0;
    for (size_t t = 0; t < nt; ++t) {
        if (monitor.stopped_at(t)) return false;
        const Tri& f = mesh.triangles[t];
        const Vec3& a = mesh.vertices[f[0]];
        total += 0.5 * (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).norm();
        cumulative.push_back(total);
    }
    if (!(total > 0)) return true;
    Rng rng(seed);
    out.reserve(n);
    if (triangle_of_sample) triangle_of_sample->reserve(n);
    for (size_t i = 0; i < n; ++i) {
        if (monitor.stopped_at(i)) return false;
        const double x = rng.uniform() * total;
        size_t t = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), x) - cumulative.begin());
        if (t >= nt) t = nt - 1;
        const Tri& f = mesh.triangles[t];
        // uniform point in a triangle: (1 - sqrt(u)) a + sqrt(u)(1 - v) b + sqrt(u) v c
        const double su = std::sqrt(rng.uniform()), v = rng.uniform();
        out.push_back((1 - su) * mesh.vertices[f[0]] + su * (1 - v) * mesh.vertices[f[1]] +
                      su * v * mesh.vertices[f[2]]);
        if (triangle_of_sample) triangle_of_sample->push_back(uint32_t(t));
    }
    return true;
}

std::vector<uint32_t> random_subset(size_t count, size_t n, uint64_t seed) {
    std::vector<uint32_t> idx(count);
    std::iota(idx.begin(), idx.end(), 0u);
    if (n == 0 || n >= count) return idx;
    Rng rng(seed);
    for (size_t i = 0; i < n; ++i) std::swap(idx[i], idx[i + rng.below(count - i)]);  // partial Fisher-Yates
    idx.resize(n);
    std::sort(idx.begin(), idx.end());
    return idx;
}

std::vector<uint32_t> remove_near_duplicates(const std::vector<Vec3>& pts, double tolerance) {
    std::vector<uint32_t> kept;
    if (pts.empty()) return kept;
    PointTree tree(pts);
    std::vector<uint8_t> removed(pts.size(), 0);
    std::vector<std::pair<size_t, double>> hits;
    for (size_t i = 0; i < pts.size(); ++i) {
        if (removed[i]) continue;
        kept.push_back(uint32_t(i));
        tree.within(pts[i], tolerance, hits);
        for (const auto& h : hits)
            if (h.first > i) removed[h.first] = 1;
    }
    return kept;
}

}  // namespace ca
