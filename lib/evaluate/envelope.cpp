// envelope.cpp: the envelope's primitives and the boundary pieces of the primitives (areas,
// area-uniform samples, closest points, bounds) that the envelope samples are drawn from.
#include "envelope.h"

#include "distance.h"
#include "parallel.h"

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

std::vector<Primitive> envelope_primitives(const Skeleton& sk) {
    const auto& balls = sk.balls;
    const size_t nb = balls.size();
    std::vector<Primitive> prims;
    std::vector<char> edge_in_face(sk.edges.size(), 0), ball_on_edge(nb, 0);
    auto edge_index = [&](uint32_t a, uint32_t b) {
        const std::array<uint32_t, 2> key{a, b};
        return size_t(std::lower_bound(sk.edges.begin(), sk.edges.end(), key) - sk.edges.begin());
    };
    for (const Tri& f : sk.faces) {
        prims.push_back(make_primitive(balls, Kind::slab, f[0], f[1], f[2]));
        edge_in_face[edge_index(f[0], f[1])] = 1;
        edge_in_face[edge_index(f[0], f[2])] = 1;
        edge_in_face[edge_index(f[1], f[2])] = 1;
    }
    for (size_t i = 0; i < sk.edges.size(); ++i) {
        const auto& e = sk.edges[i];
        ball_on_edge[e[0]] = ball_on_edge[e[1]] = 1;
        if (!edge_in_face[i]) prims.push_back(make_primitive(balls, Kind::cone, e[0], e[1], 0));
    }
    for (uint32_t i = 0; i < nb; ++i)
        if (!ball_on_edge[i]) prims.push_back(make_primitive(balls, Kind::sphere, i, 0, 0));
    return prims;
}

std::vector<Piece> boundary_pieces(const Skeleton& sk) {
    const auto& balls = sk.balls;
    std::vector<Piece> pieces;
    for (const Ball& b : balls) sphere_piece(b, pieces);
    for (const auto& e : sk.edges) cone_piece(balls[e[0]], balls[e[1]], pieces);
    for (const Tri& f : sk.faces) slab_pieces(balls[f[0]], balls[f[1]], balls[f[2]], pieces);
    return pieces;
}

bool sample_boundary(const Envelope& env, const std::vector<Piece>& pieces, size_t target, uint64_t seed,
                     double tol, int threads, const Monitor& monitor, const char* stage, double from,
                     double to, std::vector<Vec3>& boundary) {
    constexpr size_t kBatch = 4096;
    boundary.clear();
    double total_area = 0;
    for (const Piece& pc : pieces) total_area += pc.area;
    if (total_area > 0) {
        Rng rng(seed);
        size_t generated = 0;
        for (int round = 0; round < 8 && boundary.size() < target; ++round) {
            // expected fraction kept so far (start optimistic), with a margin
            const double frac = generated ? std::max(double(boundary.size()) / double(generated), 1e-3) : 1.0;
            double want = double(target - boundary.size()) / frac * (round ? 1.1 : 1.0);
            want = std::min(want, 20.0 * double(target));
            std::vector<Vec3> cand;
            cand.reserve(size_t(want) + pieces.size());
            for (const Piece& pc : pieces) {
                const size_t cnt = size_t(std::floor(want * pc.area / total_area + rng.uniform()));
                for (size_t k = 0; k < cnt; ++k) cand.push_back(sample_piece(pc, rng));
            }
            generated += cand.size();
            std::vector<char> keep(cand.size(), 0);
            const double f0 = from + (to - from) * round / 8.0, f1 = from + (to - from) * (round + 1) / 8.0;
            if (!parallel_for(cand.size(), threads, kBatch, monitor, stage, f0, f1, [&](size_t b, size_t e) {
                    for (size_t i = b; i < e; ++i) keep[i] = env.F(cand[i], -tol) > -tol;
                }))
                return false;
            for (size_t i = 0; i < cand.size(); ++i)
                if (keep[i]) boundary.push_back(cand[i]);
        }
    }
    return true;
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
