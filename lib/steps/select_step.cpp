// select_step.cpp: step 2 as one request: the request checked, then its strategy run: the
// target_error search, the lowest HD within target_count, or the plain cover (select_balls).
#include "steps.h"

#include "target_count_hd.h"
#include "target_error.h"

#include <cmath>
#include <cstdio>

namespace ca {

namespace {

Status check_request(const CandidateSet& set, const SelectRequest& r) {
    const SelectOptions& o = r.select;
    if (o.dilation != Dilation::offset && o.dilation != Dilation::scale)
        return fail(Code::invalid_argument, "unknown dilation " + std::to_string(int32_t(o.dilation)));
    const int32_t solver = int32_t(o.cover.solver);
    if (solver < int32_t(Solver::exact) || solver > int32_t(Solver::capp))
        return fail(Code::invalid_argument, "unknown solver " + std::to_string(solver));
    if (std::isnan(o.cover.time_limit_s)) return fail(Code::invalid_argument, "time_limit_s is NaN");
    if (o.cover.effort != Effort::fast && o.cover.effort != Effort::prove)
        return fail(Code::invalid_argument, "unknown effort " + std::to_string(int32_t(o.cover.effort)));
    if (o.target_count && !(std::isfinite(o.target_tolerance) && o.target_tolerance > 0))
        return fail(Code::invalid_argument, "target_tolerance must be a finite number > 0");
    if (!(std::isfinite(r.target_error) && r.target_error >= 0))
        return fail(Code::invalid_argument, "target_error must be a finite number >= 0 (percent of the bbox diagonal; 0 = off)");
    if (r.probe_fit != FitMode::off && r.probe_fit != FitMode::once)
        return fail(Code::invalid_argument, "probe_fit must be 0 or 1, not " + std::to_string(int32_t(r.probe_fit)));
    // a mask is one flag per sample or ball, or none
    const auto count = [](const char* name, size_t given, size_t want, const char* what) {
        return fail(Code::invalid_input, std::string(name) + " has " + std::to_string(given) + " entries; the candidate set has " +
                                             std::to_string(want) + " " + what);
    };
    const size_t ns = set.cover_samples.size(), nb = set.balls.size();
    const CoverOptions& c = o.cover;
    if (!c.ignorable_samples.empty() && c.ignorable_samples.size() != ns)
        return count("ignorable_samples", c.ignorable_samples.size(), ns, "samples");
    if (!c.forced_in.empty() && c.forced_in.size() != nb) return count("forced_in", c.forced_in.size(), nb, "balls");
    if (!c.forced_out.empty() && c.forced_out.size() != nb) return count("forced_out", c.forced_out.size(), nb, "balls");
    return Status::success();
}

}  // namespace

Status select_step(const CandidateSet& set, const SelectRequest& request, const Monitor& monitor, SelectResult& out) {
    out = SelectResult{};
    Status st = check_request(set, request);
    if (!st.ok()) return st;
    const SelectOptions& so = request.select;
    const bool target_error = request.target_error > 0;  // the rest is checked by select_target_error
    // target_count with the offset dilation on a set with a surface: the lowest HD within K balls
    // (the scale dilation and caller arrays keep the plain smallest dilation)
    const bool lowest_hd =
        !target_error && so.target_count > 0 && so.dilation == Dilation::offset && set.surface.kind().has_surface();
    // the searches judge each probe as connect_step (default request, fit = probe_fit) and
    // evaluate_step (default options) would
    ConnectRequest probe;
    probe.fit = request.probe_fit;
    probe.connect.threads = so.threads;
    EvaluateOptions evaluation;
    evaluation.threads = so.threads;
    if (target_error) {
        TargetErrorOptions te;
        te.target_error = request.target_error;
        te.connect = probe.connect;
        te.fit = fit_options(probe, set);
        te.evaluate = evaluation;
        // On a mesh with unfitted probes, each probe's cover is also measured fitted (fit once, as
        // connect fits a selection judged fitted), and the lower HD of the two is judged: one search
        // finds the fewest balls within E, fitted or not.
        if (!te.fit) {
            ConnectRequest fitted_probe = probe;
            fitted_probe.fit = FitMode::once;
            te.also_fitted = fit_options(fitted_probe, set);
        }
        TargetErrorResult ter;
        st = select_target_error(set, so, te, monitor, ter);
        if (!st.ok()) return st;
        const bool fitted = ter.fitted;
        out.selection = std::move(ter.selection);
        out.selection.judged_fitted = fitted;
        out.hd_reached = ter.evaluation.hd_two_sided;
        if (ter.stopped) {
            // the best selection so far, with the time limit's status (ca_select keeps the result)
            out.stopped = true;
            char text[200];
            std::snprintf(text, sizeof text,
                          "time limit reached in the target error search after %llu probes: the best selection so far "
                          "is returned (%zu balls, two-sided HD %.3f %%, target %s)",
                          (unsigned long long)out.selection.probes, out.selection.indices.size(), out.hd_reached,
                          ter.reached ? "reached" : "not reached");
            return fail(Code::time_limit, text);
        }
        if (!ter.reached) {
            // the caller gets the best probe with a status of its own, never a silent success
            char text[160];
            std::snprintf(text, sizeof text, "target error %.4g %% not reached: the lowest two-sided HD found is %.3f %% (%zu balls, %llu probes)",
                          request.target_error, out.hd_reached, out.selection.indices.size(),
                          (unsigned long long)out.selection.probes);
            return fail(Code::target_not_reached, text);
        }
    } else if (lowest_hd) {
        TargetCountHdOptions tc;
        tc.connect = probe.connect;
        tc.fit = fit_options(probe, set);
        tc.evaluate = evaluation;
        TargetCountHdResult tcr;
        st = select_target_count_hd(set, so, tc, monitor, tcr);
        if (!st.ok()) return st;
        out.selection = std::move(tcr.selection);
        out.hd_reached = tcr.evaluation.hd_two_sided;
        if (tcr.stopped) {
            // the best selection so far, with the time limit's status (ca_select keeps the result)
            out.selection.sized_by_count = true;
            out.stopped = true;
            char text[200];
            std::snprintf(text, sizeof text,
                          "time limit reached in the target count search after %zu probes: the best selection so far is "
                          "returned (%zu balls, two-sided HD %.3f %%)",
                          tcr.probes.size(), out.selection.indices.size(), out.hd_reached);
            return fail(Code::time_limit, text);
        }
    } else {
        st = select_balls(set, so, monitor, out.selection);
        if (!st.ok()) return st;
    }
    out.selection.sized_by_count = so.target_count > 0;
    if (!out.selection.cover.uncovered.empty())
        monitor.note(2, std::to_string(out.selection.cover.uncovered.size()) +
                            " samples are covered by no ball and were skipped");
    return Status::success();
}

}  // namespace ca
