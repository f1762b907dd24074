// mesh_topology.h: the half-edges of a triangle mesh bucketed by vertex, and what the surface
// preparation reads from them once for the later steps: whether the mesh is closed (its winding
// number integer-valued) and the genus of each connected part from its Euler characteristic (the
// skeleton's loops are checked against it, connect/loops.cpp).
#pragma once
#include "common.h"

namespace ca {

// Half-edges (a, b) of the triangles' corners mapped by `vertex` (identity when empty; triangles
// with a corner out of range or two corners mapped to one vertex have none), bucketed by their
// smaller vertex u (a counting sort): bucket u is key[start[u] .. start[u+1]), each key the
// larger vertex * 2 + (1 if the half-edge runs downwards, larger -> smaller), each bucket
// sorted, so the half-edges on one edge are adjacent.
struct HalfEdgeBuckets {
    std::vector<uint32_t> start;   // vertex count + 1 offsets
    std::vector<uint64_t> key;
};
// Stopped by `monitor` (tested every few thousand triangles and vertices): empty buckets.
HalfEdgeBuckets half_edge_buckets(const Mesh& mesh, const std::vector<uint32_t>& vertex = {},
                                  const Monitor& monitor = Monitor{});

struct MeshTopology {
    // Per connected part (triangles sharing a welded vertex), in order of each part's first
    // triangle: its genus, or -1 when unknown (the part is open or not edge-manifold, or its Euler
    // characteristic is not that of a closed orientable surface).
    std::vector<long> part_genus;
    std::vector<uint32_t> triangle_part;   // the part of each triangle
    std::vector<uint8_t> part_open;        // per part: 1 if an edge of it is on one triangle only (a boundary)
    long genus = -1;                       // sum over the parts; -1 if any part is unknown
    // Every edge has as many half-edges one way as the other (and every triangle is valid): the
    // winding number is then an integer off the surface.
    bool closed = false;
    size_t open_parts() const;             // parts with a boundary (sheets, cards, open cloth)
};

// From the buckets of the mesh's welded corners (half_edge_buckets with the weld map, or with
// none when the triangles already refer to welded vertices, as after merge_duplicate_geometry).
// Triangles with two corners on one welded vertex are ignored. A part is closed and
// edge-manifold when every edge is on exactly two of its triangles; then chi = V - E + F and
// genus = (2 - chi) / 2. Stopped by `monitor`: an empty result (genus -1, not closed).
MeshTopology mesh_topology(const Mesh& mesh, const std::vector<uint32_t>& weld, const HalfEdgeBuckets& edges,
                           const Monitor& monitor = Monitor{});
// The same, welding vertices with equal coordinates first (duplicates.h).
MeshTopology mesh_topology(const Mesh& mesh);

}  // namespace ca
