// distance.cpp: exact unsigned point-to-mesh distance. Closest point on a triangle by Ericson's
// Voronoi-region walk (degenerate triangles fall back to their edges), and an AABB tree over the
// triangles searched nearest-child-first, pruning every box (of a node or of one triangle)
// farther than the best hit so far.
#include "distance.h"
#include "bvh.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ca {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return a + t * ab;
}

Vec3 closest_on_edges(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 best = closest_on_segment(p, a, b);
    for (const Vec3& q : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)})
        if ((q - p).squaredNorm() < (best - p).squaredNorm()) best = q;
    return best;
}

// x / y for a ratio known to lie in [0, 1]; 0 when y vanishes (both ends coincide).
double ratio(double x, double y) { return y > 0 ? std::clamp(x / y, 0.0, 1.0) : 0.0; }

double box_distance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
}

}  // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a;
    // Zero-area or needle-like triangle: its closest point is on one of its edges.
    const double scale = std::max({ab.squaredNorm(), ac.squaredNorm(), (c - b).squaredNorm()});
    if (!(ab.cross(ac).squaredNorm() > 1e-20 * scale * scale)) return closest_on_edges(p, a, b, c);

    const Vec3 ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;                                      // vertex region A
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;                                     // vertex region B
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ratio(d1, d1 - d3) * ab;  // edge AB
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;                                     // vertex region C
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ratio(d2, d2 - d6) * ac;  // edge AC
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)                           // edge BC
        return b + ratio(d4 - d3, (d4 - d3) + (d5 - d6)) * (c - b);
    const double sum = va + vb + vc;                                       // face region
    if (!(sum > 0)) return closest_on_edges(p, a, b, c);                   // rounding guard
    return a + (vb / sum) * ab + (vc / sum) * ac;
}

struct MeshDistance::Impl {
    std::shared_ptr<const detail::TriangleTree> tree;
    const detail::Bvh& bvh;
    const std::vector<std::array<Vec3, 3>>& tris;   // triangle corners, in bvh.order
    explicit Impl(std::shared_ptr<const detail::TriangleTree> t) : tree(std::move(t)), bvh(tree->bvh), tris(tree->tris) {}

    // Squared distance to the closest triangle if it is below best2 (then `found` is set).
    double nearest(const Vec3& p, double best2, Vec3& closest, uint32_t& slot, bool& found) const {
        found = false;
        if (bvh.nodes.empty()) return best2;
        struct Entry { uint32_t node; double d2; };
        Entry stack[128];   // nearest-first DFS of a median-split tree: depth + 1 entries at most
        int top = 0;
        stack[top++] = {0, box_distance2(p, bvh.nodes[0].lo, bvh.nodes[0].hi)};
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.d2 >= best2) continue;
            const detail::BvhNode& node = bvh.nodes[e.node];
            if (node.leaf()) {
                for (uint32_t i = node.begin; i < node.end; ++i) {
                    // the triangle's box is no farther than the triangle: a box at best2 or
                    // beyond cannot hold a closer point (a few operations against the walk's ~150)
                    const auto& t = tris[i];
                    if (box_distance2(p, t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])) >= best2)
                        continue;
                    const Vec3 c = closest_point_on_triangle(p, t[0], t[1], t[2]);
                    const double d2 = (c - p).squaredNorm();
                    if (d2 < best2) { best2 = d2; closest = c; slot = i; found = true; }
                }
                continue;
            }
            Entry l{node.left, box_distance2(p, bvh.nodes[node.left].lo, bvh.nodes[node.left].hi)};
            Entry r{node.right, box_distance2(p, bvh.nodes[node.right].lo, bvh.nodes[node.right].hi)};
            if (l.d2 < r.d2) std::swap(l, r);            // push the farther child first
            if (l.d2 < best2) stack[top++] = l;
            if (r.d2 < best2) stack[top++] = r;
        }
        return best2;
    }
};

MeshDistance::MeshDistance(const Mesh& mesh) : MeshDistance(detail::build_triangle_tree(mesh)) {}

MeshDistance::MeshDistance(std::shared_ptr<const detail::TriangleTree> tree)
    : impl_(std::make_unique<Impl>(std::move(tree))) {}

MeshDistance::~MeshDistance() = default;
MeshDistance::MeshDistance(MeshDistance&&) noexcept = default;
MeshDistance& MeshDistance::operator=(MeshDistance&&) noexcept = default;

double MeshDistance::distance(const Vec3& p, Vec3* closest, uint32_t* triangle) const {
    if (!impl_) return kInf;
    Vec3 c;
    uint32_t slot = 0;
    bool found = false;
    const double d2 = impl_->nearest(p, kInf, c, slot, found);
    if (!found) return kInf;
    if (closest) *closest = c;
    if (triangle) *triangle = impl_->bvh.order[slot];
    return std::sqrt(d2);
}

double MeshDistance::distance_below(const Vec3& p, double upper) const {
    if (!impl_ || !(upper > 0)) return upper;
    Vec3 c;
    uint32_t slot = 0;
    bool found = false;
    const double d2 = impl_->nearest(p, upper * upper, c, slot, found);
    return found ? std::min(std::sqrt(d2), upper) : upper;
}

double mesh_distance_brute_force(const Mesh& mesh, const Vec3& p) {
    double best2 = kInf;
    for (const Tri& f : mesh.triangles) {
        if (!detail::triangle_ok(mesh, f)) continue;
        const Vec3 c = closest_point_on_triangle(p, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
        best2 = std::min(best2, (c - p).squaredNorm());
    }
    return std::sqrt(best2);
}

}  // namespace ca
