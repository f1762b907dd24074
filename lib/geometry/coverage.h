// coverage.h: the sparse coverage relation between surface samples and dilated candidate
// balls: sample j is covered by ball i iff |c_i - s_j| <= r'_i. Built with one k-d tree radius
// query per ball (nanoflann); stored both ways (ball -> samples, sample -> balls) as sorted
// compressed lists. Never dense.
#pragma once
#include "common.h"

namespace ca {

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
