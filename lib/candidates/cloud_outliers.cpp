// cloud_outliers.cpp: the outlier filter of point clouds. A point is an outlier if it is isolated
// (its 8th-nearest-neighbour distance is above max(3 x the median, median + 10 robust standard
// deviations), the deviation estimated as 1.4826 x the median absolute deviation), or if it lies
// off the plane of its 16 nearest neighbours (least squares, itself left out) by more than 0.7 x
// its 16th-nearest distance. Both thresholds sit far beyond what sampling density variations and
// curvature give on a clean cloud (a point on a sphere is off its neighbours' plane by about
// d16^2 / 2R), so clean clouds lose no point; far outliers and points flung off the surface by
// scan errors are dropped before the winding number, the candidates and the cover samples.
#include "candidates_internal.h"
#include "median.h"

#include "kdtree.h"
#include "normals.h"

#include <algorithm>
#include <cmath>

namespace ca {
namespace cand {

namespace {

constexpr size_t kIsolationRank = 8;     // the k of the k-th-nearest-neighbour distance
constexpr size_t kPlaneNeighbours = 16;  // the neighbourhood of the local plane
constexpr double kMedianFactor = 3, kMadFactor = 10, kMadToSigma = 1.4826, kOffPlane = 0.7;

}  // namespace

size_t find_cloud_outliers(const std::vector<Vec3>& pts, std::vector<uint8_t>& outlier, int threads) {
    outlier.assign(pts.size(), 0);
    if (pts.size() <= kPlaneNeighbours + 1) return 0;   // too few points to tell the surface from outliers
    std::vector<double> kth(pts.size(), 0);
    for_each_neighbourhood(pts, kPlaneNeighbours, [&](size_t i, const size_t* idx, const double* d2, size_t found) {
        // idx[0] is the point itself (the points are de-duplicated)
        if (found > kIsolationRank) kth[i] = std::sqrt(d2[kIsolationRank]);
        Vec3 mean, n;
        if (found > 3 && fit_plane(pts, idx + 1, found - 1, mean, n))
            outlier[i] = std::abs((pts[i] - mean).dot(n)) > kOffPlane * std::sqrt(d2[found - 1]);
    }, threads);
    const double med = median_of(kth);
    std::vector<double> dev(kth.size());
    for (size_t i = 0; i < kth.size(); ++i) dev[i] = std::abs(kth[i] - med);
    const double mad = median_of(dev);
    const double limit = std::max(kMedianFactor * med, med + kMadFactor * kMadToSigma * mad);
    size_t count = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        outlier[i] = outlier[i] || kth[i] > limit;
        count += outlier[i];
    }
    return count;
}

}  // namespace cand
}  // namespace ca
