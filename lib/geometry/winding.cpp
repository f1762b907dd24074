// winding.cpp: generalised winding numbers. Exact per-triangle solid angles (Van Oosterom-
// Strackee, atan2 form), and the hierarchical approximation of Barill et al. 2018: every BVH
// node stores a Taylor expansion (dipole, first- and second-order moments) of its triangles'
// solid-angle field about its area-weighted centroid; a query uses it when it is farther than
// beta * radius from that centre and recurses otherwise (leaves are summed exactly).
#include "winding.h"
#include "bvh.h"
#include "far_field.h"
#include <Eigen/Geometry>
#include <cmath>

namespace ca {
using detail::Expansion;
namespace {

constexpr double kFourPi = 4.0 * 3.14159265358979323846;

// Signed solid angle of triangle (a, b, c) seen from q; positive when q is behind the triangle
// (on the side opposite to its right-handed normal). Degenerate triangles give 0, never NaN.
double solid_angle(const Vec3& q, const Vec3& a0, const Vec3& b0, const Vec3& c0) {
    const Vec3 a = a0 - q, b = b0 - q, c = c0 - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    if (num == 0) return 0.0;   // coplanar with q (or zero area): atan2(0, den < 0) would give 2 pi
    const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    return 2.0 * std::atan2(num, den);
}


}  // namespace

struct WindingNumber::Impl {
    double beta = 2.0;
    std::shared_ptr<const detail::TriangleTree> tree;
    const detail::Bvh& bvh;
    const std::vector<std::array<Vec3, 3>>& tris;   // triangle corners, in bvh.order
    std::vector<Expansion> exp;                     // one per BVH node
    explicit Impl(std::shared_ptr<const detail::TriangleTree> t) : tree(std::move(t)), bvh(tree->bvh), tris(tree->tris) {}
};

WindingNumber::WindingNumber(const Mesh& mesh, double beta) : WindingNumber(detail::build_triangle_tree(mesh), beta) {}

WindingNumber::WindingNumber(std::shared_ptr<const detail::TriangleTree> tree, double beta,
                             const std::function<bool()>& stop)
    : impl_(std::make_unique<Impl>(std::move(tree))) {
    Impl& m = *impl_;
    m.beta = (beta >= 0 && std::isfinite(beta)) ? beta : 2.0;
    // Bottom-up (children follow their parent in bvh.nodes): a leaf sums its triangles' moments
    // about its centre, a parent shifts its children's moments to its own centre, so the build
    // is O(F) apart from the radius (the farthest corner from the centre, over the node's triangles).
    m.exp.resize(m.bvh.nodes.size());
    std::vector<double> weight(m.bvh.nodes.size(), 0.0);   // total area per node
    std::vector<Vec3> weighted(m.bvh.nodes.size());        // area-weighted centroid sum per node
    for (size_t n = m.bvh.nodes.size(); n-- > 0;) {
        // a node's radius pass reads all its triangles: near the root a test every node, below
        // every kStopCheckItems nodes
        if (stop && (n % detail::kStopCheckItems == 0 || m.bvh.nodes[n].end - m.bvh.nodes[n].begin > detail::kStopCheckItems) &&
            stop()) {
            impl_.reset();
            return;
        }
        const detail::BvhNode& node = m.bvh.nodes[n];
        Expansion& e = m.exp[n];
        if (node.leaf()) {
            weighted[n].setZero();
            for (uint32_t i = node.begin; i < node.end; ++i) {
                const auto& v = m.tris[i];
                const Vec3 a = 0.5 * (v[1] - v[0]).cross(v[2] - v[0]);
                const Vec3 c = (v[0] + v[1] + v[2]) / 3.0;
                weight[n] += a.norm();
                weighted[n] += a.norm() * c;
            }
            e.centre = weight[n] > 0 ? Vec3(weighted[n] / weight[n]) : Vec3(0.5 * (node.lo + node.hi));
            for (uint32_t i = node.begin; i < node.end; ++i) {
                const auto& v = m.tris[i];
                const Vec3 a = 0.5 * (v[1] - v[0]).cross(v[2] - v[0]);
                const Vec3 c = (v[0] + v[1] + v[2]) / 3.0;
                Eigen::Matrix3d S = Eigen::Matrix3d::Zero();   // E[(x - centre)(x - centre)^T] over the triangle
                for (const Vec3& p : v) S += (p - c) * (p - c).transpose();
                const Vec3 d = c - e.centre;
                S = S / 12.0 + d * d.transpose();
                e.N += a;
                e.M += a * d.transpose();
                for (int k = 0; k < 3; ++k) e.Q[k] += a[k] * S;
            }
        } else {
            weight[n] = weight[node.left] + weight[node.right];
            weighted[n] = weighted[node.left] + weighted[node.right];
            e.centre = weight[n] > 0 ? Vec3(weighted[n] / weight[n]) : Vec3(0.5 * (node.lo + node.hi));
            for (uint32_t c : {node.left, node.right}) {
                const Expansion& ch = m.exp[c];
                const Vec3 s = ch.centre - e.centre;   // d about the parent = d about the child + s
                e.N += ch.N;
                e.M += ch.M + ch.N * s.transpose();
                for (int k = 0; k < 3; ++k) {
                    const Vec3 row = ch.M.row(k).transpose();
                    e.Q[k] += ch.Q[k] + row * s.transpose() + s * row.transpose() + ch.N[k] * (s * s.transpose());
                }
            }
        }
        double r2 = 0;
        for (uint32_t i = node.begin; i < node.end; ++i)
            for (const Vec3& p : m.tris[i]) r2 = std::max(r2, (p - e.centre).squaredNorm());
        e.radius = std::sqrt(r2);
    }
}

WindingNumber::~WindingNumber() = default;
WindingNumber::WindingNumber(WindingNumber&&) noexcept = default;
WindingNumber& WindingNumber::operator=(WindingNumber&&) noexcept = default;

double WindingNumber::operator()(const Vec3& q) const {
    if (!impl_ || impl_->bvh.nodes.empty()) return 0.0;
    const Impl& m = *impl_;
    return detail::far_field_sum(m.bvh.nodes, m.exp, m.beta, q, [&](const Vec3& p, uint32_t i) {
               return solid_angle(p, m.tris[i][0], m.tris[i][1], m.tris[i][2]);
           }) / kFourPi;
}

double winding_number_brute_force(const Mesh& mesh, const Vec3& q) {
    double omega = 0;
    for (const Tri& f : mesh.triangles) {
        if (!detail::triangle_ok(mesh, f)) continue;
        omega += solid_angle(q, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
    }
    return omega / kFourPi;
}

double signed_volume(const Mesh& mesh) {
    double v = 0;
    for (const Tri& f : mesh.triangles) {
        if (!detail::triangle_ok(mesh, f)) continue;
        v += mesh.vertices[f[0]].dot(mesh.vertices[f[1]].cross(mesh.vertices[f[2]]));
    }
    return v / 6.0;
}

}  // namespace ca
