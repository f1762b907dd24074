// proxy_placement.cpp: each primitive as an engine places it (proxies.h, ProxyPlacement): the
// node's translation and rotation and the shape's parameters in the node's frame, as glTF's
// KHR_implicit_shapes defines them (a capsule along the node's +Y, a box axis-aligned in it).
#include "proxies.h"

#include <cmath>

namespace ca {

namespace {

// q and -q are the same rotation: the one with w >= 0, so equal primitives give equal numbers.
Eigen::Quaterniond canonical(Eigen::Quaterniond q) {
    q.normalize();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    return q;
}

ProxyPlacement sphere(const Ball& b) {
    ProxyPlacement out;
    out.kind = ProxyKind::sphere;
    out.translation = b.center;
    out.radius_top = out.radius_bottom = b.radius;
    return out;
}

}  // namespace

ProxyPlacement proxy_placement(const Proxy& p) {
    switch (p.kind) {
    case ProxyKind::sphere: return sphere(p.a);
    case ProxyKind::capsule: {
        const Vec3 d = p.b.center - p.a.center;
        const double length = d.norm();
        // one ball inside the other (or both the same): the hull is the larger ball
        if (!(length > std::abs(p.a.radius - p.b.radius))) return sphere(p.a.radius >= p.b.radius ? p.a : p.b);
        ProxyPlacement out;
        out.kind = ProxyKind::capsule;
        out.translation = 0.5 * (p.a.center + p.b.center);
        out.axis = d / length;
        out.rotation = canonical(Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), out.axis));
        out.radius_top = p.b.radius;
        out.radius_bottom = p.a.radius;
        out.height = length;
        return out;
    }
    case ProxyKind::box: {
        ProxyPlacement out;
        out.kind = ProxyKind::box;
        out.translation = p.a.center;
        // a rotation needs a right-handed frame; a box is symmetric, so flipping its third edge
        // direction leaves it the same box
        Eigen::Matrix3d axes = p.axes;
        if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
        out.rotation = canonical(Eigen::Quaterniond(axes));
        out.axis = out.rotation * Vec3::UnitY();
        out.size = 2 * p.half;
        return out;
    }
    }
    return sphere(p.a);
}

}  // namespace ca
