// mesh_convert.h: a mesh read by examples/io (caio::MeshData) as the core's ca::Mesh, for tests
// and benchmarks that call the core directly.
#pragma once
#include "common.h"
#include "mesh_io.h"

#include <string>

inline ca::Mesh to_core_mesh(const caio::MeshData& m) {
    ca::Mesh out;
    for (size_t i = 0; i + 2 < m.positions.size(); i += 3)
        out.vertices.emplace_back(m.positions[i], m.positions[i + 1], m.positions[i + 2]);
    for (size_t i = 0; i + 2 < m.triangles.size(); i += 3)
        out.triangles.push_back({m.triangles[i], m.triangles[i + 1], m.triangles[i + 2]});
    return out;
}

// Reads a mesh file as a core mesh; false (and `error` set) when it cannot be read.
inline bool read_core_mesh(const std::string& path, ca::Mesh& out, std::string& error) {
    caio::MeshData data;
    if (!caio::read_mesh(path, data, error)) return false;
    out = to_core_mesh(data);
    return true;
}
