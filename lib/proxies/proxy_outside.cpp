// proxy_outside.cpp: how far a primitive may reach outside the shape, as a proven bound rather than
// a sample. A primitive is the union of the balls B(c(t), r(t)) interpolated along its segment
// (the convex hull of two balls is that union). A ball whose centre lies at depth D (distance to
// the surface, negative outside) reaches at most r - D outside, since B(c, D) is inside. The bound
// r(t) - D(c(t)) changes with t by at most |c2 - c1| + |r2 - r1| per unit (D is 1-Lipschitz), so
// between two samples it is at most their mean plus half the step times that slope; the segment is
// sampled coarsely and halved where that could still exceed 0 and the largest sample.
// The other way round, any point of a primitive shows how far it reaches at least: points on the
// interpolated spheres give a measured excess that the true one is never below.
#include "proxies.h"

#include "distance.h"
#include "winding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ca {

namespace {

// Spacing of the depth samples along a capsule's segment, first and finest (internal units: the
// model's longest side is 1); the finest adds a slack of half a step of the bound's slope.
constexpr double kCoarseStep = 0.05;
constexpr double kSegmentStep = 0.004;
// The measured excess: this many directions (a Fibonacci sphere) on interpolated spheres this far
// apart along the segment.
constexpr int kMeasureDirections = 64;
constexpr double kMeasureStep = 0.02;

}  // namespace

double outside_bound(const Proxy& p, const ShapeQueries& shape, double enough) {
    if (p.kind == ProxyKind::sphere) return std::max(0.0, p.a.radius - shape.depth(p.a.center));
    const Vec3 e = p.b.center - p.a.center;
    const double length = e.norm(), dr = p.b.radius - p.a.radius;
    auto g = [&](double t) { return p.a.radius + t * dr - shape.depth(p.a.center + t * e); };
    // Over [a, b] the bound is at most (g(a) + g(b)) / 2 + slope (b - a) / 2. Intervals are halved,
    // coarse first, until that is at most `enough` (at least 0: the caller needs no finer answer
    // there), at most the largest sampled value plus the slack of the finest step, or the interval
    // is the finest step.
    const double slope = length + std::abs(dr);
    const size_t coarse = std::max<size_t>(1, size_t(std::ceil(length / kCoarseStep)));
    std::vector<double> ts(coarse + 1), gs(coarse + 1);
    double best = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i <= coarse; ++i) {
        ts[i] = double(i) / double(coarse);
        gs[i] = g(ts[i]);
        best = std::max(best, gs[i]);
    }
    const double finest_slack = 0.5 * slope * kSegmentStep / std::max(length, kSegmentStep);
    struct Interval { double a, b, ga, gb; };
    std::vector<Interval> stack;
    for (size_t i = coarse; i-- > 0;) stack.push_back({ts[i], ts[i + 1], gs[i], gs[i + 1]});
    double bound = std::max(0.0, best);
    while (!stack.empty()) {
        const Interval iv = stack.back();
        stack.pop_back();
        const double upper = 0.5 * (iv.ga + iv.gb) + 0.5 * slope * (iv.b - iv.a);
        if (upper <= std::max({0.0, enough, best + finest_slack})) {
            bound = std::max(bound, upper);
            continue;
        }
        if ((iv.b - iv.a) * length <= kSegmentStep) {
            bound = std::max(bound, upper);
            continue;
        }
        const double m = 0.5 * (iv.a + iv.b), gm = g(m);
        best = std::max(best, gm);
        stack.push_back({m, iv.b, gm, iv.gb});
        stack.push_back({iv.a, m, iv.ga, gm});
    }
    return std::max(0.0, bound);
}

double outside_measured(const Proxy& p, const ShapeQueries& shape) {
    const Vec3 e = p.b.center - p.a.center;
    const double length = p.kind == ProxyKind::sphere ? 0 : e.norm(), dr = p.b.radius - p.a.radius;
    const size_t steps = std::max<size_t>(1, size_t(std::ceil(length / kMeasureStep)));
    const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
    double worst = 0;
    // a sphere: its one ball; a capsule: the spheres strictly between its balls
    const size_t first = p.kind == ProxyKind::sphere ? 0 : 1, last = p.kind == ProxyKind::sphere ? 0 : steps - 1;
    for (size_t i = first; i <= last && (p.kind == ProxyKind::sphere || steps > 1); ++i) {
        const double t = double(i) / double(steps);
        const Vec3 c = p.a.center + t * e;
        const double r = p.a.radius + t * dr;
        for (int k = 0; k < kMeasureDirections; ++k) {
            const double z = 1 - (2 * k + 1) / double(kMeasureDirections), rho = std::sqrt(1 - z * z);
            const Vec3 x = c + r * Vec3(rho * std::cos(golden * k), rho * std::sin(golden * k), z);
            if (!shape.winding->inside(x)) worst = std::max(worst, shape.distance->distance(x));
        }
    }
    return worst;
}

}  // namespace ca
