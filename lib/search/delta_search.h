// delta_search.h: the delta search of the error-bounded selection (target_error.h), apart from
// what a probe runs, so that it can be driven by any probe function (a synthetic HD(delta) in the
// tests). It chooses the deltas, judges each probe against E and keeps the best one.
//
// Phase 1 (bracket and refine): the first probe is at `start`. While the probes pass (HD <= E)
// delta grows by E / HD (at least 1.25, at most 4 times; doubled from a delta without a cover; to
// kLargestDelta), while they fail it shrinks by E / HD (at least to a half, at most to a quarter;
// not below `floor`): the HD grows about in proportion to delta. Once a passing delta and a
// larger failing one bracket the largest passing delta, the bracket is cut where the HD, linear
// between its ends, meets E (a quarter to three quarters in), to `tolerance` (or, with
// count_down, until lo's balls are at most hi's + 1), keeping a third of max_probes (rounded
// down) for phase 2. This assumes HD(delta) is monotone, which it is not (the fit, the
// connection): a delta above the bracket, or between two failing probes, can pass.
// Phase 2 (neighbourhood), with the probes left: when a probe passes, the gap between the best
// passing delta L and the nearest failing delta H above it is bisected (not with count_down when
// their counts differ by at most one), then 1.1 H, 1.25 H, 1.5 H, 2 H, 3 H (1.25 L, 1.5 L, 2 L when
// no probe above L failed) and 0.9 L are probed; when none passes, 1.25 and 1.5 times the start, then the midpoints of
// adjacent probed deltas (the widest gap by ratio first, of equal ones the larger). The candidate list is recomputed after every probe
// (a new best moves L and H), deltas already probed (or out of [floor, kLargestDelta]) are
// skipped, and the phase ends when no candidate is left or max_probes probes have run.
// The best probe: passing first, then fewer balls, lower HD, larger delta; when none passes, the
// lowest HD (then fewer balls). Deterministic: the deltas depend only on the probes' results.
#pragma once
#include "delta_probe.h"

#include <functional>
#include <vector>

namespace ca {

// A delta doubled at most this far: at 1 (the longest bbox side) every ball covers the shape.
constexpr double kLargestDelta = 1.0;

struct DeltaSearchOptions {
    double start = 0.02;          // the first delta (> 0)
    double floor = 0.005;         // halving stops here (a cover exists at and above it)
    double tolerance = 1e-3;      // bisection stops when the bracket is narrower
    double target_error = 2;      // E: a probe passes when its HD <= E
    uint32_t max_probes = 14;     // probes run, those without a cover included
    bool count_down = false;      // the caller then probes the count below the best itself: a
                                  // bracket whose ends' counts differ by one is not refined
};

struct DeltaSearchResult {
    std::vector<TargetErrorProbe> probes;  // in the order they ran (uncoverable ones left out)
    size_t best = 0;              // index in probes of the best one (when probes is not empty)
    uint32_t runs = 0;            // probes run, uncoverable ones included
};

// probe(d, summary): runs one probe at delta d and fills summary.delta, balls and hd (passed is
// set by the search). Its status: success; Code::uncoverable (no cover at d: not kept, the
// descent stops); anything else stops the search and is returned. keep(): called right after a
// probe that is the best so far (the caller keeps what that probe produced).
Status search_delta(const DeltaSearchOptions& opt, const std::function<Status(double, TargetErrorProbe&)>& probe,
                    const std::function<void()>& keep, DeltaSearchResult& out);

// The better of two probes (the order above).
bool better_probe(const TargetErrorProbe& a, const TargetErrorProbe& b);

}  // namespace ca
