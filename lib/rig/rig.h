// rig.h: a rig from a medial skeleton: its curve skeleton (a tree over the balls that keeps the
// junctions and the branches that reach out of the shape's body, and crosses sheets along their
// fattest balls), joints spaced along it, and per-vertex joint weights from the correspondence's
// continuous ball weights. Everything in the caller's units.
#pragma once
#include "correspondence.h"

#include <array>
#include <vector>

namespace ca {

struct RigOptions {
    int64_t root = -1;            // the root's ball; -1: the largest ball (the lowest index of equals)
    uint32_t max_joints = 64;     // at most this many joints (>= 1): fewer branches, then wider spacing
    // Joints along a branch about this far apart, a fraction of the longest side of the balls'
    // bounding box (> 0); junctions and tips are always joints.
    double joint_spacing = 0.1;
    // A branch is kept when its tip's ball reaches past every ball of the tree by more than this
    // many times that ball's radius, and the branch is longer than this many tip radii (>= 0):
    // sheets' rims, bumps and crevices do not, limbs do.
    double min_branch = 1.5;
    CorrespondOptions correspond;  // the ball weights the joint weights are made from
};

// The curve skeleton: a tree over some of the skeleton's balls, cut into branches between its
// key balls (the root, junctions, tips).
struct CurveTree {
    uint32_t root = 0;
    std::vector<int64_t> parent;          // per ball: its parent in the tree; -1 at the root and off the tree
    std::vector<char> in_tree;            // per ball
    // Each branch: the key ball it starts from, then its balls down to the next key ball (included).
    std::vector<uint32_t> branch_start;
    std::vector<std::vector<uint32_t>> branches;
    // The skeleton's graph (its edges, plus the shortest links that join its components) as
    // adjacency lists with lengths.
    std::vector<std::vector<std::pair<uint32_t, double>>> graph;
};

// The tree, rooted at opt.root or the largest ball. The skeleton must pass check_skeleton.
Status curve_tree(const Skeleton& s, const RigOptions& opt, CurveTree& out);

struct Rig {
    // Joints in an order where every parent comes before its children; joint 0 is the root.
    std::vector<Vec3> joints;
    std::vector<int32_t> parent;          // -1 for the root
    std::vector<uint32_t> joint_ball;     // the ball each joint sits on
    std::vector<uint32_t> joint_branch;   // the branch each joint ends or lies on (the root: 0)
    size_t branch_count = 0;
    // Per ball: its joint weights (sum 1) and branch. A ball on the tree between two joints blends
    // them near its ends; a ball off the tree takes those of the nearest tree ball along the graph.
    std::vector<SparseWeights> ball_joints;
    std::vector<uint32_t> ball_branch;
    // Per point: kInfluences joints and weights (sum 1, decreasing; unused: weight 0, the first
    // joint), the branch of its heaviest ball.
    std::vector<std::array<uint32_t, kInfluences>> vertex_joints;
    std::vector<std::array<double, kInfluences>> vertex_weights;
    std::vector<uint32_t> vertex_branch;
};

// Joints along the tree's branches, opt.joint_spacing apart (wider while more than
// opt.max_joints), and every ball's joint weights and branch.
void place_joints(const Skeleton& s, const CurveTree& tree, const RigOptions& opt, Rig& rig);

// The joint weights of every point: its ball blend (BallBlend) mapped through the balls' joint
// weights, cut to the kInfluences largest as top_weights does (opt.correspond.threads).
Status skin_points(const std::vector<Vec3>& points, const Skeleton& s, const RigOptions& opt, const Monitor& monitor,
                   Rig& rig);

}  // namespace ca
