// evaluation.cpp: measuring a skeleton against its input surface (ca_evaluate: one- and two-sided
// Hausdorff distances) and the report's fields of the result; shared by a run's --evaluate (and
// --target-count) and the evaluate command.
#include "cli.h"

namespace cli {

bool evaluate(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton_view& skeleton,
              const ca_evaluate_options& options, ca_evaluation& out, Failure& failure) {
    const ca_surface_view view = surface_view(mesh);
    out.struct_size = sizeof out;
    const ca_status st = ca_evaluate(ctx, &view, &skeleton, &options, &out);
    if (st != CA_OK) failure = library_failure(ctx, st, "evaluation");
    return st == CA_OK;
}

void add_evaluation(Json& j, const ca_evaluation& e) {
    j["hd_surface_to_recon"] = e.hd_surface_to_recon;
    j["hd_recon_to_surface"] = e.hd_recon_to_surface;
    j["hd_two_sided"] = e.hd_two_sided;
    j["mean_surface_to_recon"] = e.mean_surface_to_recon;
    j["mean_recon_to_surface"] = e.mean_recon_to_surface;
    j["evaluate_surface_samples"] = e.surface_samples_used;
    j["evaluate_envelope_samples"] = e.envelope_samples_used;
}

}  // namespace cli
