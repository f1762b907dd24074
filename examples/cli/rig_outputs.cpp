// rig_outputs.cpp: --correspondence FILE.json and --rig OUT.glb: the input's vertices matched to
// the skeleton (ca_correspond) and the rig (ca_rig_build), written as JSON (per vertex, in input
// order: balls, weights, nearest primitive, branch) and as a skinned glTF (rig_writer.h) with the
// engine proxies, if any, as colliders. Also the rig itself (build_rig), which the bone colliders
// of an input without a skin take too.
#include "cli.h"
#include "output_file.h"
#include "rig_writer.h"

#include <memory>

namespace cli {

RigPtr build_rig(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton* sk, const RunOptions& o, Failure& failure) {
    const ca_surface_view surface = surface_view(mesh, o.point_normals);
    const ca_skeleton_view view = skeleton_view(sk);
    ca_rig* raw = nullptr;
    const ca_status st = ca_rig_build(ctx, &surface, &view, &o.rig, &raw);
    RigPtr rig(raw, ca_rig_destroy);
    if (st != CA_OK) {
        failure = library_failure(ctx, st, "rig");
        rig.reset();
    }
    return rig;
}

bool write_rig_outputs(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton* sk, const RunOptions& o,
                       const Outputs& out, const std::vector<caio::ProxyData>& proxies, Json& report, Failure& failure) {
    if (out.correspondence.empty() && out.rig.empty()) return true;
    const RigPtr rig = build_rig(ctx, mesh, sk, o, failure);
    if (!rig) return false;
    const size_t nv = ca_rig_vertex_count(rig.get()), nj = ca_rig_joint_count(rig.get());
    report["rig"] = {{"joints", nj}, {"branches", ca_rig_branch_count(rig.get())}};

    std::string err;
    if (!out.correspondence.empty()) {
        ca_correspondence_options copt;
        ca_correspondence_options_init(&copt);
        copt.smoothing = o.rig.smoothing;
        const ca_surface_view surface = surface_view(mesh, o.point_normals);
        const ca_skeleton_view view = skeleton_view(sk);
        ca_correspondence* c_raw = nullptr;
        const ca_status st = ca_correspond(ctx, &surface, &view, &copt, &c_raw);
        std::unique_ptr<ca_correspondence, void (*)(ca_correspondence*)> c(c_raw, ca_correspondence_destroy);
        if (st != CA_OK) return failure = library_failure(ctx, st, "correspondence"), false;
        const uint32_t* balls = ca_correspondence_balls(c.get());
        const double* weights = ca_correspondence_weights(c.get());
        const int32_t* kinds = ca_correspondence_nearest_kinds(c.get());
        const uint32_t* nearest = ca_correspondence_nearest_indices(c.get());
        const uint32_t* branch = ca_rig_vertex_branches(rig.get());
        static const char* kind_names[] = {"ball", "edge", "face"};
        Json vertices = Json::array();
        for (size_t i = 0; i < nv; ++i) {
            Json b = Json::array(), w = Json::array();
            for (size_t k = 0; k < CA_INFLUENCES; ++k) {
                if (weights[CA_INFLUENCES * i + k] <= 0) continue;
                b.push_back(balls[CA_INFLUENCES * i + k]);
                w.push_back(weights[CA_INFLUENCES * i + k]);
            }
            vertices.push_back({{"balls", b}, {"weights", w}, {"nearest", {{"kind", kind_names[kinds[i]]}, {"index", nearest[i]}}},
                                {"branch", branch[i]}});
        }
        const Json doc = {{"format_version", kFormatVersion}, {"balls", ca_skeleton_vertex_count(sk)},
                          {"branches", ca_rig_branch_count(rig.get())}, {"vertices", vertices}};
        if (!caio::write_bytes(out.correspondence, doc.dump() + "\n", err)) return failure = file_failure(err), false;
    }
    if (!out.rig.empty()) {
        caio::RigData data;
        const double* p = ca_rig_joint_positions(rig.get());
        data.joints.assign(p, p + 3 * nj);
        data.parents.assign(ca_rig_joint_parents(rig.get()), ca_rig_joint_parents(rig.get()) + nj);
        data.vertex_joints.assign(ca_rig_vertex_joints(rig.get()), ca_rig_vertex_joints(rig.get()) + CA_INFLUENCES * nv);
        data.vertex_weights.assign(ca_rig_vertex_weights(rig.get()), ca_rig_vertex_weights(rig.get()) + CA_INFLUENCES * nv);
        if (!caio::write_rig_glb(out.rig, mesh, data, err, proxies)) return failure = file_failure(err), false;
    }
    return true;
}

}  // namespace cli
