// ca_select.cpp: step 2 at the C boundary: the minimum set cover of a candidate set, and the
// selection's getters. A selection holds a reference to its candidate set (results.h).
#include "conversions.h"
#include "results.h"
#include "struct_size.h"

#include "target_count_hd.h"
#include "target_error.h"

#include <cmath>

using ca::Code;
using ca::Status;
using ca::Vec3;
using namespace capi;

namespace {

// How the delta searches measure each probe: as ca_evaluate does with its defaults.
ca::EvaluateOptions default_evaluation(int32_t threads) {
    const ca_evaluate_options eo = defaults<ca_evaluate_options>();
    ca::EvaluateOptions e;
    e.surface_samples = eo.surface_samples;
    e.envelope_samples = eo.envelope_samples;
    e.seed = eo.seed;
    e.threads = threads;
    return e;
}

}  // namespace

extern "C" {

ca_status ca_select(ca_context* ctx, const ca_candidate_set* set, const ca_select_options* options, ca_selection** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        ca_select_options o;
        Status st = read_arguments({{out, "out"}, {set, "set"}}, options, o);
        if (!st.ok()) return st;
        if (o.dilation != CA_DILATE_OFFSET && o.dilation != CA_DILATE_SCALE)
            return ca::fail(Code::invalid_argument, "unknown dilation " + std::to_string(o.dilation));
        if (o.solver < CA_SOLVER_EXACT || o.solver > CA_SOLVER_CAPP)
            return ca::fail(Code::invalid_argument, "unknown solver " + std::to_string(o.solver));
        if (std::isnan(o.time_limit_s)) return ca::fail(Code::invalid_argument, "time_limit_s is NaN");
        if (o.effort != CA_EFFORT_FAST && o.effort != CA_EFFORT_PROVE)
            return ca::fail(Code::invalid_argument, "unknown effort " + std::to_string(o.effort));
        if (o.target_count && !(std::isfinite(o.target_tolerance) && o.target_tolerance > 0))
            return ca::fail(Code::invalid_argument, "target_tolerance must be a finite number > 0");
        if (!(std::isfinite(o.target_error) && o.target_error >= 0))
            return ca::fail(Code::invalid_argument, "target_error must be a finite number >= 0 (percent of the bbox diagonal; 0 = off)");
        if (o.probe_fit != 0 && o.probe_fit != 1)
            return ca::fail(Code::invalid_argument, "probe_fit must be 0 or 1, not " + std::to_string(o.probe_fit));
        const bool target_error = o.target_error > 0;  // the rest is checked by select_target_error
        // target_count with the offset dilation on a set with a surface: the lowest HD within K
        // balls (the scale dilation and caller arrays keep the plain smallest dilation)
        const bool lowest_hd = !target_error && o.target_count > 0 && o.dilation == CA_DILATE_OFFSET &&
                               !set->core.surface.mesh.vertices.empty();
        ca::SelectOptions so;
        so.dilation = static_cast<ca::Dilation>(o.dilation);
        so.delta = o.delta;
        so.scale = o.scale;
        so.skip_uncoverable = o.skip_uncoverable != 0;
        so.cover.solver = static_cast<ca::Solver>(o.solver);
        so.cover.time_limit_s = o.time_limit_s;
        so.cover.effort = static_cast<ca::Effort>(o.effort);
        so.target_count = o.target_count;
        so.target_tolerance = o.target_tolerance;
        so.dc_threshold = o.divide_threshold;
        so.threads = ctx->desc.threads;
        const size_t ns = set->core.cover_samples.size(), nb = set->core.balls.size();
        if (o.ignorable_samples) so.cover.ignorable_samples.assign(o.ignorable_samples, o.ignorable_samples + ns);
        if (o.forced_in) so.cover.forced_in.assign(o.forced_in, o.forced_in + nb);
        if (o.forced_out) so.cover.forced_out.assign(o.forced_out, o.forced_out + nb);

        capi::Pending<ca_selection> res(capi::make_result<ca_selection>(ctx));
        ca_selection& r = *res.obj;
        retain_set(set);
        r.set = set;
        double hd_reached = -1;
        // the delta searches judge each probe as ca_connect (at its defaults, with fit = probe_fit)
        // and ca_evaluate at its defaults would
        ca_connect_options probe_co = defaults<ca_connect_options>();
        probe_co.fit = o.probe_fit;
        const ca::ConnectOptions probe_connect = connect_options(probe_co, set->core, ctx->desc.threads);
        const std::optional<ca::FitOptions> probe_fit = fit_options(probe_co, set->core, ctx->desc.threads);
        if (target_error) {
            ca::TargetErrorOptions te;
            te.target_error = o.target_error;
            te.connect = probe_connect;
            te.fit = probe_fit;
            te.evaluate = default_evaluation(ctx->desc.threads);
            ca::TargetErrorResult ter;
            st = ca::select_target_error(set->core, so, te, ctx->monitor(), ter);
            if (!st.ok()) return st;
            r.core = std::move(ter.selection);
            hd_reached = ter.evaluation.hd_two_sided;
            if (!ter.reached)
                ctx->log(2, "target_error " + std::to_string(o.target_error) + " % not reached: the lowest HD found is " +
                                std::to_string(hd_reached) + " %");
        } else if (lowest_hd) {
            ca::TargetCountHdOptions tc;
            tc.connect = probe_connect;
            tc.fit = probe_fit;
            tc.evaluate = default_evaluation(ctx->desc.threads);
            ca::TargetCountHdResult tcr;
            st = ca::select_target_count_hd(set->core, so, tc, ctx->monitor(), tcr);
            if (!st.ok()) return st;
            r.core = std::move(tcr.selection);
            hd_reached = tcr.evaluation.hd_two_sided;
        } else {
            st = ca::select_balls(set->core, so, ctx->monitor(), r.core);
            if (!st.ok()) return st;
        }
        const ca::Normalization& n = set->core.surface.norm;
        const size_t k = r.core.indices.size();
        r.indices.assign(r.allocator, k);
        r.radii.assign(r.allocator, k);
        r.dilated.assign(r.allocator, k);
        std::vector<Vec3> c(k);
        for (size_t i = 0; i < k; ++i) {
            const ca::Ball& b = set->core.balls[r.core.indices[i]];
            r.indices.data[i] = r.core.indices[i];
            c[i] = b.center;
            r.radii.data[i] = b.radius * n.scale;
            r.dilated.data[i] = r.core.dilated_radii[i] * n.scale;
        }
        fill(r.centers, r.allocator, c, n);
        r.uncovered.assign(r.allocator, r.core.cover.uncovered.size());
        for (size_t i = 0; i < r.uncovered.size; ++i) r.uncovered.data[i] = r.core.cover.uncovered[i];
        const ca::CoverResult& cr = r.core.cover;
        ca_select_stats& s = r.stats;
        s.struct_size = sizeof s;
        s.proven_optimal = cr.proven_optimal;
        s.solver = o.solver;
        s.objective = cr.objective;
        s.lower_bound = cr.lower_bound;
        s.gap = cr.gap;
        s.delta_absolute = r.core.delta * n.scale;
        s.time_reduce_s = cr.time_reduce_s;
        s.time_solve_s = cr.time_solve_s;
        s.time_total_s = r.core.time_total_s;
        s.rows_before = cr.rows_before; s.cols_before = cr.cols_before;
        s.rows_after = cr.rows_after; s.cols_after = cr.cols_after; s.forced = cr.forced;
        s.components = cr.components;
        s.probes = r.core.probes;
        s.parts = r.core.parts;
        s.scale_used = r.core.scale;
        s.time_coverage_s = r.core.time_coverage_s;
        s.cbc_components = cr.cbc_components;
        s.rowgen_rounds = cr.rowgen_rounds;
        s.hd_reached = hd_reached;
        if (!cr.uncovered.empty())
            ctx->log(2, std::to_string(cr.uncovered.size()) + " samples are covered by no ball and were skipped");
        *out = res.release();
        return Status::success();
    });
}

void ca_selection_destroy(ca_selection* s) { destroy_result(s); }  // releases its set
size_t ca_selection_count(const ca_selection* s) { return s ? s->indices.size : 0; }
const uint32_t* ca_selection_indices(const ca_selection* s) { return s ? s->indices.data : nullptr; }
const double* ca_selection_centers(const ca_selection* s) { return s ? s->centers.data : nullptr; }
const double* ca_selection_radii(const ca_selection* s) { return s ? s->radii.data : nullptr; }
const double* ca_selection_dilated_radii(const ca_selection* s) { return s ? s->dilated.data : nullptr; }
size_t ca_selection_uncovered_count(const ca_selection* s) { return s ? s->uncovered.size : 0; }
const uint32_t* ca_selection_uncovered(const ca_selection* s) { return s ? s->uncovered.data : nullptr; }

ca_status ca_selection_stats(const ca_selection* sel, ca_select_stats* stats) {
    if (!sel || !stats) return CA_ERROR_NULL_POINTER;
    return guarded_status([&] { return write_output(sel->stats, stats); });
}

}  // extern "C"
