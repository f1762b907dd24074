// make_inputs.cpp: writes the benchmarks' generated inputs as files, for the command-line tool
// and profilers: torus_2m.ply (2 000 000 triangles, binary PLY), tetra_7500.obj (30 000
// coincident triangles), polygon_100k.obj (one face of 100 000 vertices), single_line.obj (one
// 50 MB face line). usage: make_inputs OUT_DIR
#include "bench_inputs.h"

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: make_inputs OUT_DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    caio::MeshData tetra = bench::tetrahedron_copies(7500);
    std::string obj;
    for (size_t i = 0; i < tetra.positions.size(); i += 3)
        obj += "v " + std::to_string(tetra.positions[i]) + " " + std::to_string(tetra.positions[i + 1]) + " " +
               std::to_string(tetra.positions[i + 2]) + "\n";
    for (size_t i = 0; i < tetra.triangles.size(); i += 3)
        obj += "f " + std::to_string(tetra.triangles[i] + 1) + " " + std::to_string(tetra.triangles[i + 1] + 1) + " " +
               std::to_string(tetra.triangles[i + 2] + 1) + "\n";
    const bool ok = bench::write_binary_ply(dir + "/torus_2m.ply", bench::torus(2000, 500)) &&
                    bench::write_text(dir + "/tetra_7500.obj", obj) &&
                    bench::write_text(dir + "/polygon_100k.obj", bench::polygon_obj(100000)) &&
                    bench::write_text(dir + "/single_line.obj", bench::single_line_obj(50u << 20));
    if (!ok) std::fprintf(stderr, "make_inputs: cannot write to %s\n", dir.c_str());
    return ok ? 0 : 1;
}
