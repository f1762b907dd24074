// proxies.h: engine proxies from a medial skeleton (docs/proxies.md): at most K convex primitives,
// spheres or tapered capsules (two balls and their medial cone: the convex hull of the two
// spheres), that a game engine takes as colliders, broad-phase volumes or shadow casters.
// Two modes: `inscribed` primitives stay inside the shape (no farther out than the skeleton's own
// balls and edges), `conservative` primitives together contain every point of the surface.
// The pipeline, one file per step:
//   proxy_candidates.cpp  the primitives to choose from: every ball, every edge, and capsules
//                         between balls further apart along the skeleton's edges
//   proxy_outside.cpp     how far each candidate may reach outside the shape (a proven bound from
//                         the depth of its balls' centres) and how far the skeleton does reach
//   surface_cells.cpp     the surface cut into small triangles whose corners are the samples
//   choose_proxies.cpp    the choice of at most K candidates at the least error (greedy, swaps)
//   inside_grid.cpp       conservative: the shape's inside on voxels, a candidate's volume outside
//   hug_candidates.cpp    conservative: skeleton primitives grown by offsets, boxes fitted to groups
//                         of surface points
//   hug_choice.cpp        conservative: the candidates of least outside volume that hold every
//                         surface point, at most K (a weighted cover, lib/cover/weighted_cover.h)
//   proxy_stats.cpp       the achieved errors and the volume outside the shape
//   proxy_placement.cpp   each primitive as an engine places it (a node's translation, rotation
//                         and shape parameters)
//   proxies.cpp           the whole step: candidates, choice, conservative growth, stats
#pragma once
#include "common.h"
#include "shape_queries.h"
#include "skeleton.h"

#include <memory>

namespace ca {

class WindingNumber;
class MeshDistance;

enum class ProxyKind : int32_t { sphere = 0, capsule = 1, box = 2 };
// What the output may hold: spheres only; tapered capsules and spheres; oriented boxes and spheres;
// or all three, each part of the shape taking whichever primitive serves it best.
enum class ProxyShapes : int32_t { spheres = 0, capsules = 1, boxes = 2, all = 3 };
enum class ProxyMode : int32_t { inscribed = 0, conservative = 1 };

struct ProxyOptions {
    ProxyShapes shapes = ProxyShapes::capsules;
    ProxyMode mode = ProxyMode::inscribed;
    uint32_t count = 16;               // K >= 1: at most this many primitives
    uint32_t surface_samples = 20000;  // about this many corners of the surface cells (surface_cells.cpp)
    uint32_t evaluate_samples = 20000; // the stats: surface and primitive-boundary samples each
    uint32_t volume_samples = 100000;  // the stats: Monte Carlo points for the volume outside the shape
    uint64_t seed = 1;
    int32_t threads = 0;               // 0 = all cores
};

// One primitive, convex: a sphere (ball a; b equals a), the convex hull of balls a and b (a tapered
// capsule), or an oriented box: centre a.center (b equals a, both radii 0), its edges along the
// columns of `axes` (orthonormal, right-handed), half their lengths in `half`.
struct Proxy {
    ProxyKind kind = ProxyKind::sphere;
    Ball a, b;
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    Vec3 half = Vec3::Zero();
};

// An oriented box primitive (axes orthonormal and right-handed, half-lengths >= 0).
Proxy make_box(const Vec3& center, const Eigen::Matrix3d& axes, const Vec3& half);

// Exact signed distance (negative inside) to a primitive.
double proxy_distance(const Proxy& p, const Vec3& x);

// How an engine places a primitive (proxy_placement.cpp; the glTF KHR_implicit_shapes conventions):
// a node at `translation` turned by `rotation` (node frame to the primitive's frame) holds
//  - a sphere of radius `radius_top` (= radius_bottom) at its origin;
//  - a capsule along its +Y axis: the hull of the ball of radius_top at +height/2 and the ball of
//    radius_bottom at -height/2 (height > 0; the library's ball b on top, a at the bottom);
//  - a box of full extents `size` along its x y z axes, centred at its origin.
// A capsule whose balls coincide, or one of whose balls holds the other, is that larger ball: a
// sphere. `axis` is the node's +Y axis turned by `rotation` (a capsule: from a towards b).
struct ProxyPlacement {
    ProxyKind kind = ProxyKind::sphere;
    Vec3 translation = Vec3::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    Vec3 axis = Vec3::UnitY();
    double radius_top = 0, radius_bottom = 0, height = 0;
    Vec3 size = Vec3::Zero();
};
ProxyPlacement proxy_placement(const Proxy& p);

struct ProxyStats {
    // percent of the surface's bounding-box diagonal, as evaluate.h measures a skeleton
    double hd_surface_to_proxies = 0, mean_surface_to_proxies = 0;
    double hd_proxies_to_surface = 0, mean_proxies_to_surface = 0;
    double hd_two_sided = 0;
    // proven bound of how far any point of a primitive lies outside the shape, and how far the
    // skeleton's own balls and edges reach outside at least (measured at points of them; inscribed:
    // the first is at most the second)
    double outside_bound = 0, skeleton_outside = 0;  // percent of the diagonal
    // Monte Carlo over the primitives' bounding box: volume of their union, and of its part
    // outside the shape (winding-number inside test); internal units cubed
    double union_volume = 0, outside_volume = 0;
    // conservative: the most any primitive was grown to contain its surface cells (percent of the
    // diagonal); inscribed: the most any candidate was shrunk
    double radius_change = 0;
    size_t candidates = 0;             // primitives chosen from
    size_t surface_cells = 0;          // triangles the surface was cut into
    double diagonal = 0;               // internal units
    double time_s = 0;
    // conservative: the choice's objective, the sum of the chosen candidates' volumes outside the
    // shape (on the choice's voxels; overlaps counted once per primitive), and the cover solver's
    // lower bound on it over the same candidates (internal units cubed, like the volumes above)
    double outside_objective = 0, outside_lower_bound = 0;
};

struct ProxyResult {
    std::vector<Proxy> proxies;        // internal units
    ProxyStats stats;
};

// ---- the steps (internal units) ----

// The surface as small triangles (surface_cells.cpp): corner points and, per cell, its three
// corners. Each mesh triangle is cut into n x n similar triangles, n from its longest edge and a
// spacing that gives about `target` corners over the whole mesh.
struct SurfaceCells {
    std::vector<Vec3> points;
    std::vector<Tri> cells;
};
SurfaceCells surface_cells(const Mesh& mesh, size_t target);

// The candidates (proxy_candidates.cpp): a sphere per ball; with capsules, a capsule per edge and
// per pair of balls joined by a path of edges (the nearest few along the paths from each ball).
std::vector<Proxy> proxy_candidates(const Skeleton& skeleton, ProxyShapes shapes);

// A bound of the farthest any point of p lies outside the shape (0: all inside): every point of
// p lies in a ball of the segment's interpolation, and a ball whose centre is at depth D sticks
// out by at most r - D; that is bounded between samples along the segment by its Lipschitz slope.
// A bound at most `enough` is not refined further (the answer is then some value <= enough).
double outside_bound(const Proxy& p, const ShapeQueries& shape, double enough = 0);

// How far p reaches outside the shape at least: the largest distance outside the shape over points
// of p (Fibonacci directions on a sphere's ball; on a capsule, on the spheres interpolated strictly
// between its balls, which are measured as spheres of their own). The true excess is never below it.
double outside_measured(const Proxy& p, const ShapeQueries& shape);

// p with both radii (a box: its half-lengths) reduced by `by` (at least 0); a negative `by` grows
// it. Every signed distance outside p grows by at least `by` (a sphere or capsule: exactly, while
// the radii stay positive), so growing by the largest signed distance of some points holds them.
Proxy shrunk(const Proxy& p, double by);

// The choice (choose_proxies.cpp): cost[c * points + i] is candidate c's error at point i.
// Minimises the largest error over the points where each point takes its best chosen candidate
// (then the sum of squares), with at most `count` candidates. No candidate is added once the
// largest error is within `tolerance` of what all candidates together reach, nor one that lowers
// neither by `min_gain` (a fraction); a chosen one is removed when the largest error stays within
// that reach (or as it was) and the sum grows by less than `min_gain` without it.
// Deterministic: ties go to the lower index.
std::vector<uint32_t> choose_proxies(const std::vector<float>& cost, size_t candidates, size_t points,
                                     size_t count, double tolerance, double min_gain, int threads);

// ---- conservative: the choice that hugs the shape ----

// The shape's inside at voxel centres origin + (i + 1/2, j + 1/2, k + 1/2) step over the mesh's
// box (inside_grid.cpp), about `voxels` of them; beyond the lattice is outside.
struct InsideGrid {
    Vec3 origin = Vec3::Zero();
    double step = 1;
    long n[3] = {0, 0, 0};
    std::vector<uint8_t> inside;  // x fastest
    Vec3 center(long i, long j, long k) const {
        return origin + step * Vec3(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
    }
    bool inside_at(long i, long j, long k) const;
};
Status inside_grid(const Mesh& mesh, const ShapeQueries& shape, size_t voxels, int threads, const Monitor& monitor,
                   InsideGrid& out);
// The primitive's axis-aligned bounding box (lower, upper corner).
std::pair<Vec3, Vec3> proxy_box(const Proxy& p);
// For each offset (ascending, >= 0): the volume of the voxels outside the shape whose centre lies
// within that distance of p (in p grown by it).
std::vector<double> outside_volumes(const Proxy& p, const std::vector<double>& offsets, const InsideGrid& grid);

// The candidates (hug_candidates.cpp): the offsets every skeleton primitive is grown by, and
// boxes fitted to groups of the points.
const std::vector<double>& hug_offsets();
// A tight box around points[indices]: in the frame of their principal axes or in the axes' own
// frame, whichever box is smaller.
Proxy fit_box(const std::vector<Vec3>& points, const std::vector<uint32_t>& indices);
// A capsule of equal radii around points[indices]: along their principal axis, the segment inset
// by the radius at both ends, the radius the least that holds them all (a sphere when they
// project to one point).
Proxy fit_capsule(const std::vector<Vec3>& points, const std::vector<uint32_t>& indices);
// Groups of points for boxes: the nodes of a tree that cuts each group in two where the two
// children's boxes have the least total volume, down to groups of min_size points.
std::vector<std::vector<uint32_t>> point_groups(const std::vector<Vec3>& points, size_t min_size);

struct HugChoice {
    std::vector<Proxy> chosen;          // grown by their offsets
    double objective = 0, lower_bound = 0;
    size_t candidates = 0;
};
// At most opt.count candidates that together hold every one of `points`, of least total volume
// outside the shape (hug_choice.cpp).
Status hug_choice(const Mesh& mesh, const ShapeQueries& shape, const Skeleton& skeleton, const std::vector<Vec3>& points,
                  const ProxyOptions& opt, int threads, const Monitor& monitor, HugChoice& out);

// Monte Carlo volumes (proxy_stats.cpp): `samples` seeded uniform points in the primitives' bounding
// box; the volume of their union, and of its part outside the shape (winding-number inside test).
// False when `monitor` said stop (progress reported as `stage`).
bool union_volumes(const std::vector<Proxy>& proxies, const ShapeQueries& shape, size_t samples, uint64_t seed,
                   int threads, const Monitor& monitor, const char* stage, double& union_volume,
                   double& outside_volume);
// The stats (proxy_stats.cpp) of `proxies` against the mesh.
Status proxy_stats(const Mesh& mesh, const std::vector<Proxy>& proxies, const ShapeQueries& shape,
                   const ProxyOptions& opt, const Monitor& monitor, ProxyStats& out);

// The whole step (proxies.cpp) on a triangle mesh in internal units with its queries (built here
// when null) and a skeleton of that shape.
Status make_proxies(const Mesh& mesh, ShapeQueries shape, const Skeleton& skeleton, const ProxyOptions& opt,
                    const Monitor& monitor, ProxyResult& out);

}  // namespace ca
