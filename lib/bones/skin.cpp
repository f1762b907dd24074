// skin.cpp: the skin checked and prepared (bones.h): joint indices in range, a hierarchy without
// cycles, finite non-negative weights normalised per vertex (a joint named twice in one vertex's
// slots gets their sum), finite inverse binds; and the map of a primitive into a joint's frame,
// exact only for a rotation (or reflection) with a uniform scale.
#include "bones.h"

#include <Eigen/SVD>
#include <cmath>
#include <map>

namespace ca {

Status prepare_skin(const Skin& skin, size_t vertex_count, const BoneColliderOptions& opt, PreparedSkin& out) {
    out = PreparedSkin{};
    const size_t nj = skin.joint_count();
    if (nj == 0) return fail(Code::invalid_input, "the skin has no joints");
    if (skin.influences < 1 || skin.influences > 8)
        return fail(Code::invalid_input, "skin influences must be 1 to 8 joints per vertex (got " +
                                             std::to_string(skin.influences) + ")");
    if (skin.vertex_joints.size() != vertex_count * skin.influences ||
        skin.vertex_weights.size() != vertex_count * skin.influences)
        return fail(Code::invalid_input, "the skin's vertex arrays must hold " + std::to_string(skin.influences) +
                                             " entries for each of the surface's " + std::to_string(vertex_count) +
                                             " vertices");
    if (!skin.inverse_bind.empty() && skin.inverse_bind.size() != nj)
        return fail(Code::invalid_input, "the skin needs one inverse bind matrix per joint");
    for (size_t j = 0; j < nj; ++j) {
        const int32_t p = skin.parents[j];
        if (p < -1 || p >= int64_t(nj))
            return fail(Code::invalid_input, "joint " + std::to_string(j) + " has parent " + std::to_string(p) + " of " +
                                                 std::to_string(nj) + " joints (-1 for a root)");
    }
    // cycles: walking up from any joint must reach a root within nj steps
    for (size_t j = 0; j < nj; ++j) {
        int64_t k = int64_t(j);
        size_t steps = 0;
        while (k >= 0 && steps <= nj) k = skin.parents[size_t(k)], ++steps;
        if (k >= 0) return fail(Code::invalid_input, "the skin's joint hierarchy has a cycle through joint " + std::to_string(j));
    }
    out.inverse_bind.assign(nj, Eigen::Matrix4d::Identity());
    for (size_t j = 0; j < skin.inverse_bind.size(); ++j) {
        const Eigen::Matrix4d& m = skin.inverse_bind[j];
        if (!m.allFinite()) return fail(Code::invalid_input, "inverse bind matrix of joint " + std::to_string(j) + " has a NaN or infinite value");
        if (std::abs(m(3, 0)) > 1e-9 || std::abs(m(3, 1)) > 1e-9 || std::abs(m(3, 2)) > 1e-9 || std::abs(m(3, 3) - 1) > 1e-9)
            return fail(Code::invalid_input, "inverse bind matrix of joint " + std::to_string(j) +
                                                 " is not affine (its last row must be 0 0 0 1)");
        out.inverse_bind[j] = m;
    }
    for (uint32_t j : opt.skip_joints)
        if (j >= nj)
            return fail(Code::invalid_argument, "skip joint " + std::to_string(j) + " out of range (" + std::to_string(nj) + " joints)");
    out.parents = skin.parents;
    out.weights.resize(vertex_count);
    const size_t k = skin.influences;
    for (size_t v = 0; v < vertex_count; ++v) {
        std::map<uint32_t, double> sum;
        double total = 0;
        for (size_t i = 0; i < k; ++i) {
            const uint32_t j = skin.vertex_joints[v * k + i];
            const double w = skin.vertex_weights[v * k + i];
            if (!std::isfinite(w) || w < 0)
                return fail(Code::invalid_input, "vertex " + std::to_string(v) + " has a NaN, infinite or negative weight");
            if (j >= nj)
                return fail(Code::invalid_input, "vertex " + std::to_string(v) + " references joint " + std::to_string(j) +
                                                     " of " + std::to_string(nj));
            if (w > 0) sum[j] += w, total += w;
        }
        if (!(total > 0) || !std::isfinite(total)) continue;   // drives no joint
        for (const auto& [j, w] : sum) out.weights[v].emplace_back(j, w / total);
    }
    return Status::success();
}

bool map_proxy(const Eigen::Matrix4d& m, const Proxy& p, bool grow, Proxy& out) {
    const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a);
    const Vec3 s = svd.singularValues();
    if (!(s[2] > 0) || (s[0] - s[2]) > kUniformScaleTolerance * s[0]) return false;
    out = p;
    const double scale = grow ? s[0] : s[2];
    // the image of a ball B(c, r) lies within B(Mc + t, s_max r) and holds B(Mc + t, s_min r); the
    // primitive is the union of the balls interpolated between its two, so its image does too
    for (Ball* b : {&out.a, &out.b}) {
        b->center = a * b->center + m.block<3, 1>(0, 3);
        b->radius *= scale;
    }
    return true;
}

}  // namespace ca
