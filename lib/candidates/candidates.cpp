// candidates.cpp: surface samples and inner candidate balls (Voronoi, random, point cloud).
#include "candidates.h"

#include "delaunay.h"
#include "distance.h"
#include "kdtree.h"
#include "parallel.h"
#include "sampling.h"
#include "winding.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace ca {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Independent streams for the different random choices of one seed.
uint64_t stream_seed(uint64_t seed, uint64_t stream) { return seed * 0x9E3779B97F4A7C15ull + stream * 0xD1B54A32D192ED03ull + stream; }

constexpr double kDuplicateTolerance = 1e-7;   // internal units (1e-7 of the longest bbox side)

bool in_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
}

Status cancelled() { return fail(Code::cancelled, "cancelled"); }

// Circumcentres of the Delaunay tetrahedra of pts, de-duplicated, within the (slightly grown)
// bounding box; `accept(center, tet)` decides which are inner.
// `accept(unique, raw, raw_tets, keep)` sees the candidate centres (raw, one per tetrahedron
// in raw_tets) and fills keep[k] for raw[unique[k]]. The tetrahedra are left in `tets`.
template <class Accept>
Status voronoi_vertices(const std::vector<Vec3>& pts, int threads, const Monitor& monitor, Accept&& accept,
                        std::vector<Ball>& balls, std::vector<Tet>& tets) {
    if (!monitor.report("delaunay", 0)) return cancelled();
    Status st = delaunay_tetrahedra(pts, tets);
    if (!st.ok()) return st;
    if (!monitor.report("delaunay", 1)) return cancelled();
    auto [lo, hi] = bounding_box(pts);
    const double margin = 1e-3 * (hi - lo).maxCoeff();
    lo.array() -= margin;
    hi.array() += margin;
    std::vector<Ball> raw;
    std::vector<Tet> raw_tets;
    raw.reserve(tets.size());
    for (const Tet& t : tets) {
        Vec3 c;
        if (!circumcenter(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]], c) || !in_box(c, lo, hi)) continue;
        raw.push_back({c, (c - pts[t[0]]).norm()});
        raw_tets.push_back(t);
    }
    // A Voronoi ball is empty: its radius is the distance to the nearest sample. Near-flat
    // tetrahedra (joggled or co-spherical samples) can give circumradii larger than that, i.e.
    // balls that stick out of the shape; clamp them.
    PointTree sample_tree(pts);
    if (!parallel_for(raw.size(), threads, 8192, monitor, "delaunay", [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i) {
                size_t idx;
                double d2;
                if (sample_tree.nearest(raw[i].center, 1, &idx, &d2) == 1)
                    raw[i].radius = std::min(raw[i].radius, std::sqrt(d2));
            }
        }))
        return cancelled();
    std::vector<Vec3> centers(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) centers[i] = raw[i].center;
    // cospherical sample sets give the same Voronoi vertex several times
    std::vector<uint32_t> unique = remove_near_duplicates(centers, 1e-9);
    std::vector<uint8_t> keep(unique.size(), 0);
    st = accept(unique, raw, raw_tets, keep);
    if (!st.ok()) return st;
    for (size_t k = 0; k < unique.size(); ++k)
        if (keep[k]) balls.push_back(raw[unique[k]]);
    return Status::success();
}

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

// The surface structures (winding numbers, distances, hole caps) are built beside the sampling
// and the Delaunay step; `structures.wait()` gives them.
struct SurfaceStructures {
    std::shared_ptr<const WindingNumber> winding;
    std::shared_ptr<const MeshDistance> distance;
    std::unique_ptr<const MeshDistance> cap_distance;   // null when the mesh has no holes
};

Status mesh_voronoi_candidates(const CandidateOptions& opt, const Monitor& monitor, Beside& structures,
                               const SurfaceStructures& built, int threads, CandidateSet& out) {
    std::vector<Vec3> samples = sample_surface(out.surface.mesh, opt.voronoi_samples, stream_seed(opt.seed, 2));
    std::vector<Vec3> unique;
    for (uint32_t i : remove_near_duplicates(samples, kDuplicateTolerance)) unique.push_back(samples[i]);
    out.dense_samples = unique;
    // Every tetrahedron's circumcentre is tested (not only the de-duplicated candidates) so the
    // connection step gets the inner flags of the whole Voronoi diagram; the candidates keep
    // exactly the flags they had.
    std::vector<uint8_t> raw_inner;
    std::vector<Tet> raw_tets_kept;
    Status st = voronoi_vertices(unique, threads, monitor,
        [&](const std::vector<uint32_t>& ids, const std::vector<Ball>& raw, const std::vector<Tet>& raw_tets,
            std::vector<uint8_t>& keep) {
            raw_inner.assign(raw.size(), 0);
            structures.wait();
            const WindingNumber& winding = *built.winding;
            const bool done = parallel_for(raw.size(), threads, 8192, monitor, "inside", [&](size_t b, size_t e) {
                for (size_t k = b; k < e; ++k) raw_inner[k] = winding.inside(raw[k].center);
            });
            if (!done) return cancelled();
            for (size_t k = 0; k < ids.size(); ++k) keep[k] = raw_inner[ids[k]];
            raw_tets_kept = raw_tets;
            return Status::success();
        }, out.balls, out.voronoi_tets);
    if (!st.ok()) return st;
    // Tetrahedra without a usable circumcentre (flat, or far outside the box) are outer.
    out.voronoi_inner.assign(out.voronoi_tets.size(), 0);
    {
        size_t r = 0;
        for (size_t t = 0; t < out.voronoi_tets.size() && r < raw_tets_kept.size(); ++t)
            if (out.voronoi_tets[t] == raw_tets_kept[r]) out.voronoi_inner[t] = raw_inner[r++];
    }
    return Status::success();
}

Status mesh_random_candidates(const CandidateOptions& opt, const Monitor& monitor, Beside& structures,
                              const SurfaceStructures& built, int threads, CandidateSet& out) {
    const Mesh& mesh = out.surface.mesh;
    structures.wait();
    const WindingNumber& winding = *built.winding;
    auto [lo, hi] = bounding_box(mesh.vertices);
    const Vec3 extent = hi - lo;
    Rng rng(stream_seed(opt.seed, 3));
    const size_t want = opt.random_candidates;
    const size_t max_attempts = std::max<size_t>(want * 200, 100000);
    std::vector<Vec3> inner;
    size_t attempts = 0;
    while (inner.size() < want && attempts < max_attempts) {
        const size_t batch = std::min<size_t>(std::max<size_t>(2 * (want - inner.size()), 4096), max_attempts - attempts);
        std::vector<Vec3> pts(batch);
        for (Vec3& p : pts) p = lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()).cwiseProduct(extent);
        attempts += batch;
        std::vector<uint8_t> in(batch, 0);
        if (!parallel_for(batch, threads, 8192, monitor, "inside", [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) in[i] = winding.inside(pts[i]);
            }))
            return cancelled();
        for (size_t i = 0; i < batch && inner.size() < want; ++i)
            if (in[i]) inner.push_back(pts[i]);
    }
    const MeshDistance& distance = *built.distance;
    out.balls.resize(inner.size());
    if (!parallel_for(inner.size(), threads, 4096, monitor, "candidates", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) out.balls[i] = {inner[i], distance.distance(inner[i])};
        }))
        return cancelled();
    out.balls.erase(std::remove_if(out.balls.begin(), out.balls.end(), [](const Ball& x) { return !(x.radius > 0); }),
                    out.balls.end());
    out.dense_samples = sample_surface(mesh, opt.voronoi_samples, stream_seed(opt.seed, 2));
    return Status::success();
}

}  // namespace

Status generate_candidates(Surface surface, const CandidateOptions& opt, const Monitor& monitor, CandidateSet& out) {
    out = CandidateSet{};
    out.surface = std::move(surface);
    if (opt.cover_samples == 0 && !out.surface.point_cloud)
        return fail(Code::invalid_argument, "cover_samples must be at least 1");
    if (opt.generator == Generator::voronoi && opt.voronoi_samples < 5 && !out.surface.point_cloud)
        return fail(Code::invalid_argument, "voronoi_samples must be at least 5");
    if (opt.generator == Generator::random && opt.random_candidates == 0)
        return fail(Code::invalid_argument, "random_candidates must be at least 1");
    if (out.surface.point_cloud && opt.generator != Generator::voronoi)
        return fail(Code::invalid_argument, "point clouds support the Voronoi candidate generator only");
    const int threads = resolve_threads(opt.threads);

    auto t0 = Clock::now();
    if (!monitor.report("sampling", 0)) return cancelled();
    Status st;
    if (out.surface.point_cloud) {
        out.time_sampling_s = seconds_since(t0);
        st = point_cloud_candidates(opt, monitor, threads, out);
    } else {
        // The surface structures are built on a second thread while this one samples and runs
        // the Delaunay step (the same structures either way); they only read the mesh.
        SurfaceStructures built;
        const Mesh& mesh = out.surface.mesh;
        Beside structures(
            [&built, &mesh] {
                built.winding = std::make_shared<const WindingNumber>(mesh);
                built.distance = std::make_shared<const MeshDistance>(mesh);
                // open meshes: no ball reaches out through a hole (hole_caps.cpp)
                const Mesh caps = hole_caps(mesh);
                if (!caps.triangles.empty()) built.cap_distance = std::make_unique<const MeshDistance>(caps);
            },
            threads > 1);
        out.cover_samples = sample_surface(mesh, opt.cover_samples, stream_seed(opt.seed, 1));
        out.time_sampling_s = seconds_since(t0);
        st = opt.generator == Generator::voronoi ? mesh_voronoi_candidates(opt, monitor, structures, built, threads, out)
                                                 : mesh_random_candidates(opt, monitor, structures, built, threads, out);
        structures.wait();
        const MeshDistance* cap_distance = built.cap_distance.get();
        if (st.ok() && cap_distance && !clamp_to_hole_caps(out, *cap_distance, threads, monitor)) st = cancelled();
        if (st.ok()) {
            out.fallback_balls = add_fallback_balls(out, *built.winding, *built.distance, cap_distance, threads);
            out.winding = std::move(built.winding);
            out.distance = std::move(built.distance);
        }
        if (st.ok() && opt.connect_samples > 0)
            out.connect_samples = sample_surface(out.surface.mesh, opt.connect_samples, stream_seed(opt.seed, 4));
    }
    if (!st.ok()) return st;
    out.time_candidates_s = seconds_since(t0) - out.time_sampling_s;
    if (out.balls.empty())
        return fail(Code::no_candidates, "no candidate ball lies inside the shape (is the surface closed around a "
                                         "volume? try more samples or the random generator)");
    return Status::success();
}

}  // namespace ca
