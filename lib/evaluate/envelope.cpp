// envelope.cpp: the envelope's primitives and the boundary pieces of the primitives (areas,
// area-uniform samples, closest points, bounds) that the envelope samples are drawn from.
#include "envelope.h"

#include "distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace ca {
namespace eval {

std::vector<Vec3> centers_of(const std::vector<Primitive>& prims) {
    std::vector<Vec3> out;
    for (const Primitive& q : prims) out.push_back(q.bc);
    return out;
}
std::vector<double> radii_of(const std::vector<Primitive>& prims) {
    std::vector<double> out;
    for (const Primitive& q : prims) out.push_back(q.br);
    return out;
}

Primitive make_primitive(const std::vector<Ball>& balls, Kind kind, uint32_t i, uint32_t j,
                         uint32_t k) {
    Primitive q{kind, {i, j, k}, Vec3::Zero(), 0};
    const int nv = kind == Kind::sphere ? 1 : kind == Kind::cone ? 2 : 3;
    Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
    for (int t = 0; t < nv; ++t) {
        const Ball& bl = balls[q.v[t]];
        lo = lo.cwiseMin(bl.center - Vec3::Constant(bl.radius));
        hi = hi.cwiseMax(bl.center + Vec3::Constant(bl.radius));
    }
    q.bc = 0.5 * (lo + hi);
    for (int t = 0; t < nv; ++t) {
        const Ball& bl = balls[q.v[t]];
        q.br = std::max(q.br, (bl.center - q.bc).norm() + bl.radius);
    }
    q.br *= 1 + 1e-12;
    return q;
}

void orthonormal_frame(const Vec3& a, Vec3& w1, Vec3& w2) {
    const Vec3 helper = std::abs(a.x()) < 0.6 ? Vec3::UnitX()
                        : std::abs(a.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ();
    w1 = a.cross(helper).normalized();
    w2 = a.cross(w1);
}

void sphere_piece(const Ball& b, std::vector<Piece>& out) {
    const double area = 4 * kPi * b.radius * b.radius;
    if (area > 0) out.push_back({Kind::sphere, {b.center, Vec3::Zero(), Vec3::Zero()},
                                 {b.radius, 0}, area});
}

// Lateral surface of the cone: the tangent segments c_i + r_i n, n = -s a + sqrt(1-s^2) w.
void cone_piece(const Ball& b1, const Ball& b2, std::vector<Piece>& out) {
    const Vec3 e = b2.center - b1.center;
    const double L = e.norm(), dr = b2.radius - b1.radius;
    if (!(L > std::abs(dr))) return;
    const double slant = std::sqrt(L * L - dr * dr);
    const double k = slant / L;   // sqrt(1 - s^2)
    const double area = kPi * (b1.radius + b2.radius) * k * slant;
    if (!(area > 0)) return;
    Piece pc{Kind::cone, {b1.center, b2.center, Vec3::Zero()}, {b1.radius, b2.radius}, area};
    out.push_back(pc);
}

// The two tangent triangles of a slab (none if the tangent planes do not exist).
void slab_pieces(const Ball& b1, const Ball& b2, const Ball& b3, std::vector<Piece>& out) {
    const Vec3 e1 = b1.center - b3.center, e2 = b2.center - b3.center;
    const double l1 = e1.norm(), l2 = e2.norm();
    const Vec3 cr = e1.cross(e2);
    const double crn = cr.norm();
    if (!(crn > 1e-12 * l1 * l2) || l1 == 0 || l2 == 0) return;
    const Vec3 m = cr / crn, u1 = e1 / l1, u2 = m.cross(u1);
    const double g = e2.dot(u1), hgt = e2.dot(u2);
    const double a1 = -(b1.radius - b3.radius) / l1;
    const double a2 = (-(b2.radius - b3.radius) - a1 * g) / hgt;
    const double aa = a1 * a1 + a2 * a2;
    if (!(aa < 1)) return;
    const double s = std::sqrt(1 - aa);
    for (double sign : {1.0, -1.0}) {
        const Vec3 n = a1 * u1 + a2 * u2 + sign * s * m;
        Piece pc{Kind::slab,
                 {b1.center + b1.radius * n, b2.center + b2.radius * n, b3.center + b3.radius * n},
                 {0, 0}, 0};
        pc.area = 0.5 * (pc.p[1] - pc.p[0]).cross(pc.p[2] - pc.p[0]).norm();
        if (pc.area > 0) out.push_back(pc);
    }
}

Vec3 sample_piece(const Piece& pc, Rng& rng) {
    switch (pc.kind) {
        case Kind::sphere: {
            const double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
            const double q = std::sqrt(std::max(0.0, 1 - z * z));
            return pc.p[0] + pc.r[0] * Vec3(q * std::cos(phi), q * std::sin(phi), z);
        }
        case Kind::cone: {
            const Vec3 e = pc.p[1] - pc.p[0];
            const double L = e.norm(), dr = pc.r[1] - pc.r[0];
            const Vec3 a = e / L;
            const double s = dr / L, k = std::sqrt(std::max(0.0, 1 - s * s));
            Vec3 w1, w2;
            orthonormal_frame(a, w1, w2);
            const double th = 2 * kPi * rng.uniform();
            const Vec3 n = -s * a + k * (std::cos(th) * w1 + std::sin(th) * w2);
            // position along the segment with density proportional to the circle radius,
            // (1-t) r1 + t r2: a mixture of densities 2(1-t) and 2t
            const double pick = rng.uniform() * (pc.r[0] + pc.r[1]);
            const double u = rng.uniform();
            const double t = pick < pc.r[0] ? 1 - std::sqrt(u) : std::sqrt(u);
            const Vec3 q1 = pc.p[0] + pc.r[0] * n, q2 = pc.p[1] + pc.r[1] * n;
            return q1 + t * (q2 - q1);
        }
        case Kind::slab: {
            const double su = std::sqrt(rng.uniform()), v = rng.uniform();
            return (1 - su) * pc.p[0] + su * (1 - v) * pc.p[1] + su * v * pc.p[2];
        }
    }
    return pc.p[0];
}

// Closest point of a boundary piece to p (for a cone: on the tangent segment in p's meridian
// half-plane, since the lateral surface is a surface of revolution).
Vec3 closest_on_piece(const Piece& pc, const Vec3& p) {
    switch (pc.kind) {
        case Kind::sphere: {
            const Vec3 d = p - pc.p[0];
            const double n = d.norm();
            return pc.p[0] + pc.r[0] * (n > 0 ? Vec3(d / n) : Vec3(Vec3::UnitX()));
        }
        case Kind::cone: {
            const Vec3 e = pc.p[1] - pc.p[0];
            const double L = e.norm(), s = (pc.r[1] - pc.r[0]) / L;
            const Vec3 a = e / L;
            const Vec3 rel = p - pc.p[0];
            Vec3 w = rel - rel.dot(a) * a;
            const double wn = w.norm();
            if (wn > 0) {
                w /= wn;
            } else {
                Vec3 w2;
                orthonormal_frame(a, w, w2);
            }
            const Vec3 n = -s * a + std::sqrt(std::max(0.0, 1 - s * s)) * w;
            const Vec3 q1 = pc.p[0] + pc.r[0] * n, q2 = pc.p[1] + pc.r[1] * n;
            const Vec3 d = q2 - q1;
            const double l2 = d.squaredNorm();
            const double t = l2 > 0 ? std::clamp((p - q1).dot(d) / l2, 0.0, 1.0) : 0.0;
            return q1 + t * d;
        }
        case Kind::slab: return closest_point_on_triangle(p, pc.p[0], pc.p[1], pc.p[2]);
    }
    return pc.p[0];
}

// Bounding sphere of a piece.
std::pair<Vec3, double> piece_bound(const Piece& pc) {
    switch (pc.kind) {
        case Kind::sphere: return {pc.p[0], pc.r[0] * (1 + 1e-12)};
        case Kind::cone: {
            const Vec3 c = 0.5 * (pc.p[0] + pc.p[1]);
            return {c, (0.5 * (pc.p[1] - pc.p[0]).norm() + std::max(pc.r[0], pc.r[1])) * (1 + 1e-12)};
        }
        case Kind::slab: {
            const Vec3 c = (pc.p[0] + pc.p[1] + pc.p[2]) / 3.0;
            const double r = std::max({(pc.p[0] - c).norm(), (pc.p[1] - c).norm(), (pc.p[2] - c).norm()});
            return {c, r * (1 + 1e-12)};
        }
    }
    return {pc.p[0], 0};
}

}  // namespace eval
}  // namespace ca
