// mesh_topology.h: the genus of each connected part of a triangle mesh, from its Euler
// characteristic (the skeleton's loops are checked against it, connect/loops.cpp), and the
// half-edges bucketed by vertex that the closedness and hole tests read.
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

// Half-edges (a, b), a != b, of the triangles' corners mapped by `vertex` (identity when empty),
// bucketed by their smaller vertex u (a counting sort): bucket u is key[start[u] .. start[u+1]),
// each key the larger vertex * 2 + (1 if the half-edge runs downwards, larger -> smaller), each
// bucket sorted, so the half-edges on one edge are adjacent.
struct HalfEdgeBuckets {
    std::vector<uint32_t> start;   // vertex count + 1 offsets
    std::vector<uint64_t> key;
};
// Stopped by `monitor` (tested every few thousand triangles and vertices): empty buckets.
HalfEdgeBuckets half_edge_buckets(const Mesh& mesh, const std::vector<uint32_t>& vertex = {},
                                  const Monitor& monitor = Monitor{});

}  // namespace ca
