// surface.cpp: validation and normalisation of the caller's mesh or oriented point cloud.
#include "surface.h"
#include "duplicates.h"
#include "hole_caps.h"
#include "kdtree.h"
#include "normals.h"
#include "patch_signs.h"
#include "winding.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

namespace ca {

std::pair<Vec3, Vec3> bounding_box(const std::vector<Vec3>& pts) {
    if (pts.empty()) return {Vec3::Zero(), Vec3::Zero()};
    Vec3 lo = pts[0], hi = pts[0];
    for (const Vec3& p : pts) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
    return {lo, hi};
}

// On coordinates normalised to the bounding box (origin lo, longest side 1), so boxes near the
// ends of the double range (1e300, 1e-300) neither overflow nor underflow the covariance.
static bool all_in_one_plane(const std::vector<Vec3>& pts, const Vec3& lo, double longest) {
    Vec3 mean = Vec3::Zero();
    for (const Vec3& p : pts) mean += (p - lo) / longest;
    mean /= double(pts.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Vec3& p : pts) {
        const Vec3 q = (p - lo) / longest - mean;
        cov += q * q.transpose();
    }
    cov /= double(pts.size());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    // smallest standard deviation relative to the size of the model
    return std::sqrt(std::max(0.0, es.eigenvalues()[0])) <= 1e-9;
}

namespace {
// The points of `missing` take their PCA direction (normals.h), signed to agree with the given
// normals among their 16 nearest neighbours (where none is given, the sign is left to the
// orientation check that follows).
void fill_missing_normals(const std::vector<Vec3>& pts, const std::vector<size_t>& missing, std::vector<Vec3>& normals,
                          int threads) {
    const std::vector<Vec3> pca = estimate_normals(pts, 16, threads);
    std::vector<uint8_t> given(pts.size(), 1);
    for (size_t i : missing) given[i] = 0;
    const PointTree tree(pts);
    size_t idx[17];
    double d2[17];
    for (size_t i : missing) {
        Vec3 around = Vec3::Zero();
        const size_t found = tree.nearest(pts[i], 17, idx, d2);
        for (size_t k = 0; k < found; ++k)
            if (given[idx[k]]) around += normals[idx[k]];
        normals[i] = around.dot(pca[i]) < 0 ? Vec3(-pca[i]) : pca[i];
    }
}

// Most given normals lie within about 37 degrees of their neighbourhood's PCA direction (either
// sign): they describe the surface, whatever their signs.
bool follows_surface(const std::vector<Vec3>& given, const std::vector<Vec3>& pca) {
    size_t along = 0;
    for (size_t i = 0; i < given.size(); ++i) along += std::abs(given[i].dot(pca[i])) > 0.8;
    return along >= 0.8 * double(given.size());
}
// The PCA neighbourhood of follows_surface's second try: on a dense noisy cloud the 16 nearest
// neighbours lie within the noise band, so their PCA direction is mostly noise; 64 neighbours span
// about twice the radius, where the surface's extent dominates the noise again.
constexpr size_t kNoisyPcaNeighbours = 64;
}  // namespace

namespace {

// Finite coordinates and triangle indices in range. Each pass below over the vertices or
// triangles tests the stop request every few thousand items or right after it: on a mesh of
// millions of triangles every pass takes tens of milliseconds, and a cancel must take effect
// within 0.1 s.
Status check_mesh_arrays(const Mesh& raw, const Monitor& monitor) {
    const size_t nv = raw.vertices.size();
    for (size_t i = 0; i < nv; ++i) {
        if (monitor.stopped_at(i)) return monitor.stop_status("surface");
        if (!raw.vertices[i].allFinite())
            return fail(Code::invalid_input, "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
    }
    for (size_t t = 0; t < raw.triangles.size(); ++t) {
        if (monitor.stopped_at(t)) return monitor.stop_status("surface");
        for (uint32_t v : raw.triangles[t])
            if (v >= nv)
                return fail(Code::invalid_input, "triangle " + std::to_string(t) + " references vertex " +
                                                     std::to_string(v) + " of " + std::to_string(nv));
    }
    return Status::success();
}

// A point cloud's given normals made unit length; `missing` gets the points whose normal is zero
// ("none": estimated later). None given at all: `normals` is cleared (all estimated).
Status check_given_normals(size_t nv, std::vector<Vec3>& normals, std::vector<size_t>& missing, Surface& out) {
    if (normals.size() != nv)
        return fail(Code::invalid_input, "a point cloud (no triangles) needs one normal per point (" +
                                             std::to_string(normals.size()) + " normals for " +
                                             std::to_string(nv) + " points)");
    // A zero normal means "none" (scanners and exporters write 0 0 0 where they have none): it is
    // estimated below. NaN or infinite ones are errors.
    for (size_t i = 0; i < nv; ++i) {
        const double len = normals[i].norm();
        if (!std::isfinite(len))
            return fail(Code::invalid_input, "normal " + std::to_string(i) + " is NaN or infinite");
        if (len < 1e-12) {
            missing.push_back(i);
            continue;
        }
        normals[i] /= len;
    }
    out.normals_replaced = missing.size();
    if (missing.size() == nv) normals.clear(), missing.clear();   // none given: all estimated
    return Status::success();
}

// The points of the shape: what the triangles use (a point cloud: every point).
Status shape_points(const Mesh& raw, bool cloud, const Monitor& monitor, std::vector<Vec3>& used) {
    if (cloud) {
        used = raw.vertices;
        return Status::success();
    }
    const size_t nv = raw.vertices.size();
    std::vector<uint8_t> referenced(nv, 0);
    for (size_t t = 0; t < raw.triangles.size(); ++t) {
        if (monitor.stopped_at(t)) return monitor.stop_status("surface");
        for (uint32_t v : raw.triangles[t]) referenced[v] = 1;
    }
    reserve_large(used, nv);
    for (size_t i = 0; i < nv; ++i)
        if (referenced[i]) used.push_back(raw.vertices[i]);
    if (monitor.stopped()) return monitor.stop_status("surface");
    if (used.empty()) return fail(Code::degenerate_input, "the mesh has no triangles");
    return Status::success();
}

// The unit-cube normalisation of the shape's points (out.norm), and whether a mesh is flat;
// the vertices mapped to internal units.
Status normalise(Mesh& raw, bool cloud, const std::vector<Vec3>& used, const Monitor& monitor, Surface& out) {
    auto [lo, hi] = bounding_box(used);
    if (monitor.stopped()) return monitor.stop_status("surface");
    const double longest = (hi - lo).maxCoeff();
    if (!(longest > 0)) return fail(Code::degenerate_input, "all input points coincide");
    if (!std::isfinite(longest))
        return fail(Code::invalid_input, "the input's bounding box is too large to represent");
    // A flat mesh has area, so it has a skeleton: the sheet itself. A flat point cloud carries no
    // surface the winding number could close around, and its normals say nothing of a side.
    if (all_in_one_plane(used, lo, longest)) {
        if (cloud) return fail(Code::degenerate_input, "all points of the cloud lie in one plane: a point cloud needs a solid");
        out.flat = true;
    }

    if (monitor.stopped()) return monitor.stop_status("surface");
    out.norm.origin = lo;
    out.norm.scale = longest;
    for (size_t i = 0; i < raw.vertices.size(); ++i) {
        if (monitor.stopped_at(i)) return monitor.stop_status("surface");
        raw.vertices[i] = out.norm.to_internal(raw.vertices[i]);
    }
    return Status::success();
}

// Meshes, in internal units: the zero-area triangles dropped, the hole caps and the topology
// found, and an inward-facing mesh flipped.
Status tidy_mesh(Mesh& raw, const Monitor& monitor, Surface& out) {
    // drop zero-area triangles (they carry no surface and no winding number), in place
    std::vector<uint8_t> zero_area(raw.triangles.size(), 0);
    size_t zero = 0;
    for (size_t k = 0; k < raw.triangles.size(); ++k) {
        if (monitor.stopped_at(k)) return monitor.stop_status("surface");
        const Tri t = raw.triangles[k];
        const Vec3& a = raw.vertices[t[0]];
        const double area2 = (raw.vertices[t[1]] - a).cross(raw.vertices[t[2]] - a).norm();
        if (!(area2 > 1e-14)) zero_area[k] = 1, ++zero;
    }
    if (zero == raw.triangles.size()) return fail(Code::degenerate_input, "every triangle has zero area");
    // The holes are found before the zero-area triangles go: exporters seal a T-junction (an
    // edge of one side split by a vertex on the other) with a sliver on its three collinear
    // points, and without it the junction is a slit whose vertex at a hole lies on four
    // boundary edges, so the hole would not be a loop and would get no cap.
    Mesh caps_only;
    if (zero > 0) {
        const HalfEdgeBuckets with_slivers = half_edge_buckets(raw, {}, monitor);
        if (monitor.stopped()) return monitor.stop_status("surface");
        caps_only = hole_caps(raw, with_slivers);
    }
    size_t kept = 0;
    for (size_t k = 0; k < raw.triangles.size(); ++k)
        if (!zero_area[k]) raw.triangles[kept++] = raw.triangles[k];
    out.dropped_triangles += raw.triangles.size() - kept;
    raw.triangles.resize(kept);
    // an inward-facing mesh has negative signed volume: flip it so inside means w > 1/2. An
    // open mesh's signed volume depends on the origin (a large hole facing away from it can
    // turn its sign), so it is taken with the holes capped (hole_caps.h: oriented like the
    // mesh; closed meshes have no caps). One pass over the half-edges finds the caps and the
    // topology (the merge left the triangles on welded vertices: the buckets need no map)
    const HalfEdgeBuckets edges = half_edge_buckets(raw, {}, monitor);
    if (monitor.stopped()) return monitor.stop_status("surface");
    out.caps = zero > 0 ? std::move(caps_only) : hole_caps(raw, edges);
    out.topology = mesh_topology(raw, {}, edges, monitor);
    if (monitor.stopped()) return monitor.stop_status("surface");
    const double volume = signed_volume(raw) + signed_volume(out.caps);
    if (monitor.stopped()) return monitor.stop_status("surface");
    if (volume < 0) {
        for (Tri& t : raw.triangles) std::swap(t[1], t[2]);
        for (Tri& t : out.caps.triangles) std::swap(t[1], t[2]);
        out.flipped = true;
    }
    if (monitor.stopped()) return monitor.stop_status("surface");
    return Status::success();
}

// Point clouds, in internal units: missing normals are estimated, unoriented ones oriented
// (normals.h), trusted ones checked and oriented when their signs disagree; the outward sign is
// fixed by the winding number when the candidates are built.
Status prepare_cloud_normals(const std::vector<Vec3>& pts, const std::vector<size_t>& missing, PointNormals trust,
                             int threads, std::vector<Vec3>& normals, Surface& out) {
    out.normals_source = NormalSource::given;
    if (!missing.empty()) fill_missing_normals(pts, missing, normals, threads);
    if (normals.empty()) {
        normals = estimate_normals(pts, 16, threads);
        out.normals_source = NormalSource::estimated;
    } else {
        out.disagreement_given = sign_disagreement(pts, normals, 8, threads);
        if (trust == PointNormals::unoriented || out.disagreement_given > kMaxSignDisagreement)
            out.normals_source = NormalSource::oriented;
    }
    std::vector<Vec3> given;
    if (out.normals_source == NormalSource::oriented && trust == PointNormals::trusted) given = normals;
    if (out.normals_source != NormalSource::given)
        orient_normals(pts, normals, 16, out.normals_source == NormalSource::estimated, threads);
    out.disagreement = out.normals_source == NormalSource::given ? out.disagreement_given
                                                                 : sign_disagreement(pts, normals, 8, threads);
    // Trusted normals that orientation does not make at least twice as consistent by the pair
    // rule are judged by the winding number instead (patch_signs.h: its residual depends on
    // no offsets between neighbours, which noise makes say little about signs). Unless
    // orientation at least halves that residual too, the signs were not wrong, and the
    // caller's normals are kept if they describe the surface: their directions follow PCA's
    // (of 16 neighbours, or of 64 on dense noisy clouds), or the winding number finds them
    // consistent on its own
    const auto keep_given = [&] {
        if (out.disagreement < kSignCheckGain * out.disagreement_given) return false;
        const double residual = winding_residual(pts, given, threads);
        if (winding_residual(pts, normals, threads) < kSignCheckGain * residual) return false;
        return residual < kMaxWindingResidual || follows_surface(given, estimate_normals(pts, 16, threads)) ||
               follows_surface(given, estimate_normals(pts, kNoisyPcaNeighbours, threads));
    };
    if (!given.empty() && keep_given()) {
        normals = std::move(given);
        out.normals_source = NormalSource::given;
        out.disagreement = out.disagreement_given;
        out.sign_check_inconclusive = true;
    }
    // estimated normals, and unoriented ones whose directions follow the surface, are judged
    // by the winding number's jump across the surface when the candidates are built: on
    // sparse clouds neighbours disagree at thin parts without the orientation being wrong,
    // so the pair rule would refuse usable clouds
    if (out.normals_source != NormalSource::estimated && !out.sign_check_inconclusive &&
        out.disagreement > kMaxSignDisagreement &&
        !(trust == PointNormals::unoriented && follows_surface(normals, estimate_normals(pts, 16, threads))))
        return fail(Code::invalid_input,
                    "the point cloud's normals could not be oriented consistently: after orientation " +
                        std::to_string(int(std::lround(100 * out.disagreement))) +
                        "% of neighbouring pairs still point against each other (too sparse or too noisy?)");
    return Status::success();
}

}  // namespace

Status prepare_surface(Mesh raw, std::vector<Vec3> normals, Surface& out, bool require_normals, PointNormals trust,
                       const Monitor& monitor, int threads) {
    out = Surface{};
    const size_t nv = raw.vertices.size();
    if (nv == 0) return fail(Code::degenerate_input, "the input has no vertices");
    Status st = check_mesh_arrays(raw, monitor);
    if (!st.ok()) return st;
    const bool cloud = raw.triangles.empty();
    if (!cloud) {
        // repeated geometry would only repeat work (duplicates.h)
        const MergeCounts merged = merge_duplicate_geometry(raw, monitor);
        if (merged.stopped) return monitor.stop_status("surface");
        out.dropped_triangles = merged.degenerate;
        out.duplicate_triangles = merged.duplicate;
    }
    if (cloud && (!require_normals || trust == PointNormals::estimate)) normals.clear();
    std::vector<size_t> missing;   // points whose given normal is zero
    if (cloud && require_normals && !normals.empty()) {
        st = check_given_normals(nv, normals, missing, out);
        if (!st.ok()) return st;
    }
    std::vector<Vec3> used;
    st = shape_points(raw, cloud, monitor, used);
    if (st.ok()) st = normalise(raw, cloud, used, monitor, out);
    if (st.ok() && !cloud) st = tidy_mesh(raw, monitor, out);
    if (st.ok() && cloud && require_normals) st = prepare_cloud_normals(raw.vertices, missing, trust, threads, normals, out);
    if (!st.ok()) return st;
    out.mesh = std::move(raw);
    out.normals = std::move(normals);
    out.point_cloud = cloud;
    return Status::success();
}

}  // namespace ca
