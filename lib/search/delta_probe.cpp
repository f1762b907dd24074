// delta_probe.cpp: select + connect (+ fit) + evaluate at one delta (delta_probe.h).
#include "delta_probe.h"

namespace ca {

Status stop_cause(const Status& st, const Monitor& monitor) {
    if (st.code == Code::cancelled && !monitor.cancelled() && monitor.deadline.expired())
        return fail(Code::time_limit, "time limit reached in " + st.message);
    return st;
}

Status probe_delta(const CandidateSet& set, const SelectOptions& opt, const ConnectOptions& connect,
                   const std::optional<FitOptions>& fit, const EvaluateOptions& evaluate_opt,
                   const EvaluationSurface& surface, const Monitor& monitor, DeltaProbe& out) {
    out = DeltaProbe{};
    Status st = select_balls(set, opt, monitor, out.selection);
    if (st.ok()) st = connect_balls(set, out.selection, connect, monitor, out.skeleton);
    FitStats fit_stats;
    if (st.ok() && fit) st = fit_skeleton(set, out.selection, *fit, monitor, out.skeleton, fit_stats);
    if (st.ok()) st = evaluate(surface, out.skeleton, evaluate_opt, monitor, out.evaluation, true);
    if (!st.ok()) return stop_cause(st, monitor);
    out.summary.delta = out.selection.delta;
    out.summary.balls = out.selection.indices.size();
    out.summary.hd = out.evaluation.hd_two_sided;
    return st;
}

}  // namespace ca
