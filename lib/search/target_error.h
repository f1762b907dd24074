// target_error.h: error-bounded selection. The fewest balls whose skeleton, connected and
// measured exactly as the evaluation does (evaluate.h), has a two-sided Hausdorff distance of at
// most E % of the bounding-box diagonal, found by a search over the offset delta on one
// candidate set: each probe selects at one delta, connects and evaluates.
//
// The search (delta_search.h): bracket the largest passing delta (HD <= E) by doubling or
// halving from the given delta, bisect it, then probe the neighbourhood of the best probe (the HD
// is not monotone in delta), at most max_probes probes in all. The result is the best passing probe
// (fewest balls, then lowest HD, then larger delta), or, when none passes, the probe of lowest HD
// with `reached` false.
//
// Each probe is measured coarsely first (coarse_envelope_samples samples of E's boundary, about
// a lower bound of the exact HD): above E it fails on that figure (its hd is the coarse one);
// otherwise it is measured exactly (evaluate's hd_only on the surface prepared once), which
// decides whether it passes.
//
// What this guarantees: the returned selection's HD, measured with the given evaluation
// options, is the HD reported (it is not re-sampled), and is <= E when `reached`. The HD is not
// monotone in delta, so a delta between two probes may give fewer balls within E: no bound
// holds between probes. With an optimal solver the cover size is non-increasing in delta, so
// the largest passing delta found usually carries the fewest balls.
#pragma once
#include "delta_probe.h"

namespace ca {

struct TargetErrorOptions {
    double target_error = 2;      // E, percent of the input bounding-box diagonal (> 0)
    ConnectOptions connect;       // how each probe is connected (the caller's or the defaults)
    std::optional<FitOptions> fit;  // set: each probe is fitted after connecting (fit.h), so the HD
                                    // judged is the fitted skeleton's
    EvaluateOptions evaluate;     // how each probe is measured (ca_evaluate's defaults)
    uint32_t max_probes = 14;     // select + connect + evaluate runs, at most
    uint32_t coarse_envelope_samples = 10000;  // the coarse measurement's samples of E's boundary
};

struct TargetErrorResult {
    Selection selection;          // the chosen probe's selection (delta = its offset; probes = the
                                  // probes run; time_total_s = the whole search)
    Skeleton skeleton;            // its connected skeleton, internal units
    EvaluateResult evaluation;    // its measurement
    bool reached = false;         // some probe had HD <= target_error
    std::vector<TargetErrorProbe> probes;  // in the order they ran
};

// Offset dilation only (opt.dilation == offset, opt.target_count == 0); the set must have a
// surface (not one built from caller arrays). opt.target_tolerance is the bisection tolerance
// on delta. A probe below the starting delta that finds samples no ball covers ends the
// descent; a start without a cover doubles delta until one exists. When the time limit runs out after a probe has finished, the best probe so far is
// returned; a cancel returns the stop status.
Status select_target_error(const CandidateSet& set, const SelectOptions& opt, const TargetErrorOptions& te,
                           const Monitor& monitor, TargetErrorResult& out);

}  // namespace ca
