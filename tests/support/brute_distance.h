// brute_distance.h: the tests' own signed distance to a sphere or tapered capsule (the hull of its
// balls a and b), independent of the library's closed form: the hull is the union of the
// interpolated balls, so the distance is min over t of |x - c(t)| - r(t), a convex function of t,
// minimised here by ternary search and compared with both ends.
#pragma once
#include "proxies.h"

#include <algorithm>

inline double brute_distance(const ca::Proxy& p, const ca::Vec3& x) {
    auto f = [&](double t) {
        return (x - (p.a.center + t * (p.b.center - p.a.center))).norm() - (p.a.radius + t * (p.b.radius - p.a.radius));
    };
    double lo = 0, hi = 1;
    for (int i = 0; i < 60; ++i) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (f(m1) <= f(m2)) hi = m2;
        else lo = m1;
    }
    return std::min({f(0), f(1), f(0.5 * (lo + hi))});
}
