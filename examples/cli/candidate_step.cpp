// candidate_step.cpp: a run's candidates: generated from the input (ca_candidates), with a
// samples file (--surface-samples) or a ball file (--candidates FILE) replacing its part through
// ca_candidates_from_arrays; then --export-samples and --export-candidates write what the
// selection will see.
#include "run_steps.h"

#include <algorithm>
#include <cmath>

namespace cli {
namespace {

// The longest side of the input's bounding box (0 when there is none): a file's candidates keep
// delta relative to it, as generated ones do.
double longest_bbox_side(const caio::MeshData& mesh) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i + 2 < mesh.positions.size(); i += 3)
        for (size_t k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], mesh.positions[i + k]);
            hi[k] = std::max(hi[k], mesh.positions[i + k]);
        }
    const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    return std::isfinite(longest) && longest > 0 ? longest : 0;
}

}  // namespace

bool make_candidates(Run& run, const caio::MeshData& mesh, const RunOptions& o, Failure& failure) {
    std::string err;
    const bool from_file = o.candidate_kind != "voronoi" && o.candidate_kind != "random";
    std::vector<double> file_samples, file_centers, file_radii, unused;
    if (!o.surface_samples_file.empty() && !caio::read_points(o.surface_samples_file, file_samples, unused, err))
        return failure = file_failure(err), false;
    if (from_file) {
        if (!caio::read_points(o.candidate_kind, file_centers, file_radii, err)) return failure = file_failure(err), false;
        if (file_radii.size() * 3 != file_centers.size() || file_radii.empty())
            return failure = file_failure(o.candidate_kind + ": every candidate needs a radius (v x y z r)"), false;
    }
    ca_status st;
    if (!(from_file && !o.surface_samples_file.empty())) {
        const ca_surface_view view = surface_view(mesh, o.point_normals);
        if ((st = ca_candidates(run.ctx, &view, &o.candidates, &run.set)) != CA_OK)
            return failure = library_failure(run.ctx, st, "candidates"), false;
        run.normals = ca_candidate_set_normals(run.set);
        run.flipped = ca_candidate_set_flipped(run.set) != 0;
    }
    if (from_file || !o.surface_samples_file.empty()) {
        // delta stays relative to the input's longest bbox side
        const double* sp = file_samples.empty() ? ca_candidate_set_samples(run.set) : file_samples.data();
        const size_t sn = file_samples.empty() ? ca_candidate_set_sample_count(run.set) : file_samples.size() / 3;
        const double* cp = file_centers.empty() ? ca_candidate_set_centers(run.set) : file_centers.data();
        const double* rp = file_radii.empty() ? ca_candidate_set_radii(run.set) : file_radii.data();
        const size_t cn = file_radii.empty() ? ca_candidate_set_count(run.set) : file_radii.size();
        ca_candidate_set* replaced = nullptr;
        st = ca_candidates_from_arrays(run.ctx, sp, sn, 0, cp, 0, rp, 0, cn, longest_bbox_side(mesh), &replaced);
        if (st != CA_OK) return failure = library_failure(run.ctx, st, "candidates"), false;
        ca_candidate_set_destroy(run.set);
        run.set = replaced;
    }
    return true;
}

bool export_candidates(const ca_candidate_set* set, const Outputs& out, Failure& failure) {
    std::string err;
    const size_t ns = ca_candidate_set_sample_count(set), nc = ca_candidate_set_count(set);
    if (!out.export_samples.empty()) {
        const std::vector<double> xyz(ca_candidate_set_samples(set), ca_candidate_set_samples(set) + 3 * ns);
        if (!caio::write_points(out.export_samples, xyz, {}, err)) return failure = file_failure(err), false;
    }
    if (!out.export_candidates.empty()) {
        const std::vector<double> xyz(ca_candidate_set_centers(set), ca_candidate_set_centers(set) + 3 * nc);
        const std::vector<double> r(ca_candidate_set_radii(set), ca_candidate_set_radii(set) + nc);
        if (!caio::write_points(out.export_candidates, xyz, r, err)) return failure = file_failure(err), false;
    }
    return true;
}

}  // namespace cli
