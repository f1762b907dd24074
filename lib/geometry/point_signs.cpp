// point_signs.cpp: each normal's sign checked against the winding number of the rest of the cloud
// (point_signs.h).
#include "point_signs.h"

#include "kdtree.h"
#include "parallel.h"
#include "point_winding.h"

#include <cmath>

namespace ca {
namespace {

constexpr double kFourPi = 4.0 * 3.14159265358979323846;
// Probes this fraction of the point's 8th-neighbour distance to either side, as the patch vote's:
// far enough that the neighbours' dipoles act as a surface, near enough to stay inside thin parts.
constexpr double kProbeDepth = 0.5;

}  // namespace

size_t refine_point_signs(const std::vector<Vec3>& pts, std::vector<Vec3>& normals, int rounds, int threads) {
    const size_t n = pts.size();
    if (n < 3 || normals.size() != n) return 0;
    std::vector<double> depth(n, 0.0);
    for_each_neighbourhood(pts, 8, [&](size_t i, const size_t*, const double* d2, size_t found) {
        if (found) depth[i] = kProbeDepth * std::sqrt(d2[found - 1]);
    }, threads);
    size_t negated = 0;
    std::vector<uint8_t> flip(n, 0);
    for (int round = 0; round < rounds; ++round) {
        const PointCloudWinding w(pts, normals, 2.0, threads);
        const std::vector<double>& area = w.areas();
        // each point decides its own flip from the normals of the round before
        parallel_for(n, threads, 1024, Monitor{}, "point signs", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                flip[i] = 0;
                const double t = depth[i];
                if (!(t > 0)) continue;
                // the point's own dipole adds a / (4 pi t^2) behind it and takes as much in front
                const double own = 2.0 * area[i] / (kFourPi * t * t);
                flip[i] = w(pts[i] - t * normals[i]) - w(pts[i] + t * normals[i]) - own < 0;
            }
        });
        size_t changed = 0;
        for (size_t i = 0; i < n; ++i)
            if (flip[i]) normals[i] = -normals[i], ++changed;
        negated += changed;
        if (changed == 0) break;
    }
    return negated;
}

}  // namespace ca
