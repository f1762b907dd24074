// primitives.cpp: exact signed distances (negative inside) to the reconstruction's primitives:
// spheres, medial cones (edges) and medial slabs (faces).
#include "evaluate.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ca {

// ---------------------------------------------------------------------------------------------
// Signed distances to one primitive
// ---------------------------------------------------------------------------------------------

double sd_sphere(const Vec3& p, const Vec3& c, double r) { return (p - c).norm() - r; }

namespace {

// The sphere at p's direction from centre c with weight 1 on ball `i`.
void nearest_ball(const Vec3& p, const Vec3& c, int i, NearestSphere* at) {
    if (!at) return;
    *at = NearestSphere{};
    at->w[i] = 1;
    const Vec3 d = p - c;
    const double n = d.norm();
    if (n > 0) at->u = d / n;
}

}  // namespace

double sd_cone(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2, NearestSphere* at) {
    const Vec3 e = c2 - c1;
    const double L = e.norm();
    const double dr = r2 - r1;
    if (L <= std::abs(dr)) {
        nearest_ball(p, r1 >= r2 ? c1 : c2, r1 >= r2 ? 0 : 1, at);
        return r1 >= r2 ? sd_sphere(p, c1, r1) : sd_sphere(p, c2, r2);
    }
    const Vec3 a = e / L;
    const Vec3 w = p - c1;
    const double u = w.dot(a);
    const double h = (w - u * a).norm();
    const double t = std::clamp((u + h * dr / std::sqrt(L * L - dr * dr)) / L, 0.0, 1.0);
    const Vec3 d = p - (c1 + t * e);
    const double dn = d.norm();
    if (at) {
        *at = NearestSphere{};
        at->w[0] = 1 - t;
        at->w[1] = t;
        if (dn > 0) at->u = d / dn;
    }
    return dn - (r1 + t * dr);
}

double sd_slab(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2,
               const Vec3& c3, double r3, NearestSphere* at) {
    auto edges = [&] {
        if (!at)
            return std::min({sd_cone(p, c1, r1, c2, r2), sd_cone(p, c1, r1, c3, r3),
                             sd_cone(p, c2, r2, c3, r3)});
        // the same minimum, keeping the attaining cone's sphere on the slab's balls
        const int pair[3][2] = {{0, 1}, {0, 2}, {1, 2}};
        NearestSphere n[3];
        const double d[3] = {sd_cone(p, c1, r1, c2, r2, &n[0]), sd_cone(p, c1, r1, c3, r3, &n[1]),
                             sd_cone(p, c2, r2, c3, r3, &n[2])};
        int k = 0;
        for (int j = 1; j < 3; ++j)
            if (d[j] < d[k]) k = j;
        *at = NearestSphere{};
        at->w[pair[k][0]] = n[k].w[0];
        at->w[pair[k][1]] = n[k].w[1];
        at->u = n[k].u;
        return d[k];
    };
    const Vec3 e1 = c1 - c3, e2 = c2 - c3;
    const double l1 = e1.norm(), l2 = e2.norm();
    const Vec3 cr = e1.cross(e2);
    const double crn = cr.norm();
    if (!(crn > 1e-12 * l1 * l2) || l1 == 0 || l2 == 0) return edges();   // collinear centres

    // Orthonormal frame of the centres' plane: u1 along e1, u2 in-plane, m the normal. In it,
    // e1 = (l1, 0) and e2 = (g, hgt); the Gram system a.e1 = -d1, a.e2 = -d2 is triangular.
    const Vec3 m = cr / crn;
    const Vec3 u1 = e1 / l1;
    const Vec3 u2 = m.cross(u1);
    const double g = e2.dot(u1), hgt = e2.dot(u2);
    const double d1 = r1 - r3, d2 = r2 - r3;
    const double a1 = -d1 / l1;
    const double a2 = (-d2 - a1 * g) / hgt;
    const double aa = a1 * a1 + a2 * a2;
    if (!(aa < 1)) return edges();   // no tangent plane touches all three balls
    const double s = std::sqrt(1 - aa);
    if (s == 0) return edges();

    // The tangent plane on p's side of the centres' plane: n = a +- s m, rho >= 0.
    const Vec3 pc = p - c3;
    const double hz = pc.dot(m);
    const double sign = hz >= 0 ? 1.0 : -1.0;
    const Vec3 n = a1 * u1 + a2 * u2 + (sign * s) * m;
    const double rho = hz / (sign * s);
    const Vec3 x = pc - rho * n;   // foot point, relative to c3, in the centres' plane
    const double b2 = x.dot(u2) / hgt;
    const double b1 = (x.dot(u1) - b2 * g) / l1;
    if (b1 >= 0 && b2 >= 0 && b1 + b2 <= 1) {
        // the attaining sphere is centred at the foot point; p lies along n from it
        if (at) {
            at->w[0] = b1;
            at->w[1] = b2;
            at->w[2] = 1 - b1 - b2;
            at->u = n;
        }
        return n.dot(pc) - r3;
    }
    return edges();
}

}  // namespace ca
