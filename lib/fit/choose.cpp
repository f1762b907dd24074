// choose.cpp: the thorough fit (FitOptions::thorough): the regular fit and a second one with twice
// the boundary samples, both from the connected skeleton, and the choice between them by the
// evaluator's two-sided Hausdorff distance. The fit's own samples can miss the evaluator's worst
// point, and which of the two misses it less differs from model to model, so the choice is made
// by measuring both rather than by a rule; the first is kept on a tie, so the thorough fit is never
// farther than the regular one by evaluate() at its defaults.
#include "fit.h"

#include "evaluate.h"
#include "timing.h"

#include <algorithm>

namespace ca {

FitOptions second_fit_options(const FitOptions& opt) {
    FitOptions o = opt;
    o.thorough = false;
    o.envelope_samples = 2 * std::max<uint32_t>(opt.envelope_samples, 1);
    return o;
}

Status fit_skeleton(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const Monitor& monitor,
                    Skeleton& sk, FitStats& stats) {
    if (!opt.thorough) return fit_once(set, sel, opt, monitor, sk, stats);
    const auto t0 = Clock::now();
    FitOptions first_opt = opt;
    first_opt.thorough = false;
    Skeleton second = sk;
    Status st = fit_once(set, sel, first_opt, monitor, sk, stats);
    if (!st.ok()) return st;
    // nothing was fitted (no triangle mesh, no balls, no iterations): nothing to choose between
    if (stats.iterations == 0) return st;
    FitStats second_stats;
    st = fit_once(set, sel, second_fit_options(opt), monitor, second, second_stats);
    if (!st.ok()) return st;
    // the evaluator as ca_evaluate runs it at its defaults (its samples and seed); threads do not
    // change its result
    EvaluateOptions eo;
    eo.threads = opt.threads;
    std::shared_ptr<const EvaluationSurface> surface;
    st = prepare_evaluation(set.surface.mesh, eo, surface, &set.queries);
    if (!st.ok()) return st;
    // the HD only: the same maxima, without the means
    EvaluateResult first_eval, second_eval;
    st = evaluate(*surface, sk, eo, monitor, first_eval, true);
    if (!st.ok()) return st;
    st = evaluate(*surface, second, eo, monitor, second_eval, true);
    if (!st.ok()) return st;
    const double hd_first = first_eval.hd_two_sided, hd_second = second_eval.hd_two_sided;
    if (hd_second < hd_first) {
        sk = std::move(second);
        second_stats.iterations += stats.iterations;
        second_stats.accepted += stats.accepted;
        second_stats.error_before = stats.error_before;
        stats = second_stats;
        stats.kept = 1;
    } else {
        stats.iterations += second_stats.iterations;
        stats.accepted += second_stats.accepted;
        stats.kept = 0;
    }
    stats.hd_first = hd_first;
    stats.hd_second = hd_second;
    stats.time_s = seconds_since(t0);
    return Status::success();
}

}  // namespace ca
