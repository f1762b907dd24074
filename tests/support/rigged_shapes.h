// rigged_shapes.h: synthetic skinned characters for the bone-collider tests, built from the
// shapes of shapes.h: a bent arm (a capsule of three bones, bent at its two inner joints by
// linear blend skinning, so the bind pose is bent and every joint's inverse bind turns) and a Y
// body (a torso ball and three limbs meeting at it, one limb with a twist joint that drives
// nothing and whose world matrix carries a uniform scale). Weights fall off smoothly with the
// distance to each bone's segment (a Gaussian, the heaviest four kept, normalised).
#pragma once
#include "bones.h"
#include "support/shapes.h"

#include <cmath>
#include <numeric>

namespace rigged {

struct RiggedShape {
    ca::Mesh mesh;                                   // the bind pose
    std::vector<int32_t> parents;
    std::vector<Eigen::Matrix4d> joint_world;        // bind-pose world matrix of each joint
    std::vector<std::pair<ca::Vec3, ca::Vec3>> bones;   // each joint's segment in the bind pose (a point: none)
    uint32_t influences = 4;
    std::vector<uint32_t> vertex_joints;
    std::vector<double> vertex_weights;

    ca::Skin skin() const {
        ca::Skin s;
        s.parents = parents;
        for (const Eigen::Matrix4d& w : joint_world) s.inverse_bind.push_back(w.inverse());
        s.influences = influences;
        s.vertex_joints = vertex_joints;
        s.vertex_weights = vertex_weights;
        return s;
    }
    // The weight of joint j at vertex v (0 when absent).
    double weight(uint32_t v, uint32_t j) const {
        double w = 0;
        for (uint32_t k = 0; k < influences; ++k)
            if (vertex_joints[v * influences + k] == j) w += vertex_weights[v * influences + k];
        return w;
    }
};

inline Eigen::Matrix4d affine(const Eigen::Matrix3d& r, const ca::Vec3& t, double scale = 1) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = scale * r;
    m.block<3, 1>(0, 3) = t;
    return m;
}
inline Eigen::Matrix3d turn(double degrees, const ca::Vec3& axis) {
    return Eigen::AngleAxisd(degrees * 3.14159265358979323846 / 180, axis.normalized()).toRotationMatrix();
}
inline ca::Vec3 apply(const Eigen::Matrix4d& m, const ca::Vec3& x) {
    return m.topLeftCorner<3, 3>() * x + m.block<3, 1>(0, 3);
}

inline double segment_distance(const ca::Vec3& x, const ca::Vec3& a, const ca::Vec3& b) {
    const ca::Vec3 d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((x - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (x - (a + t * d)).norm();
}

// Weights from the distance to the bones' segments (joints with `weighted` false get none).
inline void weigh(RiggedShape& s, const std::vector<std::pair<ca::Vec3, ca::Vec3>>& segments,
                  const std::vector<bool>& weighted, double sigma) {
    const size_t nj = segments.size();
    s.vertex_joints.clear();
    s.vertex_weights.clear();
    for (const ca::Vec3& x : s.mesh.vertices) {
        std::vector<std::pair<double, uint32_t>> w;
        for (size_t j = 0; j < nj; ++j) {
            if (!weighted[j]) continue;
            const double d = segment_distance(x, segments[j].first, segments[j].second);
            w.emplace_back(std::exp(-0.5 * d * d / (sigma * sigma)) + 1e-12, uint32_t(j));
        }
        std::sort(w.begin(), w.end(), [](auto& a, auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
        w.resize(std::min<size_t>(w.size(), s.influences), {0.0, 0u});
        double total = 0;
        for (auto& e : w) total += e.first;
        for (uint32_t k = 0; k < s.influences; ++k) {
            s.vertex_joints.push_back(k < w.size() ? w[k].second : 0);
            s.vertex_weights.push_back(k < w.size() ? w[k].first / total : 0.0);
        }
    }
}

// An arm of three bones along x in its rest pose (a capsule, x from -1.8 to 1.8), bent by linear
// blend skinning at its elbow and wrist; the bind pose is the bent one.
inline RiggedShape bent_arm() {
    RiggedShape s;
    const ca::Mesh rest = shapes::capsule(1.5, 0.3, 96, 48);
    const std::vector<std::pair<ca::Vec3, ca::Vec3>> rest_bones = {
        {{-1.5, 0, 0}, {-0.5, 0, 0}}, {{-0.5, 0, 0}, {0.5, 0, 0}}, {{0.5, 0, 0}, {1.5, 0, 0}}};
    s.parents = {-1, 0, 1};
    s.mesh = rest;
    weigh(s, rest_bones, {true, true, true}, 0.25);
    // rest world matrices: each joint at its bone's start, turned about x (so its frame is not the
    // world's); posed: the root turned and moved, the elbow and wrist bent
    const Eigen::Matrix3d twist[3] = {turn(30, {1, 0, 0}), turn(-50, {1, 0, 0}), turn(80, {1, 0, 0})};
    const Eigen::Matrix3d bend[3] = {turn(25, {0, 1, 1}), turn(45, {0, 0, 1}), turn(35, {0, 1, 0})};
    std::vector<Eigen::Matrix4d> rest_world(3), posed(3);
    for (int j = 0; j < 3; ++j) {
        rest_world[size_t(j)] = affine(twist[j], rest_bones[size_t(j)].first);
        const Eigen::Matrix4d local_rest =
            j == 0 ? rest_world[0] : Eigen::Matrix4d(rest_world[size_t(j - 1)].inverse() * rest_world[size_t(j)]);
        const Eigen::Matrix4d local_posed = local_rest * affine(bend[j], ca::Vec3::Zero());
        posed[size_t(j)] = j == 0 ? Eigen::Matrix4d(affine(Eigen::Matrix3d::Identity(), ca::Vec3(0.2, -0.1, 0.4)) * local_posed)
                                  : Eigen::Matrix4d(posed[size_t(j - 1)] * local_posed);
    }
    for (size_t v = 0; v < rest.vertices.size(); ++v) {
        ca::Vec3 x = ca::Vec3::Zero();
        for (uint32_t j = 0; j < 3; ++j) x += s.weight(uint32_t(v), j) * apply(posed[j] * rest_world[j].inverse(), rest.vertices[v]);
        s.mesh.vertices[v] = x;
    }
    s.joint_world = posed;
    for (size_t j = 0; j < 3; ++j)
        s.bones.emplace_back(apply(posed[j] * rest_world[j].inverse(), rest_bones[j].first),
                             apply(posed[j] * rest_world[j].inverse(), rest_bones[j].second));
    return s;
}

// A Y body: a torso ball (joint 0) and three limbs (joints 1 to 3, children of 0) in the xy plane,
// each a capsule from near the centre outwards; joint 4, a child of limb 1, drives nothing.
// Limb 2's world matrix has a uniform scale of 2 (its inverse bind scales by 1/2).
inline RiggedShape y_body() {
    RiggedShape s;
    s.mesh = shapes::sphere(0.55, 32, 64);
    s.parents = {-1, 0, 0, 0, 1};
    std::vector<std::pair<ca::Vec3, ca::Vec3>> bones = {{{0, 0, 0}, {0, 0, 0}}};
    s.joint_world.push_back(affine(turn(30, {0, 0, 1}), ca::Vec3::Zero()));
    for (int k = 0; k < 3; ++k) {
        const double a = 90 + 120 * k;
        const Eigen::Matrix3d r = turn(a, {0, 0, 1});
        const ca::Vec3 dir = r * ca::Vec3::UnitX();
        const double half = 0.7 + 0.15 * k, radius = 0.22 + 0.04 * k;
        ca::Mesh limb = shapes::capsule(half, radius, 64, 40);
        for (ca::Vec3& v : limb.vertices) v = r * v + (0.35 + half) * dir;
        s.mesh = shapes::merged(s.mesh, limb);
        bones.emplace_back(0.35 * dir, (0.35 + 2 * half) * dir);
        s.joint_world.push_back(affine(r * turn(20.0 * k, {1, 0, 0}), 0.35 * dir, k == 1 ? 2.0 : 1.0));
    }
    bones.push_back(bones[1]);
    s.joint_world.push_back(affine(turn(90, {0, 0, 1}), bones[1].second));
    weigh(s, bones, {true, true, true, true, false}, 0.3);
    s.bones = bones;
    return s;
}

}  // namespace rigged
