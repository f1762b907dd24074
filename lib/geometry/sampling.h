// sampling.h: seeded, area-uniform samples on a triangle mesh; seeded subsets of point clouds;
// removal of exact and near-duplicate points (before Qhull).
#pragma once
#include "common.h"

namespace ca {

// n points distributed uniformly by area over the mesh's triangles. Deterministic for a seed.
std::vector<Vec3> sample_surface(const Mesh& mesh, size_t n, uint64_t seed,
                                 std::vector<uint32_t>* triangle_of_sample = nullptr);
// The same samples into `out`, testing `monitor` every few thousand triangles and samples;
// false (out unspecified) once it says stop.
bool sample_surface(const Mesh& mesh, size_t n, uint64_t seed, std::vector<Vec3>& out, const Monitor& monitor,
                    std::vector<uint32_t>* triangle_of_sample = nullptr);

// A seeded random subset of min(n, pts.size()) indices (n == 0: all), in ascending order.
std::vector<uint32_t> random_subset(size_t count, size_t n, uint64_t seed);

// Indices of the points kept after removing those within `tolerance` of an earlier kept point.
std::vector<uint32_t> remove_near_duplicates(const std::vector<Vec3>& pts, double tolerance);

}  // namespace ca
