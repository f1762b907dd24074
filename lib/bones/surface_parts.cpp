// surface_parts.cpp: which joint dominates each part of the surface (bones.h). Skinning
// interpolates the corners' weights linearly over a triangle, so where joint j outweighs joint k
// is a half-plane of the triangle: the piece j dominates is the triangle clipped by one half-plane
// per other joint of its corners, a convex polygon, found exactly (Sutherland-Hodgman on
// barycentric coordinates). A convex collider that holds a polygon's corners holds the polygon.
#include "bones.h"

#include "rng.h"

#include <cmath>

namespace ca {

namespace {

// Weight of joint j at a vertex (0 when it is not among the vertex's joints).
double weight_of(const PreparedSkin& skin, uint32_t v, uint32_t j) {
    for (const auto& [k, w] : skin.weights[v])
        if (k == j) return w;
    return 0;
}

using Poly = std::vector<Vec3>;   // barycentric coordinates of the polygon's corners

// The polygon clipped to f(bary) >= 0, f linear (its values at the triangle's corners).
Poly clip(const Poly& in, const Vec3& f) {
    Poly out;
    const size_t n = in.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3& p = in[i];
        const Vec3& q = in[(i + 1) % n];
        const double fp = f.dot(p), fq = f.dot(q);
        if (fp >= 0) out.push_back(p);
        if ((fp >= 0) != (fq >= 0)) {
            const double t = fp / (fp - fq);
            out.push_back(p + t * (q - p));
        }
    }
    return out;
}

}  // namespace

std::vector<SurfacePart> surface_parts(const Mesh& mesh, const PreparedSkin& skin) {
    std::vector<SurfacePart> parts(skin.parents.size());
    for (SurfacePart& p : parts) p.polygon_start.push_back(0);
    std::vector<uint32_t> joints;
    for (const Tri& t : mesh.triangles) {
        joints.clear();
        for (uint32_t v : t)
            for (const auto& jw : skin.weights[v]) joints.push_back(jw.first);
        std::sort(joints.begin(), joints.end());
        joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
        if (joints.empty()) continue;
        std::vector<Vec3> w(joints.size());   // per joint, its weights at the three corners
        for (size_t a = 0; a < joints.size(); ++a)
            for (int c = 0; c < 3; ++c) w[a][c] = weight_of(skin, t[size_t(c)], joints[a]);
        const Vec3 &A = mesh.vertices[t[0]], &B = mesh.vertices[t[1]], &C = mesh.vertices[t[2]];
        for (size_t a = 0; a < joints.size(); ++a) {
            Poly poly{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
            for (size_t b = 0; b < joints.size() && poly.size() >= 3; ++b)
                if (b != a) poly = clip(poly, w[a] - w[b]);
            if (poly.size() < 3) continue;
            SurfacePart& part = parts[joints[a]];
            const Vec3 first = poly[0].x() * A + poly[0].y() * B + poly[0].z() * C;
            Vec3 prev = first;
            double area = 0;
            part.corners.push_back(first);
            for (size_t i = 1; i < poly.size(); ++i) {
                const Vec3 x = poly[i].x() * A + poly[i].y() * B + poly[i].z() * C;
                area += 0.5 * (prev - first).cross(x - first).norm();
                part.corners.push_back(x);
                prev = x;
            }
            part.area += area;
            part.polygon_start.push_back(uint32_t(part.corners.size()));
        }
    }
    return parts;
}

int32_t dominant_joint(const Mesh& mesh, const PreparedSkin& skin, uint32_t t, const Vec3& bary) {
    int32_t best = -1;
    double best_w = 0;
    const Tri& tri = mesh.triangles[t];
    for (int c = 0; c < 3; ++c)
        for (const auto& jw : skin.weights[tri[size_t(c)]]) {
            double w = 0;
            for (int d = 0; d < 3; ++d) w += bary[d] * weight_of(skin, tri[size_t(d)], jw.first);
            if (w > best_w || (w == best_w && best >= 0 && int32_t(jw.first) < best)) {
                best_w = w;
                best = int32_t(jw.first);
            }
        }
    return best;
}

Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1), d20 = v2.dot(v0), d21 = v2.dot(v1);
    const double den = d00 * d11 - d01 * d01;
    if (!(den > 0)) return Vec3(1, 0, 0);
    Vec3 l;
    l[1] = (d11 * d20 - d01 * d21) / den;
    l[2] = (d00 * d21 - d01 * d20) / den;
    l[0] = 1 - l[1] - l[2];
    l = l.cwiseMax(0.0);
    return l / l.sum();
}

std::vector<Vec3> sample_part(const SurfacePart& part, size_t n, uint64_t seed) {
    // fan triangles of every polygon, picked by area
    std::vector<std::array<uint32_t, 3>> fans;
    std::vector<double> cumulative;
    double total = 0;
    for (size_t p = 0; p + 1 < part.polygon_start.size(); ++p) {
        const uint32_t s = part.polygon_start[p], e = part.polygon_start[p + 1];
        for (uint32_t i = s + 1; i + 1 < e; ++i) {
            total += 0.5 * (part.corners[i] - part.corners[s]).cross(part.corners[i + 1] - part.corners[s]).norm();
            fans.push_back({s, i, i + 1});
            cumulative.push_back(total);
        }
    }
    std::vector<Vec3> out;
    if (fans.empty() || !(total > 0)) return out;
    Rng rng(seed);
    out.reserve(n);
    for (size_t k = 0; k < n; ++k) {
        const double u = rng.uniform() * total;
        size_t f = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
        f = std::min(f, fans.size() - 1);
        double r1 = rng.uniform(), r2 = rng.uniform();
        if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
        const auto& tri = fans[f];
        out.push_back(part.corners[tri[0]] + r1 * (part.corners[tri[1]] - part.corners[tri[0]]) +
                      r2 * (part.corners[tri[2]] - part.corners[tri[0]]));
    }
    return out;
}

}  // namespace ca
