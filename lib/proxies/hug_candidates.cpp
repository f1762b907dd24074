// hug_candidates.cpp: what the conservative choice picks from, beside the skeleton's own
// primitives (proxy_candidates.cpp). Each skeleton primitive is a candidate at several growths
// (offsets): medial balls touch the surface, and a grown one holds the band of surface around its
// contacts, a larger band for a larger growth at the price of more volume outside. Oriented boxes
// are fitted to groups of surface points: the nodes of a tree that cuts a group in two where the
// children's boxes have the least volume (a plank, a wall, a table top becomes one node), and the points a skeleton primitive
// holds (hug_choice.cpp). A box is the tighter of the one in the points' principal axes and the
// one in the model's axes (buildings and furniture are mostly axis-aligned). The same groups give
// capsules along their principal axis (a limb whose skeleton has no single long edge).
#include "proxies.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace ca {

namespace {

// Offsets in internal units (the model's longest side is 1).
const std::vector<double> kOffsets = {0.0, 0.005, 0.012, 0.025, 0.045, 0.07};
// The tree stops halving at this depth (at most 2^depth leaves).
constexpr int kMaxDepth = 14;
// A group is cut by one of kCuts - 1 evenly spaced planes across each side of its box.
constexpr int kCuts = 8;

Proxy box_in_frame(const std::vector<Vec3>& points, const std::vector<uint32_t>& indices, const Eigen::Matrix3d& axes) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (uint32_t i : indices) {
        const Vec3 q = axes.transpose() * points[i];
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    return make_box(axes * (0.5 * (lo + hi)), axes, 0.5 * (hi - lo));
}

double box_volume(const Proxy& p) { return 8 * p.half.x() * p.half.y() * p.half.z(); }

}  // namespace

const std::vector<double>& hug_offsets() { return kOffsets; }

Proxy fit_box(const std::vector<Vec3>& points, const std::vector<uint32_t>& indices) {
    const Proxy aligned = box_in_frame(points, indices, Eigen::Matrix3d::Identity());
    if (indices.size() < 4) return aligned;
    Vec3 mean = Vec3::Zero();
    for (uint32_t i : indices) mean += points[i];
    mean /= double(indices.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (uint32_t i : indices) cov += (points[i] - mean) * (points[i] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Eigen::Matrix3d axes = eig.eigenvectors();
    if (!axes.allFinite()) return aligned;
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);  // right-handed
    const Proxy principal = box_in_frame(points, indices, axes);
    return box_volume(principal) < box_volume(aligned) ? principal : aligned;
}

Proxy fit_capsule(const std::vector<Vec3>& points, const std::vector<uint32_t>& indices) {
    Vec3 mean = Vec3::Zero();
    for (uint32_t i : indices) mean += points[i];
    mean /= double(std::max<size_t>(indices.size(), 1));
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (uint32_t i : indices) cov += (points[i] - mean) * (points[i] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Vec3 dir = eig.eigenvectors().col(2);
    if (!dir.allFinite() || dir.norm() < 0.5) dir = Vec3::UnitX();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, r = 0;
    for (uint32_t i : indices) {
        const double t = dir.dot(points[i] - mean);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
        r = std::max(r, (points[i] - mean - t * dir).norm());
    }
    // the segment pulled in by the radius at both ends (the caps reach the extreme points), then
    // the radius grown to hold every point
    const double inset = std::min(r, 0.5 * (hi - lo));
    Proxy p{ProxyKind::capsule, Ball{mean + (lo + inset) * dir, 0.0}, Ball{mean + (hi - inset) * dir, 0.0}};
    double need = 0;
    for (uint32_t i : indices) need = std::max(need, proxy_distance(p, points[i]));
    p.a.radius = p.b.radius = need;
    if ((p.b.center - p.a.center).norm() == 0) p.kind = ProxyKind::sphere;
    return p;
}

std::vector<std::vector<uint32_t>> point_groups(const std::vector<Vec3>& points, size_t min_size) {
    std::vector<std::vector<uint32_t>> out;
    struct Node { std::vector<uint32_t> indices; int depth; };
    std::vector<Node> stack;
    Node root{{}, 0};
    for (uint32_t i = 0; i < points.size(); ++i) root.indices.push_back(i);
    stack.push_back(std::move(root));
    while (!stack.empty()) {
        Node node = std::move(stack.back());
        stack.pop_back();
        if (node.indices.size() < std::max<size_t>(min_size, 1)) continue;
        const Proxy box = fit_box(points, node.indices);
        out.push_back(node.indices);
        if (node.depth >= kMaxDepth || node.indices.size() < 2 * min_size) continue;
        // the cut of least total child volume (boxes in this box's frame) among kCuts planes
        // across each of its sides: an L of two planks is cut where they meet
        Vec3 best_dir = box.axes.col(0);
        double best_cut = 0, best_volume = std::numeric_limits<double>::infinity();
        for (int axis = 0; axis < 3; ++axis)
            for (int q = 1; q < kCuts; ++q) {
                const Vec3 dir = box.axes.col(axis);
                const double cut = dir.dot(box.a.center) + box.half[axis] * (2.0 * q / kCuts - 1);
                Vec3 lo[2], hi[2];
                for (int k = 0; k < 2; ++k) {
                    lo[k] = Vec3::Constant(std::numeric_limits<double>::infinity());
                    hi[k] = -lo[k];
                }
                for (uint32_t i : node.indices) {
                    const Vec3 local = box.axes.transpose() * points[i];
                    const int k = dir.dot(points[i]) < cut ? 0 : 1;
                    lo[k] = lo[k].cwiseMin(local);
                    hi[k] = hi[k].cwiseMax(local);
                }
                double volume = 0;
                for (int k = 0; k < 2; ++k)
                    if (lo[k].x() <= hi[k].x()) volume += (hi[k] - lo[k]).prod();
                if (volume < best_volume * (1 - 1e-12)) {
                    best_volume = volume;
                    best_dir = dir;
                    best_cut = cut;
                }
            }
        Node left{{}, node.depth + 1}, right{{}, node.depth + 1};
        for (uint32_t i : node.indices) (best_dir.dot(points[i]) < best_cut ? left : right).indices.push_back(i);
        if (left.indices.empty() || right.indices.empty()) continue;  // all points in one place
        stack.push_back(std::move(right));
        stack.push_back(std::move(left));
    }
    return out;
}

}  // namespace ca
