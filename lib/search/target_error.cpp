// target_error.cpp: the error-bounded selection (target_error.h): probes of select + connect +
// evaluate over the offset delta on one candidate set, the deltas chosen by search_delta
// (delta_search.h); the best probe's selection, skeleton and evaluation are returned.
#include "target_error.h"

#include "delta_search.h"
#include "target_count_hd.h"

#include <algorithm>
#include <cmath>

namespace ca {

Status select_target_error(const CandidateSet& set, const SelectOptions& opt, const TargetErrorOptions& te,
                           const Monitor& monitor, TargetErrorResult& out) {
    const auto t0 = Clock::now();
    out = TargetErrorResult{};
    if (!(std::isfinite(te.target_error) && te.target_error > 0))
        return fail(Code::invalid_argument, "target_error must be a finite number > 0");
    if (opt.dilation != Dilation::offset)
        return fail(Code::invalid_argument, "target_error searches the offset delta: it needs the offset dilation");
    if (opt.target_count > 0) return fail(Code::invalid_argument, "target_error and target_count cannot both be set");
    if (!(std::isfinite(opt.delta) && opt.delta > 0)) return fail(Code::invalid_argument, "delta must be a finite number > 0");
    if (!(std::isfinite(opt.target_tolerance) && opt.target_tolerance > 0))
        return fail(Code::invalid_argument, "target_tolerance must be a finite number > 0");
    if (!set.surface.kind().has_surface())
        return fail(Code::invalid_argument,
                    "target_error measures the skeleton against the surface: the candidate set has none (caller arrays)");
    if (te.max_probes == 0) return fail(Code::invalid_argument, "max_probes must be at least 1");

    std::shared_ptr<const EvaluationSurface> surface;
    Status prepared = prepare_evaluation(set.surface.mesh, te.evaluate, surface, &set.queries);
    if (!prepared.ok()) return prepared;
    SelectOptions probe_opt = opt;
    DeltaProbe last, best;
    // coarse to fine: a probe is measured coarsely first; one whose coarse HD (about a lower bound
    // of the exact one: fewer samples of E's boundary) is above E fails on it, the others are
    // measured exactly, which decides whether they pass
    const EvaluateOptions coarse = coarse_evaluation(te.evaluate, te.coarse_envelope_samples);
    auto probe = [&](double d, TargetErrorProbe& summary) {
        probe_opt.delta = d;
        Status st = probe_delta(set, probe_opt, te.connect, te.fit, coarse, *surface, monitor, last);
        if (st.ok() && last.summary.hd <= te.target_error) {
            st = evaluate(*surface, last.skeleton, te.evaluate, monitor, last.evaluation, true);
            last.summary.hd = last.evaluation.hd_two_sided;
        } else if (st.ok()) {
            last.summary.exact = false;
        }
        summary = last.summary;
        return st;
    };
    auto keep = [&] { best = std::move(last); };
    DeltaSearchOptions so;
    so.start = opt.delta;
    so.floor = kFallbackReach;
    so.tolerance = opt.target_tolerance;
    so.target_error = te.target_error;
    so.max_probes = te.max_probes;
    DeltaSearchResult r;
    const Status st = search_delta(so, probe, keep, r);
    const bool have_best = !r.probes.empty();
    // the time limit after a finished probe returns the best so far
    if (!st.ok() && !(st.code == Code::time_limit && have_best)) return st;
    if (!have_best) return fail(Code::uncoverable, "no delta tried gives a cover of every sample");
    // none passed and the best was measured coarsely only: its exact HD is the one reported (a
    // monitor that has stopped leaves the coarse figure, marked so in the probe list)
    if (!best.summary.exact && !monitor.stopped()) {
        if (evaluate(*surface, best.skeleton, te.evaluate, monitor, best.evaluation, true).ok()) {
            best.summary.exact = true;
            r.probes[r.best].hd = best.evaluation.hd_two_sided;
            r.probes[r.best].exact = true;
        }
    }
    out.selection = std::move(best.selection);
    out.selection.probes = r.runs;
    out.selection.time_total_s = seconds_since(t0);  // the whole search
    out.skeleton = std::move(best.skeleton);
    out.evaluation = best.evaluation;
    out.reached = r.probes[r.best].passed;
    out.probes = std::move(r.probes);
    return Status::success();
}

}  // namespace ca
