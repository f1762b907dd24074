// place_joints.cpp: the rig's joints on the curve skeleton (rig.h): the root, every junction and
// tip, and balls about joint_spacing apart along each branch (the spacing widened until the joints
// fit max_joints); then every ball's joint weights. A ball between joints P and C (C the child)
// at arc-length fraction t belongs to P, blending linearly towards C over the last quarter
// (reaching half at C) and towards P's parent over the first quarter (half at P), so the weights
// agree where segments meet and change continuously along the tree.
#include "rig.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace ca {
namespace {

constexpr double kBlend = 0.25;   // the fraction of a segment blended at each end

// The balls' bounding box's longest side (balls included).
double longest_side(const Skeleton& s) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Ball& b : s.balls) {
        lo = lo.cwiseMin(b.center - Vec3::Constant(b.radius));
        hi = hi.cwiseMax(b.center + Vec3::Constant(b.radius));
    }
    return (hi - lo).maxCoeff();
}

// The balls of each branch that become joints (its last ball always) at this spacing.
std::vector<std::vector<size_t>> joint_positions(const Skeleton& s, const CurveTree& tree, double spacing) {
    std::vector<std::vector<size_t>> out;
    for (size_t b = 0; b < tree.branches.size(); ++b) {
        const auto& chain = tree.branches[b];
        std::vector<double> arc(chain.size());
        Vec3 prev = s.balls[tree.branch_start[b]].center;
        double total = 0;
        for (size_t k = 0; k < chain.size(); ++k) {
            total += (s.balls[chain[k]].center - prev).norm();
            prev = s.balls[chain[k]].center;
            arc[k] = total;
        }
        const int segments = std::max(1, int(std::lround(total / spacing)));
        std::vector<size_t> at;
        size_t k = 0;
        for (int j = 1; j < segments; ++j) {
            const double target = total * j / segments;
            while (k + 1 < chain.size() && std::abs(arc[k + 1] - target) <= std::abs(arc[k] - target)) ++k;
            if (k + 1 < chain.size() && (at.empty() || at.back() < k)) at.push_back(k);
        }
        at.push_back(chain.size() - 1);
        out.push_back(at);
    }
    return out;
}

}  // namespace

void place_joints(const Skeleton& s, const CurveTree& tree, const RigOptions& opt, Rig& rig) {
    const size_t n = s.balls.size();
    double spacing = opt.joint_spacing * longest_side(s);
    if (!(spacing > 0)) spacing = 1;
    std::vector<std::vector<size_t>> at = joint_positions(s, tree, spacing);
    for (;;) {
        size_t count = 1;
        bool spread = true;   // every branch down to its end joint alone
        for (const auto& a : at) {
            count += a.size();
            spread = spread && a.size() == 1;
        }
        if (count <= opt.max_joints || spread) break;
        spacing *= 1.25;
        at = joint_positions(s, tree, spacing);
    }

    rig.joints.assign(1, s.balls[tree.root].center);
    rig.parent.assign(1, -1);
    rig.joint_ball.assign(1, tree.root);
    rig.joint_branch.assign(1, 0);
    rig.branch_count = tree.branches.size();
    rig.ball_joints.assign(n, {});
    rig.ball_branch.assign(n, 0);
    std::vector<int64_t> joint_of(n, -1);
    joint_of[tree.root] = 0;
    rig.ball_joints[tree.root] = {{0u, 1.0}};
    if (!tree.branches.empty()) rig.ball_branch[tree.root] = 0;

    for (size_t b = 0; b < tree.branches.size(); ++b) {
        const auto& chain = tree.branches[b];
        // the joints along the branch, each as the index into the chain
        int64_t p = joint_of[tree.branch_start[b]];
        size_t first = 0;   // the chain's first ball after joint p
        for (size_t a : at[b]) {
            const uint32_t ball = chain[a];
            const int32_t c = int32_t(rig.joints.size());
            rig.joints.push_back(s.balls[ball].center);
            rig.parent.push_back(int32_t(p));
            rig.joint_ball.push_back(ball);
            rig.joint_branch.push_back(uint32_t(b));
            joint_of[ball] = c;
            // the balls from `first` to `a`, by arc length between joints p and c
            const Vec3 start = rig.joints[size_t(p)];
            std::vector<double> arc;
            double total = 0;
            Vec3 prev = start;
            for (size_t k = first; k <= a; ++k) {
                total += (s.balls[chain[k]].center - prev).norm();
                prev = s.balls[chain[k]].center;
                arc.push_back(total);
            }
            const int32_t g = rig.parent[size_t(p)];
            for (size_t k = first; k <= a; ++k) {
                const double t = total > 0 ? arc[k - first] / total : 1.0;
                SparseWeights w;
                if (t < kBlend && g >= 0) {
                    const double x = 0.5 + 0.5 * t / kBlend;
                    w = {{uint32_t(p), x}, {uint32_t(g), 1 - x}};
                } else if (t > 1 - kBlend) {
                    const double x = 0.5 * (t - (1 - kBlend)) / kBlend;
                    w = {{uint32_t(p), 1 - x}, {uint32_t(c), x}};
                } else {
                    w = {{uint32_t(p), 1.0}};
                }
                rig.ball_joints[chain[k]] = w;
                rig.ball_branch[chain[k]] = uint32_t(b);
            }
            p = c;
            first = a + 1;
        }
    }

    // balls off the tree: those of the nearest tree ball along the graph
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<uint32_t> source(n, 0);
    using Entry = std::pair<double, uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (uint32_t v = 0; v < n; ++v)
        if (tree.in_tree[v]) {
            dist[v] = 0;
            source[v] = v;
            queue.emplace(0.0, v);
        }
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > dist[v]) continue;
        for (const auto& [w, len] : tree.graph[v])
            if (d + len < dist[w] || (d + len == dist[w] && source[v] < source[w])) {
                dist[w] = d + len;
                source[w] = source[v];
                queue.emplace(dist[w], w);
            }
    }
    for (uint32_t v = 0; v < n; ++v)
        if (!tree.in_tree[v]) {
            rig.ball_joints[v] = rig.ball_joints[source[v]];
            rig.ball_branch[v] = rig.ball_branch[source[v]];
        }
}

}  // namespace ca
