// bench_pipeline.cpp: the whole pipeline at the defaults on every mesh of <data>/meshes/paper:
// |S|, |P|, |V|, proven optimal?, gap, time per stage, and the skeleton's Hausdorff distances to
// the input (evaluation protocol of docs/evaluation.md, % of the bbox diagonal); the same selection
// connected by the other route (power diagram) and measured by the same evaluator, which is the
// measurement behind the default route for meshes. Also the two Coverage Axis reference
// instances (the reference code's own samples and candidates) against their known optima, and the
// pipeline's time at 1 and at 2 worker threads with the speed-up.
// usage: bench_pipeline [DATA_ROOT] [--fit-only | --threads-only] [--covered-fit]   (default ../shared/data;
// skipped when missing).
// --fit-only: the pipeline and its fitted twin only (no power route, Delaunay step or reference
// instances), for comparing fits. --threads-only: only the times at 1 and 2 worker threads.
// --covered-fit: the fitted twin with CA_FIT_COVERED instead of CA_FIT_ONCE.
#include "bench_common.h"
#include "bench_surface.h"
#include "delaunay.h"
#include "sampling.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

// The same pipeline (without the evaluation) at 1 and at 2 worker threads.
void threads_table(const std::vector<std::string>& models, const ca_candidate_options& co, const ca_select_options& so,
                   const ca_connect_options& cop) {
    std::printf("\n## The pipeline at 1 and 2 worker threads (ca_context_desc.threads)\n\n");
    std::printf("| model | 1 thread s | 2 threads s | speed-up | same balls |\n|---|---|---|---|---|\n");
    double sum1 = 0, sum2 = 0;
    for (const std::string& path : models) {
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) continue;
        const bench::PipelineRun r1 = bench::run_pipeline(mesh, co, so, cop, false, nullptr, nullptr, CA_POINT_NORMALS_TRUSTED, 1);
        const bench::PipelineRun r2 = bench::run_pipeline(mesh, co, so, cop, false, nullptr, nullptr, CA_POINT_NORMALS_TRUSTED, 2);
        if (r1.status != CA_OK || r2.status != CA_OK) {
            std::printf("| %s | failed: %s |\n", bench::stem(path).c_str(), (r1.status != CA_OK ? r1 : r2).message.c_str());
            continue;
        }
        const double t1 = r1.t_candidates + r1.t_select + r1.t_connect, t2 = r2.t_candidates + r2.t_select + r2.t_connect;
        sum1 += t1;
        sum2 += t2;
        std::printf("| %s | %.3f | %.3f | %.2f | %s |\n", bench::stem(path).c_str(), t1, t2, t2 > 0 ? t1 / t2 : 0.0,
                    r1.balls == r2.balls && r1.edges == r2.edges && r1.faces == r2.faces ? "yes" : "NO");
    }
    std::printf("\nall models: %.3f s at 1 thread, %.3f s at 2 threads, speed-up %.2f\n", sum1, sum2, sum2 > 0 ? sum1 / sum2 : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
    std::string root = "../shared/data";
    bool fit_only = false, threads_only = false, covered_fit = false;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--fit-only") fit_only = true;
        else if (std::string(argv[i]) == "--threads-only") threads_only = true;
        else if (std::string(argv[i]) == "--covered-fit") covered_fit = true;
        else root = argv[i];
    }
    const auto models = bench::paper_models("bench_pipeline", root);
    if (models.empty()) return 0;
    const bench::DefaultOptions d;
    ca_connect_options power;
    ca_connect_options_init(&power);
    power.method = CA_CONNECT_POWER;
    ca_connect_options fit;
    ca_connect_options_init(&fit);
    fit.fit = covered_fit ? CA_FIT_COVERED : CA_FIT_ONCE;
    if (threads_only) {
        threads_table(models, d.candidates, d.select, d.connect);
        return 0;
    }

    std::printf("\n## Pipeline at the defaults (|S| 1500, Voronoi candidates of 4000 samples, delta 0.02, exact cover with the fast effort (the default), connection auto = medial route)\n\n");
    std::printf("| model | tris | |S| | |P| | |V| | optimal | gap %% | candidates s | select s | connect s | total s | Delaunay s | S->E %% | E->S %% | HD %% | power: HD %% | connect s | fitted: HD %% | fit s | uncovered | balls |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    double sum = 0, worst = 0, hd_sum = 0, hd_power_sum = 0, hd_fit_sum = 0, fit_sum = 0, fit_worst = 0;
    int power_better = 0;
    double ball_sum = 0;
    int n_opt = 0, n = 0;
    std::vector<double> totals, delaunays, fitted_totals;
    double fit_worst_closed = 0, fit_balls = 0, fit_uncovered = 0;
    std::string fit_worst_model;
    for (const std::string& path : models) {
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) { std::printf("| %s | read failed: %s |\n", bench::stem(path).c_str(), err.c_str()); continue; }
        bench::PipelineRun r = bench::run_pipeline(mesh, d.candidates, d.select, d.connect, true, fit_only ? nullptr : &power, &fit);
        if (r.status != CA_OK) {
            std::printf("| %s | %zu | failed: %s |\n", bench::stem(path).c_str(), mesh.triangles.size() / 3, r.message.c_str());
            continue;
        }
        const double total = r.t_candidates + r.t_select + r.t_connect;
        // the Delaunay step alone (Qhull on as many surface samples as the candidate step uses): the
        // floor of the Voronoi route
        double t_delaunay = 0;
        ca::Surface surf;
        if (!fit_only && bench::load_surface(path, surf)) {
            const std::vector<ca::Vec3> pts = ca::sample_surface(surf.mesh, d.candidates.voronoi_samples, 2);
            std::vector<ca::Tet> tets;
            const auto t = std::chrono::steady_clock::now();
            ca::delaunay_tetrahedra(pts, tets, ca::Monitor{}, "delaunay");
            t_delaunay = bench::seconds_since(t);
        }
        totals.push_back(total);
        delaunays.push_back(t_delaunay);
        sum += total;
        worst = std::max(worst, total);
        n_opt += r.optimal;
        ball_sum += double(r.balls);
        ++n;
        hd_sum += r.eval.hd_two_sided;
        hd_power_sum += r.alt_eval.hd_two_sided;
        power_better += r.alt_eval.hd_two_sided < r.eval.hd_two_sided;
        hd_fit_sum += r.fit_eval.hd_two_sided;
        fit_sum += r.t_fit;
        fit_worst = std::max(fit_worst, r.t_fit);
        fitted_totals.push_back(total + r.t_fit);
        fit_balls += double(r.fit_balls);
        fit_uncovered += double(r.fit_uncovered);
        // closed models only (an open one is measured against its open surface: docs/fidelity.md)
        if (r.fit_open_parts == 0 && r.fit_eval.hd_two_sided > fit_worst_closed) {
            fit_worst_closed = r.fit_eval.hd_two_sided;
            fit_worst_model = bench::stem(path);
        }
        std::printf("| %s | %zu | %zu | %zu | %zu | %s | %.2f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %zu | %zu |\n",
                    bench::stem(path).c_str(), mesh.triangles.size() / 3, r.samples, r.candidates, r.balls,
                    r.optimal ? "yes" : "no", 100 * r.gap, r.t_candidates, r.t_select, r.t_connect, total, t_delaunay,
                    r.eval.hd_surface_to_recon, r.eval.hd_recon_to_surface, r.eval.hd_two_sided,
                    r.alt_eval.hd_two_sided, r.t_alt_connect, r.fit_eval.hd_two_sided, r.t_fit, r.fit_uncovered, r.fit_balls);
    }
    std::printf("\n%d models, %d proven optimal; pipeline mean %.3f s, max %.3f s; mean two-sided Hausdorff %.3f %% "
                "(power route on the same balls: %.3f %%, better on %d models); peak RSS %.0f MB\n", n, n_opt,
                n ? sum / n : 0.0, worst, n ? hd_sum / n : 0.0, n ? hd_power_sum / n : 0.0, power_better,
                bench::peak_rss_mb());
    auto median = [](std::vector<double> v) {
        if (v.empty()) return 0.0;
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    };
    std::printf("pipeline median %.3f s; Delaunay step median %.3f s (target: pipeline median <= max(0.2 s, 2 x Delaunay) = %.3f s)\n",
                median(totals), median(delaunays), std::max(0.2, 2 * median(delaunays)));
    std::printf("fitted (ca_connect_options.fit): mean two-sided Hausdorff %.3f %%, fit mean %.3f s, max %.3f s\n",
                n ? hd_fit_sum / n : 0.0, n ? fit_sum / n : 0.0, fit_worst);
    std::printf("fitted (%s): worst closed model %s %.3f %%, mean balls %.1f (unfitted %.1f), uncovered samples %.0f in all, "
                "pipeline with the fit median %.3f s\n", covered_fit ? "CA_FIT_COVERED" : "CA_FIT_ONCE",
                fit_worst_model.c_str(), fit_worst_closed, n ? fit_balls / n : 0.0, n ? ball_sum / n : 0.0, fit_uncovered,
                median(fitted_totals));

    if (fit_only) return 0;
    threads_table(models, d.candidates, d.select, d.connect);

    // Reference instances: the reference implementation's samples and candidates.
    std::printf("\n## Reference instances (samples and candidates of the reference code)\n\n");
    std::printf("| instance | delta | |S| x |P| | known optimum | ours | proven optimal | select s (median of 5) |\n|---|---|---|---|---|---|---|\n");
    for (const bench::ReferenceInstance& ref : bench::reference_instances()) {
        bench::ReferenceData in;
        if (!bench::read_reference(root, ref, in)) continue;
        ca_context* ctx = nullptr;
        ca_context_create(nullptr, &ctx);
        ca_candidate_set* set = nullptr;
        ca_selection* sel = nullptr;
        ca_candidates_from_arrays(ctx, in.samples.data(), in.samples.size() / 3, 0, in.centers.data(), 0, in.radii.data(), 0,
                                  in.radii.size(), in.longest, &set);
        ca_select_options o;
        ca_select_options_init(&o);
        o.delta = ref.delta;
        // the median of kRuns selections: a single timing varies with the machine
        constexpr int kRuns = 5;
        std::vector<double> times;
        ca_status st = CA_OK;
        for (int run = 0; run < kRuns && st == CA_OK; ++run) {
            ca_selection_destroy(sel);
            sel = nullptr;
            const auto t = std::chrono::steady_clock::now();
            st = ca_select(ctx, set, &o, &sel);
            times.push_back(bench::seconds_since(t));
        }
        std::sort(times.begin(), times.end());
        const double secs = times[times.size() / 2];
        ca_select_stats ss;
        ss.struct_size = sizeof ss;
        if (st == CA_OK) ca_selection_stats(sel, &ss);
        std::printf("| %s | %.3f | %zu x %zu | %d | %zu | %s | %.3f |\n", ref.candidates, ref.delta, in.samples.size() / 3, in.radii.size(),
                    ref.known, st == CA_OK ? ca_selection_count(sel) : 0, st == CA_OK && ss.proven_optimal ? "yes" : "no", secs);
        ca_selection_destroy(sel);
        ca_candidate_set_destroy(set);
        ca_context_destroy(ctx);
    }
    return 0;
}
