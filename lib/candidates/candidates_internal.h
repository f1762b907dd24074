// candidates_internal.h: what the candidate generators share (candidates.cpp drives them); not part
// of the library's interface.
#pragma once
#include <atomic>
#include "candidates.h"

#include "distance.h"
#include "kdtree.h"
#include "parallel.h"
#include "winding.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace ca {
namespace cand {

// Independent streams for the different random choices of one seed.
inline uint64_t stream_seed(uint64_t seed, uint64_t stream) { return seed * 0x9E3779B97F4A7C15ull + stream * 0xD1B54A32D192ED03ull + stream; }

constexpr double kDuplicateTolerance = 1e-7;   // internal units (1e-7 of the longest bbox side)


// The surface structures (the shape queries: winding number, distance, hole caps) are built
// beside the sampling and the Delaunay step; `structures.wait()` gives them.
struct SurfaceStructures {
    ShapeQueries queries;   // winding and distance on the second thread, cap_distance on this one
    // The build stops early on a cancel, the time limit or `abandon` (the step failed meanwhile);
    // then `stopped` is set and the structures must not be used.
    std::atomic<bool> abandon{false};
    bool stopped = false;
};
// After structures.wait(): the stop status if the build stopped early, else success.
inline Status structures_status(const SurfaceStructures& built, const Monitor& monitor) {
    return built.stopped ? monitor.stop_status("surface structures") : Status::success();
}

// fallback_balls.cpp: the cover samples no candidate reaches within kFallbackReach: those that no
// ball's reach covers by the coverage rule (coverage.h), asked per sample of a tree of the ball
// centres, which stops at the first ball that reaches. None when an input is not finite (as
// build_coverage refuses it) or `monitor` stopped the queries (the caller tests monitor.stopped()).
std::vector<size_t> unreached_samples(const CandidateSet& set, int threads, const Monitor& monitor);

// surface_balls.cpp: a surface ball under every cover sample no candidate reaches within
// kFallbackReach (appended; sets set.surface_balls), radius from the local thickness measured with
// `distance` (null, or a flat mesh: radius 0). Returns how many; 0 when `monitor` stopped it.
size_t add_surface_balls(CandidateSet& set, const MeshDistance* distance, int threads, const Monitor& monitor);

// voronoi.cpp: circumcentres of the Delaunay tetrahedra of pts, de-duplicated, within the (slightly
// grown) bounding box. `accept(unique, raw, raw_tets, keep)` sees the candidate centres (raw, one
// per tetrahedron in raw_tets) and fills keep[k] for raw[unique[k]]. The tetrahedra are left in `tets`.
using AcceptVertices = std::function<Status(const std::vector<uint32_t>& unique, const std::vector<Ball>& raw,
                                            const std::vector<Tet>& raw_tets, std::vector<uint8_t>& keep)>;
Status voronoi_vertices(const std::vector<Vec3>& pts, int threads, const Monitor& monitor, const AcceptVertices& accept,
                        std::vector<Ball>& balls, std::vector<Tet>& tets);
// voronoi.cpp: the Voronoi vertices of pts whose centre `inside` holds, and the inner flag of every
// tetrahedron left in `tets` (its circumcentre inside; flat or far ones outer), which the medial
// connection route reuses instead of a second Delaunay. Every circumcentre is tested, on `threads`
// threads; `ready` runs before the first test (a mesh's waits for its winding number).
Status inner_voronoi_vertices(const std::vector<Vec3>& pts, int threads, const Monitor& monitor,
                              const std::function<Status()>& ready, const std::function<bool(const Vec3&)>& inside,
                              std::vector<Ball>& balls, std::vector<Tet>& tets, std::vector<uint8_t>& inner);
// voronoi.cpp: the inner Voronoi vertices of dense surface samples of a mesh.
Status mesh_voronoi_candidates(const CandidateOptions& opt, const Monitor& monitor, Beside& structures,
                               const SurfaceStructures& built, int threads, CandidateSet& out);
// random_candidates.cpp: up to opt.random_candidates uniform points of the bounding box of pts
// that are inside (seeded by opt.seed); false if cancelled.
bool random_inner_points(const std::vector<Vec3>& pts, const CandidateOptions& opt,
                         const std::function<bool(const Vec3&)>& inside, int threads, const Monitor& monitor,
                         std::vector<Vec3>& inner);
// random_candidates.cpp: random inner points of the bounding box, with their distances to the surface.
Status mesh_random_candidates(const CandidateOptions& opt, const Monitor& monitor, Beside& structures,
                              const SurfaceStructures& built, int threads, CandidateSet& out);
// cloud_outliers.cpp: marks the outliers of de-duplicated cloud points (outlier[i] = 1) and
// returns their count (0 on clean clouds); the neighbourhoods are searched on `threads` threads.
size_t find_cloud_outliers(const std::vector<Vec3>& pts, std::vector<uint8_t>& outlier, int threads = 1);
// cloud_local_planes.cpp: the plane of each cloud point's 16 nearest neighbours, oriented by its
// unit outward normal, and whether the cloud is noisy (the points lie off their planes by more
// than the curvature of a clean cloud explains).
class LocalPlanes {
public:
    LocalPlanes(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, int threads = 1);
    bool noisy() const;
    double noise_ratio() const { return noise_ratio_; }   // median off-plane distance / median d16
    double scale_growth() const { return scale_growth_; } // median off-plane distance, 16 over 8 neighbours
    double noise() const { return noise_; }               // noise deviation estimate: 1.4826 x median off-plane distance
    double height(const Vec3& q) const;   // signed distance of q above the plane of its nearest point
    Vec3 project(const Vec3& q) const;    // q moved onto the plane of its nearest point
private:
    size_t nearest(const Vec3& q) const;
    std::vector<Vec3> mean_, normal_;
    PointTree tree_;
    double noise_ratio_ = 0, scale_growth_ = 0, noise_ = 0;
};
// Drops the balls whose centre is above the local plane (height > 0); returns how many.
size_t drop_outside_local_planes(const LocalPlanes& planes, int threads, const Monitor& monitor, std::vector<Ball>& balls);
// Drops the balls that are not within reach; returns how many (0 when `monitor` stopped it: the
// caller tests monitor.stopped()).
size_t drop_beyond_reach(const CloudReach& reach, int threads, const Monitor& monitor, std::vector<Ball>& balls);
// point_cloud.cpp: the candidates (Voronoi or random) and fallback balls of an oriented point cloud.
Status point_cloud_candidates(const CandidateOptions& opt, const Monitor& monitor, int threads, CandidateSet& out);

}  // namespace cand
}  // namespace ca
