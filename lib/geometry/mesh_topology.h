// mesh_topology.h: the genus of each connected part of a triangle mesh, from its Euler
// characteristic. The skeleton's loops are checked against it (connect/loops.cpp).
#pragma once
#include "common.h"

namespace ca {

struct MeshTopology {
    // Per connected part (triangles sharing a welded vertex), in order of each part's first
    // triangle: its genus, or -1 when unknown (the part is open or not edge-manifold, or its Euler
    // characteristic is not that of a closed orientable surface).
    std::vector<long> part_genus;
    std::vector<uint32_t> triangle_part;   // the part of each triangle
    long genus = -1;                       // sum over the parts; -1 if any part is unknown
};

// Vertices with equal coordinates are welded first (duplicates.h); triangles with two corners at
// one position are ignored. A part is closed and edge-manifold when every edge is on exactly two
// of its triangles; then chi = V - E + F and genus = (2 - chi) / 2.
MeshTopology mesh_topology(const Mesh& mesh);

}  // namespace ca
