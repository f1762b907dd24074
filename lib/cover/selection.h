// selection.h: step 2 of the pipeline. Dilate the candidate balls (offset r + delta or scale
// r * sigma), build the sparse coverage relation with the surface samples, and choose the
// fewest balls that cover every sample (setcover.h). Two extensions:
//  - target size: the smallest dilation whose cover has at most `target_count` balls;
//  - divide and conquer for many samples (paper §8.1): spatial parts solved separately, merged.
#pragma once
#include "candidates.h"
#include "setcover.h"

namespace ca {

enum class Dilation : int32_t { offset = 0, scale = 1 };

struct SelectOptions {
    Dilation dilation = Dilation::offset;
    double delta = 0.02;     // internal units = fraction of the longest bbox side
    double scale = 1.5;
    bool skip_uncoverable = false;
    // Worker threads of the coverage queries and the local search (0 = all cores, 1 = serial);
    // the result is the same for any number. CoverOptions::search_threads, when set, wins.
    int32_t threads = 0;
    CoverOptions cover;      // solver, time limit (per solve: per probe / per part), masks

    // Target size (0 = off): return a selection of at most target_count balls with the smallest
    // dilation (delta, or sigma for Dilation::scale) found by bisection, starting from the
    // delta/scale above (doubled until the cover has <= target_count balls). Coverage only grows
    // with the dilation, so the optimum cover size is non-increasing in it: with the exact
    // solver and every probe proven optimal, the returned dilation d satisfies
    //   optimum(d) <= target_count  and  optimum(d - target_tolerance) > target_count
    // (or d is the lower end: 0 for offset, 1 for scale). A probe that is not proven optimal
    // (time limit, heuristic solver) may overestimate its optimum, and d may then be larger
    // than the true smallest one. Each probe only decides whether K balls suffice
    // (CoverOptions::give_up_above = K: a solve stops once its bound exceeds K), so a probe far
    // below the threshold costs little; the decisions and d are those of full solves.
    // Selection::probes counts the solves.
    uint32_t target_count = 0;
    double target_tolerance = 1e-4;  // absolute, in delta (internal units) or sigma

    // Divide and conquer: with more than dc_threshold samples (0 = never), the samples are split
    // spatially (median cuts along the longest box side) into parts of at most dc_part_samples,
    // each part is covered by its own exact/heuristic solve (every ball that covers one of its
    // samples allowed), the union is made irredundant (or replaced by the global greedy cover
    // when that is smaller). The lower bound reported is the larger of the largest part bound
    // (each part is a relaxation of the whole problem) and the global reduction's bound (forced
    // balls + disjoint kernel rows); proven_optimal is 1 only when it meets the objective.
    // Below the threshold the whole problem takes the exact path, where row generation keeps a
    // large kernel tractable: at |S| = 30 000 it gave smaller covers with tighter bounds than
    // the parts in the same time (bench_select), hence the high default.
    uint32_t dc_threshold = 100000;
    uint32_t dc_part_samples = 2500;
};

struct Selection {
    std::vector<uint32_t> indices;      // into CandidateSet::balls
    std::vector<double> dilated_radii;  // per selected ball, internal units
    double delta = 0;                   // the offset in internal units (0 for scale)
    double scale = 0;                   // the scale factor used (0 for offset)
    CoverResult cover;
    uint32_t probes = 0;                // target size: number of set-cover solves
    uint32_t parts = 0;                 // divide and conquer: number of parts (0 = not used)
    bool sized_by_count = false;        // made by target_count (select_step): few balls, fitted by default
    bool judged_fitted = false;         // a target_error search judged it by its fitted skeleton (fitted by default)
    double time_coverage_s = 0, time_total_s = 0;
};

// The dilated radius of a ball under the options.
double dilate(double radius, const SelectOptions& opt);

Status select_balls(const CandidateSet& set, const SelectOptions& opt, const Monitor& monitor, Selection& out);

}  // namespace ca
