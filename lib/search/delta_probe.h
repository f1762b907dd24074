// delta_probe.h: one probe of the delta searches (target_error.h, target_count_hd.h): select at
// one offset delta on a candidate set, connect, optionally fit (fit.h), evaluate against the
// set's surface, so that every search measures its candidates exactly as ca_connect +
// ca_evaluate would.
#pragma once
#include "candidates.h"
#include "connect.h"
#include "evaluate.h"
#include "fit.h"
#include "selection.h"

#include <optional>

namespace ca {

struct TargetErrorProbe {
    double delta = 0;             // internal units (fraction of the longest bbox side)
    size_t balls = 0;
    double hd = 0;                // two-sided HD, percent of the diagonal
    bool passed = false;          // target_error: hd <= E; target_count: balls <= K
    bool exact = true;            // target_count: false when hd is the coarse measurement only
};

// One probe with everything it produced (kept by a search while it is the best so far).
struct DeltaProbe {
    TargetErrorProbe summary;     // delta, balls and hd set; passed left to the search
    Selection selection;
    Skeleton skeleton;
    EvaluateResult evaluation;    // the HD only (hd_two_sided and the one-sided maxima)
};

// A step stopped as cancelled while no cancel was asked but the time limit has run out (the fit
// reports every stop as a cancel): the time limit's status, so that a search keeps its best so
// far; any other status unchanged.
Status stop_cause(const Status& st, const Monitor& monitor);

// Selects with `opt` at opt.delta (opt.target_count as given: 0 for one solve), connects with
// `connect`, fits with `fit` when it is set (fit_skeleton: a no-op without a triangle mesh) and
// evaluates with `evaluate` against set.surface.mesh, prepared once by the search (`surface`,
// prepare_evaluation with the same options): only the HD is measured (evaluate's hd_only, the same
// maxima as ca_evaluate). The first failing step's status is returned (Code::uncoverable when no
// cover exists at that delta).
Status probe_delta(const CandidateSet& set, const SelectOptions& opt, const ConnectOptions& connect,
                   const std::optional<FitOptions>& fit, const EvaluateOptions& evaluate,
                   const EvaluationSurface& surface, const Monitor& monitor, DeltaProbe& out);

}  // namespace ca
