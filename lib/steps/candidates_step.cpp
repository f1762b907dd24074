// candidates_step.cpp: step 1 as one request: the caller's surface prepared and its candidates
// generated, or a candidate set from the caller's own samples and balls.
#include "steps.h"

#include "parallel.h"

#include <cmath>

namespace ca {

Status check_surface_input(const SurfaceInput& surface) {
    const PointNormals p = surface.point_normals;
    if (p != PointNormals::trusted && p != PointNormals::unoriented && p != PointNormals::estimate)
        return fail(Code::invalid_argument, "surface->point_normals is " + std::to_string(int32_t(p)) +
                                                "; expected CA_POINT_NORMALS_TRUSTED (0), UNORIENTED (1) or ESTIMATE (2)");
    // checked even where they are not used (estimate): a count that does not match is the caller's error
    const size_t nn = surface.normals.size(), nv = surface.mesh.vertices.size();
    if (surface.mesh.triangles.empty() && nn > 0 && nn != nv)
        return fail(Code::invalid_input, "surface->normals has " + std::to_string(nn) + " entries for " +
                                             std::to_string(nv) + " points; a point cloud needs one normal per point");
    return Status::success();
}

Status check_mesh_set(const CandidateSet& set, const char* what) {
    if (set.surface.kind().is_mesh()) return Status::success();
    return fail(Code::invalid_argument, std::string(what) +
                                            " need a candidate set made from a triangle mesh (not a point cloud or caller arrays)");
}

Status candidates_step(SurfaceInput surface, const CandidateOptions& opt, const Monitor& monitor, CandidateSet& out) {
    if (opt.generator != Generator::voronoi && opt.generator != Generator::random)
        return fail(Code::invalid_argument, "unknown candidate generator " + std::to_string(int32_t(opt.generator)));
    Status st = check_surface_input(surface);
    if (!st.ok()) return st;
    if (monitor.stopped()) return monitor.stop_status("surface");
    const PointNormals trust = surface.point_normals;
    Surface surf;
    st = prepare_surface(std::move(surface.mesh), std::move(surface.normals), surf, true, trust, monitor,
                                resolve_threads(opt.threads));
    if (!st.ok()) return st;
    if (trust == PointNormals::trusted && surf.normals_source == NormalSource::oriented)
        monitor.note(2, "the point normals point against each other at " +
                            std::to_string(int(std::lround(100 * surf.disagreement_given))) +
                            "% of neighbouring pairs; they were re-oriented");
    if (monitor.stopped()) return monitor.stop_status("surface");
    if (surf.flipped) monitor.note(2, "the mesh faces inward (negative signed volume); it was flipped");
    if (surf.normals_replaced)
        monitor.note(1, std::to_string(surf.normals_replaced) + " zero point normals (none given) were estimated");
    if (surf.dropped_triangles) monitor.note(1, std::to_string(surf.dropped_triangles) + " zero-area triangles were ignored");
    if (surf.duplicate_triangles)
        monitor.note(1, std::to_string(surf.duplicate_triangles) + " repeated triangles were merged");
    st = generate_candidates(std::move(surf), opt, monitor, out);
    if (!st.ok()) return st;
    monitor.note(1, std::to_string(out.cover_samples.size()) + " surface samples, " + std::to_string(out.balls.size()) +
                        " candidate balls");
    if (out.surface_balls)
        monitor.note(1, std::to_string(out.surface_balls) +
                            " surface balls for samples no inner ball reaches (open sheets or thin parts)");
    if (out.report.delaunay_failed)
        monitor.note(2, "the Delaunay step failed (Qhull, after its retries); the candidates are fallback and surface balls");
    return Status::success();
}

Status candidates_from_arrays(const std::vector<Vec3>& samples, const std::vector<Vec3>& centers,
                              const std::vector<double>& radii, double reference_length, CandidateSet& out) {
    out = CandidateSet{};
    if (samples.empty()) return fail(Code::degenerate_input, "no surface samples");
    if (centers.empty()) return fail(Code::no_candidates, "no candidate balls");
    if (centers.size() != radii.size())
        return fail(Code::invalid_input, std::to_string(centers.size()) + " centres but " + std::to_string(radii.size()) + " radii");
    if (!(std::isfinite(reference_length) && reference_length >= 0))
        return fail(Code::invalid_argument, "reference_length must be finite and >= 0");
    for (size_t i = 0; i < samples.size(); ++i)
        if (!samples[i].allFinite()) return fail(Code::invalid_input, "sample " + std::to_string(i) + " has a NaN or infinite coordinate");
    for (size_t i = 0; i < centers.size(); ++i)
        if (!centers[i].allFinite()) return fail(Code::invalid_input, "ball " + std::to_string(i) + " has a NaN or infinite centre");
    auto [lo, hi] = bounding_box(samples);
    const double length = reference_length > 0 ? reference_length : (hi - lo).maxCoeff();
    if (!(length > 0)) return fail(Code::degenerate_input, "all samples coincide; give reference_length");
    out.surface.norm.origin = lo;
    out.surface.norm.scale = length;
    for (const Vec3& p : samples) out.cover_samples.push_back(out.surface.norm.to_internal(p));
    for (size_t i = 0; i < centers.size(); ++i) {
        const double r = radii[i];
        if (!(std::isfinite(r) && r >= 0))
            return fail(Code::invalid_input, "ball " + std::to_string(i) + " has a negative, NaN or infinite radius");
        out.balls.push_back({out.surface.norm.to_internal(centers[i]), r / length});
    }
    return Status::success();
}

}  // namespace ca
