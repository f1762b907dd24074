// selection.h: step 2 of the pipeline. Dilate the candidate balls (offset r + delta or scale
// r * sigma), build the sparse coverage relation with the surface samples, and choose the
// fewest balls that cover every sample (setcover.h).
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
    CoverOptions cover;      // solver, time limit, masks
};

struct Selection {
    std::vector<uint32_t> indices;      // into CandidateSet::balls
    std::vector<double> dilated_radii;  // per selected ball, internal units
    double delta = 0;                   // the offset in internal units (0 for scale)
    CoverResult cover;
    double time_coverage_s = 0, time_total_s = 0;
};

// The dilated radius of a ball under the options.
double dilate(double radius, const SelectOptions& opt);

Status select_balls(const CandidateSet& set, const SelectOptions& opt, const Monitor& monitor, Selection& out);

}  // namespace ca
