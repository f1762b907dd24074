// bench_target_error.cpp: the error-bounded selection (ca_select_options.target_error) on every
// mesh of <data>/meshes/paper: at --target-error 2, the balls, the two-sided Hausdorff distance
// it reached (% of the bbox diagonal), the delta, the probes and the time; beside it a sweep of
// fixed deltas (each selected, connected and evaluated at the defaults) and the smallest ball
// count of the sweep that reaches HD <= 2 %. Summary: how many closed models reach 2 %, and on
// how many the search needs fewer, as many or more balls than the sweep's best.
// usage: bench_target_error [DATA_ROOT]   (default ../shared/data; skipped when missing)
#include "bench_common.h"
#include "connect.h"
#include "support/mesh_convert.h"

#include <cmath>
#include <vector>

namespace {

constexpr double kTarget = 2.0;
const double kSweep[] = {0.005, 0.0075, 0.01, 0.0125, 0.015, 0.02, 0.025, 0.03, 0.04};

struct Probe {
    ca_status status = CA_OK;
    size_t balls = 0;
    double hd = 0, delta = 0, seconds = 0;
    uint64_t probes = 0;
};

// Select with `so` on `set`, then (unless target_error measured it) connect and evaluate at the
// defaults.
Probe run(ca_context* ctx, const ca_surface_view& v, const ca_candidate_set* set, const ca_select_options& so) {
    Probe p;
    const auto t = std::chrono::steady_clock::now();
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    p.status = ca_select(ctx, set, &so, &sel);
    if (p.status == CA_OK) {
        ca_select_stats ss;
        ss.struct_size = sizeof ss;
        ca_selection_stats(sel, &ss);
        p.balls = ca_selection_count(sel);
        p.delta = ss.delta_absolute / ca_candidate_set_reference_length(set);
        p.probes = ss.probes;
        p.hd = ss.hd_reached;
        if (p.hd < 0) {
            p.status = ca_connect(ctx, set, sel, nullptr, &sk);
            size_t edges = 0, faces = 0, components = 0;
            long betti1 = 0;
            ca_evaluation ev{};
            if (p.status == CA_OK) p.status = bench::measure_skeleton(ctx, v, sk, true, edges, faces, components, betti1, ev);
            p.hd = ev.hd_two_sided;
        }
    }
    p.seconds = bench::seconds_since(t);
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    const auto models = bench::list_files(root + "/meshes/paper", ".obj");
    if (models.empty()) {
        std::printf("bench_target_error: no models under %s/meshes/paper, skipped\n", root.c_str());
        return 0;
    }
    std::printf("\n## Error-bounded selection: --target-error %.0f against a delta sweep\n\n", kTarget);
    std::printf("Defaults otherwise (|S| 1500, Voronoi candidates, exact cover, fast effort, medial route, evaluation "
                "30 000 / 100 000 samples). Sweep deltas:");
    for (double d : kSweep) std::printf(" %g", d);
    std::printf("; \"sweep best\" is the fewest balls among them with HD <= %.0f %%.\n\n", kTarget);
    std::printf("| model | closed | target: balls | HD %% | delta | probes | s | sweep best: balls | HD %% | delta | sweep s |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    int closed_models = 0, closed_reached = 0, fewer = 0, same = 0, more = 0, sweep_none = 0;
    double target_s = 0, sweep_s = 0;
    for (const std::string& path : models) {
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) {
            std::printf("| %s | read failed: %s |\n", bench::stem(path).c_str(), err.c_str());
            continue;
        }
        const bool closed = ca::closed_mesh(to_core_mesh(mesh));
        ca_context* ctx = nullptr;
        ca_context_create(nullptr, &ctx);
        const ca_surface_view v = bench::surface_view(mesh);
        ca_candidate_set* set = nullptr;
        if (ca_candidates(ctx, &v, nullptr, &set) != CA_OK) {
            std::printf("| %s | candidates failed: %s |\n", bench::stem(path).c_str(), ca_context_last_error(ctx));
            ca_context_destroy(ctx);
            continue;
        }
        ca_select_options so;
        ca_select_options_init(&so);
        so.target_error = kTarget;
        const Probe te = run(ctx, v, set, so);
        so.target_error = 0;
        Probe best;
        bool found = false;
        double s_sweep = 0;
        for (double d : kSweep) {
            so.delta = d;
            const Probe p = run(ctx, v, set, so);
            s_sweep += p.seconds;
            if (p.status != CA_OK || p.hd > kTarget) continue;
            if (!found || p.balls < best.balls || (p.balls == best.balls && p.hd < best.hd)) best = p;
            found = true;
        }
        ca_candidate_set_destroy(set);
        ca_context_destroy(ctx);
        const bool reached = te.status == CA_OK && te.hd <= kTarget;
        if (closed) {
            ++closed_models;
            closed_reached += reached;
        }
        target_s += te.seconds;
        sweep_s += s_sweep;
        if (!found) ++sweep_none;
        else if (reached && te.balls < best.balls) ++fewer;
        else if (reached && te.balls == best.balls) ++same;
        else ++more;
        if (te.status != CA_OK)
            std::printf("| %s | %s | failed (%d) | | | | %.1f |", bench::stem(path).c_str(), closed ? "yes" : "no", te.status,
                        te.seconds);
        else
            std::printf("| %s | %s | %zu | %.3f%s | %.4f | %llu | %.1f |", bench::stem(path).c_str(), closed ? "yes" : "no",
                        te.balls, te.hd, reached ? "" : " (not reached)", te.delta, (unsigned long long)te.probes, te.seconds);
        if (found) std::printf(" %zu | %.3f | %.4g | %.1f |\n", best.balls, best.hd, best.delta, s_sweep);
        else std::printf(" none | | | %.1f |\n", s_sweep);
        std::fflush(stdout);
    }
    std::printf("\nClosed models reaching HD <= %.0f %% with --target-error %.0f: %d of %d. Against the sweep's best "
                "(models where a swept delta reaches it): fewer balls on %d, as many on %d, more (or target not reached) "
                "on %d; no swept delta reaches it on %d. Time: target %.0f s, sweep %.0f s in all.\n",
                kTarget, kTarget, closed_reached, closed_models, fewer, same, more, sweep_none, target_s, sweep_s);
    return 0;
}
