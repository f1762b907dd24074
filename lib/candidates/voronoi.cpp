// voronoi.cpp: Voronoi candidates: the circumcentres of the Delaunay tetrahedra of dense samples,
// radii clamped to the nearest sample; for meshes those inside by the winding number.
#include "candidates_internal.h"

#include "delaunay.h"
#include "kdtree.h"
#include "sampling.h"

#include <algorithm>
#include <cmath>

namespace ca {
namespace cand {

namespace {

bool in_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
}

}  // namespace

Status voronoi_vertices(const std::vector<Vec3>& pts, int threads, const Monitor& monitor, const AcceptVertices& accept,
                        std::vector<Ball>& balls, std::vector<Tet>& tets) {
    if (!monitor.report("delaunay", 0)) return monitor.stop_status("delaunay");
    Status st = delaunay_tetrahedra(pts, tets, monitor, "delaunay");
    if (!st.ok()) return st;
    if (!monitor.report("delaunay", 1)) return monitor.stop_status("delaunay");
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
    // balls that stick out of the shape; clamp them. Only a sample nearer than the circumradius
    // (with a relative margin far above rounding) can lower the radius, so the search starts
    // from that bound; a sample it finds has the squared distance an unbounded search gives.
    const PackedPointTree sample_tree(pts);
    constexpr double kBoundMargin = 1e-9;
    if (!parallel_for(raw.size(), threads, 8192, monitor, "delaunay", [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i) {
                // a query near the centre of co-spherical samples visits all of them: the stop
                // request is tested every few queries, not only per chunk
                if (i % 64 == 0 && monitor.stopped()) return;
                const double bound2 = raw[i].radius * raw[i].radius * (1 + kBoundMargin);
                const double d2 = sample_tree.nearest_squared_below(raw[i].center, bound2);
                if (d2 < bound2) raw[i].radius = std::min(raw[i].radius, std::sqrt(d2));
            }
        }))
        return monitor.stop_status("delaunay");
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

Status mesh_voronoi_candidates(const CandidateOptions& opt, const Monitor& monitor, Beside& structures,
                               const SurfaceStructures& built, int threads, CandidateSet& out) {
    std::vector<Vec3> samples = sample_surface(out.surface.mesh, opt.voronoi_samples, stream_seed(opt.seed, 2));
    std::vector<Vec3> unique;
    for (uint32_t i : remove_near_duplicates(samples, kDuplicateTolerance)) unique.push_back(samples[i]);
    out.dense_samples = unique;
    // Every tetrahedron's circumcentre is tested (not only the de-duplicated candidates) so the
    // connection step gets the inner flags of the whole Voronoi diagram; the candidates keep
    // exactly the flags they had.
    return inner_voronoi_vertices(
        unique, threads, monitor,
        [&] {
            structures.wait();
            return structures_status(built, monitor);
        },
        [&](const Vec3& c) { return built.queries.winding->inside(c); }, out.balls, out.voronoi_tets,
        out.voronoi_inner);
}

Status inner_voronoi_vertices(const std::vector<Vec3>& pts, int threads, const Monitor& monitor,
                              const std::function<Status()>& ready, const std::function<bool(const Vec3&)>& inside,
                              std::vector<Ball>& balls, std::vector<Tet>& tets, std::vector<uint8_t>& inner) {
    std::vector<uint8_t> raw_inner;
    std::vector<Tet> raw_tets_kept;
    Status st = voronoi_vertices(pts, threads, monitor,
        [&](const std::vector<uint32_t>& ids, const std::vector<Ball>& raw, const std::vector<Tet>& raw_tets,
            std::vector<uint8_t>& keep) {
            raw_inner.assign(raw.size(), 0);
            if (const Status rs = ready(); !rs.ok()) return rs;
            const bool done = parallel_for(raw.size(), threads, 8192, monitor, "inside", [&](size_t b, size_t e) {
                for (size_t k = b; k < e; ++k) raw_inner[k] = inside(raw[k].center);
            });
            if (!done) return monitor.stop_status("inside");
            for (size_t k = 0; k < ids.size(); ++k) keep[k] = raw_inner[ids[k]];
            raw_tets_kept = raw_tets;
            return Status::success();
        }, balls, tets);
    if (!st.ok()) return st;
    // Tetrahedra without a usable circumcentre (flat, or far outside the box) are outer.
    inner.assign(tets.size(), 0);
    for (size_t t = 0, r = 0; t < tets.size() && r < raw_tets_kept.size(); ++t)
        if (tets[t] == raw_tets_kept[r]) inner[t] = raw_inner[r++];
    return Status::success();
}


}  // namespace cand
}  // namespace ca
