// random_candidates.cpp: random candidates: uniform points of the bounding box inside the mesh (by the
// winding number; the sampling loop is shared with point clouds), each with its distance to the surface as radius.
#include "candidates_internal.h"

#include "sampling.h"
#include "rng.h"

#include <algorithm>

namespace ca {
namespace cand {

bool random_inner_points(const std::vector<Vec3>& pts, const CandidateOptions& opt,
                         const std::function<bool(const Vec3&)>& inside, int threads, const Monitor& monitor,
                         std::vector<Vec3>& inner) {
    auto [lo, hi] = bounding_box(pts);
    const Vec3 extent = hi - lo;
    Rng rng(stream_seed(opt.seed, 3));
    const size_t want = opt.random_candidates;
    const size_t max_attempts = std::max<size_t>(want * 200, 100000);
    inner.clear();
    size_t attempts = 0;
    while (inner.size() < want && attempts < max_attempts) {
        const size_t batch = std::min<size_t>(std::max<size_t>(2 * (want - inner.size()), 4096), max_attempts - attempts);
        std::vector<Vec3> trial(batch);
        for (Vec3& p : trial) p = lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()).cwiseProduct(extent);
        attempts += batch;
        std::vector<uint8_t> in(batch, 0);
        if (!parallel_for(batch, threads, 8192, monitor, "inside", [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) in[i] = inside(trial[i]);
            }))
            return false;
        for (size_t i = 0; i < batch && inner.size() < want; ++i)
            if (in[i]) inner.push_back(trial[i]);
    }
    return true;
}

Status mesh_random_candidates(const CandidateOptions& opt, const Monitor& monitor, Beside& structures,
                              const SurfaceStructures& built, int threads, CandidateSet& out) {
    const Mesh& mesh = out.surface.mesh;
    structures.wait();
    if (const Status ss = structures_status(built, monitor); !ss.ok()) return ss;
    const WindingNumber& winding = *built.queries.winding;
    std::vector<Vec3> inner;
    if (!random_inner_points(mesh.vertices, opt, [&](const Vec3& p) { return winding.inside(p); }, threads, monitor,
                             inner))
        return monitor.stop_status("inside");
    const MeshDistance& distance = *built.queries.distance;
    out.balls.resize(inner.size());
    if (!parallel_for(inner.size(), threads, 4096, monitor, "candidates", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) out.balls[i] = {inner[i], distance.distance(inner[i])};
        }))
        return monitor.stop_status("candidates");
    out.balls.erase(std::remove_if(out.balls.begin(), out.balls.end(), [](const Ball& x) { return !(x.radius > 0); }),
                    out.balls.end());
    out.dense_samples = sample_surface(mesh, opt.voronoi_samples, stream_seed(opt.seed, 2));
    return Status::success();
}


}  // namespace cand
}  // namespace ca
