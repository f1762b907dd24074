// surface_balls.cpp: makes every cover sample of a surface with area coverable. Open sheets
// (foliage cards, sails, banners, decals, water planes), single-sided parts and parts too thin for
// the inside test have no inner ball near some samples: the inner Voronoi vertices and the
// fallback balls (fallback_balls.cpp) both need an inside. The medial surface of a zero-thickness
// sheet is the sheet itself, so under each cover sample that no candidate reaches within
// kFallbackReach this adds a surface ball:
//  * on a two-sided part thinner than kThinGap (the surface is met again along the sample's
//    normal line within that distance): the ball midway between the two sides, touching both
//    (radius = its distance to the surface, about half the gap);
//  * elsewhere (a single-sided sheet, a card, a plane): the point of the surface at the sample,
//    radius 0.
// A radius-0 surface ball covers its own sample at every dilation (the coverage rule counts
// distance 0 as covered), a thin part's ball for every offset delta >= kFallbackReach (its centre
// is at most kThinGap / 2 = kFallbackReach from the sample), so a cover exists wherever the
// fallback balls promise one, and the minimum cover takes surface balls only where no medial ball
// serves. They are
// appended after every other candidate; CandidateSet::surface_balls counts them.
#include "candidates_internal.h"

#include "distance.h"
#include "parallel.h"

#include <cmath>
#include <optional>

namespace ca {
namespace {

// A part is thin (two-sided) when the surface is met again within this distance along the normal
// line of a sample; thicker open parts are sheets in their own right. Unit-cube units.
constexpr double kThinGap = 2 * kFallbackReach;
// Steps of the probe along each side of the normal line, up to kThinGap / 2.
constexpr int kGapSteps = 8;

// The ball midway across a thin part at sample s (unit normal n of its triangle): along each side
// of the normal line, the first depth t at which another part of the surface is nearer than s
// (distance d < t) gives the gap t + d (exact for a parallel opposite side); the smaller gap wins.
// None when neither side meets the surface within kThinGap.
std::optional<Ball> thin_part_ball(const Vec3& s, const Vec3& n, const MeshDistance& distance) {
    double best_gap = kThinGap;
    Vec3 best_dir = Vec3::Zero();
    for (const double side : {-1.0, 1.0}) {
        const Vec3 dir = side * n;
        for (int k = 1; k <= kGapSteps; ++k) {
            const double t = 0.5 * kThinGap * double(k) / kGapSteps;
            const double d = distance.distance_below(s + t * dir, t);
            if (d < 0.9 * t) {
                if (t + d < best_gap) best_gap = t + d, best_dir = dir;
                break;
            }
        }
    }
    if (!(best_gap < kThinGap)) return std::nullopt;
    const Vec3 c = s + 0.5 * best_gap * best_dir;
    return Ball{c, distance.distance(c)};
}

}  // namespace

namespace cand {

size_t add_surface_balls(CandidateSet& set, const MeshDistance* distance, int threads, const Monitor& monitor) {
    const std::vector<size_t> unreached = unreached_samples(set, threads, monitor);
    if (unreached.empty() || monitor.stopped()) return 0;
    std::vector<Ball> balls(unreached.size());
    const Mesh& mesh = set.surface.mesh;
    const bool probe = distance && !set.surface.flat && set.surface.kind().is_mesh();
    Monitor quiet = monitor;
    quiet.progress = nullptr;
    const bool done = parallel_for(unreached.size(), resolve_threads(threads), 256, quiet, "surface balls", [&](size_t b, size_t e) {
        for (size_t k = b; k < e; ++k) {
            const Vec3& s = set.cover_samples[unreached[k]];
            balls[k] = {s, 0.0};
            if (!probe) continue;
            uint32_t tri = 0;
            distance->distance(s, nullptr, &tri);
            const Tri& f = mesh.triangles[tri];
            const Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]]).cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]);
            if (!(n.norm() > 0)) continue;
            if (const std::optional<Ball> thin = thin_part_ball(s, n.normalized(), *distance)) balls[k] = *thin;
        }
    });
    if (!done) return 0;
    set.balls.insert(set.balls.end(), balls.begin(), balls.end());
    set.surface_balls = balls.size();
    return balls.size();
}

}  // namespace cand
}  // namespace ca
