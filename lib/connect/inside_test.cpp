// inside_test.cpp: the inside test for skeleton elements (InsideTest, rule in connect.h). On an
// open mesh the envelope rule also holds against the hole caps (hole_caps.h).
// An element is tested at hundreds of grid points; most of the cost is the winding number and the
// distance to the surface at each. Two exact shortcuts skip most of those queries without
// changing any decision (a cache of "probes" per element, points where the exact distance d to
// the surface is known):
//  * the distance is 1-Lipschitz: dist(p) >= d(q) - |p - q|, which often proves the envelope
//    condition dist(p) >= r(p) - tol at the grid points near a probe q;
//  * on a closed mesh (every directed edge matched by its reverse) the exact winding number is
//    an integer, constant on each ball B(q, d(q)) that the surface does not cross, so a point in
//    that ball is inside iff q is (the hierarchical approximation errs by far less than 1/2), and
//    two probes whose balls overlap are on the same side. On open meshes (holes) the winding
//    number varies continuously and is evaluated at every point.
#include "connect.h"

#include "bvh.h"
#include "distance.h"
#include "kdtree.h"
#include "mesh_topology.h"
#include "point_winding.h"
#include "winding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ca {

namespace {

// A test point closer than this fraction of a vertex's radius to that vertex's centre is inside
// that (inner) ball; the margin absorbs Voronoi balls that graze the surface between samples.
constexpr double kBallTrust = 0.95;

bool in_ball(const Vec3& p, const Ball& b) { return (p - b.center).squaredNorm() < kBallTrust * kBallTrust * b.radius * b.radius; }

// Margin (internal units, the model spans ~1) by which a shortcut must hold; distances are
// computed to ~1e-16, so a decision within this margin is always evaluated directly.
constexpr double kProbeMargin = 1e-9;
// Probes searched per test point (the most recent ones: grid points are visited row by row).
constexpr size_t kProbeWindow = 48;

}  // namespace

struct InsideTest::Impl {
    std::shared_ptr<const WindingNumber> winding;   // meshes only (the candidate set's, if it has them)
    std::shared_ptr<const MeshDistance> distance;   // meshes only (envelope rule, shortcuts)
    std::shared_ptr<const MeshDistance> caps;       // open meshes: the hole caps (envelope rule)
    bool closed = false;                      // winding number integer-valued (shortcut allowed)
    std::shared_ptr<const PointCloudWinding> cloud_winding;   // point clouds (the candidate set's)
    std::shared_ptr<const CloudReach> cloud_reach;            // point clouds: the reach rule (candidates.h)
    std::vector<Vec3> cloud_points;           // point clouds: the points (envelope rule)
    std::unique_ptr<PointTree> cloud_tree;
    std::vector<Vec3> centers;                // the candidate balls (point clouds without a winding number)
    std::vector<double> radii;
    std::unique_ptr<PointTree> tree;
};

// The per-element probe cache (meshes). Each query answers exactly what the direct evaluation
// at p would answer.
class InsideTest::Probes {
public:
    explicit Probes(const InsideTest::Impl& impl) : impl_(impl) {}

    // dist(p) >= need (need > 0), as distance_below(p, need) >= need would decide.
    bool distance_at_least(const Vec3& p, double need) {
        const size_t stop = probes_.size() > kProbeWindow ? probes_.size() - kProbeWindow : 0;
        for (size_t i = probes_.size(); i-- > stop;)
            if (probes_[i].d - (p - probes_[i].q).norm() >= need + kProbeMargin) return true;
        const Probe& pr = add(p);
        return !(pr.d2 < need * need) || pr.d >= need;
    }

    // Winding number > 1/2 at p.
    bool inside(const Vec3& p) {
        if (!impl_.closed) return impl_.winding->inside(p);
        const size_t stop = probes_.size() > kProbeWindow ? probes_.size() - kProbeWindow : 0;
        for (size_t i = probes_.size(); i-- > stop;) {
            Probe& pr = probes_[i];
            const double reach = pr.d - kProbeMargin;
            if (reach > 0 && (p - pr.q).squaredNorm() < reach * reach) return resolve(i);
        }
        add(p);
        return resolve(probes_.size() - 1);
    }

private:
    struct Probe {
        Vec3 q;
        double d2, d;      // exact squared distance and distance to the surface
        int in;            // winding number > 1/2 at q: 1, 0, or -1 (not evaluated yet)
    };
    // Whether probe i is inside: inherited from a probe whose ball overlaps its ball (the union
    // of the two surface-free balls is connected), else the winding number at its point.
    bool resolve(size_t i) {
        Probe& pr = probes_[i];
        if (pr.in < 0) {
            const size_t stop = probes_.size() > kProbeWindow ? probes_.size() - kProbeWindow : 0;
            for (size_t j = probes_.size(); j-- > stop && pr.in < 0;) {
                const Probe& o = probes_[j];
                const double reach = pr.d + o.d - kProbeMargin;
                if (o.in >= 0 && pr.d > kProbeMargin && o.d > kProbeMargin && (pr.q - o.q).squaredNorm() < reach * reach)
                    pr.in = o.in;
            }
            if (pr.in < 0) pr.in = impl_.winding->inside(pr.q) ? 1 : 0;
        }
        return pr.in == 1;
    }
    // The exact distance at p. It is at most d(q) + |p - q| for every probe q (1-Lipschitz), so the
    // nearest-triangle search starts pruned by the smallest such bound (widened far beyond
    // rounding): it then finds the same closest triangle, hence the same value, as the unbounded
    // search, which remains the fallback when nothing lies below the bound.
    Probe& add(const Vec3& p) {
        double bound = std::numeric_limits<double>::infinity();
        const size_t stop = probes_.size() > kProbeWindow ? probes_.size() - kProbeWindow : 0;
        for (size_t i = probes_.size(); i-- > stop;) bound = std::min(bound, probes_[i].d + (p - probes_[i].q).norm());
        const double upper = bound * (1 + 1e-9) + kProbeMargin;
        double d = std::isfinite(upper) ? impl_.distance->distance_below(p, upper) : upper;
        if (!(d < upper)) d = impl_.distance->distance(p);
        probes_.push_back({p, d * d, d, -1});
        return probes_.back();
    }
    const InsideTest::Impl& impl_;
    std::vector<Probe> probes_;
};

InsideTest::InsideTest(const CandidateSet& set) : impl_(std::make_unique<Impl>()) {
    if (set.surface.kind().is_mesh()) {
        impl_->winding = set.queries.winding;
        impl_->distance = set.queries.distance;
        impl_->closed = set.surface.topology.closed;
        impl_->caps = set.queries.cap_distance;
        return;
    }
    impl_->cloud_winding = set.queries.cloud_winding;
    impl_->cloud_reach = set.queries.cloud_reach;
    // the distance to the surface of a point cloud: to its nearest point (an overestimate by at
    // most the sample spacing, far below the envelope tolerance delta)
    impl_->cloud_points = set.dense_samples.empty() ? set.cover_samples : set.dense_samples;
    impl_->cloud_tree = std::make_unique<PointTree>(impl_->cloud_points);
    if (impl_->cloud_winding) return;
    for (const Ball& b : set.balls) {
        impl_->centers.push_back(b.center);
        impl_->radii.push_back(b.radius);
    }
    impl_->tree = std::make_unique<PointTree>(impl_->centers);
}
InsideTest::~InsideTest() = default;
InsideTest::InsideTest(InsideTest&&) noexcept = default;
InsideTest& InsideTest::operator=(InsideTest&&) noexcept = default;

bool InsideTest::inside(const Vec3& p) const {
    if (impl_->winding) return impl_->winding->inside(p);
    if (impl_->cloud_winding) return impl_->cloud_winding->inside(p);
    // Point clouds without their winding number: inside one of the 16 nearest candidate balls (shrunk by kBallTrust). Not used
    // for meshes: Voronoi balls clamped to the nearest sample can graze thin features.
    constexpr size_t k = 16;
    size_t idx[k];
    double d2[k];
    const size_t found = impl_->tree->nearest(p, k, idx, d2);
    for (size_t i = 0; i < found; ++i)
        if (d2[i] < kBallTrust * kBallTrust * impl_->radii[idx[i]] * impl_->radii[idx[i]]) return true;
    return false;
}

// One test point: the envelope condition (tol >= 0), then inside one of the element's
// own balls, inside the shape, or (outside_tol > 0, meshes) at most outside_tol outside it.
bool InsideTest::point_ok(Probes* probes, const Vec3& p, double r, double tol, double outside_tol,
                          const Ball* const* own, int n_own) const {
    if (tol >= 0 && probes) {
        const double need = r - tol;
        if (need > 0 && !probes->distance_at_least(p, need)) return false;
        // the hole caps bound the element as the surface does: nothing bulges out through a hole
        if (need > 0 && impl_->caps && impl_->caps->distance_below(p, need) < need) return false;
    } else if (tol >= 0 && impl_->cloud_tree) {
        const double need = r - tol;
        if (need > 0 && impl_->cloud_tree->distance(p) < need) return false;
    }
    for (int i = 0; i < n_own; ++i)
        if (in_ball(p, *own[i])) return true;
    if (probes ? probes->inside(p) : inside(p)) return true;
    return outside_tol > 0 && impl_->distance && impl_->distance->distance_below(p, outside_tol) < outside_tol;
}

// Point clouds: the element's interpolated balls (or, for a segment with `balls` false, its centre
// line) stay within reach of the cloud (CloudReach), tested
// at spacing max(h, reach / 2): the rule itself allows the reach, and each test costs a sphere of
// distance queries. True where the candidate set has no reach rule (meshes, caller arrays).
bool InsideTest::segment_within_reach(const Ball& a, const Ball& b, double h, bool balls) const {
    const CloudReach* reach = impl_->cloud_reach.get();
    if (!reach) return true;
    const int n = std::max(1, int(std::ceil((b.center - a.center).norm() / std::max(h, 0.5 * reach->reach()))));
    for (int i = 1; i < n; ++i) {
        const double t = double(i) / n;
        const double r = balls ? (1 - t) * a.radius + t * b.radius : 0;
        if (!reach->within({a.center + (b.center - a.center) * t, r})) return false;
    }
    return true;
}

namespace {

// The interpolated balls of a triangle at the points (i a + j b + k c) / n of its lattice, n steps
// of at most `step` along its longest side, the corners left out: true when `ok` accepts them all.
template <class Ok>
bool triangle_lattice_ok(const Ball& a, const Ball& b, const Ball& c, double step, Ok&& ok) {
    const double longest = std::max({(b.center - a.center).norm(), (c.center - b.center).norm(),
                                     (a.center - c.center).norm()});
    const int n = std::max(1, int(std::ceil(longest / step)));
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const int k = n - i - j;
            if (i == n || j == n || k == n) continue;   // the vertices themselves
            const Vec3 p = (a.center * i + b.center * j + c.center * k) / double(n);
            const double r = (a.radius * i + b.radius * j + c.radius * k) / double(n);
            if (!ok(p, r)) return false;
        }
    return true;
}

}  // namespace

bool InsideTest::triangle_within_reach(const Ball& a, const Ball& b, const Ball& c, double h) const {
    const CloudReach* reach = impl_->cloud_reach.get();
    if (!reach) return true;
    return triangle_lattice_ok(a, b, c, std::max(h, 0.5 * reach->reach()),
                               [reach](const Vec3& p, double r) { return reach->within({p, r}); });
}

bool InsideTest::segment_inside(const Ball& a, const Ball& b, double h, double tol, double outside_tol,
                                bool reach_balls) const {
    if (!segment_within_reach(a, b, h, reach_balls)) return false;
    const int n = std::max(1, int(std::ceil((b.center - a.center).norm() / h)));
    const Ball* own[2] = {&a, &b};
    std::unique_ptr<Probes> probes = impl_->winding ? std::make_unique<Probes>(*impl_) : nullptr;
    for (int i = 1; i < n; ++i) {
        const double t = double(i) / n;
        const Vec3 p = a.center + (b.center - a.center) * t;
        if (!point_ok(probes.get(), p, (1 - t) * a.radius + t * b.radius, tol, outside_tol, own, 2)) return false;
    }
    return true;
}

bool InsideTest::triangle_inside(const Ball& a, const Ball& b, const Ball& c, double h, double tol) const {
    if (!triangle_within_reach(a, b, c, h)) return false;
    const Ball* own[3] = {&a, &b, &c};
    std::unique_ptr<Probes> probes = impl_->winding ? std::make_unique<Probes>(*impl_) : nullptr;
    return triangle_lattice_ok(a, b, c, h, [&](const Vec3& p, double r) {
        return point_ok(probes.get(), p, r, tol, 0, own, 3);
    });
}

}  // namespace ca
