// bench_robustness.cpp: runs the whole pipeline on every mesh under <data>/meshes (paper, extra,
// poor, thin) and prints, per model, the skeleton or the clear error it failed with. Nothing may
// crash, hang or abort. usage: bench_robustness [DATA_ROOT]
#include "bench_common.h"

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    std::vector<std::string> models;
    for (const char* sub : {"paper", "extra", "poor", "thin"})
        for (const std::string& f : bench::list_files(root + "/meshes/" + sub, ".obj")) models.push_back(f);
    if (models.empty()) {
        std::printf("bench_robustness: no models under %s/meshes, skipped\n", root.c_str());
        return 0;
    }
    ca_candidate_options co;
    ca_candidate_options_init(&co);
    ca_select_options so;
    ca_select_options_init(&so);
    so.time_limit_s = 10;
    ca_connect_options cop;
    ca_connect_options_init(&cop);
    std::printf("\n## Every mesh under meshes/ (defaults, exact cover with a 10 s budget)\n\n");
    std::printf("| model | result | |V| | |E| | |F| | components | b1 | optimal | total s |\n|---|---|---|---|---|---|---|---|---|\n");
    int ok = 0, refused = 0;
    for (const std::string& path : models) {
        const std::string name = path.substr(root.size() + 8);
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) { std::printf("| %s | read error: %s |\n", name.c_str(), err.c_str()); ++refused; continue; }
        const auto t = std::chrono::steady_clock::now();
        bench::PipelineRun r = bench::run_pipeline(mesh, co, so, cop);
        const double secs = bench::seconds_since(t);
        if (r.status == CA_OK) {
            ++ok;
            std::printf("| %s | skeleton | %zu | %zu | %zu | %zu | %ld | %s | %.2f |\n", name.c_str(), r.balls, r.edges, r.faces,
                        r.components, r.betti1, r.optimal ? "yes" : "no", secs);
        } else {
            ++refused;
            std::printf("| %s | %s: %s | | | | | | | %.2f |\n", name.c_str(), ca_status_string(r.status), r.message.c_str(), secs);
        }
    }
    std::printf("\n%zu meshes: %d skeletons, %d clear refusals, 0 crashes\n", models.size(), ok, refused);
    return 0;
}
