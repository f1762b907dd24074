// point_cloud.cpp: candidates of an oriented point cloud. The points (de-duplicated, outliers
// dropped by cloud_outliers.cpp) get their winding number (point_winding.h); its sign fixes the
// orientation (normals pointing inward are flipped); candidates are the Voronoi vertices with winding number > 1/2 (isolated ones dropped,
// as in the paper), or random points of the bounding box with winding number > 1/2 and their
// distance to the nearest point as radius; then fallback balls make every sample coverable.
#include "candidates_internal.h"

#include "kdtree.h"
#include "point_winding.h"
#include "rng.h"
#include "sampling.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace ca {
namespace cand {

namespace {

// Oriented point clouds: drop isolated candidates (paper: among the 100 nearest candidates, fewer
// than 20 within 0.02 means outlier). The 20 nearest are among the 100, so this is: fewer than 20
// candidates within 0.02 at all, counted by a search that stops at the 20th; the queries are split
// across `threads`.
std::vector<Ball> cluster_filter(const std::vector<Ball>& balls, int threads) {
    const size_t k = 100, min_close = 20;
    const double radius = 0.02;
    if (balls.size() <= k) return balls;
    std::vector<Vec3> centers(balls.size());
    for (size_t i = 0; i < balls.size(); ++i) centers[i] = balls[i].center;
    const PointTree tree(centers);
    std::vector<uint8_t> keep(balls.size(), 0);
    const size_t workers = size_t(std::max(1, threads));
    const size_t chunk = (balls.size() + workers - 1) / workers;
    run_workers(workers, [&](size_t w) {
        for (size_t i = w * chunk; i < std::min(balls.size(), (w + 1) * chunk); ++i)
            keep[i] = tree.count_within_squared(centers[i], radius * radius, min_close) >= min_close;
    });
    std::vector<Ball> out;
    for (size_t i = 0; i < balls.size(); ++i)
        if (keep[i]) out.push_back(balls[i]);
    return out;
}

// Depth (internal units) at which the orientation probes sit below and above the points.
constexpr double kOrientationProbe = 0.01;
// Above this fraction of inconsistent probes the orientation is not trusted (the cloud is refused).
constexpr double kMaxInconsistent = 0.3;
// Noisy clouds: the winding number is trusted only this many noise deviations below the surface
// (the fallback balls of samples with no inside point just below them start deeper).
constexpr double kNoiseBand = 3;

// The probe depth at point i: kOrientationProbe, but at most half the local thickness (how far
// behind p_i, along -n_i, the nearest of its 16 neighbours lies whose normal points the other
// way: the far side of a thin part), so that the inner probe does not leave the part through
// its far side (noise moving the point inward makes that likelier); not below a quarter of
// kOrientationProbe, nearer to which the point's own dipole would decide the jump.
double probe_depth(const PointTree& tree, const std::vector<Vec3>& pts, const std::vector<Vec3>& nrm, size_t i) {
    size_t idx[16];
    double d2[16];
    const size_t found = tree.nearest(pts[i], 16, idx, d2);
    double depth = kOrientationProbe;
    for (size_t j = 0; j < found; ++j) {
        const double behind = -(pts[idx[j]] - pts[i]).dot(nrm[i]);
        if (behind > 0 && nrm[idx[j]].dot(nrm[i]) < -0.5)
            depth = std::min(depth, std::max(0.5 * behind, 0.25 * kOrientationProbe));
    }
    return depth;
}

// Winding numbers at up to 500 points pushed a little along their normals (probe_depth), to
// either side. `mean`: the mean over both sides, about (1 + 0) / 2 for outward normals and
// (0 - 1) / 2 for inward ones (reversing every normal negates the winding number).
// `inconsistent`: the fraction of points where w jumps by less than 1/2 across the surface (1 for
// consistently oriented normals, on closed and open clouds alike).
struct OrientationProbes {
    double mean = 0, inconsistent = 0;
};
OrientationProbes probe_orientation(const PointCloudWinding& w, const std::vector<Vec3>& pts,
                                    const std::vector<Vec3>& nrm) {
    const size_t step = std::max<size_t>(1, pts.size() / 500);
    const PointTree tree(pts);
    OrientationProbes out;
    size_t n = 0;
    for (size_t i = 0; i < pts.size(); i += step, ++n) {
        const double depth = probe_depth(tree, pts, nrm, i);
        const double in = w(pts[i] - depth * nrm[i]), outside = w(pts[i] + depth * nrm[i]);
        out.mean += 0.5 * (in + outside);
        out.inconsistent += std::abs(in - outside) < 0.5;
    }
    if (n) out.mean /= double(n), out.inconsistent /= double(n);
    return out;
}

// Drops the outliers of the de-duplicated points upts (and their normals unrm); `kept` gets the
// input points that are not outliers nor duplicates of one (only when there are outliers).
void drop_outliers(const std::vector<Vec3>& pts, std::vector<Vec3>& upts, std::vector<Vec3>& unrm,
                   std::vector<uint32_t>& kept, size_t& count, int threads) {
    std::vector<uint8_t> outlier;
    count = find_cloud_outliers(upts, outlier, threads);
    if (count == 0) return;
    const PointTree tree(upts);   // an input point is dropped with the unique point it merged into
    for (size_t i = 0; i < pts.size(); ++i) {
        size_t idx = 0;
        double d2 = 0;
        if (tree.nearest(pts[i], 1, &idx, &d2) == 1 && !outlier[idx]) kept.push_back(uint32_t(i));
    }
    size_t n = 0;
    for (size_t i = 0; i < upts.size(); ++i)
        if (!outlier[i]) upts[n] = upts[i], unrm[n] = unrm[i], ++n;
    upts.resize(n);
    unrm.resize(n);
}

// Also the inner flags of every tetrahedron (inner_voronoi_vertices, by the cloud's winding number).
Status voronoi_cloud_candidates(const std::vector<Vec3>& upts, const PointCloudWinding& winding, int threads,
                                const Monitor& monitor, std::vector<Ball>& out, std::vector<Tet>& tets,
                                std::vector<uint8_t>& inner) {
    std::vector<Ball> balls;
    const Status st = inner_voronoi_vertices(
        upts, threads, monitor, [] { return Status::success(); },
        [&](const Vec3& c) { return winding.inside(c); }, balls, tets, inner);
    if (!st.ok()) return st;
    out = cluster_filter(balls, threads);
    return Status::success();
}

Status random_cloud_candidates(const CandidateOptions& opt, const std::vector<Vec3>& upts,
                               const PointCloudWinding& winding, int threads, const Monitor& monitor,
                               std::vector<Ball>& out) {
    std::vector<Vec3> inner;
    if (!random_inner_points(upts, opt, [&](const Vec3& p) { return winding.inside(p); }, threads, monitor, inner))
        return monitor.stop_status("inside");
    const PointTree tree(upts);
    out.resize(inner.size());
    if (!parallel_for(inner.size(), threads, 4096, monitor, "candidates", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) out[i] = {inner[i], tree.distance(inner[i])};
        }))
        return monitor.stop_status("candidates");
    out.erase(std::remove_if(out.begin(), out.end(), [](const Ball& x) { return !(x.radius > 0); }), out.end());
    return Status::success();
}

}  // namespace


Status point_cloud_candidates(const CandidateOptions& opt, const Monitor& monitor, int threads, CandidateSet& out) {
    const std::vector<Vec3>& pts = out.surface.mesh.vertices;
    std::vector<Vec3>& nrm = out.surface.normals;
    std::vector<uint32_t> unique = remove_near_duplicates(pts, kDuplicateTolerance);
    std::vector<Vec3> upts(unique.size()), unrm(unique.size());
    for (size_t i = 0; i < unique.size(); ++i) { upts[i] = pts[unique[i]]; unrm[i] = nrm[unique[i]]; }
    // the points cover samples are drawn from: all of them unless outliers are dropped
    std::vector<uint32_t> kept;
    if (opt.filter_outliers) drop_outliers(pts, upts, unrm, kept, out.report.outliers, threads);
    if (!monitor.report("inside", 0)) return monitor.stop_status("inside");
    auto winding = std::make_shared<PointCloudWinding>(upts, unrm, 2.0, threads);
    const OrientationProbes probes = probe_orientation(*winding, upts, unrm);
    out.report.orientation_inconsistent = probes.inconsistent;
    if (probes.inconsistent > kMaxInconsistent)
        return fail(Code::invalid_input,
                    "the point cloud's normals are not consistently oriented: the winding number jumps by less than "
                    "1/2 across the surface at " + std::to_string(int(std::lround(100 * probes.inconsistent))) +
                    "% of the probe points" +
                    (out.surface.normals_source == NormalSource::given
                         ? std::string(" (pass the normals as unoriented to re-orient them, or omit them)")
                         : std::string(" even after orientation (too sparse or too noisy for its thin parts?)")));
    if (probes.mean < 0) {
        // inward normals: flip them all (the winding number changes sign)
        for (Vec3& n : nrm) n = -n;
        for (Vec3& n : unrm) n = -n;
        winding = std::make_shared<PointCloudWinding>(upts, unrm, 2.0, threads);
        out.surface.flipped = true;
    }
    // noisy clouds: cover the denoised surface (cloud_local_planes.cpp)
    const LocalPlanes planes(upts, unrm, threads);
    out.report.noise_ratio = planes.noise_ratio();
    out.noisy_cloud = planes.noisy();
    out.report.noise_scale_growth = planes.scale_growth();
    std::vector<Vec3> sample_normals;
    const size_t pool = out.report.outliers ? kept.size() : pts.size();
    for (uint32_t k : random_subset(pool, opt.cover_samples, stream_seed(opt.seed, 1))) {
        const uint32_t i = out.report.outliers ? kept[k] : k;
        out.cover_samples.push_back(planes.noisy() ? planes.project(pts[i]) : pts[i]);
        sample_normals.push_back(nrm[i]);
    }
    out.dense_samples = upts;
    Status st = opt.generator == Generator::voronoi
                    ? voronoi_cloud_candidates(upts, *winding, threads, monitor, out.balls, out.voronoi_tets, out.voronoi_inner)
                    : random_cloud_candidates(opt, upts, *winding, threads, monitor, out.balls);
    if (!st.ok()) return st;
    if (planes.noisy()) out.report.outside_local_plane = drop_outside_local_planes(planes, threads, monitor, out.balls);
    // no ball reaches outside far from every point (cloud_reach.cpp); the fallback balls below
    // cover what the dropped ones reached, grown only while they stay within reach
    auto reach = std::make_shared<const CloudReach>(upts, winding, threads, monitor);
    if (monitor.stopped()) return monitor.stop_status("candidates");
    out.report.beyond_reach = drop_beyond_reach(*reach, threads, monitor, out.balls);
    if (monitor.stopped()) return monitor.stop_status("candidates");
    CloudNoise noise;
    if (planes.noisy()) {
        noise.depth = kNoiseBand * planes.noise();
        noise.below_surface = [&planes](const Vec3& c) { return planes.height(c) <= 0; };
    }
    noise.untrusted_signs = out.surface.normals_source != NormalSource::given;
    noise.within_reach = [&reach](const Ball& b) { return reach->within(b); };
    out.report.fallback_balls = add_cloud_fallback_balls(out, *winding, sample_normals, noise, threads, monitor);
    if (monitor.stopped()) return monitor.stop_status("fallback balls");
    if (!opt.volumetric_only) {
        add_surface_balls(out, nullptr, threads, monitor);
        if (monitor.stopped()) return monitor.stop_status("surface balls");
    }
    out.queries.cloud_winding = std::move(winding);
    out.queries.cloud_reach = std::move(reach);
    return Status::success();
}


}  // namespace cand
}  // namespace ca
