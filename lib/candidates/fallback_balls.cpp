// fallback_balls.cpp: makes every surface sample coverable. Thin features (tentacle tips,
// sharp ears) can have no inner Voronoi vertex near them, so no dilated candidate reaches some
// samples and the set cover is infeasible. Under each sample that no candidate reaches within
// kFallbackReach (in unit-cube units) this adds an inner ball touching the surface at that sample:
// its centre moves inward along the normal (of the nearest triangle on a mesh, of the sample on a
// point cloud), doubling the depth t while the distance to the surface stays within
// kFallbackReach / 2 of t (the ball still touches the surface at the sample and nowhere nearer),
// so the ball grows towards the medial axis (like the shrinking-ball construction of the medial
// axis). Its dilated radius reaches the sample for every offset delta >= kFallbackReach / 2, so a
// cover exists for every delta >= kFallbackReach. The optimiser uses such balls only where nothing
// else covers the sample. Samples where no point below the surface is inside (open sheets, open
// scans, non-orientable strips) get no ball and are still reported as uncoverable. On an open
// mesh the radius is also the distance to the hole caps (hole_caps.cpp); on a point cloud it is
// the distance to the nearest cloud point, and inside means point-cloud winding number > 1/2. On
// a noisy cloud the winding number fluctuates around 1/2 within the noise band below the
// (denoised) sample, so a sample with no inside point just below it gets its ball deeper, up to
// CloudNoise::depth (such a ball reaches the sample for offsets delta >= its depth), and a centre
// must also lie below the local plane at its nearest point, as the candidates' (a ball grown
// along a sample's normal can otherwise end up outside, where w fluctuates above 1/2).
// On a cloud whose normals were estimated or re-oriented, scattered wrong signs remain, and a wrong
// sign at a sample both points its normal outward and (with its wrongly signed neighbours) lifts w
// above 1/2 just outside it, so the ball would be grown outside. There the side is chosen by rays
// instead, which need no signs: from a sample on a closed surface, rays into the inside end on the
// surface's far side, rays into the outside mostly leave the bounding box. The ball is grown on
// the side whose rays escape less (ties: the normal's side) while w > 1/2; where w is nowhere
// above 1/2 on that side but the rays find it clearly enclosed and the other side open, it is
// grown there by the distances alone (the touching rule above); otherwise on the other side while
// w > 1/2. Clouds with trusted given normals keep the normal's side.
#include "candidates_internal.h"
#include "median.h"

#include "coverage.h"
#include "distance.h"
#include "kdtree.h"
#include "point_winding.h"
#include "surface.h"
#include "winding.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace ca {
namespace cand {

std::vector<size_t> unreached_samples(const CandidateSet& set, int threads, const Monitor& monitor) {
    std::vector<Vec3> centers(set.balls.size());
    std::vector<double> reach2(set.balls.size());
    for (size_t i = 0; i < set.balls.size(); ++i) {
        const double reach = set.balls[i].radius + kFallbackReach;
        if (!set.balls[i].center.allFinite() || !std::isfinite(reach) || reach < 0) return {};
        centers[i] = set.balls[i].center;
        reach2[i] = covered_radius2(reach);
    }
    for (const Vec3& s : set.cover_samples)
        if (!s.allFinite()) return {};
    const PackedPointTree tree(centers, reach2);
    std::vector<uint8_t> reached(set.cover_samples.size(), 0);
    // the queries make no progress calls of their own (a progress call's stop would not be seen
    // by the caller's monitor.stopped()); the cancel flag and the budget still stop them
    Monitor quiet = monitor;
    quiet.progress = nullptr;
    if (!parallel_for(set.cover_samples.size(), resolve_threads(threads), 8192, quiet, "fallback", [&](size_t b, size_t e) {
            for (size_t j = b; j < e; ++j) reached[j] = tree.reaches(set.cover_samples[j]);
        }))
        return {};
    std::vector<size_t> out;
    for (size_t j = 0; j < set.cover_samples.size(); ++j)
        if (!reached[j]) out.push_back(j);
    return out;
}

}  // namespace cand

namespace {
using cand::unreached_samples;

// The ball under sample s (unit inward direction -n): false if no point below s is inside.
// `noise_depth` > 0 (noisy clouds): the inside test is unreliable within that depth, so when no
// shallow point is inside, deeper ones are tried, doubling from kFallbackReach up to it.
bool grow_ball(const Vec3& s, const Vec3& n, const std::function<bool(const Vec3&)>& inside,
               const std::function<double(const Vec3&)>& radius_at, Ball& best, double noise_depth = 0,
               const std::function<bool(const Ball&)>& fits = nullptr) {
    // first depth inside the shape: half the reach, smaller for thinner parts
    best = {s, -1};
    double depth = 0.5 * kFallbackReach;
    for (; depth > 1e-4 * kFallbackReach; depth *= 0.25) {
        const Vec3 c = s - depth * n;
        if (!inside(c)) continue;
        best = {c, radius_at(c)};
        break;
    }
    for (double t = kFallbackReach; !(best.radius > 0) && t <= noise_depth; t *= 2) {
        const Vec3 c = s - t * n;
        if (inside(c)) best = {c, radius_at(c)}, depth = t;
    }
    if (!(best.radius > 0)) return false;
    // grow towards the medial axis while the ball still touches the surface at s only:
    // double the depth, then bisect between the last good and the first bad depth
    auto touches_at_s = [&](double t, Ball& ball) {
        const Vec3 c = s - t * n;
        if (!inside(c)) return false;
        const double r = radius_at(c);
        if (t - r > 0.5 * kFallbackReach) return false;
        if (fits && !fits({c, r})) return false;
        ball = {c, r};
        return true;
    };
    double good = depth, bad = 0;
    for (double t = 2 * depth; t < 1.0; t *= 2) {
        if (!touches_at_s(t, best)) { bad = t; break; }
        good = t;
    }
    for (int step = 0; step < 6 && bad > 0; ++step) {
        const double mid = 0.5 * (good + bad);
        if (touches_at_s(mid, best)) good = mid;
        else bad = mid;
    }
    touches_at_s(good, best);
    return true;
}

// Untrusted signs: how open each side of a cloud sample is, by rays through the cloud. A ray
// hits the surface where it comes within `tol_` of a cloud point (kRayTolerance x the median 8th-
// neighbour distance: closer than the gaps between points, so rays do not slip through the
// sampled surface, and far enough that a grazing ray does not stop at once); it escapes where it
// leaves the points' bounding box grown by kRayMargin. It is marched by the distance to the
// nearest point (less half the tolerance, at least half of it: no point lies nearer the path).
class SideRays {
public:
    SideRays(const std::vector<Vec3>& pts, const PointTree& tree, int threads) : tree_(tree) {
        std::vector<double> d8(pts.size(), 0);
        for_each_neighbourhood(pts, 8, [&](size_t i, const size_t*, const double* d2, size_t found) {
            d8[i] = std::sqrt(d2[found - 1]);
        }, threads);
        tol_ = kRayTolerance * median_of(std::move(d8));
        const auto [lo, hi] = bounding_box(pts);
        lo_ = lo - Vec3::Constant(kRayMargin), hi_ = hi + Vec3::Constant(kRayMargin);
    }
    // The fraction of kRays rays from s, spread over a cone of half-angle kRayCone around the unit
    // vector `axis`, that escape. They start kRayStart tolerances out along the axis, past the
    // sampled surface around s, so that only the far side of the part or another part stops them.
    double escaping(const Vec3& s, const Vec3& axis) const {
        const Vec3 u = axis.unitOrthogonal(), v = axis.cross(u);
        const double lowest = std::cos(kRayCone);
        size_t escaped = 0;
        for (size_t k = 0; k < kRays; ++k) {
            // Fibonacci points on the spherical cap: evenly spread directions
            const double z = 1 - (1 - lowest) * (double(k) + 0.5) / double(kRays), rho = std::sqrt(1 - z * z);
            const double phi = 2.399963229728653 * double(k);
            const Vec3 d = z * axis + rho * std::cos(phi) * u + rho * std::sin(phi) * v;
            Vec3 x = s + (kRayStart * tol_ / z) * d;
            bool hit = false;
            for (int step = 0; step < kMaxSteps && !hit; ++step) {
                const double dist = tree_.distance(x);
                hit = dist < tol_;
                x += std::max(dist - 0.5 * tol_, 0.5 * tol_) * d;
                if ((x.array() < lo_.array()).any() || (x.array() > hi_.array()).any()) break;
            }
            escaped += !hit;
        }
        return double(escaped) / double(kRays);
    }

private:
    static constexpr size_t kRays = 16;
    static constexpr double kRayCone = 50 * 3.14159265358979323846 / 180;
    static constexpr double kRayTolerance = 0.75, kRayStart = 1.2, kRayMargin = 0.05;
    static constexpr int kMaxSteps = 300;
    const PointTree& tree_;
    double tol_ = 0;
    Vec3 lo_, hi_;
};

// A ball is grown by the distances alone, on the side the winding number calls inside nowhere,
// only where that side is clearly enclosed: at most this fraction of its rays escape, and at least
// this fraction more on the other side. Where both sides are open the part is thinner than the
// rays' start (they begin beyond its far side) and they tell nothing.
constexpr double kEnclosed = 0.25;

}  // namespace

size_t add_fallback_balls(CandidateSet& set, const WindingNumber& winding, const MeshDistance& distance,
                          const MeshDistance* caps, int threads, const Monitor& monitor) {
    // radius at c: distance to the surface, and to the hole caps of an open mesh (a ball under a
    // hole must not grow out through it)
    auto radius_at = [&](const Vec3& c) {
        const double r = distance.distance(c);
        return caps ? caps->distance_below(c, r) : r;
    };
    auto inside = [&](const Vec3& c) { return winding.inside(c); };
    const Mesh& mesh = set.surface.mesh;
    if (!set.surface.kind().is_mesh() || set.cover_samples.empty()) return 0;
    size_t added = 0;
    const std::vector<size_t> unreached = unreached_samples(set, threads, monitor);
    for (size_t k = 0; k < unreached.size(); ++k) {
        if (monitor.stopped_at(k)) break;
        const Vec3& s = set.cover_samples[unreached[k]];
        Vec3 closest;
        uint32_t tri = 0;
        distance.distance(s, &closest, &tri);
        const Tri& f = mesh.triangles[tri];
        Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]]).cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]);
        if (!(n.norm() > 0)) continue;
        n.normalize();
        Ball best;
        if (!grow_ball(s, n, inside, radius_at, best)) continue;
        set.balls.push_back(best);
        ++added;
    }
    return added;
}

size_t add_cloud_fallback_balls(CandidateSet& set, const PointCloudWinding& winding, const std::vector<Vec3>& normals,
                                const CloudNoise& noise, int threads, const Monitor& monitor) {
    if (set.cover_samples.empty() || set.dense_samples.empty() || normals.size() != set.cover_samples.size()) return 0;
    const PointTree tree(set.dense_samples);
    auto radius_at = [&](const Vec3& c) { return tree.distance(c); };
    auto inside = [&](const Vec3& c) { return winding.inside(c) && (!noise.below_surface || noise.below_surface(c)); };
    auto anywhere = [&](const Vec3& c) { return !noise.below_surface || noise.below_surface(c); };
    size_t added = 0;
    const std::vector<size_t> unreached = unreached_samples(set, threads, monitor);
    std::unique_ptr<SideRays> rays;
    if (noise.untrusted_signs && !unreached.empty()) rays = std::make_unique<SideRays>(set.dense_samples, tree, resolve_threads(threads));
    for (size_t k = 0; k < unreached.size(); ++k) {
        // a sample's rays march up to thousands of steps: tested every sample then
        if (rays ? monitor.stopped() : monitor.stopped_at(k)) break;
        const size_t j = unreached[k];
        const Vec3& s = set.cover_samples[j];
        Vec3 n = normals[j];
        Ball best;
        bool grown = false;
        if (rays) {
            // n: towards the more open side
            const double front = rays->escaping(s, n), behind = rays->escaping(s, -n);
            if (behind > front) n = -n;
            grown = grow_ball(s, n, inside, radius_at, best, noise.depth, noise.within_reach);
            const bool clear = std::min(front, behind) <= kEnclosed && std::abs(front - behind) >= kEnclosed;
            if (!grown && clear) grown = grow_ball(s, n, anywhere, radius_at, best, 0, noise.within_reach);
            if (!grown) grown = grow_ball(s, -n, inside, radius_at, best, noise.depth, noise.within_reach);
        } else {
            grown = grow_ball(s, n, inside, radius_at, best, noise.depth, noise.within_reach);
        }
        if (!grown) continue;
        set.balls.push_back(best);
        ++added;
    }
    return added;
}

}  // namespace ca
