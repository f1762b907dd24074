// bench_formats.cpp: every readable format on one model each (tests/data/formats: fox.obj and the
// first 500 points of fish_points.xyz re-encoded by make_formats.py): read through read_mesh, then
// the whole pipeline at the defaults. Prints a Markdown table: format | file | read ok? | input
// vertices | triangles | normals | read ms (median of 5) | pipeline status | |V| (balls) |
// pipeline s. The clouds are small (500 points) so the files stay small; the pipeline status
// shows how the cloud route fares on them, which is not the readers' business.
// usage: bench_formats [DATA_ROOT]   (the argument is accepted for `make bench` and unused: the
// models are the repository's own)
#include "bench_common.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

int main() {
    const std::string dir = std::string(CA_TEST_DATA) + "/formats/";
    const std::vector<std::string> files = {
        "../fox.obj", "fox.off", "fox.ply", "fox.stl", "fox_ascii.stl", "fox.gltf", "fox_embedded.gltf",
        "fox_nodes.gltf", "fox.glb", "fox.dae", "fish500.xyz", "fish500_nonormals.xyz", "fish500.ply",
        "fish500_nonormals.ply", "fish500.obj", "fish500_nonormals.obj", "fish500.pts", "fish500_plain.pts"};
    const bench::DefaultOptions d;
    std::printf("\n## Readers: one model per format (tests/data/formats), then the pipeline at the defaults\n\n");
    std::printf("| format | file | read ok? | input vertices | triangles | normals | read ms | pipeline | |V| | pipeline s |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& f : files) {
        const std::string path = dir + f;
        const std::string name = f.substr(f.find_last_of('/') + 1);
        const std::string format = name.substr(name.find_last_of('.') + 1);
        caio::MeshData mesh;
        std::string err;
        std::vector<double> ms;
        bool ok = true;
        for (int rep = 0; rep < 5 && ok; ++rep) {
            const auto t = std::chrono::steady_clock::now();
            ok = caio::read_mesh(path, mesh, err);
            ms.push_back(1000 * bench::seconds_since(t));
        }
        if (!ok) {
            std::printf("| %s | %s | no: %s | | | | | | | |\n", format.c_str(), name.c_str(), err.c_str());
            continue;
        }
        std::sort(ms.begin(), ms.end());
        const auto t = std::chrono::steady_clock::now();
        const bench::PipelineRun r = bench::run_pipeline(mesh, d.candidates, d.select, d.connect);
        const double total = bench::seconds_since(t);
        std::printf("| %s | %s | yes | %zu | %zu | %s | %.2f | %s | %s | %.3f |\n", format.c_str(), name.c_str(),
                    mesh.positions.size() / 3, mesh.triangles.size() / 3, mesh.normals.empty() ? "no" : "yes",
                    ms[ms.size() / 2], ca_status_string(r.status), r.status == CA_OK ? std::to_string(r.balls).c_str() : "-", total);
    }
    return 0;
}
