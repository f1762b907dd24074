// skin_points.cpp: the rig's per-point joint weights (rig.h): a point's continuous ball blend
// (BallBlend) mapped through each ball's joint weights, then cut to the kInfluences largest as
// top_weights does, so the joint weights are as continuous over the surface as the ball weights.
#include "rig.h"

#include "parallel.h"

#include <algorithm>

namespace ca {

Status skin_points(const std::vector<Vec3>& points, const Skeleton& s, const RigOptions& opt, const Monitor& monitor,
                   Rig& rig) {
    const BallBlend blend(s, opt.correspond);
    const size_t m = points.size();
    rig.vertex_joints.assign(m, {});
    rig.vertex_weights.assign(m, {});
    rig.vertex_branch.assign(m, 0);
    const bool done = parallel_for(m, resolve_threads(opt.correspond.threads), 4096, monitor, "rig", [&](size_t b, size_t e) {
        SparseWeights balls, joints;
        NearestKind kind;
        uint32_t index;
        for (size_t i = b; i < e; ++i) {
            blend.blend(points[i], balls, kind, index);
            joints.clear();
            uint32_t heaviest = balls[0].first;
            double most = -1;
            for (const auto& [ball, w] : balls) {
                if (w > most) {
                    most = w;
                    heaviest = ball;
                }
                for (const auto& [joint, u] : rig.ball_joints[ball]) joints.emplace_back(joint, w * u);
            }
            std::sort(joints.begin(), joints.end());
            size_t k = 0;
            for (size_t j = 0; j < joints.size(); ++j) {
                if (k > 0 && joints[k - 1].first == joints[j].first) joints[k - 1].second += joints[j].second;
                else joints[k++] = joints[j];
            }
            joints.resize(k);
            top_weights(joints, rig.vertex_joints[i], rig.vertex_weights[i]);
            rig.vertex_branch[i] = rig.ball_branch[heaviest];
        }
    });
    if (!done) return monitor.stop_status("rig");
    return Status::success();
}

}  // namespace ca
