// proxy_outside.cpp: how far a primitive may reach outside the shape, as a proven bound rather than
// a sample. A primitive is the union of the balls B(c(t), r(t)) interpolated along its segment
// (the convex hull of two balls is that union). A ball whose centre lies at depth D (distance to
// the surface, negative outside) reaches at most r - D outside, since B(c, D) is inside. The bound
// r(t) - D(c(t)) changes with t by at most |c2 - c1| + |r2 - r1| per unit (D is 1-Lipschitz), so
// its maximum over samples along the segment plus half a step of that slope bounds the primitive.
#include "proxies.h"

#include "distance.h"
#include "winding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ca {

namespace {

// Spacing of the depth samples along a capsule's segment (internal units: the model's longest
// side is 1); the slack it adds is half of it plus half the radius change per step.
constexpr double kSegmentStep = 0.004;

}  // namespace

double ShapeQueries::depth(const Vec3& x) const {
    const double d = distance->distance(x);
    return winding->inside(x) ? d : -d;
}

double outside_bound(const Proxy& p, const ShapeQueries& shape) {
    if (p.kind == ProxyKind::sphere) return std::max(0.0, p.a.radius - shape.depth(p.a.center));
    const Vec3 e = p.b.center - p.a.center;
    const double length = e.norm(), dr = p.b.radius - p.a.radius;
    const size_t steps = std::max<size_t>(1, size_t(std::ceil(length / kSegmentStep)));
    double worst = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i <= steps; ++i) {
        const double t = double(i) / double(steps);
        worst = std::max(worst, p.a.radius + t * dr - shape.depth(p.a.center + t * e));
    }
    const double slack = 0.5 * (length + std::abs(dr)) / double(steps);
    return std::max(0.0, worst + slack);
}

}  // namespace ca
