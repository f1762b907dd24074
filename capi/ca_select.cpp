// ca_select.cpp: step 2 at the C boundary: the options and masks converted for the core's step
// (lib/steps/select_step.cpp), the selection's arrays and stats in the caller's units, and its
// getters. A selection holds a reference to its candidate set (results.h).
#include "conversions.h"
#include "results.h"

using ca::Status;
using ca::Vec3;
using namespace capi;

namespace {

// The selection's arrays and stats in the caller's units.
void publish(ca_selection& r, const ca_candidate_set& set, const ca::SelectRequest& request, double hd_reached) {
    const ca::Normalization& n = set.core.surface.norm;
    const size_t k = r.core.indices.size();
    r.indices.assign(r.allocator, k);
    r.radii.assign(r.allocator, k);
    r.dilated.assign(r.allocator, k);
    std::vector<Vec3> c(k);
    for (size_t i = 0; i < k; ++i) {
        const ca::Ball& b = set.core.balls[r.core.indices[i]];
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
    s.solver = static_cast<int32_t>(request.select.cover.solver);
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
}

}  // namespace

extern "C" {

ca_status ca_select(ca_context* ctx, const ca_candidate_set* set, const ca_select_options* options, ca_selection** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        ca_select_options o;
        Status st = read_arguments({{out, "out"}, {set, "set"}}, options, o);
        if (!st.ok()) return st;
        ca::SelectRequest request = to_core(o, ctx->desc.threads);
        ca::CoverOptions& cover = request.select.cover;
        // a caller of ABI 1 or 2 has no counts: its masks have one entry per sample or ball
        const bool counts =
            options && has_field(options->struct_size, offsetof(ca_select_options, ignorable_samples_count));
        const size_t ns = set->core.cover_samples.size(), nb = set->core.balls.size();
        const struct Mask {
            const uint8_t* array;
            size_t count, implied;
            const char *name, *count_name;
            std::vector<uint8_t>& out;
        } masks[] = {
            {o.ignorable_samples, o.ignorable_samples_count, ns, "ignorable_samples", "ignorable_samples_count",
             cover.ignorable_samples},
            {o.forced_in, o.forced_in_count, nb, "forced_in", "forced_in_count", cover.forced_in},
            {o.forced_out, o.forced_out_count, nb, "forced_out", "forced_out_count", cover.forced_out},
        };
        for (const Mask& m : masks) {
            size_t n;
            st = array_count(m.array, m.count, counts, m.implied, m.name, m.count_name, n);
            if (!st.ok()) return st;
            m.out.assign(m.array, m.array + n);
        }
        capi::Pending<ca_selection> res(capi::make_result<ca_selection>(ctx));
        ca_selection& r = *res.obj;
        retain_set(set);
        r.set = set;
        ca::SelectResult result;
        st = ca::select_step(set->core, request, ctx->monitor(), result);
        // a target not reached, and a search the time limit ended, still return their best
        // selection, with that status
        if (!st.ok() && st.code != ca::Code::target_not_reached && !(st.code == ca::Code::time_limit && result.stopped))
            return st;
        r.core = std::move(result.selection);
        publish(r, *set, request, result.hd_reached);
        *out = res.release();
        return st;
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
