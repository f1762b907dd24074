// evaluate_command.cpp: `coverage-axis evaluate INPUT SKELETON.ma`: measures any medial mesh
// (ours or another tool's) against its input: one- and two-sided Hausdorff distances between
// the surface and the union of the skeleton's spheres, cones and slabs, in % of the bbox diagonal.
#include "cli.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace cli {

int evaluate_command(int argc, char** argv) {
    std::string input, skeleton_path;
    bool json = false;
    ca_evaluate_options options;
    ca_evaluate_options_init(&options);
    CLI::App app{"Measures a medial skeleton against its input surface (Hausdorff distances in % of the bbox diagonal).",
                 "coverage-axis evaluate"};
    app.add_option("INPUT", input, "the input mesh or point cloud")->required();
    app.add_option("SKELETON", skeleton_path, "the skeleton (.ma)")->required();
    app.add_option("--surface-samples", options.surface_samples, "area-uniform samples of the input (plus its vertices)")
        ->capture_default_str()->check(CLI::Range(1u, 100000000u));
    app.add_option("--envelope-samples", options.envelope_samples, "samples of the reconstruction's boundary")
        ->capture_default_str()->check(CLI::Range(1u, 100000000u));
    app.add_option("--seed", options.seed, "random seed")->capture_default_str();
    app.add_flag("--json", json, "print one JSON object on stdout (on failure too: {\"error\": ...})");
    json = std::any_of(argv + 1, argv + argc, [](const char* a) { return std::strcmp(a, "--json") == 0; });
    auto fail = [&](const Failure& f) {
        if (json) {
            Json j = report_header(input);
            j["error"] = error_json(f);
            std::printf("%s\n", j.dump().c_str());
        } else {
            std::fprintf(stderr, "coverage-axis: %s\n", f.message.c_str());
        }
        return f.exit_code;
    };
    std::string usage;
    const int parsed = parse_command_line(app, argc, argv, usage);
    if (parsed == 2) return fail({"USAGE_ERROR", -1, usage, 2});
    if (parsed >= 0) return parsed;

    caio::MeshData mesh;
    caio::SkeletonData sk;
    std::string err;
    if (!read_input(input, "", ReadLimits{}, mesh, err) || !caio::read_ma(skeleton_path, sk, err)) return fail(file_failure(err));
    ca_context* ctx = nullptr;
    const ca_status st = ca_context_create(nullptr, &ctx);
    if (st != CA_OK) return fail(library_failure(nullptr, st, "context"));
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    view.centers = sk.centers.data();
    view.radii = sk.radii.data();
    view.vertex_count = sk.radii.size();
    view.edges = sk.edges.data();
    view.edge_count = sk.edges.size() / 2;
    view.faces = sk.faces.data();
    view.face_count = sk.faces.size() / 3;
    ca_evaluation e;
    Failure failure;
    const bool ok = evaluate(ctx, mesh, view, options, e, failure);
    ca_context_destroy(ctx);
    if (!ok) return fail(failure);
    if (json) {
        Json j = report_header(input);
        j["dropped"] = mesh.dropped;
        j["skin"] = skin_json(mesh);
        j["skeleton"] = skeleton_path;
        j["vertices"] = view.vertex_count;
        j["edges"] = view.edge_count;
        j["faces"] = view.face_count;
        add_evaluation(j, e);
        j["diagonal"] = e.diagonal;
        j["time_s"] = e.time_s;
        std::printf("%s\n", j.dump().c_str());
    } else {
        std::printf("skeleton    %s: %zu vertices, %zu edges, %zu faces\n", skeleton_path.c_str(), view.vertex_count,
                    view.edge_count, view.face_count);
        std::printf("surface->reconstruction   max %.3f %%  mean %.3f %%  (of the bbox diagonal %.6g)\n",
                    e.hd_surface_to_recon, e.mean_surface_to_recon, e.diagonal);
        std::printf("reconstruction->surface   max %.3f %%  mean %.3f %%\n", e.hd_recon_to_surface, e.mean_recon_to_surface);
        std::printf("two-sided Hausdorff       %.3f %%   (%.2f s, %llu surface / %llu envelope samples)\n", e.hd_two_sided,
                    e.time_s, (unsigned long long)e.surface_samples_used, (unsigned long long)e.envelope_samples_used);
    }
    return 0;
}

}  // namespace cli
