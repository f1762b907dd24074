// target_count_hd.h: the lowest error for a ball budget, the reverse of target_error.h. Among
// the offset deltas giving at most K balls on one candidate set, the one whose skeleton,
// connected and measured exactly as the evaluation does (evaluate.h), has the lowest two-sided
// Hausdorff distance, found by probes of select + connect + evaluate (delta_probe.h).
//
// The search: the first probe is the target size (selection.h, SelectOptions::target_count):
// the smallest delta d0 whose cover has at most K balls, found by bisection. The HD is not
// monotone in delta (a larger delta gives fewer balls, but a different cover that may sit
// better), so the next probes are at d0 * (1 + step * i), i = 1 .. max_probes - 1 (when d0 is 0,
// the lower end, at opt.delta * step * i). A probe with more than K balls (a solver that did not
// reach the optimum) is never returned. Each probe is measured coarsely (coarse_envelope_samples
// samples of E's boundary instead of evaluate's envelope_samples); the target size's probe, then
// those with at most K balls whose coarse HD is below the best exact HD so far (lowest coarse HD
// first) are measured exactly (evaluate's hd_only on the surface prepared once). The result is
// the exactly measured probe of lowest HD among those with at most K balls, ties to fewer balls,
// then to the smaller delta.
//
// What this guarantees: at most K balls; an HD (the one reported, exact, not re-sampled) no
// higher than that of the plain target size's result, which is the first probe; deterministic
// for given options. It is the best of the exactly measured probes only: a probe whose coarse HD
// misjudged it, or an untried delta, may do better.
#pragma once
#include "delta_probe.h"

#include <vector>

namespace ca {

struct TargetCountHdOptions {
    ConnectOptions connect;       // how each probe is connected (the caller's or the defaults)
    std::optional<FitOptions> fit;  // set: each probe is fitted after connecting (fit.h), so the HD
                                    // judged is the fitted skeleton's
    EvaluateOptions evaluate;     // how each probe is measured (ca_evaluate's defaults)
    uint32_t max_probes = 9;      // select + connect + evaluate runs, the first included (>= 1)
    double step = 0.02;           // relative delta step between probes (> 0)
    uint32_t coarse_envelope_samples = 10000;  // the coarse measurement's samples of E's boundary
};

struct TargetCountHdResult {
    Selection selection;          // the chosen probe's selection (delta = its offset; probes = the
                                  // set-cover solves of the whole search; time_total_s = the search)
    Skeleton skeleton;            // its connected skeleton, internal units
    EvaluateResult evaluation;    // its measurement
    std::vector<TargetErrorProbe> probes;  // in the order they ran; passed = at most K balls; hd
                                           // exact where `exact`, else the coarse measurement
    bool stopped = false;         // the time limit ended the search early: the best so far (its
                                  // HD the coarse one when no probe could be measured exactly)
};

// The coarse measurement of a probe: `exact` with at most `envelope_samples` samples of E's
// boundary (the surface samples and seed unchanged, so a surface prepared for `exact` serves both).
EvaluateOptions coarse_evaluation(const EvaluateOptions& exact, uint32_t envelope_samples);

// Offset dilation only, opt.target_count = K > 0; the set must have a surface (not one built
// from caller arrays). opt.delta is where the target size's bracket starts, opt.target_tolerance
// its bisection tolerance. When the time limit runs out after the first probe has finished, the
// best probe so far is returned (the probes measured so far, the best exact one); a cancel
// returns the stop status. Progress: stage "target count: probes", the share of probes run.
Status select_target_count_hd(const CandidateSet& set, const SelectOptions& opt, const TargetCountHdOptions& tc,
                              const Monitor& monitor, TargetCountHdResult& out);

}  // namespace ca
