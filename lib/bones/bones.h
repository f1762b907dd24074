// bones.h: a collider per bone of a skin (docs/bone_colliders.md): for each joint that dominates
// enough of the surface (its interpolated weight is the heaviest there), one tapered capsule or
// sphere fitted to that part from the medial balls whose contact points fall in it, grown to hold
// every point of the part (`conservative`) or shrunk to stay inside the shape (`inscribed`), and
// expressed in the joint's frame (inverse bind applied) so that it moves with the bone.
// The pipeline, one file per step:
//   skin.cpp            the skin checked (hierarchy, indices, finite weights, inverse binds that
//                       are a rotation and a uniform scale) and each vertex's weights normalised
//   surface_parts.cpp   which joint dominates each part of the surface: every triangle cut
//                       exactly into the convex pieces where one joint's weight is the heaviest
//   part_balls.cpp      the medial balls of each part: the candidate set's inner balls whose
//                       contact point (nearest surface point) lies in the part
//   fit_bone.cpp        one tapered capsule or sphere per part: started from the part's medial
//                       balls, shaped to the least volume that still holds the part's points
//                       (conservative) or the largest pair of medial balls that stays inside
//   bone_stats.cpp      containment of fresh samples per part, Monte Carlo union and outside
//                       volume, overlap of each collider with its parent's
//   bone_colliders.cpp  the whole step: parts, fits, the joints' frames, the stats
// Everything here is in internal units (the candidate set's surface) but the joint frames, which
// bone_colliders.cpp applies last in the caller's units.
#pragma once
#include "proxies.h"
#include "surface.h"

namespace ca {

// A skin as the caller gives it (glTF skins, assimp aiBone): joints with a hierarchy and inverse
// bind matrices, up to 8 weighted joints per vertex of the surface (in its bind pose).
struct Skin {
    std::vector<int32_t> parents;              // one per joint; -1 for a root
    std::vector<Eigen::Matrix4d> inverse_bind; // one per joint (surface frame -> joint frame); empty: identity
    uint32_t influences = 0;                   // joints per vertex, 1..8
    std::vector<uint32_t> vertex_joints;       // vertices * influences
    std::vector<double> vertex_weights;        // vertices * influences, finite, >= 0
    size_t joint_count() const { return parents.size(); }
};

struct BoneColliderOptions {
    ProxyMode mode = ProxyMode::conservative;
    ProxyShapes shapes = ProxyShapes::capsules;    // capsules (tapered capsule or sphere) or spheres
    // A joint dominating less than this fraction of the surface's area gets no collider (twist and
    // finger bones that hold too little for a ragdoll body).
    double min_share = 0.005;
    // A collider whose larger radius is below this (percent of the surface's bounding-box diagonal)
    // is dropped.
    double min_size = 0.5;
    std::vector<uint32_t> skip_joints;             // joints that get no collider
    uint32_t surface_samples = 2000;               // points of each part the shape is fitted on
    uint32_t evaluate_samples = 100000;            // fresh surface samples for the containment stats
    uint64_t seed = 1;
    int32_t threads = 0;                           // 0 = all cores
};

// A skin checked and made ready (skin.cpp): per vertex, its distinct joints and their weights
// normalised to sum 1 (none where all were zero); per joint, its inverse bind split into a
// rotation-with-uniform-scale `linear` (columns of equal length `scale`) and a translation.
struct PreparedSkin {
    std::vector<int32_t> parents;
    std::vector<std::vector<std::pair<uint32_t, double>>> weights;   // per vertex
    std::vector<Eigen::Matrix4d> inverse_bind;                        // identity where none given
};
// Checks the skin against a surface of `vertex_count` vertices and options (joint indices, cycles,
// finite non-negative weights, finite inverse binds with a last row 0 0 0 1, skip joints in range).
Status prepare_skin(const Skin& skin, size_t vertex_count, const BoneColliderOptions& opt, PreparedSkin& out);

// The affine map of an inverse bind applied to a primitive: exact for a rotation (or reflection)
// with a uniform scale. `tolerance` (relative) is how far the columns may stray from orthogonal
// and equal length; beyond it false (a capsule under shear or non-uniform scale is no capsule).
// Within it, radii scale by the largest singular value (conservative: the image of the primitive
// is held) or the smallest (inscribed: the image holds it).
bool map_proxy(const Eigen::Matrix4d& m, const Proxy& p, bool grow, Proxy& out);
constexpr double kUniformScaleTolerance = 1e-4;

// ---- the parts (surface_parts.cpp) ----

// Part of the surface one joint dominates: convex polygons (each a piece of one triangle, corners
// in order) where that joint's interpolated weight is at least every other's.
struct SurfacePart {
    std::vector<Vec3> corners;                 // all polygons' corners, in order
    std::vector<uint32_t> polygon_start;       // polygon i: corners [start[i], start[i+1]); one more entry
    double area = 0;
};
// The parts of all joints (joint_count of them; empty where a joint dominates nothing).
std::vector<SurfacePart> surface_parts(const Mesh& mesh, const PreparedSkin& skin);
// The interpolated weights at barycentric coordinates `bary` of triangle t, and the joint of the
// heaviest (the lowest index among equal ones); -1 where every weight is zero.
int32_t dominant_joint(const Mesh& mesh, const PreparedSkin& skin, uint32_t t, const Vec3& bary);
// Barycentric coordinates of p (on or near the triangle's plane) in triangle a b c (Ericson, Real-Time
// Collision Detection, 3.4), clamped to the triangle.
Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);
// n area-uniform points of a part (seeded).
std::vector<Vec3> sample_part(const SurfacePart& part, size_t n, uint64_t seed);

// ---- the medial balls of each part (part_balls.cpp) ----

// For each joint, the candidate set's inner balls (balls[0, inner)) whose nearest surface point
// lies in that joint's part (by dominant_joint there).
std::vector<std::vector<Ball>> part_balls(const Mesh& mesh, const ShapeQueries& shape, const std::vector<Ball>& balls,
                                          size_t inner, const PreparedSkin& skin, int threads, const Monitor& monitor);

// ---- the fit (fit_bone.cpp) ----

// Volume of a primitive (a sphere or the convex hull of two balls), exactly.
double proxy_volume(const Proxy& p);
// One collider for a part, from its medial balls (may be empty) and `points` (samples of the
// part): conservative: the tapered capsule (or sphere) of least volume found that holds `points`,
// then grown to hold every corner of the part (so every point of it: the shape is convex);
// inscribed: the pair of medial balls whose hull, shrunk by its outside bound, is largest.
Proxy fit_bone(const SurfacePart& part, const std::vector<Ball>& balls, const std::vector<Vec3>& points,
               const ShapeQueries& shape, const BoneColliderOptions& opt);
// Conservative: `start` refitted (Nelder-Mead on its balls) to the least volume outside the body
// (shape.winding; measured on seeded points, softly) plus a fraction of its own volume plus
// `weight` times its overlap with `neighbours` (measured on seeded points inside each, softly),
// still holding `points`; then grown to hold every corner of the part. Without a winding number:
// its own volume in full plus the overlap.
Proxy fit_apart(const SurfacePart& part, const std::vector<Vec3>& points, const Proxy& start,
                const std::vector<Proxy>& neighbours, double weight, const ShapeQueries& shape, uint64_t seed);
// p grown (or shrunk) uniformly until it holds every point of `points` with no slack (plus `margin`).
Proxy hold_points(const Proxy& p, const std::vector<Vec3>& points, double margin);

// ---- the stats (bone_stats.cpp) ----

struct BoneCollider {
    uint32_t joint = 0;
    Proxy shape;                    // the result: in the joint's frame, caller's units
    Proxy surface_shape;            // the same in the surface's internal frame (for the stats)
    int32_t parent = -1;            // collider of the nearest ancestor joint that has one
    double contained = 1;           // fraction of the part's fresh samples held
    double overlap = 0;             // volume of overlap with the parent collider (internal units^3)
};

struct BoneColliderStats {
    double contained_fraction = 1;      // over all parts' fresh samples together
    double union_volume = 0, outside_volume = 0;   // internal units^3 (converted by the step)
    double neighbour_overlap = 0;       // sum of the colliders' overlaps with their parents
    uint64_t joints_with_collider = 0, joints_skipped = 0;
    double time_s = 0;
};

// Fills each collider's `contained` and `overlap` and the totals, from the surface shapes.
Status bone_stats(const Mesh& mesh, const ShapeQueries& shape, const PreparedSkin& skin,
                  std::vector<BoneCollider>& colliders, const BoneColliderOptions& opt, const Monitor& monitor,
                  BoneColliderStats& out);
// Monte Carlo volume of the overlap of two primitives (seeded points in their boxes' intersection).
double overlap_volume(const Proxy& a, const Proxy& b, size_t samples, uint64_t seed);

struct BoneColliderResult {
    std::vector<BoneCollider> colliders;   // in joint order
    BoneColliderStats stats;
};

// The whole step (bone_colliders.cpp) on a triangle mesh in internal units, its queries, the
// candidate balls (the first `inner` are inner balls), and the skin in the caller's units
// (`norm` maps between them).
Status make_bone_colliders(const Mesh& mesh, const ShapeQueries& shape, const Normalization& norm,
                           const std::vector<Ball>& balls, size_t inner, const Skin& skin,
                           const BoneColliderOptions& opt, const Monitor& monitor, BoneColliderResult& out);

}  // namespace ca
