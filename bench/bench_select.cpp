// bench_select.cpp: the selection engine alone, per instance: size before/after the reduction,
// kernel components, |V| for exact / greedy / Coverage Axis++, lower bound and gap of the exact
// solve, time per phase (coverage, reduction, solve) and the peak memory of the instance (each
// instance runs in its own forked child; the peak includes candidate generation): after the
// fast selection, which runs first (what a default run needs), and after all four selections.
// Instances: the Ant references, every paper model at the defaults and with 10 000 random
// candidates, and three models with |S| = 30 000 (the whole problem, the library's default
// there, and divide and conquer forced with a threshold of 8000).
// usage: bench_select [DATA_ROOT] [TIME_LIMIT_S]   (default ../shared/data, 5 s; skipped when missing)
#include "bench_common.h"
#include "bench_surface.h"
#include "candidates.h"
#include "selection.h"

#include <cmath>
#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

namespace {

double g_time_limit = 5.0;


// One instance: exact with the fast effort (the default) and with the prove effort (under the
// time limit), greedy, capp on the same candidates; prints one table row.
void run_instance(const std::string& name, const ca::CandidateSet& set, double delta, uint32_t dc_threshold = 0) {
    ca::SelectOptions o;
    o.delta = delta;
    o.cover.time_limit_s = g_time_limit;
    o.skip_uncoverable = true;  // random candidates may miss a few samples: benchmark the rest
    if (dc_threshold) o.dc_threshold = dc_threshold;
    ca::Selection fa, ex, gr, cp;
    const auto tf = std::chrono::steady_clock::now();
    const bool f_ok = ca::select_balls(set, o, ca::Monitor{}, fa).ok();
    const double fast_wall = bench::seconds_since(tf);
    const double fast_peak = bench::peak_rss_mb();  // candidates and the fast selection only
    o.cover.effort = ca::Effort::prove;
    const double c0 = bench::cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    ca::Status st = ca::select_balls(set, o, ca::Monitor{}, ex);
    const double wall = bench::seconds_since(t0), cpu = bench::cpu_seconds() - c0;
    if (!st.ok()) {
        std::printf("| %s | %zu x %zu | failed: %s |\n", name.c_str(), set.cover_samples.size(), set.balls.size(), st.message.c_str());
        return;
    }
    o.cover.solver = ca::Solver::greedy;
    const bool g_ok = ca::select_balls(set, o, ca::Monitor{}, gr).ok();
    o.cover.solver = ca::Solver::capp;
    const bool c_ok = ca::select_balls(set, o, ca::Monitor{}, cp).ok();
    const ca::CoverResult& r = ex.cover;
    std::printf("| %s | %zu x %zu | %zu x %zu | %zu | %zu | %s | %.2f | %.3f | %zu | %s | %zu | %zu | %.0f | %.2f | %s | %.3f | %.4f | %.3f | %.3f / %.3f | %.0f | %.0f |\n",
                name.c_str(), r.rows_before, r.cols_before, r.rows_after, r.cols_after,
                ex.parts ? size_t(ex.parts) : r.components, f_ok ? fa.indices.size() : 0,
                f_ok && fa.cover.proven_optimal ? "yes" : "no", f_ok ? 100 * fa.cover.gap : 100.0, fast_wall,
                ex.indices.size(), r.proven_optimal ? "yes" : "no",
                g_ok ? gr.indices.size() : 0, c_ok ? cp.indices.size() : 0, r.lower_bound, 100 * r.gap,
                ex.parts ? "d&c" : (r.cbc_components ? "cbc" : "bound"), ex.time_coverage_s, r.time_reduce_s,
                r.time_solve_s, wall, cpu, fast_peak, bench::peak_rss_mb());
}

// Runs `fn` in a forked child so that the peak memory is per instance.
template <class F>
void in_child(F fn) {
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        fn();
        std::fflush(stdout);
        _exit(0);
    }
    int status = 0;
    if (pid > 0) waitpid(pid, &status, 0);
}

// `dc_threshold` 0: the library default.
void model_instance(const std::string& path, ca::Generator gen, uint32_t samples, uint32_t dc_threshold = 0) {
    in_child([&] {
        ca::Surface s;
        const std::string name = bench::stem(path) + (gen == ca::Generator::random ? " (random)" : "") +
                                 (samples != 1500 ? " |S| " + std::to_string(samples) : "") +
                                 (dc_threshold ? " d&c" : "");
        if (!bench::load_surface(path, s)) { std::printf("| %s | read failed |\n", name.c_str()); return; }
        ca::CandidateOptions co;
        co.generator = gen;
        co.random_candidates = 10000;
        co.cover_samples = samples;
        ca::CandidateSet set;
        const ca::Status st = ca::generate_candidates(std::move(s), co, ca::Monitor{}, set);
        if (!st.ok()) { std::printf("| %s | candidates failed: %s |\n", name.c_str(), st.message.c_str()); return; }
        run_instance(name, set, 0.02, dc_threshold);
    });
}

}  // namespace

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    if (argc > 2) g_time_limit = std::atof(argv[2]);
    const auto models = bench::paper_models("bench_select", root);
    if (models.empty()) return 0;
    std::printf("\n## Selection engine (exact time limit %.1f s; times in s; peak MB per instance incl. candidates)\n\n%s\n\n", g_time_limit, bench::kCpuClock);
    std::printf("| instance | rows x cols | kernel | comps/parts | fast | optimal | gap %% | wall s | prove | optimal | "
                "greedy | capp | bound | gap %% | how | coverage | reduce | solve | wall / cpu | fast peak MB | peak MB |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");

    for (const bench::ReferenceInstance& ref : bench::reference_instances()) {
        in_child([&] {
            bench::ReferenceData in;
            if (!bench::read_reference(root, ref, in)) return;
            // the normalisation of bench_pipeline: min corner at 0, longest side 1
            const std::vector<double>&s = in.samples, &c = in.centers, &r = in.radii;
            const double L = in.longest;
            const ca::Vec3 o(in.lo[0], in.lo[1], in.lo[2]);
            ca::CandidateSet set;
            for (size_t i = 0; i + 2 < s.size(); i += 3) set.cover_samples.push_back((ca::Vec3(s[i], s[i + 1], s[i + 2]) - o) / L);
            for (size_t i = 0; i + 2 < c.size(); i += 3)
                set.balls.push_back(ca::Ball{(ca::Vec3(c[i], c[i + 1], c[i + 2]) - o) / L, r[i / 3] / L});
            run_instance(ref.name, set, ref.delta);
        });
    }
    for (const std::string& m : models) model_instance(m, ca::Generator::voronoi, 1500);
    for (const std::string& m : models) model_instance(m, ca::Generator::random, 1500);
    for (const char* big : {"bunny", "armadillo", "fertility"}) {
        model_instance(root + "/meshes/paper/" + big + ".obj", ca::Generator::voronoi, 30000);        // whole problem
        model_instance(root + "/meshes/paper/" + big + ".obj", ca::Generator::voronoi, 30000, 8000);  // forced d&c
    }
    return 0;
}
