// point_cloud.cpp: candidates of an oriented point cloud: the Voronoi vertices on the inner side of
// their samples' normals, with the isolated ones (outliers) dropped.
#include "candidates_internal.h"

#include "kdtree.h"
#include "sampling.h"

namespace ca {
namespace cand {

namespace {

// Oriented point clouds: drop isolated candidates (paper: among the 100 nearest candidates, fewer
// than 20 within 0.02 means outlier).
std::vector<Ball> cluster_filter(const std::vector<Ball>& balls) {
    const size_t k = 100, min_close = 20;
    const double radius = 0.02;
    if (balls.size() <= k) return balls;
    std::vector<Vec3> centers(balls.size());
    for (size_t i = 0; i < balls.size(); ++i) centers[i] = balls[i].center;
    PointTree tree(centers);
    std::vector<Ball> out;
    std::vector<size_t> idx(k);
    std::vector<double> d2(k);
    for (const Ball& b : balls) {
        const size_t found = tree.nearest(b.center, k, idx.data(), d2.data());
        size_t close = 0;
        for (size_t i = 0; i < found; ++i) close += d2[i] <= radius * radius;
        if (close >= min_close) out.push_back(b);
    }
    return out;
}

}  // namespace


Status point_cloud_candidates(const CandidateOptions& opt, const Monitor& monitor, int threads, CandidateSet& out) {
    const std::vector<Vec3>& pts = out.surface.mesh.vertices;
    const std::vector<Vec3>& nrm = out.surface.normals;
    for (uint32_t i : random_subset(pts.size(), opt.cover_samples, stream_seed(opt.seed, 1)))
        out.cover_samples.push_back(pts[i]);
    std::vector<uint32_t> unique = remove_near_duplicates(pts, kDuplicateTolerance);
    std::vector<Vec3> upts(unique.size()), unrm(unique.size());
    for (size_t i = 0; i < unique.size(); ++i) { upts[i] = pts[unique[i]]; unrm[i] = nrm[unique[i]]; }
    out.dense_samples = upts;
    std::vector<Ball> balls;
    std::vector<Tet> tets_unused;
    Status st = voronoi_vertices(upts, threads, monitor,
        [&](const std::vector<uint32_t>& ids, const std::vector<Ball>& raw, const std::vector<Tet>& tets,
            std::vector<uint8_t>& keep) {
            for (size_t k = 0; k < ids.size(); ++k) {
                const Vec3& c = raw[ids[k]].center;
                bool inner = true;
                for (uint32_t v : tets[ids[k]]) inner = inner && (upts[v] - c).dot(unrm[v]) > 0;
                keep[k] = inner;
            }
            return Status::success();
        }, balls, tets_unused);
    if (!st.ok()) return st;
    out.balls = cluster_filter(balls);
    return Status::success();
}


}  // namespace cand
}  // namespace ca
