// run_report.cpp: the JSON reports: the fields every report starts with (format, tool, library
// and ABI versions, the input), the input's skin, and the --json report of a finished run: the
// input, the candidates, the selection and its reduction, the skeleton, the files written, the
// rig and proxy fields, the evaluation, the HD reached and each stage's seconds.
#include "run_steps.h"

#include <cmath>

namespace cli {

Json report_header(const std::string& input) {
    return Json{{"format_version", kFormatVersion}, {"tool_version", CA_TOOL_VERSION}, {"library_version", library_version()},
                {"abi_version", ca_abi_version()}, {"input", input}};
}

Json skin_json(const caio::MeshData& mesh) {
    if (mesh.skin.empty()) return nullptr;
    return Json{{"joints", mesh.skin.joint_names.size()}, {"influences", mesh.skin.influences}};
}

namespace {

double round4(double t) { return std::round(t * 1e4) / 1e4; }

// The input's and the candidates' fields of the report.
void add_input_fields(Json& j, const caio::MeshData& mesh, const Run& run) {
    j["input_vertices"] = mesh.positions.size() / 3;
    j["input_triangles"] = mesh.triangles.size() / 3;
    j["input_normals"] = mesh.triangles.empty() && !mesh.normals.empty();
    j["dropped"] = mesh.dropped;
    j["skin"] = skin_json(mesh);
    j["normals"] = normals_name(run.normals);
    j["flipped"] = run.flipped;
    j["surface_samples"] = ca_candidate_set_sample_count(run.set);
    j["candidates"] = ca_candidate_set_count(run.set);
    j["outliers"] = ca_candidate_set_outlier_count(run.set);
    j["normals_replaced"] = ca_candidate_set_normals_replaced(run.set);
}

// The skeleton's fields of the report.
void add_skeleton_fields(Json& j, const ca_skeleton_stats& ks, size_t selected) {
    j["selected"] = selected;
    j["edges"] = ks.edges;
    j["faces"] = ks.faces;
    j["components"] = ks.components;
    j["isolated"] = ks.isolated;
    j["betti1"] = ks.betti1;
    j["genus"] = ks.genus;
    j["thin_handles"] = ks.thin_handles;
    j["medial_balls"] = ks.medial_balls;
    j["surface_balls"] = ks.surface_balls;
    j["open_parts"] = ks.open_parts;
    if (ks.fitted) {
        j["fit"] = {{"error_before", ks.fit_error_before}, {"error_after", ks.fit_error_after},
                    {"time_s", ks.fit_time_s}, {"uncovered", ks.fit_uncovered}};
    }
}

// The selection's fields of the report.
void add_selection_fields(Json& j, const ca_select_stats& ss, const Run& run, const RunOptions& o) {
    j["uncovered"] = ca_selection_uncovered_count(run.sel);
    j["optimal"] = ss.proven_optimal != 0;
    j["objective"] = std::llround(ss.objective);
    j["lower_bound"] = std::llround(ss.lower_bound);
    j["gap"] = ss.gap;
    j["delta"] = ss.delta_absolute;
    j["scale"] = ss.scale_used;
    j["reference_length"] = ca_candidate_set_reference_length(run.set);
    j["solver"] = o.solver;
    j["effort"] = o.effort;
}

// The report's "outputs": each file the run wrote, by its kind.
Json outputs_json(const Outputs& out) {
    Json j = {{"ma", out.ma}};
    for (const auto& [key, path] : {std::pair<const char*, const std::string&>{"obj", out.obj}, {"ply", out.ply},
                                    {"gltf", out.gltf}, {"preview", out.preview}, {"proxies_json", out.proxies_json},
                                    {"correspondence", out.correspondence}, {"rig", out.rig}, {"colliders", out.colliders},
                                    {"bone_colliders", out.bone_colliders}, {"bone_colliders_json", out.bone_colliders_json}})
        if (!path.empty()) j[key] = path;
    return j;
}

// The report's "time_s": each stage's seconds, and the whole run's.
Json times_json(const StageTimes& t, double total) {
    return Json{{"read", round4(t.read)},       {"candidates", round4(t.candidates)}, {"select", round4(t.select)},
                {"connect", round4(t.connect)}, {"write", round4(t.write)},           {"evaluate", round4(t.evaluate)},
                {"proxies", round4(t.proxies)}, {"total", round4(total)}};
}

}  // namespace

Json run_report(const std::string& input, const caio::MeshData& mesh, const Run& run, const RunResults& results,
                const RunOptions& o, const Outputs& out, const Outcome& r) {
    const double total = since(run.start);
    const ca_select_stats& ss = results.select;
    const ca_skeleton_stats& ks = results.skeleton;
    Json j = report_header(input);
    add_input_fields(j, mesh, run);
    add_skeleton_fields(j, ks, results.selected);
    add_selection_fields(j, ss, run, o);
    j["connect"] = ks.method == CA_CONNECT_MEDIAL ? "medial" : "power";
    j["probes"] = ss.probes;
    j["parts"] = ss.parts;
    j["reduction"] = {{"rows_before", ss.rows_before}, {"cols_before", ss.cols_before}, {"rows_after", ss.rows_after},
                      {"cols_after", ss.cols_after}, {"forced", ss.forced}};
    j["output"] = out.ma;
    j["outputs"] = outputs_json(out);
    for (auto& [key, value] : results.rig.items()) j[key] = value;
    if (results.evaluated) add_evaluation(j, results.evaluation);
    if (!o.proxies.empty()) j["proxies"] = results.proxy_stats;
    // --target-count: the HD of what was written (the library's search measured the default
    // connection, fitted with --fit, which --connect changes)
    if (o.select.target_count > 0) j["hd_reached"] = results.evaluation.hd_two_sided;
    else if (ss.hd_reached >= 0) j["hd_reached"] = ss.hd_reached;
    else j["hd_reached"] = nullptr;
    if (o.select.target_error > 0) {
        j["target_reached"] = !r.target_missed;
        // no lower bound on the count is known (docs/fidelity.md): null, never a guess
        j["balls_lower_bound"] = nullptr;
    }
    if (r.target_missed) j["error"] = error_json(r.failure);
    j["time_s"] = times_json(run.times, total);
    return j;
}

}  // namespace cli
