// bench_surface.h: for the benchmarks that call the C++ core directly (bench_select,
// bench_reduce): a mesh file read into a prepared (validated, normalised) ca::Surface.
#pragma once
#include "mesh_io.h"
#include "surface.h"

#include <string>

namespace bench {

inline bool load_surface(const std::string& path, ca::Surface& s) {
    caio::MeshData md;
    std::string err;
    if (!caio::read_mesh(path, md, err)) return false;
    ca::Mesh m;
    for (size_t i = 0; i + 2 < md.positions.size(); i += 3)
        m.vertices.emplace_back(md.positions[i], md.positions[i + 1], md.positions[i + 2]);
    for (size_t i = 0; i + 2 < md.triangles.size(); i += 3)
        m.triangles.push_back({md.triangles[i], md.triangles[i + 1], md.triangles[i + 2]});
    return ca::prepare_surface(std::move(m), {}, s).ok();
}

}  // namespace bench
