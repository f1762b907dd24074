// candidates.h: step 1 of the pipeline. Surface samples S to cover, and candidate balls P:
// inside Voronoi vertices of |C| surface samples (radius = circumradius), random interior points
// (radius = exact distance to the mesh), or for oriented point clouds the Voronoi vertices on the
// inner side of all four generating points' normals, with the outlier filter of the paper; then
// fallback balls under samples nothing reaches, and surface balls on what has no inside.
// For meshes it also keeps what the connection step needs: denser surface samples for the
// power diagram, and the Delaunay tetrahedra of the Voronoi samples with their inner flags
// (the inner Voronoi diagram = medial mesh of the medial-axis route).
#pragma once
#include "common.h"
#include "delaunay.h"
#include "hole_caps.h"
#include "shape_queries.h"
#include "surface.h"

#include <atomic>
#include <functional>
#include <memory>

namespace ca {

enum class Generator : int32_t { voronoi = 0, random = 1 };

struct CandidateOptions {
    Generator generator = Generator::voronoi;
    uint32_t cover_samples = 1500;
    uint32_t voronoi_samples = 4000;
    uint32_t random_candidates = 10000;
    // Surface samples for the power-diagram connection (meshes; 0 = reuse the Voronoi samples).
    // Point clouds always use their own (de-duplicated) points.
    uint32_t connect_samples = 10000;
    uint64_t seed = 1;
    int32_t threads = 0;    // 0 = all cores
    // Point clouds: drop outlier points (cloud_outliers.cpp) before building anything on them.
    bool filter_outliers = true;
    // Only inner (volumetric) balls: no surface balls for samples nothing inner reaches
    // (surface_balls.cpp), which then stay uncoverable as the paper's method has them.
    bool volumetric_only = false;
};

// Everything later steps need, in internal (unit-cube) units.
class PointTree;

// Point clouds (cloud_reach.cpp): whether a ball stays within reach of the cloud: every point of
// its sphere farther than reach() from the nearest cloud point is inside by the winding number and
// enclosed by the cloud (rays from it meet the cloud). reach() is max(kCloudReach, the median
// 8th-neighbour distance). The candidate step drops the candidates that are not and bounds the
// fallback balls by it; the connection step keeps no element whose interpolated balls are not.
class CloudReach {
public:
    // Stopped by `monitor` (tested every few thousand points), the grid is incomplete: the caller
    // tests monitor.stopped() and drops the object.
    CloudReach(std::vector<Vec3> pts, std::shared_ptr<const PointCloudWinding> winding, int threads = 1,
               const Monitor& monitor = Monitor{});
    ~CloudReach();
    bool within(const Ball& b) const;   // a ball of radius 0: its centre, as a point of a sphere
    double reach() const { return reach_; }
    // At most 1/16 of the rays from q leave the grown bounding box without meeting a wall.
    bool enclosed(const Vec3& q) const;
private:
    std::vector<Vec3> pts_;
    std::unique_ptr<PointTree> tree_;
    std::shared_ptr<const PointCloudWinding> winding_;
    std::vector<Vec3> directions_, rays_;
    double reach_ = 0;
    // the wall grid: voxels of side cell_ from lo_, 1 where a cloud point is within the wall radius
    Vec3 lo_ = Vec3::Zero();
    double cell_ = 1;
    size_t dims_[3] = {0, 0, 0};
    std::vector<uint8_t> walls_;   // per voxel: wall (within the wall radius), near / maybe (all / part within the reach)
    // far probes' verdicts (0 not yet known, 1 inside and enclosed, 2 not) per cell of side
    // side_cell_ from lo_: a cache of a pure function, filled by whichever thread asks first
    bool far_point_inside(const Vec3& q) const;
    bool point_within(const Vec3& q) const;   // within the reach, or inside and enclosed
    double side_cell_ = 1;
    size_t side_dims_[3] = {0, 0, 0};
    std::unique_ptr<std::atomic<uint8_t>[]> verdicts_;
};

// What the candidate step did, filled as it goes: counts and times for the caller's log, the
// C ABI's getters and the tests. Kept apart from the data the later steps use.
struct CandidateReport {
    size_t outliers = 0;                  // point clouds: points dropped as outliers (cloud_outliers.cpp)
    size_t beyond_reach = 0;              // point clouds: candidates dropped as reaching outside the cloud (cloud_reach.cpp)
    size_t outside_local_plane = 0;       // point clouds: candidates dropped outside the local surface (cloud_local_planes.cpp)
    double noise_ratio = 0;               // point clouds: median off-plane distance / spacing (cloud_local_planes.cpp)
    double noise_scale_growth = 0;        // point clouds: the same over 16 and 8 neighbours (cloud_local_planes.cpp)
    double orientation_inconsistent = 0;  // point clouds: fraction of orientation probes failing (point_cloud.cpp)
    size_t fallback_balls = 0;            // balls added by add_fallback_balls (after the generator's)
    // Meshes: the Delaunay step of the Voronoi generator failed (Qhull could not build it even
    // with joggle, e.g. on a nearly flat mesh); the candidates are the fallback and surface balls.
    bool delaunay_failed = false;
    size_t hole_clamped = 0;              // radii clamped by clamp_to_hole_caps (open meshes)
    double time_sampling_s = 0, time_candidates_s = 0;
};

struct CandidateSet {
    Surface surface;                      // empty mesh when built from caller arrays
    std::vector<Vec3> cover_samples;      // S
    std::vector<Vec3> dense_samples;      // the Voronoi samples C (or the points of a cloud)
    std::vector<Vec3> connect_samples;    // power-diagram samples (empty: use dense_samples)
    // Voronoi generator (mesh or point cloud): the Delaunay tetrahedra of dense_samples and, per
    // tetrahedron, whether its circumcentre is inside the shape (winding number > 1/2; flat ones outer).
    // Empty otherwise (the medial-axis route then builds them itself).
    std::vector<Tet> voronoi_tets;
    std::vector<uint8_t> voronoi_inner;
    // The inside test, distances, hole caps or cloud reach of the surface (shape_queries.h), built
    // once by generate_candidates and only read after it; none for caller arrays. Whoever changes
    // surface.mesh afterwards must build them again.
    ShapeQueries queries;
    // point clouds: judged noisy (cloud_local_planes.cpp: the report's noise_ratio and
    // noise_scale_growth); the connection step then takes the power route
    bool noisy_cloud = false;
    std::vector<Ball> balls;              // P, undilated medial radii
    // of which surface balls (surface_balls.cpp): the last ones, on open sheets and thin parts
    // that no inner ball reaches
    size_t surface_balls = 0;
    CandidateReport report;               // what the step did (counts, times); no later step reads it
};

Status generate_candidates(Surface surface, const CandidateOptions& opt, const Monitor& monitor,
                           CandidateSet& out);

// Every cover sample that no candidate reaches within kFallbackReach gets a small inner ball
// under it (fallback_balls.cpp), so a cover exists for every offset delta >= kFallbackReach.
constexpr double kFallbackReach = 0.005;   // unit-cube units (0.5 % of the longest bbox side)
// Point clouds: no candidate's sphere reaches outside farther than this from every cloud point
// (or than the cloud's median 8th-neighbour distance, if larger; cloud_reach.cpp).
constexpr double kCloudReach = 0.03;   // unit-cube units (3 % of the longest bbox side)
// `caps` (optional): distances to the hole caps of an open mesh, which also bound the radius.
// `threads`: for the coverage queries (0 = all cores). When `monitor` says stop (tested in the
// coverage queries and every Monitor::kCheckEvery samples; its progress callback is not called)
// it returns early with part of the balls added: the caller tests monitor.stopped().
size_t add_fallback_balls(CandidateSet& set, const WindingNumber& winding, const MeshDistance& distance,
                          const MeshDistance* caps = nullptr, int threads = 0, const Monitor& monitor = Monitor{});

// Point clouds: the same balls, grown along the cover samples' unit outward normals
// (`normals[j]` for cover_samples[j]), inside by the cloud's winding number, radius = distance
// to the nearest point of dense_samples. `noise` (noisy clouds; default: clean): where no point
// just below a sample is inside, points down to noise.depth are tried, and a centre must also pass
// noise.below_surface. With noise.untrusted_signs (normals estimated or re-oriented) the side of
// each ball is the one rays through the cloud find enclosed (fallback_balls.cpp). Stops as
// add_fallback_balls does.
struct CloudNoise {
    double depth = 0;                                  // the inside test is unreliable above this depth
    std::function<bool(const Vec3&)> below_surface;    // null: no further test
    // The normals were estimated or re-oriented (not given and trusted): some signs are wrong, so
    // the side of each ball is chosen by rays through the cloud, not by the normal's sign alone.
    bool untrusted_signs = false;
    // Not noise but the same kind of bound: a ball stops growing where it would no longer pass
    // this (cloud_reach.cpp: its sphere stays within reach of the cloud); null: no such bound.
    std::function<bool(const Ball&)> within_reach;
};
size_t add_cloud_fallback_balls(CandidateSet& set, const PointCloudWinding& winding, const std::vector<Vec3>& normals,
                                const CloudNoise& noise = {}, int threads = 0, const Monitor& monitor = Monitor{});

// Open meshes (hole_caps.cpp): every candidate's radius is clamped to its distance to the hole
// caps (geometry/hole_caps.h: every closed boundary loop capped by a fan from its centroid), so no
// ball reaches out through a hole. Closed meshes are unchanged. False if cancelled.
bool clamp_to_hole_caps(CandidateSet& set, const MeshDistance& caps, int threads, const Monitor& monitor);

}  // namespace ca
