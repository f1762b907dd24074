// hole_caps.cpp: keeps candidate balls of an open mesh from reaching out through its holes. A
// Voronoi ball is empty of samples, but a hole has no samples, so a ball under a hole bulges out
// through it; a random candidate's radius (distance to the mesh) has the same problem. Every
// candidate's radius is clamped to its distance to the hole caps (geometry/hole_caps.h), which are
// used only for distances. Closed meshes have no caps and are unchanged.
#include "candidates.h"

#include "distance.h"
#include "parallel.h"

#include <algorithm>

namespace ca {

bool clamp_to_hole_caps(CandidateSet& set, const MeshDistance& distance, int threads, const Monitor& monitor) {
    set.report.hole_clamped = 0;
    std::vector<uint8_t> clamped(set.balls.size(), 0);
    const bool done = parallel_for(set.balls.size(), threads, 4096, monitor, "candidates", [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            Ball& ball = set.balls[i];
            const double d = distance.distance_below(ball.center, ball.radius);
            if (d < ball.radius) ball.radius = d, clamped[i] = 1;
        }
    });
    if (!done) return false;
    set.balls.erase(std::remove_if(set.balls.begin(), set.balls.end(), [](const Ball& x) { return !(x.radius > 0); }),
                    set.balls.end());
    for (uint8_t c : clamped) set.report.hole_clamped += c;
    return true;
}

}  // namespace ca
