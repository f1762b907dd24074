// cloud_local_planes.cpp: the local surface of a noisy point cloud. The local surface at a point is
// the least-squares plane of its 16 nearest neighbours (itself among them; the fit averages the
// noise out), oriented by the point's normal. The cloud counts as noisy when the median distance
// of a point to its own plane exceeds kNoisy x the median 16th-neighbour distance: on a clean
// cloud that distance is the curvature sag (about d16^2 / 4R on a sphere of radius R, a few
// percent of d16), on a scan it is the noise; and when that distance grows by less than
// kMaxGrowth from the planes of 8 neighbours to those of 16 (curvature sag grows about 2x, noise
// does not). Exactly flat 8-neighbourhoods (a CAD model's faces: median distance 0) count as
// unbounded growth: noise never fits a plane exactly, and the 16 nearest of a slab thinner than
// their spread reach its far side. Only noisy clouds are changed, in two ways:
// - the winding number fluctuates within the noise band, so Voronoi vertices between points flung
//   outward can pass the inside test (w > 1/2) while lying outside the sampled surface: a ball is
//   dropped when its centre is on the outer side of the plane at its nearest cloud point;
// - a cover sample is projected onto the plane at its nearest point, so the skeleton covers the
//   denoised surface instead of reaching out to every point the noise pushed outward;
// - noise() estimates the noise's standard deviation from the median distance to the planes,
//   the depth within which the winding number is unreliable (the fallback balls start below it).
#include "candidates_internal.h"
#include "median.h"

#include "kdtree.h"
#include "normals.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ca {
namespace cand {

namespace {
constexpr size_t kPlaneNeighbours = 16;
constexpr size_t kSmallNeighbours = 8;
constexpr double kNoisy = 0.03, kMaxGrowth = 1.6;
constexpr double kMedianToSigma = 1.4826;   // median |x| of a centred Gaussian is 0.6745 sigma
}  // namespace

LocalPlanes::LocalPlanes(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, int threads)
    : mean_(pts), normal_(normals), tree_(pts) {
    if (pts.size() <= kPlaneNeighbours) return;
    std::vector<double> residual(pts.size(), 0), small(pts.size(), 0), spacing(pts.size(), 0);
    for_each_neighbourhood(pts, kPlaneNeighbours, [&](size_t i, const size_t* idx, const double* d2, size_t found) {
        Vec3 m, n;
        spacing[i] = std::sqrt(d2[found - 1]);
        if (found > kSmallNeighbours && fit_plane(pts, idx, kSmallNeighbours + 1, m, n))
            small[i] = std::abs((pts[i] - m).dot(n));
        if (!fit_plane(pts, idx, found, m, n)) return;
        mean_[i] = m;
        normal_[i] = n.dot(normals[i]) < 0 ? Vec3(-n) : n;
        residual[i] = std::abs((pts[i] - m).dot(n));
    }, threads);
    const double d16 = median_of(spacing), r16 = median_of(residual), r8 = median_of(small);
    noise_ = kMedianToSigma * r16;
    noise_ratio_ = d16 > 0 ? r16 / d16 : 0;
    // r8 = 0 (exactly flat): unbounded growth, not noise
    scale_growth_ = r8 > 0 ? r16 / r8 : r16 > 0 ? std::numeric_limits<double>::infinity() : 0;
}

bool LocalPlanes::noisy() const { return noise_ratio_ > kNoisy && scale_growth_ < kMaxGrowth; }

size_t LocalPlanes::nearest(const Vec3& q) const {
    size_t i = 0;
    double d2 = 0;
    tree_.nearest(q, 1, &i, &d2);
    return i;
}

double LocalPlanes::height(const Vec3& q) const {
    const size_t i = nearest(q);
    return (q - mean_[i]).dot(normal_[i]);
}

Vec3 LocalPlanes::project(const Vec3& q) const {
    const size_t i = nearest(q);
    return q - (q - mean_[i]).dot(normal_[i]) * normal_[i];
}

size_t drop_outside_local_planes(const LocalPlanes& planes, int threads, const Monitor& monitor, std::vector<Ball>& balls) {
    std::vector<uint8_t> keep(balls.size(), 1);
    if (!parallel_for(balls.size(), threads, 4096, monitor, "candidates", [&](size_t b, size_t e) {
            for (size_t k = b; k < e; ++k) keep[k] = planes.height(balls[k].center) <= 0;
        }))
        return 0;
    size_t n = 0;
    for (size_t k = 0; k < balls.size(); ++k)
        if (keep[k]) balls[n++] = balls[k];
    const size_t dropped = balls.size() - n;
    balls.resize(n);
    return dropped;
}

}  // namespace cand
}  // namespace ca
