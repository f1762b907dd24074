// bench_target_error.cpp: the error-bounded selection (ca_select_options.target_error) on the closed
// meshes of <data>/meshes/paper, at E = 2, 1.5 and 1 % of the bbox diagonal, at the defaults
// otherwise. Each row: the balls returned, the two-sided HD the search measured (that of the
// skeleton ca_connect gives at its defaults: the library reports it as hd_reached), the probes,
// the wall time of ca_select; and beside them the fewest balls of any --target-count run this bench
// makes for the model whose measured HD is <= E. The target-count runs: one per E the search
// reached, at K = 90 % of the balls it returned (rounded down, at least 1), each selected, connected
// at ca_connect's defaults (a sized selection: fitted thoroughly) and evaluated at ca_evaluate's
// defaults; every run serves every E of its model. Summary per E: closed models reaching it, those
// ending with CA_ERROR_TARGET_NOT_REACHED, on how many target-error used no more balls than the
// target-count runs within E, and the median wall time. The bench stops starting models after
// its budget (kBudgetS seconds, or BENCH_TARGET_ERROR_BUDGET_S from the environment; the searches take
// tens of seconds per model on 2 cores) and names those it left out;
// the summary counts the models it ran.
// usage: bench_target_error [DATA_ROOT] [--only NAME[,NAME...]]   (default ../shared/data; skipped when
// missing; --only keeps the meshes whose file stem starts with one of the names)
#include "bench_common.h"
#include "connect.h"
#include "mesh_topology.h"
#include "support/mesh_convert.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace {

const double kTargets[] = {2.0, 1.5, 1.0};
constexpr double kBudgetS = 2100;  // no model is started after this many seconds

// The budget: BENCH_TARGET_ERROR_BUDGET_S when set to a number > 0, else kBudgetS.
double budget_s() {
    const char* env = std::getenv("BENCH_TARGET_ERROR_BUDGET_S");
    const double v = env ? std::atof(env) : 0.0;
    return v > 0 ? v : kBudgetS;
}
constexpr int kE = 3;

struct Search {
    ca_status status = CA_OK;
    size_t balls = 0;
    double hd = 0, wall_s = 0;
    uint64_t probes = 0;
    bool has_result() const { return status == CA_OK || status == CA_ERROR_TARGET_NOT_REACHED; }
};

// ca_select with target_error E: the balls, the HD it measured (hd_reached), probes, wall time.
Search search(ca_context* ctx, const ca_candidate_set* set, double E) {
    ca_select_options so;
    ca_select_options_init(&so);
    so.target_error = E;
    Search r;
    const auto t0 = std::chrono::steady_clock::now();
    ca_selection* sel = nullptr;
    r.status = ca_select(ctx, set, &so, &sel);
    r.wall_s = bench::seconds_since(t0);
    if (r.has_result()) {
        ca_select_stats ss;
        ss.struct_size = sizeof ss;
        ca_selection_stats(sel, &ss);
        r.balls = ca_selection_count(sel);
        r.probes = ss.probes;
        r.hd = ss.hd_reached;
    }
    ca_selection_destroy(sel);
    return r;
}

struct CountRun {
    uint32_t K = 0;
    size_t balls = 0;
    double hd = -1;   // -1: failed
};

// --target-count K, the defaults otherwise: its balls and HD.
CountRun count_run(ca_context* ctx, const ca_surface_view& v, const ca_candidate_set* set, uint32_t K) {
    ca_select_options so;
    ca_select_options_init(&so);
    so.target_count = K;
    const bench::SelectionRun t = bench::select_connect_evaluate(ctx, v, set, so);
    CountRun r;
    r.K = K;
    if (t.status == CA_OK) {
        r.balls = t.balls;
        r.hd = t.hd;
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    const auto models = bench::paper_models("bench_target_error", root);
    if (models.empty()) return 0;
    std::printf("\n## Error-bounded selection: --target-error 2, 1.5 and 1 against --target-count runs\n\n");
    std::printf("Closed paper meshes, defaults otherwise (|S| 1500, Voronoi candidates, exact cover, fast effort, probe_fit 0: "
                "each probe's cover judged unfitted and fitted once). Per E: the balls target-error returned, its HD (hd_reached: the "
                "skeleton ca_connect gives at its defaults), probes, wall s of ca_select; \"count\": the fewest balls of "
                "the --target-count runs of that model (K = 90 %% of each E's balls; connected at the defaults, "
                "evaluated at ca_evaluate's) with HD <= E, and its HD (\"none\": no run within E). Runs (K: balls HD) "
                "in the last column.\n\n");
    std::printf("| model | E=2: balls | HD %% | probes | s | count | HD %% | E=1.5: balls | HD %% | probes | s | count | HD %% "
                "| E=1: balls | HD %% | probes | s | count | HD %% | target-count runs |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    int closed_models = 0, reached[kE] = {}, not_reached[kE] = {}, failed[kE] = {}, no_more[kE] = {}, compared[kE] = {};
    std::vector<double> times[kE];
    std::string left_out;
    const auto start = std::chrono::steady_clock::now();
    for (const std::string& path : models) {
        if (!bench::selected(only, bench::stem(path))) continue;
        if (bench::seconds_since(start) > budget_s()) {
            left_out += (left_out.empty() ? "" : ", ") + bench::stem(path);
            continue;
        }
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) {
            std::printf("| %s | read failed: %s |\n", bench::stem(path).c_str(), err.c_str());
            continue;
        }
        const ca::Mesh core = to_core_mesh(mesh);
        if (!ca::mesh_topology(core, {}, ca::half_edge_buckets(core)).closed) continue;  // unwelded: open
        ca_context* ctx = nullptr;
        ca_context_create(nullptr, &ctx);
        const ca_surface_view v = bench::surface_view(mesh);
        ca_candidate_set* set = nullptr;
        if (ca_candidates(ctx, &v, nullptr, &set) != CA_OK) {
            std::printf("| %s | candidates failed: %s |\n", bench::stem(path).c_str(), ca_context_last_error(ctx));
            ca_context_destroy(ctx);
            continue;
        }
        ++closed_models;
        Search te[kE];
        std::vector<CountRun> runs;
        for (int e = 0; e < kE; ++e) {
            te[e] = search(ctx, set, kTargets[e]);
            if (te[e].status != CA_OK) continue;
            const uint32_t K = uint32_t(std::max<size_t>(1, size_t(std::floor(0.9 * double(te[e].balls)))));
            bool done = false;
            for (const CountRun& r : runs) done |= r.K == K;
            if (!done) runs.push_back(count_run(ctx, v, set, K));
        }
        ca_candidate_set_destroy(set);
        ca_context_destroy(ctx);
        std::printf("| %s |", bench::stem(path).c_str());
        for (int e = 0; e < kE; ++e) {
            const Search& t = te[e];
            const double E = kTargets[e];
            reached[e] += t.status == CA_OK && t.hd <= E;
            not_reached[e] += t.status == CA_ERROR_TARGET_NOT_REACHED;
            failed[e] += !t.has_result();
            times[e].push_back(t.wall_s);
            const CountRun* best = nullptr;
            for (const CountRun& r : runs)
                if (r.hd >= 0 && r.hd <= E && (!best || r.balls < best->balls)) best = &r;
            if (t.status == CA_OK) {
                ++compared[e];
                no_more[e] += !best || t.balls <= best->balls;
            }
            if (!t.has_result()) std::printf(" failed (%d) | | | %.2f |", t.status, t.wall_s);
            else
                std::printf(" %zu | %.3f%s | %llu | %.2f |", t.balls, t.hd, t.status == CA_OK ? "" : " (not reached)",
                            (unsigned long long)t.probes, t.wall_s);
            if (best) std::printf(" %zu | %.3f |", best->balls, best->hd);
            else std::printf(" none | |");
        }
        std::string rs;
        for (const CountRun& r : runs) {
            char buf[64];
            if (r.hd >= 0) std::snprintf(buf, sizeof buf, "%s%u: %zu %.3f", rs.empty() ? "" : "; ", r.K, r.balls, r.hd);
            else std::snprintf(buf, sizeof buf, "%s%u: failed", rs.empty() ? "" : "; ", r.K);
            rs += buf;
        }
        std::printf(" %s |\n", rs.c_str());
        std::fflush(stdout);
    }
    std::printf("\n");
    if (!left_out.empty())
        std::printf("Not run (the bench's %.0f s budget was spent; open or closed): %s.\n", budget_s(), left_out.c_str());
    for (int e = 0; e < kE; ++e)
        std::printf("E = %.3g %%: reached on %d of %d closed models; CA_ERROR_TARGET_NOT_REACHED on %d; other failures %d. "
                    "Target-error used no more balls than the target-count runs within E on %d of %d reached models. "
                    "Median wall time of ca_select %.2f s.\n",
                    kTargets[e], reached[e], closed_models, not_reached[e], failed[e], no_more[e], compared[e],
                    bench::median(times[e]));
    return 0;
}
