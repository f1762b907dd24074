// candidates.h: step 1 of the pipeline. Surface samples S to cover, and inner candidate balls P:
// inside Voronoi vertices of |C| surface samples (radius = circumradius), random interior points
// (radius = exact distance to the mesh), or for oriented point clouds the Voronoi vertices on the
// inner side of all four generating points' normals, with the outlier filter of the paper.
#pragma once
#include "common.h"
#include "surface.h"

namespace ca {

enum class Generator : int32_t { voronoi = 0, random = 1 };

struct CandidateOptions {
    Generator generator = Generator::voronoi;
    uint32_t cover_samples = 1500;
    uint32_t voronoi_samples = 4000;
    uint32_t random_candidates = 10000;
    uint64_t seed = 1;
    int32_t threads = 0;    // 0 = all cores
};

// Everything later steps need, in internal (unit-cube) units.
struct CandidateSet {
    Surface surface;                      // empty mesh when built from caller arrays
    std::vector<Vec3> cover_samples;      // S
    std::vector<Vec3> dense_samples;      // samples used by the connection step (C, or the points)
    std::vector<Ball> balls;              // P, undilated medial radii
    double time_sampling_s = 0, time_candidates_s = 0;
};

Status generate_candidates(Surface surface, const CandidateOptions& opt, const Monitor& monitor,
                           CandidateSet& out);

}  // namespace ca
