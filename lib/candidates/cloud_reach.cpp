// cloud_reach.cpp: point clouds: keeps every ball within reach of the cloud. A cloud says where
// the surface is only near its points; a ball whose sphere reaches far from every point is
// bounded there by nothing the cloud samples. On a closed cloud such parts of a ball lie inside,
// enclosed by the cloud; on an open scan (a partial view, fragments, a model with an open
// bottom) the Voronoi balls under the sheet hang out through the open side, and the winding
// number does not tell (under a curved sheet it stays above 1/2 far from it); a wrong-side normal
// or a noise spike lifts w above 1/2 outside the shape. The rule: every point q of a ball's sphere
// that lies farther than the reach from the nearest cloud point must be inside by the winding
// number and enclosed by the cloud: of kRays rays from q, evenly spread over all directions, at
// most kOpenRays leave the (grown) bounding box without coming within the wall radius of a cloud
// point (kOpenRays = 1/16 of them: from under a hemisphere's dome the open side takes at least
// 15 % of the directions, so nothing under an open sheet is enclosed, while a closed cloud's
// walls stop every ray). Rays need no normals, so wrong signs cannot mislead them; a hole lets
// through the rays that see it, so points whose view of a hole exceeds 1/16 of the directions
// count as outside and points deeper inside do not.
// - The reach is max(kCloudReach, median 8th-neighbour distance): nearer than the gaps between
//   points, a sphere point cannot be told from one touching the unsampled surface between them.
// - The wall radius is 0.75 x the median 8th-neighbour distance (as the fallback balls' rays):
//   more than half the gaps between neighbours, so rays do not slip through the sampled surface.
//   Rays march on a voxel grid whose voxels within the wall radius of a point are walls (a voxel
//   is a wall when any part of it is), so a step of one voxel cannot cross a wall.
// - The sphere is probed at kReachDirections evenly spread points; a ball with radius + centre
//   distance within the reach cannot leave it and is not probed. Whether a probe is within the
//   reach of a point is read from its voxel where all of the voxel is or none of it is, else
//   computed; a far probe takes the verdict (inside
//   and enclosed) of the centre of its cell of side reach / 2, computed once per cell: that
//   centre lies within the empty ball of radius reach around the probe, so on the probe's side of
//   the cloud and more than half the reach from it (cells of side reach, which give centres up to
//   0.87 of the reach away, judge too coarsely near thin parts).
#include "candidates_internal.h"
#include "median.h"

#include "kdtree.h"
#include "point_winding.h"

#include <algorithm>
#include <cmath>

namespace ca {

namespace {

constexpr size_t kReachDirections = 64;
constexpr size_t kRays = 32;
constexpr size_t kOpenRays = kRays / 16;
constexpr double kWallRadius = 0.75;   // x the median 8th-neighbour distance
constexpr size_t kMaxCells = 192;      // voxels along the longest side at most
constexpr uint8_t kWall = 1, kNear = 2, kMaybe = 4;  // voxel flags

// n evenly spread unit vectors (Fibonacci points on the sphere).
std::vector<Vec3> sphere_directions(size_t n) {
    std::vector<Vec3> out;
    out.reserve(n);
    for (size_t k = 0; k < n; ++k) {
        const double z = 1 - 2 * (double(k) + 0.5) / double(n), rho = std::sqrt(1 - z * z);
        const double phi = 2.399963229728653 * double(k);
        out.push_back(Vec3(rho * std::cos(phi), rho * std::sin(phi), z));
    }
    return out;
}

}  // namespace

CloudReach::CloudReach(std::vector<Vec3> points, std::shared_ptr<const PointCloudWinding> winding, int threads,
                       const Monitor& monitor)
    : pts_(std::move(points)), winding_(std::move(winding)) {
    const std::vector<Vec3>& pts = pts_;
    tree_ = std::make_unique<PointTree>(pts_);
    reach_ = kCloudReach;
    double d8 = 0;
    if (pts.size() > 8) {
        std::vector<double> d(pts.size(), 0);
        for_each_neighbourhood(pts, 8, [&](size_t i, const size_t*, const double* d2, size_t found) {
            d[i] = std::sqrt(d2[found - 1]);
        }, threads);
        d8 = median_of(std::move(d));
        reach_ = std::max(reach_, d8);
    }
    directions_ = sphere_directions(kReachDirections);
    rays_ = sphere_directions(kRays);
    if (pts.empty()) return;
    // the wall grid: the bounding box grown by the reach and a voxel
    const double wall = kWallRadius * d8;
    auto [lo, hi] = bounding_box(pts);
    const double side = (hi - lo).maxCoeff() + 2 * reach_;
    cell_ = std::max(side / double(kMaxCells), wall > 0 ? wall / 1.5 : side / double(kMaxCells));
    lo_ = lo - Vec3::Constant(reach_ + cell_);
    for (int a = 0; a < 3; ++a) dims_[a] = size_t(std::ceil((hi[a] - lo[a] + 2 * (reach_ + cell_)) / cell_)) + 1;
    walls_.assign(dims_[0] * dims_[1] * dims_[2], 0);
    // a voxel is a wall (kWall) when its centre is within wall + half its diagonal of a point; it
    // is near (kNear) when all of it is within the reach of one, and may be (kMaybe) when part of it
    // is
    // stamping costs a block of voxels per point: tested for a stop request every few thousand
    const double half = 0.8660254037844386 * cell_;
    const double grow = wall + half;
    const double near = std::max(0.0, reach_ - half), maybe = reach_ + half;
    const long span = long(std::ceil(std::max(grow, maybe) / cell_));
    for (size_t n = 0; n < pts.size(); ++n) {
        if (monitor.stopped_at(n)) return;
        const Vec3& p = pts[n];
        const Vec3 g = (p - lo_) / cell_;
        const long ci = long(g.x()), cj = long(g.y()), ck = long(g.z());
        for (long i = ci - span; i <= ci + span; ++i)
            for (long j = cj - span; j <= cj + span; ++j)
                for (long k = ck - span; k <= ck + span; ++k) {
                    if (i < 0 || j < 0 || k < 0 || size_t(i) >= dims_[0] || size_t(j) >= dims_[1] || size_t(k) >= dims_[2]) continue;
                    const Vec3 c = lo_ + cell_ * Vec3(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
                    const double d2 = (c - p).squaredNorm();
                    uint8_t& v = walls_[(size_t(i) * dims_[1] + size_t(j)) * dims_[2] + size_t(k)];
                    if (d2 <= grow * grow) v |= kWall;
                    if (d2 <= near * near) v |= kNear;
                    if (d2 <= maybe * maybe) v |= kMaybe;
                }
    }
    // the far points' verdicts, one per cell of side reach / 2
    side_cell_ = 0.5 * reach_;
    for (int a = 0; a < 3; ++a) side_dims_[a] = size_t(std::ceil(double(dims_[a]) * cell_ / side_cell_)) + 1;
    const size_t cells = side_dims_[0] * side_dims_[1] * side_dims_[2];
    verdicts_ = std::make_unique<std::atomic<uint8_t>[]>(cells);
    for (size_t i = 0; i < cells; ++i) verdicts_[i].store(0, std::memory_order_relaxed);
}

bool CloudReach::far_point_inside(const Vec3& q) const {
    const Vec3 g = (q - lo_) / side_cell_;
    if ((g.array() < 0).any() || g.x() >= double(side_dims_[0]) || g.y() >= double(side_dims_[1]) || g.z() >= double(side_dims_[2]))
        return false;
    const size_t i = size_t(g.x()), j = size_t(g.y()), k = size_t(g.z());
    std::atomic<uint8_t>& verdict = verdicts_[(i * side_dims_[1] + j) * side_dims_[2] + k];
    uint8_t v = verdict.load(std::memory_order_relaxed);
    if (v == 0) {
        // a pure function of the cell: threads that race store the same verdict
        const Vec3 c = lo_ + side_cell_ * Vec3(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
        v = winding_->inside(c) && enclosed(c) ? 1 : 2;
        verdict.store(v, std::memory_order_relaxed);
    }
    return v == 1;
}

bool CloudReach::enclosed(const Vec3& q) const {
    size_t open = 0;
    for (size_t r = 0; r < rays_.size(); ++r) {
        const Vec3 step = cell_ * rays_[r];
        Vec3 x = q;
        bool hit = false;
        for (;;) {
            x += step;
            const Vec3 g = (x - lo_) / cell_;
            if ((g.array() < 0).any() || g.x() >= double(dims_[0]) || g.y() >= double(dims_[1]) || g.z() >= double(dims_[2])) break;
            if (walls_[(size_t(g.x()) * dims_[1] + size_t(g.y())) * dims_[2] + size_t(g.z())] & kWall) { hit = true; break; }
        }
        if (!hit && ++open > kOpenRays) return false;
        // too many open rays already decided; too few left to open it: enclosed
        if (open + (rays_.size() - 1 - r) <= kOpenRays) return true;
    }
    return true;
}

bool CloudReach::within(const Ball& b) const {
    const double r = b.radius > 0 ? b.radius : 0;
    if (r + tree_->distance(b.center) <= reach_) return true;
    if (r == 0) return point_within(b.center);
    for (const Vec3& d : directions_)
        if (!point_within(b.center + r * d)) return false;
    return true;
}

bool CloudReach::point_within(const Vec3& q) const {
    const Vec3 g = (q - lo_) / cell_;
    if ((g.array() < 0).any() || g.x() >= double(dims_[0]) || g.y() >= double(dims_[1]) || g.z() >= double(dims_[2]))
        return false;   // beyond the grid: farther than the reach from every point
    const uint8_t v = walls_[(size_t(g.x()) * dims_[1] + size_t(g.y())) * dims_[2] + size_t(g.z())];
    if ((v & kNear) || ((v & kMaybe) && tree_->distance(q) <= reach_)) return true;
    return far_point_inside(q);
}

CloudReach::~CloudReach() = default;

namespace cand {

size_t drop_beyond_reach(const CloudReach& reach, int threads, const Monitor& monitor, std::vector<Ball>& balls) {
    std::vector<uint8_t> keep(balls.size(), 1);
    if (!parallel_for(balls.size(), threads, 1024, monitor, "candidates", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) keep[i] = reach.within(balls[i]);
        }))
        return 0;
    size_t n = 0;
    for (size_t i = 0; i < balls.size(); ++i)
        if (keep[i]) balls[n++] = balls[i];
    const size_t dropped = balls.size() - n;
    balls.resize(n);
    return dropped;
}

}  // namespace cand
}  // namespace ca
