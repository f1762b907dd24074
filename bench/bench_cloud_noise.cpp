// bench_cloud_noise.cpp: point clouds sampled from the fox, the bunny and a sphere (5000 points,
// exact normals), clean and with 0.5 % Gaussian noise of the bbox diagonal plus 1 % far outliers
// (tests/support/clouds.h): the whole pipeline at the defaults (uncoverable samples skipped) and
// h(reconstruction -> surface) by ca_evaluate against the source mesh. Target: the noisy cloud's
// h at most 2x the clean cloud's (not meaningful for the sphere, whose clean h is about 0).
#include "bench_common.h"
#include "support/clouds.h"
#include "support/shapes.h"

#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Row {
    ca_status status = CA_OK;
    size_t balls = 0, uncovered = 0;
    uint64_t outliers = 0;
    double h = 0, seconds = 0;
};

Row run(const shapes::Cloud& cloud, const ca::Mesh& mesh) {
    Row row;
    std::vector<double> pos, nrm, mpos;
    std::vector<uint32_t> none, mtri;
    for (size_t i = 0; i < cloud.points.size(); ++i)
        for (int k = 0; k < 3; ++k) pos.push_back(cloud.points[i][k]), nrm.push_back(cloud.normals[i][k]);
    for (const ca::Vec3& p : mesh.vertices) mpos.insert(mpos.end(), {p.x(), p.y(), p.z()});
    for (const ca::Tri& t : mesh.triangles) mtri.insert(mtri.end(), {t[0], t[1], t[2]});
    ca_context_desc desc;
    ca_context_desc_init(&desc);
    ca_context* ctx = nullptr;
    ca_context_create(&desc, &ctx);
    ca_candidate_set* set = nullptr;
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    const auto t0 = std::chrono::steady_clock::now();
    ca_candidate_options copt;
    ca_candidate_options_init(&copt);
    ca_select_options sopt;
    ca_select_options_init(&sopt);
    sopt.skip_uncoverable = 1;
    ca_connect_options kopt;
    ca_connect_options_init(&kopt);
    const ca_surface_view cv = bench::view_of(pos, none, nrm);
    if ((row.status = ca_candidates(ctx, &cv, &copt, &set)) == CA_OK && (row.status = ca_select(ctx, set, &sopt, &sel)) == CA_OK &&
        (row.status = ca_connect(ctx, set, sel, &kopt, &sk)) == CA_OK) {
        row.seconds = bench::seconds_since(t0);
        row.outliers = ca_candidate_set_outlier_count(set);
        row.uncovered = ca_selection_uncovered_count(sel);
        ca_skeleton_view skv;
        ca_skeleton_view_init(&skv);
        ca_skeleton_get_view(sk, &skv);
        row.balls = skv.vertex_count;
        ca_evaluate_options eopt;
        ca_evaluate_options_init(&eopt);
        ca_evaluation ev{};
        ev.struct_size = sizeof ev;
        const ca_surface_view mv = bench::view_of(mpos, mtri, {});
        if ((row.status = ca_evaluate(ctx, &mv, &skv, &eopt, &ev)) == CA_OK) row.h = ev.hd_recon_to_surface;
    }
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return row;
}

bool load(const std::string& path, ca::Mesh& mesh) {
    caio::MeshData md;
    std::string err;
    if (!caio::read_mesh(path, md, err) || md.triangles.empty()) return false;
    for (size_t i = 0; i + 2 < md.positions.size(); i += 3) mesh.vertices.emplace_back(md.positions[i], md.positions[i + 1], md.positions[i + 2]);
    for (size_t i = 0; i + 2 < md.triangles.size(); i += 3) mesh.triangles.push_back({md.triangles[i], md.triangles[i + 1], md.triangles[i + 2]});
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    std::vector<std::pair<std::string, ca::Mesh>> shapes_list;
    ca::Mesh m;
    if (load(std::string(CA_TEST_DATA) + "/fox.obj", m)) shapes_list.emplace_back("fox", m);
    m = {};
    if (load(root + "/meshes/paper/bunny.obj", m)) shapes_list.emplace_back("bunny", m);
    shapes_list.emplace_back("sphere", shapes::sphere(1.0, 96, 192));
    std::printf("\n## Clean and noisy clouds (5000 points; noisy: 0.5 %% Gaussian noise of the diagonal + 1 %% far outliers)\n\n");
    std::printf("| shape | cloud | status | outliers | balls | uncovered | h(recon -> surface) %% | s | noisy / clean h |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& [name, mesh] : shapes_list) {
        const shapes::Cloud clean = shapes::sample_cloud(mesh, 5000);
        const Row a = run(clean, mesh), b = run(shapes::noisy_cloud(clean, 0.005, 0.01), mesh);
        for (int k = 0; k < 2; ++k) {
            const Row& r = k ? b : a;
            std::printf("| %s | %s | %s | %llu | %zu | %zu | %.3f | %.2f | %s |\n", name.c_str(), k ? "noisy" : "clean",
                        r.status == CA_OK ? "ok" : ca_status_string(r.status), (unsigned long long)r.outliers, r.balls, r.uncovered,
                        r.h, r.seconds, k && a.h > 0 ? std::to_string(b.h / a.h).substr(0, 4).c_str() : "");
        }
    }
    return 0;
}
