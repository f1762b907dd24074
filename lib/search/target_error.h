// target_error.h: error-bounded selection. The fewest balls whose skeleton, connected and
// measured exactly as the evaluation does (evaluate.h), has a two-sided Hausdorff distance of at
// most E % of the bounding-box diagonal, found by a search over the offset delta on one
// candidate set: each probe selects at one delta, connects and evaluates.
//
// The search (delta_search.h): bracket the largest passing delta (HD <= E) from the given delta,
// each step scaled by E / HD (the skeleton's HD grows about in proportion to delta), refine the
// bracket, then probe the neighbourhood of the best probe (the HD is not monotone in delta), at
// most max_probes probes in all; a bracket whose ends' counts differ by one is not refined (the
// count-down probes that count). The count-down: while the best passing probe has n > 1 balls,
// the probes target_count's search (target_count_hd.h) makes for n - 1 balls: the
// target size d0 (the smallest delta with at most n - 1 balls, selection.h), then
// d0 (1 + count_down_step i), i = 1 .. count_down_sweep - 1, until one passes with fewer balls,
// which becomes the best; the first count none passes for ends it (at most max_count_down probes). The result is the best passing
// probe (fewest balls, then lowest HD, then larger delta), or, when none passes, the probe of
// lowest HD with `reached` false.
//
// Each probe is measured coarsely first (coarse_envelope_samples samples of E's boundary, about
// a lower bound of the exact HD): above E it fails on that figure (its hd is the coarse one);
// otherwise it is measured exactly (evaluate's hd_only on the surface prepared once), which
// decides whether it passes. With `also_fitted` (and `fit` unset) each probe's skeleton is
// measured unfitted and fitted with those options, and the one of lower coarse HD is judged: one
// cover per delta serves both (`fitted` says which the result is).
//
// What this guarantees: the returned selection's HD, measured with the given evaluation
// options, is the HD reported (it is not re-sampled), and is <= E when `reached`. The HD is not
// monotone in delta, so a delta between two probes may give fewer balls within E: no bound
// holds between probes, and no lower bound on the count is known (a larger untried delta, fewer
// balls, may pass). With an optimal solver the cover size is non-increasing in delta, so
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
    std::optional<FitOptions> also_fitted;  // set, with fit unset: each probe judged unfitted and
                                            // fitted with these, the lower HD of the two
    uint32_t max_probes = 10;     // select + connect + evaluate runs of the delta search, at most
    uint32_t max_count_down = 12;   // the count-down's probes after it, at most
    uint32_t count_down_sweep = 9;  // probes per count, its target size included (target_count's 9)
    double count_down_step = 0.02;  // their relative delta step (target_count's)
    uint32_t coarse_envelope_samples = 10000;  // the coarse measurement's samples of E's boundary
};

struct TargetErrorResult {
    Selection selection;          // the chosen probe's selection (delta = its offset; probes = the
                                  // probes run; time_total_s = the whole search)
    Skeleton skeleton;            // its connected skeleton, internal units
    EvaluateResult evaluation;    // its measurement
    bool reached = false;         // some probe had HD <= target_error
    bool fitted = false;          // the result's skeleton is the fitted one (fit or also_fitted)
    bool stopped = false;         // the time limit ended the search: the best probe so far
    std::vector<TargetErrorProbe> probes;  // in the order they ran
};

// Offset dilation only (opt.dilation == offset, opt.target_count == 0); the set must have a
// surface (not one built from caller arrays). opt.target_tolerance is the bisection tolerance
// on delta. A probe below the starting delta that finds samples no ball covers ends the
// descent; a start without a cover doubles delta until one exists. When the time limit runs out
// after a probe has finished, the best probe so far is returned with `stopped` set; a cancel
// returns the stop status. Progress: stage "target error: probes", the share of the probes run;
// after each probe an info note names it and the best so far.
Status select_target_error(const CandidateSet& set, const SelectOptions& opt, const TargetErrorOptions& te,
                           const Monitor& monitor, TargetErrorResult& out);

}  // namespace ca
