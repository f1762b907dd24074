// target_error.cpp: the error-bounded selection (target_error.h): probes of select + connect +
// evaluate over the offset delta on one candidate set, the deltas chosen by search_delta
// (delta_search.h); the best probe's selection, skeleton and evaluation are returned.
#include "target_error.h"

#include "delta_search.h"
#include "target_count_hd.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

    if (!(std::isfinite(te.count_down_step) && te.count_down_step > 0))
        return fail(Code::invalid_argument, "count_down_step must be a finite number > 0");
    if (te.count_down_sweep == 0) return fail(Code::invalid_argument, "count_down_sweep must be at least 1");

    std::shared_ptr<const EvaluationSurface> surface;
    Status prepared = prepare_evaluation(set.surface.mesh, te.evaluate, surface, &set.queries);
    if (!prepared.ok()) return prepared;
    SelectOptions probe_opt = opt;
    DeltaProbe last, best;
    bool last_fitted = false;
    const uint32_t planned = te.max_probes + te.max_count_down;
    uint32_t runs = 0;
    // coarse to fine: a probe is measured coarsely first; one whose coarse HD (about a lower bound
    // of the exact one: fewer samples of E's boundary) is above E fails on it, the others are
    // measured exactly, which decides whether they pass
    const EvaluateOptions coarse = coarse_evaluation(te.evaluate, te.coarse_envelope_samples);
    const bool both = !te.fit && te.also_fitted;
    auto measure = [&]() -> Status {
        Status st = probe_delta(set, probe_opt, te.connect, te.fit, coarse, *surface, monitor, last);
        last_fitted = st.ok() && te.fit && set.surface.kind().is_mesh();  // fit_skeleton: meshes only
        if (st.ok() && both && set.surface.kind().is_mesh()) {
            // the same cover fitted: the lower coarse HD of the two is judged
            Skeleton fitted = last.skeleton;
            FitStats stats;
            st = stop_cause(fit_skeleton(set, last.selection, *te.also_fitted, monitor, fitted, stats), monitor);
            EvaluateResult ev;
            if (st.ok()) st = evaluate(*surface, fitted, coarse, monitor, ev, true);
            if (st.ok() && ev.hd_two_sided < last.summary.hd) {
                last.skeleton = std::move(fitted);
                last.evaluation = ev;
                last.summary.hd = ev.hd_two_sided;
                last_fitted = true;
            }
        }
        if (st.ok() && last.summary.hd <= te.target_error) {
            st = evaluate(*surface, last.skeleton, te.evaluate, monitor, last.evaluation, true);
            last.summary.hd = last.evaluation.hd_two_sided;
        } else if (st.ok()) {
            last.summary.exact = false;
        }
        return st;
    };
    bool best_fitted = false;
    auto note = [&](TargetErrorProbe p, TargetErrorProbe b) {
        p.passed = p.hd <= te.target_error;
        if (better_probe(p, b)) b = p;
        char text[200];
        std::snprintf(text, sizeof text,
                      "target error: probe %u of at most %u: delta %.4g, %zu balls, HD %.3f %%%s; best so far %zu balls, HD %.3f %%%s",
                      runs, planned, p.delta, p.balls, p.hd, p.exact ? "" : " (coarse)", b.balls, b.hd,
                      b.passed ? " (within E)" : "");
        monitor.note(1, text);
    };
    auto probe = [&](double d, TargetErrorProbe& summary) {
        if (!monitor.report("target error: probes", double(runs) / double(planned))) return monitor.stop_status("target error");
        ++runs;
        probe_opt.delta = d;
        const Status st = measure();
        summary = last.summary;
        return st;
    };
    DeltaSearchResult r;
    auto keep = [&] {
        best = std::move(last);
        best_fitted = last_fitted;
    };
    DeltaSearchOptions so;
    so.start = opt.delta;
    so.floor = kFallbackReach;
    so.tolerance = opt.target_tolerance;
    so.target_error = te.target_error;
    so.max_probes = te.max_probes;
    so.count_down = te.max_count_down > 0;
    Status st = search_delta(so, [&](double d, TargetErrorProbe& summary) {
        const Status s = probe(d, summary);
        if (s.ok()) note(summary, r.probes.empty() ? summary : r.probes[r.best]);
        return s;
    }, keep, r);
    bool stopped = false;
    // the time limit after a finished probe returns the best so far
    if (!st.ok() && !(st.code == Code::time_limit && !r.probes.empty())) return st;
    stopped = !st.ok();
    if (r.probes.empty()) return fail(Code::uncoverable, "no delta tried gives a cover of every sample");

    // The count-down: for one ball fewer than the best passing probe, the probes target_count's
    // search makes for that count (its target size, then growing deltas) until one passes; the
    // first count none passes for ends it.
    uint32_t count_down = 0;
    auto run_one = [&](const TargetErrorProbe& b) -> Status {
        if (!monitor.report("target error: probes", double(runs) / double(planned))) return monitor.stop_status("target error");
        ++runs;
        ++count_down;
        Status s = measure();
        if (s.ok()) {
            last.summary.passed = last.summary.hd <= te.target_error;
            r.probes.push_back(last.summary);
            note(r.probes.back(), better_probe(r.probes.back(), b) ? r.probes.back() : b);
        }
        return s;
    };
    while (!stopped && count_down < te.max_count_down) {
        const TargetErrorProbe b = r.probes[r.best];
        if (!b.passed || b.balls <= 1) break;
        const size_t m = b.balls - 1;
        // the target size's bracket starts at the smallest probed delta above with fewer balls
        double upper = 0;
        for (const TargetErrorProbe& p : r.probes)
            if (p.balls <= m && p.delta > b.delta && (upper == 0 || p.delta < upper)) upper = p.delta;
        probe_opt.target_count = uint32_t(m);
        probe_opt.delta = upper > 0 ? upper : 1.25 * b.delta;
        st = run_one(b);
        probe_opt.target_count = 0;
        if (st.code == Code::invalid_argument || st.code == Code::uncoverable) break;  // no cover that small
        bool found = false;
        const double d0 = st.ok() ? last.summary.delta : 0;
        for (uint32_t i = 1; st.ok() && !(found = r.probes.back().passed && better_probe(r.probes.back(), b)); ++i) {
            if (i >= te.count_down_sweep || count_down >= te.max_count_down) break;
            probe_opt.delta = d0 * (1 + te.count_down_step * i);
            st = run_one(b);
        }
        if (st.code == Code::time_limit) {
            stopped = true;
            break;
        }
        if (!st.ok()) return st;
        if (!found) break;
        r.best = r.probes.size() - 1;
        keep();
    }
    r.runs = runs;

    // none passed and the best was measured coarsely only: its exact HD is the one reported (a
    // monitor that has stopped leaves the coarse figure, marked so in the probe list)
    if (!best.summary.exact && !monitor.stopped()) {
        if (evaluate(*surface, best.skeleton, te.evaluate, monitor, best.evaluation, true).ok()) {
            best.summary.exact = true;
            r.probes[r.best].hd = best.evaluation.hd_two_sided;
            r.probes[r.best].exact = true;
        }
    }
    monitor.report("target error: probes", 1);
    out.selection = std::move(best.selection);
    out.selection.probes = r.runs;
    out.selection.time_total_s = seconds_since(t0);  // the whole search
    out.skeleton = std::move(best.skeleton);
    out.evaluation = best.evaluation;
    out.reached = r.probes[r.best].passed;
    out.fitted = best_fitted;
    out.stopped = stopped;
    out.probes = std::move(r.probes);
    return Status::success();
}

}  // namespace ca
