// coverage.h: the sparse coverage relation between surface samples and dilated candidate
// balls: sample j is covered by ball i iff |c_i - s_j| <= r'_i. Built with one k-d tree radius
// query per ball (nanoflann); stored both ways (ball -> samples, sample -> balls) as sorted
// compressed lists. Never dense.
#pragma once
#include "common.h"

#include <cmath>
#include <limits>

namespace ca {

// The rule "ball (c, r') covers sample s": |c - s| <= r'. Compared squared, with r'^2 widened by
// a relative 1e-12 and one ulp (for r' = 0) so that a sample exactly at distance r' counts as
// covered whatever the rounding; the k-d tree query (strict d^2 < bound) uses the same bound.
inline double covered_radius2(double r) {
    return std::nextafter(r * r * (1.0 + 1e-12), std::numeric_limits<double>::infinity());
}
inline bool covers(const Vec3& c, double r, const Vec3& s) { return (c - s).squaredNorm() < covered_radius2(r); }

struct Coverage {
    size_t n_samples = 0;
    size_t n_balls = 0;
    // ball i covers samples ball_samples[ball_ptr[i] .. ball_ptr[i+1]), sorted ascending
    std::vector<uint32_t> ball_ptr, ball_samples;
    // sample j is covered by balls sample_balls[sample_ptr[j] .. sample_ptr[j+1]), sorted ascending
    std::vector<uint32_t> sample_ptr, sample_balls;

    // Fill the sample -> balls direction from the ball -> samples direction.
    void build_transpose();
};

// dilated_radii[i] = r'_i (absolute, same units as the points).
// `threads`: 0 = all cores; the result is the same for any number.
Status build_coverage(const std::vector<Vec3>& samples, const std::vector<Vec3>& centers,
                      const std::vector<double>& dilated_radii, const Monitor& monitor, Coverage& out,
                      int threads = 0);

}  // namespace ca
