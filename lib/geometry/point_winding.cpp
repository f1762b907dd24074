// point_winding.cpp: the point-cloud winding number (point_winding.h). Every point is a dipole of
// moment a_i n_i at p_i. The tree is the mesh BVH (bvh.h) built over degenerate triangles (i, i, i),
// so the points are grouped exactly as triangles are; every node stores N = sum a_i n_i,
// M = sum a_i n_i d_i^T and Q[k] = sum a_i n_i,k d_i d_i^T (d_i = p_i - centre, centre = the
// area-weighted mean) and is used when the
// query is farther than beta * radius from its centre; leaves are summed exactly.
#include "point_winding.h"
#include "bvh.h"
#include "far_field.h"
#include "kdtree.h"

#include <algorithm>
#include <cmath>

namespace ca {
using detail::Expansion;
namespace {

constexpr double kFourPi = 4.0 * 3.14159265358979323846;

// One dipole's field at q (not yet divided by 4 pi).
double dipole(const Vec3& q, const Vec3& p, const Vec3& moment) {
    const Vec3 r = p - q;
    const double r2 = r.squaredNorm();
    if (!(r2 > 0)) return 0.0;
    return moment.dot(r) / (r2 * std::sqrt(r2));
}


// A convex polygon in the tangent plane; clip() writes into a second one, and the two buffers are
// reused for all clips of a point.
using Polygon = std::vector<Eigen::Vector2d>;

// Area of the convex polygon `poly` (2-D, counter-clockwise or not).
double polygon_area(const Polygon& poly) {
    double a = 0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d& u = poly[i];
        const Eigen::Vector2d& v = poly[(i + 1) % poly.size()];
        a += u.x() * v.y() - u.y() * v.x();
    }
    return 0.5 * std::abs(a);
}

// Keeps the part of `poly` with x.dir <= offset, written to `out`.
void clip(const Polygon& poly, const Eigen::Vector2d& dir, double offset, Polygon& out) {
    out.clear();
    for (size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d& u = poly[i];
        const Eigen::Vector2d& v = poly[(i + 1) % poly.size()];
        const double su = u.dot(dir) - offset, sv = v.dot(dir) - offset;
        if (su <= 0) out.push_back(u);
        if ((su < 0) != (sv < 0) && su != sv) out.push_back(u + (v - u) * (su / (su - sv)));
    }
}

}  // namespace

std::vector<double> tangent_voronoi_areas(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, size_t k,
                                          int threads) {
    std::vector<double> areas(pts.size(), 0.0);
    if (pts.size() < 2) return areas;
    for_each_neighbourhood(pts, k, [&](size_t i, const size_t* idx, const double* d2, size_t found) {
        const Vec3& n = normals[i];
        // tangent frame
        Vec3 u = n.unitOrthogonal(), v = n.cross(u);
        double half = 0;
        for (size_t j = 0; j < found; ++j) half = std::max(half, std::sqrt(d2[j]));
        if (!(half > 0)) return;
        Polygon poly = {{-half, -half}, {half, -half}, {half, half}, {-half, half}}, next;
        poly.reserve(found + 4);   // a clip adds at most one corner to a convex polygon
        next.reserve(found + 4);
        for (size_t j = 0; j < found && !poly.empty(); ++j) {
            if (idx[j] == i) continue;
            const Vec3 d = pts[idx[j]] - pts[i];
            const Eigen::Vector2d e(d.dot(u), d.dot(v));
            const double len2 = e.squaredNorm();
            if (!(len2 > 1e-24)) continue;   // a duplicate (or a neighbour straight above): no bisector
            clip(poly, e, 0.5 * len2, next);   // x.e <= |e|^2 / 2: the side of the bisector nearer to point i
            poly.swap(next);
        }
        areas[i] = poly.size() >= 3 ? polygon_area(poly) : 0.0;
    }, threads);
    return areas;
}

struct PointCloudWinding::Impl {
    double beta = 2.0;
    detail::Bvh bvh;
    std::vector<detail::FarField> exp;   // one per BVH node
    std::vector<Vec3> pos, moment;  // points and a_i n_i, in bvh.order
    std::vector<double> areas;      // per input point
};

PointCloudWinding::PointCloudWinding(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, double beta,
                                     int threads)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.beta = (beta >= 0 && std::isfinite(beta)) ? beta : 2.0;
    if (pts.empty() || normals.size() != pts.size()) return;
    m.areas = tangent_voronoi_areas(pts, normals, 20, threads);
    Mesh dots;
    dots.vertices = pts;
    std::vector<uint32_t> ids(pts.size());
    for (uint32_t i = 0; i < pts.size(); ++i) {
        dots.triangles.push_back({i, i, i});
        ids[i] = i;
    }
    m.bvh = detail::build_bvh(dots, std::move(ids));
    for (uint32_t i : m.bvh.order) {
        m.pos.push_back(pts[i]);
        m.moment.push_back(m.areas[i] * normals[i]);
    }
    m.exp.resize(m.bvh.nodes.size());
    for (size_t n = 0; n < m.bvh.nodes.size(); ++n) {
        const detail::BvhNode& node = m.bvh.nodes[n];
        Expansion e;
        double wsum = 0;
        Vec3 csum = Vec3::Zero();
        for (uint32_t i = node.begin; i < node.end; ++i) {
            const double a = m.moment[i].norm();
            wsum += a;
            csum += a * m.pos[i];
        }
        e.centre = wsum > 0 ? Vec3(csum / wsum) : Vec3(0.5 * (node.lo + node.hi));
        for (uint32_t i = node.begin; i < node.end; ++i) {
            const Vec3 d = m.pos[i] - e.centre;
            e.N += m.moment[i];
            e.M += m.moment[i] * d.transpose();
            const Eigen::Matrix3d S = d * d.transpose();
            for (int k = 0; k < 3; ++k) e.Q[k] += m.moment[i][k] * S;
            e.radius = std::max(e.radius, d.norm());
        }
        m.exp[n] = detail::FarField(e, m.beta);
    }
}

PointCloudWinding::~PointCloudWinding() = default;
PointCloudWinding::PointCloudWinding(PointCloudWinding&&) noexcept = default;
PointCloudWinding& PointCloudWinding::operator=(PointCloudWinding&&) noexcept = default;

const std::vector<double>& PointCloudWinding::areas() const { return impl_->areas; }

double PointCloudWinding::operator()(const Vec3& q) const {
    if (!impl_ || impl_->bvh.nodes.empty()) return 0.0;
    const Impl& m = *impl_;
    return detail::far_field_sum(m.bvh.nodes, m.exp, q, [&](const Vec3& p, uint32_t i) {
               return dipole(p, m.pos[i], m.moment[i]);
           }) / kFourPi;
}

double point_winding_brute_force(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals,
                                 const std::vector<double>& areas, const Vec3& q) {
    double omega = 0;
    for (size_t i = 0; i < pts.size() && i < normals.size() && i < areas.size(); ++i)
        omega += dipole(q, pts[i], areas[i] * normals[i]);
    return omega / kFourPi;
}

}  // namespace ca
