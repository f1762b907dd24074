// evaluate_command.cpp: `coverage-axis evaluate INPUT SKELETON.ma`: measures any medial mesh
// (ours or another tool's) against its input: one- and two-sided Hausdorff distances between
// the surface and the union of the skeleton's spheres, cones and slabs, in % of the bbox diagonal.
#include "cli.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace cli {

ca_surface_view surface_view(const caio::MeshData& mesh) {
    ca_surface_view view;
    ca_surface_view_init(&view);
    view.positions = mesh.positions.data();
    view.vertex_count = mesh.positions.size() / 3;
    view.triangles = mesh.triangles.data();
    view.triangle_count = mesh.triangles.size() / 3;
    view.normals = mesh.normals.empty() ? nullptr : mesh.normals.data();
    return view;
}

bool evaluate(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton_view& skeleton,
              const ca_evaluate_options& options, ca_evaluation& out) {
    const ca_surface_view view = surface_view(mesh);
    out.struct_size = sizeof out;
    const ca_status st = ca_evaluate(ctx, &view, &skeleton, &options, &out);
    if (st != CA_OK) {
        std::fprintf(stderr, "coverage-axis: evaluation failed: %s (%s)\n", ca_context_last_error(ctx), ca_status_string(st));
        return false;
    }
    return true;
}

std::string evaluation_json(const ca_evaluation& e) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "\"hd_surface_to_recon\":%.6g,\"hd_recon_to_surface\":%.6g,\"hd_two_sided\":%.6g,"
                  "\"mean_surface_to_recon\":%.6g,\"mean_recon_to_surface\":%.6g,\"evaluate_surface_samples\":%llu,"
                  "\"evaluate_envelope_samples\":%llu",
                  e.hd_surface_to_recon, e.hd_recon_to_surface, e.hd_two_sided, e.mean_surface_to_recon,
                  e.mean_recon_to_surface, (unsigned long long)e.surface_samples_used,
                  (unsigned long long)e.envelope_samples_used);
    return buf;
}

static const char* kEvaluateUsage =
    "usage: coverage-axis evaluate INPUT SKELETON.ma [--json] [--surface-samples N] [--envelope-samples N] [--seed N]\n";

int evaluate_command(int argc, char** argv) {
    std::string input, skeleton_path;
    bool json = false;
    ca_evaluate_options options;
    ca_evaluate_options_init(&options);
    for (int i = 2; i < argc; ++i) {
        const std::string k = argv[i];
        auto count = [&](uint32_t& out) {
            if (i + 1 >= argc) return false;
            char* end = nullptr;
            const unsigned long v = std::strtoul(argv[++i], &end, 10);
            if (*end || end == argv[i] || v == 0 || v > 100000000ul) return false;
            out = uint32_t(v);
            return true;
        };
        if (k == "-h" || k == "--help") { std::fputs(kEvaluateUsage, stdout); return 0; }
        else if (k == "--json") json = true;
        else if (k == "--surface-samples") { if (!count(options.surface_samples)) { std::fprintf(stderr, "coverage-axis: --surface-samples takes a count >= 1\n"); return 2; } }
        else if (k == "--envelope-samples") { if (!count(options.envelope_samples)) { std::fprintf(stderr, "coverage-axis: --envelope-samples takes a count >= 1\n"); return 2; } }
        else if (k == "--seed") {
            uint32_t s = 0;
            if (!count(s)) { std::fprintf(stderr, "coverage-axis: --seed takes a positive integer\n"); return 2; }
            options.seed = s;
        }
        else if (!k.empty() && k[0] == '-') { std::fprintf(stderr, "coverage-axis: unknown option %s (see coverage-axis evaluate --help)\n", k.c_str()); return 2; }
        else if (input.empty()) input = k;
        else if (skeleton_path.empty()) skeleton_path = k;
        else { std::fprintf(stderr, "coverage-axis: too many arguments (see coverage-axis evaluate --help)\n"); return 2; }
    }
    if (skeleton_path.empty()) { std::fprintf(stderr, "coverage-axis: evaluate needs INPUT and SKELETON.ma (see coverage-axis evaluate --help)\n"); return 2; }

    caio::MeshData mesh;
    caio::SkeletonData sk;
    std::string err;
    if (!caio::read_mesh(input, mesh, err) || !caio::read_ma(skeleton_path, sk, err)) {
        std::fprintf(stderr, "coverage-axis: %s\n", err.c_str());
        return 3;
    }
    ca_context* ctx = nullptr;
    if (ca_context_create(nullptr, &ctx) != CA_OK) { std::fprintf(stderr, "coverage-axis: cannot create a context\n"); return 1; }
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
    const bool ok = evaluate(ctx, mesh, view, options, e);
    ca_context_destroy(ctx);
    if (!ok) return 1;
    if (json) {
        std::printf("{\"input\":\"%s\",\"skeleton\":\"%s\",\"vertices\":%zu,\"edges\":%zu,\"faces\":%zu,%s,\"time_s\":%.4f}\n",
                    input.c_str(), skeleton_path.c_str(), view.vertex_count, view.edge_count, view.face_count,
                    evaluation_json(e).c_str(), e.time_s);
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
