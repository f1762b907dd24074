// bench_robustness.cpp: runs the whole pipeline on every mesh under <data>/meshes (paper, extra,
// poor, thin) and prints, per model, the skeleton or the clear error it failed with. Nothing may
// crash, hang or abort. Then hostile generated inputs (repeated geometry, a huge polygon,
// duplicated vertices, a 2 M-triangle mesh, a 50 MB single-line OBJ), each read and run in its
// own process for its time and peak memory, beside a clean 40 k-triangle mesh (horse).
// usage: bench_robustness [DATA_ROOT]
#include "bench_common.h"
#include "bench_inputs.h"


namespace {

void generated_inputs(const std::string& root, const ca_candidate_options& co, const ca_select_options& so,
                      const ca_connect_options& cop) {
    char dir_template[] = "/tmp/bench_robustness.XXXXXX";
    const char* dir_c = mkdtemp(dir_template);
    if (!dir_c) { std::printf("\nbench_robustness: no temporary folder, generated inputs skipped\n"); return; }
    const std::string dir = dir_c;
    auto write_obj = [](const std::string& path, const caio::MeshData& m) {
        std::string s;
        char line[96];
        for (size_t i = 0; i + 2 < m.positions.size(); i += 3) {
            std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", m.positions[i], m.positions[i + 1], m.positions[i + 2]);
            s += line;
        }
        for (size_t i = 0; i + 2 < m.triangles.size(); i += 3) {
            std::snprintf(line, sizeof line, "f %u %u %u\n", m.triangles[i] + 1, m.triangles[i + 1] + 1, m.triangles[i + 2] + 1);
            s += line;
        }
        return bench::write_text(path, s);
    };
    std::string cycle = "";
    for (int k = 0; k < 8; ++k)
        cycle += "v " + std::to_string(k & 1) + " " + std::to_string((k >> 1) & 1) + " " + std::to_string(k >> 2) + "\n";
    cycle += "f";
    for (int i = 0; i < 100000; ++i) cycle += " " + std::to_string(1 + i % 8);
    cycle += "\n";
    // `made`: written; `generated`: a file of this run's temporary folder (removed after its row;
    // the reference mesh is the caller's data and is never removed)
    struct Row { const char* what; std::string path; bool made; bool generated = true; };
    std::vector<Row> rows = {
        {"clean mesh (horse, reference)", root + "/meshes/paper/horse.obj", true, false},
        {"30 000 coincident triangles (7 500 copies of a tetrahedron)", dir + "/tetra.obj",
         write_obj(dir + "/tetra.obj", bench::tetrahedron_copies(7500))},
        {"one polygon of 100 000 vertices on 8 positions (200 KB)", dir + "/polygon.obj", bench::write_text(dir + "/polygon.obj", cycle)},
        {"one polygon of 100 000 distinct vertices (a wavy circle)", dir + "/polygon_distinct.obj",
         bench::write_text(dir + "/polygon_distinct.obj", bench::polygon_obj(100000))},
        {"333 000 triangles on 8 positions", dir + "/soup.obj", write_obj(dir + "/soup.obj", bench::soup_on_cube_corners(333000))},
        {"1 000 000 vertices, each position 8 times (250 000-triangle torus)", dir + "/dupverts.ply",
         bench::write_binary_ply(dir + "/dupverts.ply", bench::duplicated_vertices(bench::torus(500, 250), 8))},
        {"2 000 000-triangle torus (binary PLY)", dir + "/torus.ply", bench::write_binary_ply(dir + "/torus.ply", bench::torus(2000, 500))},
        {"50 MB OBJ of one face line", dir + "/line.obj", bench::write_text(dir + "/line.obj", bench::single_line_obj(50u << 20))},
    };
    std::printf("\n## Generated inputs (defaults; each read and run in its own process)\n\n");
    std::printf("| input | triangles read | outcome | s (read + pipeline) | x horse | peak RSS MB |\n|---|---|---|---|---|---|\n");
    double reference = 0;
    int within = 0, measured = 0;
    for (const Row& row : rows) {
        if (!row.made) { std::printf("| %s | | not written | | | |\n", row.what); continue; }
        double peak = 0;
        const bench::Outcome o = bench::run_isolated(row.path, co, so, cop, peak);
        if (reference == 0) reference = o.seconds;
        const std::string outcome = !o.read_ok ? std::string("read error: ") + o.message
                                    : o.status == CA_OK ? std::to_string(o.balls) + " balls"
                                                        : std::string(ca_status_string(o.status)) + ": " + o.message;
        std::printf("| %s | %zu | %s | %.2f | %.1f | %.0f |\n", row.what, o.triangles, outcome.c_str(), o.seconds,
                    reference > 0 ? o.seconds / reference : 0.0, peak);
        std::fflush(stdout);
        if (row.generated) std::remove(row.path.c_str());
        // the target: at most 3x the clean mesh's time (8x for the 2 M-triangle mesh), 1.5 GB
        if (&row != &rows.front() && reference > 0) {
            const double limit = std::string(row.what).rfind("2 000 000", 0) == 0 ? 8.0 : 3.0;
            ++measured;
            within += o.seconds <= limit * reference && peak <= 1536;
        }
    }
    rmdir(dir.c_str());
    std::printf("\n%d of %d generated inputs within their time (3x horse; 2 M triangles 8x) and 1.5 GB\n", within,
                measured);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    std::vector<std::string> models;
    for (const char* sub : {"paper", "extra", "poor", "thin"})
        for (const std::string& f : bench::list_files(root + "/meshes/" + sub, ".obj")) models.push_back(f);
    if (models.empty()) {
        std::printf("bench_robustness: no models under %s/meshes, skipped\n", root.c_str());
        return 0;
    }
    bench::DefaultOptions d;
    d.select.time_limit_s = 10;
    std::printf("\n## Every mesh under meshes/ (defaults, exact cover with a 10 s budget)\n\n");
    std::printf("| model | result | |V| | |E| | |F| | components | b1 | optimal | total s |\n|---|---|---|---|---|---|---|---|---|\n");
    int ok = 0, refused = 0;
    for (const std::string& path : models) {
        const std::string name = path.substr(root.size() + 8);
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) { std::printf("| %s | read error: %s |\n", name.c_str(), err.c_str()); ++refused; continue; }
        const auto t = std::chrono::steady_clock::now();
        bench::PipelineRun r = bench::run_pipeline(mesh, d.candidates, d.select, d.connect);
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
    std::fflush(stdout);
    generated_inputs(root, d.candidates, d.select, d.connect);
    return 0;
}
