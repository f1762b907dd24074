// bone_baseline.h: the bone colliders engines generate (bench_bone_colliders' baseline), as
// Unreal's physics-asset tool makes them by default (capsules, dominant-weight vertices, oriented
// to the bone): for each joint that is the heaviest joint of at least one vertex, the bounding box
// of those vertices in the joint's bind frame (inverse bind applied), and a capsule along the
// bone's axis (+Y, as glTF and Blender point bones) through the box's centre whose radius is the
// larger half-extent across the axis and whose length is the box's length along it less the two
// caps (a sphere when the box is no longer than it is wide).
#pragma once
#include "proxies.h"

#include <Eigen/Dense>

#include <cstdint>
#include <vector>

namespace bench {

struct BoneShape {
    uint32_t joint = 0;
    ca::Proxy shape;   // in the joint's bind frame: ball a at the bottom, b at the top
};

// Each vertex's heaviest joint (-1: no weight), from `influences` joints/weights per vertex.
inline std::vector<int32_t> dominant_joints(size_t vertex_count, size_t influences, const uint32_t* joints,
                                            const double* weights) {
    std::vector<int32_t> out(vertex_count, -1);
    for (size_t i = 0; i < vertex_count; ++i) {
        double best = 0;
        for (size_t k = 0; k < influences; ++k)
            if (weights[influences * i + k] > best) best = weights[influences * i + k], out[i] = int32_t(joints[influences * i + k]);
    }
    return out;
}

// The point `x` of the mesh frame in joint j's bind frame (column-major inverse bind matrices).
inline ca::Vec3 to_joint(const double* inverse_bind, size_t j, const ca::Vec3& x) {
    const Eigen::Map<const Eigen::Matrix4d> m(inverse_bind + 16 * j);
    return (m * x.homogeneous()).head<3>();
}

inline std::vector<BoneShape> engine_capsules(const std::vector<double>& positions, size_t joint_count, size_t influences,
                                              const uint32_t* joints, const double* weights, const double* inverse_bind) {
    const size_t nv = positions.size() / 3;
    const std::vector<int32_t> dominant = dominant_joints(nv, influences, joints, weights);
    std::vector<ca::Vec3> lo(joint_count, ca::Vec3::Constant(1e300)), hi(joint_count, ca::Vec3::Constant(-1e300));
    std::vector<size_t> count(joint_count, 0);
    for (size_t i = 0; i < nv; ++i) {
        if (dominant[i] < 0) continue;
        const size_t j = size_t(dominant[i]);
        const ca::Vec3 p = to_joint(inverse_bind, j, ca::Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]));
        lo[j] = lo[j].cwiseMin(p);
        hi[j] = hi[j].cwiseMax(p);
        ++count[j];
    }
    std::vector<BoneShape> out;
    for (size_t j = 0; j < joint_count; ++j) {
        if (!count[j]) continue;
        const ca::Vec3 c = 0.5 * (lo[j] + hi[j]), e = 0.5 * (hi[j] - lo[j]);
        const double r = std::max(e.x(), e.z()), half = std::max(e.y() - r, 0.0);
        BoneShape s;
        s.joint = uint32_t(j);
        s.shape.kind = half > 0 ? ca::ProxyKind::capsule : ca::ProxyKind::sphere;
        s.shape.a = {c - ca::Vec3(0, half, 0), r};
        s.shape.b = {c + ca::Vec3(0, half, 0), r};
        out.push_back(s);
    }
    return out;
}

}  // namespace bench
