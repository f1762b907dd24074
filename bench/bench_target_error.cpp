// bench_target_error.cpp: the error-bounded selection (ca_select_options.target_error) on every
// mesh of <data>/meshes/paper: at --target-error 2, the balls, the two-sided Hausdorff distance
// it reached (% of the bbox diagonal), the HD of the .ma written from the skeleton ca_connect gives
// at its defaults (read back and measured as `coverage-axis evaluate` does), the probes and the CPU
// time, once without probe_fit (the search fits its probes only when the unfitted ones all miss)
// and once with it (probe_fit = 1: each probe is fitted); beside them a sweep of fixed deltas (each
// selected, then connected unfitted and, separately, with the fit, and evaluated) and the smallest
// ball count of each sweep that reaches HD <= 2 %. Summary, without and with probe_fit: how many
// closed models reach 2 %, how many end with CA_ERROR_TARGET_NOT_REACHED, and on how many the
// search needs fewer, as many or more balls than its sweep's best. Then the same searches at
// --target-error 1.5, without the sweep.
// usage: bench_target_error [DATA_ROOT] [--only NAME[,NAME...]]   (default ../shared/data; skipped when
// missing; --only keeps the meshes whose file stem starts with one of the names)
#include "bench_common.h"
#include "connect.h"
#include "mesh_topology.h"
#include "support/mesh_convert.h"

#include <cmath>
#include <cstdlib>
#include <unistd.h>
#include <vector>

namespace {

constexpr double kTarget = 2.0, kTighter = 1.5;
const double kSweep[] = {0.005, 0.0075, 0.01, 0.0125, 0.015, 0.02, 0.025, 0.03, 0.04};

struct Probe {
    ca_status status = CA_OK;
    size_t balls = 0;
    double hd = 0, delta = 0, cpu_s = 0;
    double ma_hd = -1;  // searches: the HD of the written .ma, read back
    uint64_t probes = 0;
    bool has_result() const { return status == CA_OK || status == CA_ERROR_TARGET_NOT_REACHED; }
};

// The .ma of `sel` connected at ca_connect's defaults, written, read back and measured with
// ca_evaluate's defaults (what `coverage-axis evaluate MESH SKELETON.ma` does).
double written_ma_hd(ca_context* ctx, const ca_surface_view& v, const ca_candidate_set* set, const ca_selection* sel) {
    ca_skeleton* sk = nullptr;
    if (ca_connect(ctx, set, sel, nullptr, &sk) != CA_OK) return -1;
    caio::SkeletonData sd;
    const size_t n = ca_skeleton_vertex_count(sk);
    sd.centers.assign(ca_skeleton_centers(sk), ca_skeleton_centers(sk) + 3 * n);
    sd.radii.assign(ca_skeleton_radii(sk), ca_skeleton_radii(sk) + n);
    sd.edges.assign(ca_skeleton_edges(sk), ca_skeleton_edges(sk) + 2 * ca_skeleton_edge_count(sk));
    sd.faces.assign(ca_skeleton_faces(sk), ca_skeleton_faces(sk) + 3 * ca_skeleton_face_count(sk));
    ca_skeleton_destroy(sk);
    const std::string path = "/tmp/bench_target_error." + std::to_string(getpid()) + ".ma";
    std::string err;
    caio::SkeletonData back;
    const bool ok = caio::write_ma(path, sd, err) && caio::read_ma(path, back, err);
    std::remove(path.c_str());
    if (!ok) return -1;
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    view.centers = back.centers.data();
    view.radii = back.radii.data();
    view.vertex_count = back.radii.size();
    view.edges = back.edges.data();
    view.edge_count = back.edges.size() / 2;
    view.faces = back.faces.data();
    view.face_count = back.faces.size() / 3;
    ca_evaluation ev{};
    ev.struct_size = sizeof ev;
    return ca_evaluate(ctx, &v, &view, nullptr, &ev) == CA_OK ? ev.hd_two_sided : -1;
}

// The two-sided HD of `sel` connected with `fit` (0/1) at the defaults otherwise.
ca_status connected_hd(ca_context* ctx, const ca_surface_view& v, const ca_candidate_set* set, const ca_selection* sel,
                       int32_t fit, double& hd) {
    ca_connect_options co;
    ca_connect_options_init(&co);
    co.fit = fit;
    ca_skeleton* sk = nullptr;
    ca_status st = ca_connect(ctx, set, sel, &co, &sk);
    size_t edges = 0, faces = 0, components = 0;
    long betti1 = 0;
    ca_evaluation ev{};
    if (st == CA_OK) st = bench::measure_skeleton(ctx, v, sk, true, edges, faces, components, betti1, ev);
    hd = ev.hd_two_sided;
    ca_skeleton_destroy(sk);
    return st;
}

// The search with `so` (target_error set): balls, the HD it measured, delta, probes, CPU time
// (the search's), and the HD of the .ma written from its result (also when not reached).
Probe search(ca_context* ctx, const ca_surface_view& v, const ca_candidate_set* set, const ca_select_options& so) {
    Probe p;
    const double c0 = bench::cpu_seconds();
    ca_selection* sel = nullptr;
    p.status = ca_select(ctx, set, &so, &sel);
    p.cpu_s = bench::cpu_seconds() - c0;
    if (p.has_result()) {
        ca_select_stats ss;
        ss.struct_size = sizeof ss;
        ca_selection_stats(sel, &ss);
        p.balls = ca_selection_count(sel);
        p.delta = ss.delta_absolute / ca_candidate_set_reference_length(set);
        p.probes = ss.probes;
        p.hd = ss.hd_reached;
        p.ma_hd = written_ma_hd(ctx, v, set, sel);
    }
    ca_selection_destroy(sel);
    return p;
}

// One swept delta, selected once and measured without (out[0]) and with (out[1]) the fit.
void sweep_delta(ca_context* ctx, const ca_surface_view& v, const ca_candidate_set* set, ca_select_options so,
                 Probe out[2]) {
    ca_selection* sel = nullptr;
    const double c0 = bench::cpu_seconds();
    const ca_status st = ca_select(ctx, set, &so, &sel);
    const double select_s = bench::cpu_seconds() - c0;
    for (int fit = 0; fit < 2; ++fit) {
        Probe& p = out[fit];
        p = Probe{};
        const double c1 = bench::cpu_seconds();
        p.status = st;
        if (st == CA_OK) {
            p.balls = ca_selection_count(sel);
            p.delta = so.delta;
            p.status = connected_hd(ctx, v, set, sel, fit, p.hd);
        }
        p.cpu_s = select_s + bench::cpu_seconds() - c1;
    }
    ca_selection_destroy(sel);
}

struct Tally {
    double target = kTarget;
    int closed_models = 0, closed_reached = 0, not_reached = 0, failed = 0, fewer = 0, same = 0, more = 0, sweep_none = 0;
    double search_s = 0, sweep_s = 0;
    void add(bool closed, const Probe& te, bool found, const Probe& best, double sweep_cpu) {
        const bool reached = te.status == CA_OK && te.hd <= target;
        if (closed) {
            ++closed_models;
            closed_reached += reached;
            not_reached += te.status == CA_ERROR_TARGET_NOT_REACHED;
            failed += !te.has_result();
        }
        search_s += te.cpu_s;
        sweep_s += sweep_cpu;
        if (!found) ++sweep_none;
        else if (reached && te.balls < best.balls) ++fewer;
        else if (reached && te.balls == best.balls) ++same;
        else ++more;
    }
    void print(const char* what, bool sweep) const {
        std::printf("%s: closed models reaching HD <= %.3g %%: %d of %d; ended with CA_ERROR_TARGET_NOT_REACHED: %d; "
                    "other failures: %d.",
                    what, target, closed_reached, closed_models, not_reached, failed);
        if (sweep)
            std::printf(" Against the sweep's best (models where a swept delta reaches it): fewer balls on %d, as many "
                        "on %d, more (or target not reached) on %d; no swept delta reaches it on %d. CPU time: search "
                        "%.0f s, sweep %.0f s in all.",
                        fewer, same, more, sweep_none, search_s, sweep_s);
        else std::printf(" CPU time: search %.0f s in all.", search_s);
        std::printf("\n");
    }
};

void print_search(const Probe& te, double target) {
    if (!te.has_result()) std::printf(" failed (%d) | | | | %.1f |", te.status, te.cpu_s);
    else
        std::printf(" %zu | %.3f%s | %.3f | %llu | %.1f |", te.balls, te.hd,
                    te.status == CA_OK ? "" : " (CA_ERROR_TARGET_NOT_REACHED)", te.ma_hd, (unsigned long long)te.probes,
                    te.cpu_s);
    (void)target;
}

void print_best(bool found, const Probe& best) {
    if (found) std::printf(" %zu | %.3f | %.4g |", best.balls, best.hd, best.delta);
    else std::printf(" none | | |");
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    const auto models = bench::list_files(root + "/meshes/paper", ".obj");
    if (models.empty()) {
        std::printf("bench_target_error: no models under %s/meshes/paper, skipped\n", root.c_str());
        return 0;
    }
    std::printf("\n## Error-bounded selection: --target-error %.0f against a delta sweep, without and with the fit\n\n",
                kTarget);
    std::printf("Defaults otherwise (|S| 1500, Voronoi candidates, exact cover, fast effort, medial route, evaluation "
                "30 000 / 100 000 samples). \"target\": probe_fit = 0 (unfitted probes; on a mesh, searched again "
                "fitted when all miss). \"fit\": probe_fit = 1 (each probe connected with fit = 1, 10 "
                "iterations), and the sweep connected with fit = 1. \".ma HD\": the result connected at ca_connect's "
                "defaults, written as .ma, read back and evaluated. Sweep deltas:");
    for (double d : kSweep) std::printf(" %g", d);
    std::printf("; \"sweep best\" is the fewest balls among them with HD <= %.0f %%. CPU s: user + system of the "
                "process, all threads.\n\n",
                kTarget);
    std::printf("| model | closed | target: balls | HD %% | .ma HD %% | probes | CPU s | fit target: balls | HD %% | .ma HD %% "
                "| probes | CPU s | sweep best: balls | HD %% | delta | fit sweep best: balls | HD %% | delta |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    Tally plain, fitted, plain15, fitted15;
    plain15.target = fitted15.target = kTighter;
    struct Tight { std::string name; bool closed; Probe te, te_fit; };
    std::vector<Tight> tight;
    for (const std::string& path : models) {
        if (!bench::selected(only, bench::stem(path))) continue;
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) {
            std::printf("| %s | read failed: %s |\n", bench::stem(path).c_str(), err.c_str());
            continue;
        }
        const ca::Mesh core = to_core_mesh(mesh);
        const bool closed = ca::mesh_topology(core, {}, ca::half_edge_buckets(core)).closed;   // unwelded
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
        const Probe te = search(ctx, v, set, so);
        so.probe_fit = 1;
        const Probe te_fit = search(ctx, v, set, so);
        so.target_error = kTighter;
        so.probe_fit = 0;
        Tight t{bench::stem(path), closed, search(ctx, v, set, so), {}};
        so.probe_fit = 1;
        t.te_fit = search(ctx, v, set, so);
        tight.push_back(t);
        so.target_error = 0;
        so.probe_fit = 0;
        Probe best[2];
        bool found[2] = {false, false};
        double sweep_s[2] = {0, 0};
        for (double d : kSweep) {
            so.delta = d;
            Probe p[2];
            sweep_delta(ctx, v, set, so, p);
            for (int f = 0; f < 2; ++f) {
                sweep_s[f] += p[f].cpu_s;
                if (p[f].status != CA_OK || p[f].hd > kTarget) continue;
                if (!found[f] || p[f].balls < best[f].balls || (p[f].balls == best[f].balls && p[f].hd < best[f].hd))
                    best[f] = p[f];
                found[f] = true;
            }
        }
        ca_candidate_set_destroy(set);
        ca_context_destroy(ctx);
        plain.add(closed, te, found[0], best[0], sweep_s[0]);
        fitted.add(closed, te_fit, found[1], best[1], sweep_s[1]);
        plain15.add(closed, t.te, false, Probe{}, 0);
        fitted15.add(closed, t.te_fit, false, Probe{}, 0);
        std::printf("| %s | %s |", bench::stem(path).c_str(), closed ? "yes" : "no");
        print_search(te, kTarget);
        print_search(te_fit, kTarget);
        print_best(found[0], best[0]);
        print_best(found[1], best[1]);
        std::printf("\n");
        std::fflush(stdout);
    }
    std::printf("\n");
    plain.print("Without probe_fit", true);
    fitted.print("With probe_fit", true);
    std::printf("\n## --target-error %.3g, without and with probe_fit (no sweep)\n\n", kTighter);
    std::printf("| model | closed | target: balls | HD %% | .ma HD %% | probes | CPU s | fit target: balls | HD %% | .ma HD %% "
                "| probes | CPU s |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Tight& t : tight) {
        std::printf("| %s | %s |", t.name.c_str(), t.closed ? "yes" : "no");
        print_search(t.te, kTighter);
        print_search(t.te_fit, kTighter);
        std::printf("\n");
    }
    std::printf("\n");
    plain15.print("Without probe_fit", false);
    fitted15.print("With probe_fit", false);
    return 0;
}
