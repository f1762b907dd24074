// duplicates.h: merging repeated geometry before any structure is built, so that the cost of
// the pipeline grows with the distinct surface, not with how often the input repeats it.
#pragma once
#include "common.h"

namespace ca {

// For every vertex, the smallest index with exactly the same coordinates (itself when unique).
// Empty when `monitor` says stop (tested every Monitor::kCheckEvery vertices).
std::vector<uint32_t> weld_map(const std::vector<Vec3>& vertices, const Monitor& monitor = Monitor{});

struct MergeCounts {
    size_t degenerate = 0;   // triangles with two corners at one position
    size_t duplicate = 0;    // triangles on the same three positions as a kept one
    bool stopped = false;    // `monitor` said stop: the mesh is unchanged
};

// Welds exactly equal vertices (triangles refer to the first vertex at each position; the vertex
// array is unchanged), drops triangles with two corners at one position, and keeps one triangle
// per set of three positions: the first in the orientation most of its copies have. When both
// orientations are equally common it keeps the first of each: the pair cancels in the winding
// number, as all the copies did, and still carries the surface for sampling and distances.
// Kept triangles stay in input order, so a mesh without repeats is returned unchanged.
// Tests `monitor` every Monitor::kCheckEvery items of each pass; stopped, it leaves the mesh as it was.
MergeCounts merge_duplicate_geometry(Mesh& mesh, const Monitor& monitor = Monitor{});

}  // namespace ca
