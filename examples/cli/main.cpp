// main.cpp: the coverage-axis command-line tool: mesh or point cloud in, medial skeleton out
// (.ma / .obj / .ply), through the library's C ABI only. Prints a one-screen summary, or one
// JSON object with --json. Exit codes: 0 success, 1 the library refused or failed (message on
// stderr), 2 bad command line, 3 a file could not be read or written.
#include "cli.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

const char* kUsage =
    "usage: coverage-axis INPUT [options]\n"
    "       coverage-axis evaluate INPUT SKELETON.ma [--json]   (see coverage-axis evaluate --help)\n"
    "  INPUT                     .obj .off .ply (mesh) or .xyz / .obj with vn (oriented point cloud)\n"
    "  -o, --output OUT.ma       write the skeleton as .ma (default: INPUT stem + .ma)\n"
    "  --obj OUT.obj             also write .obj (v, l, f)\n"
    "  --ply OUT.ply             also write .ply (radius property, edge element)\n"
    "  --delta D                 dilation offset, fraction of the longest bbox side (default %DELTA%)\n"
    "  --scale S                 dilation by scaling r' = r * S instead of an offset\n"
    "  --samples N               surface samples to cover (default %SAMPLES%)\n"
    "  --voronoi-samples N       samples for the Voronoi candidates (default %VORONOI%)\n"
    "  --candidates KIND         voronoi (default) | random[:N] (default N %RANDOM%) | FILE (v x y z r)\n"
    "  --surface-samples FILE    cover these samples (v x y z, input units) instead of sampling\n"
    "  --solver NAME             exact (default) | greedy | capp\n"
    "  --effort NAME             exact solver: fast (default: LP bound + local search, CBC only for a\n"
    "                            one-ball gap on a small kernel) | prove (CBC until proven optimal)\n"
    "  --target-count K          at most K balls, with the smallest delta (or scale) that achieves it\n"
    "  --divide N                divide and conquer above N surface samples (default %DIVIDE%; 0 = never)\n"
    "  --connect ROUTE           auto (default: medial for meshes, power for point clouds) | medial | power\n"
    "  --skip-uncoverable        ignore samples no ball covers instead of failing\n"
    "  --ignore-samples FILE     indices (0-based) of samples that need not be covered\n"
    "  --force-in FILE           indices of candidate balls that must be selected\n"
    "  --force-out FILE          indices of candidate balls that must not be selected\n"
    "  --seed N                  random seed (default %SEED%)\n"
    "  --time-limit SEC          exact solver budget in seconds (default %TIME%)\n"
    "  --threads N               worker threads (default 0 = all cores)\n"
    "  --export-samples FILE     write the covered surface samples (v x y z)\n"
    "  --export-candidates FILE  write the candidate balls (v x y z r)\n"
    "  --evaluate                measure the skeleton: Hausdorff distances in % of the bbox diagonal\n"
    "  --json                    print one JSON object on stdout\n"
    "  --quiet                   no summary, no progress bar\n";

// The usage text with the library's defaults (from the *_init functions) in place of %NAME%.
std::string usage_text() {
    ca_candidate_options co;
    ca_candidate_options_init(&co);
    ca_select_options so;
    ca_select_options_init(&so);
    auto num = [](double v) { char b[32]; std::snprintf(b, sizeof b, "%g", v); return std::string(b); };
    const std::pair<const char*, std::string> values[] = {
        {"%DELTA%", num(so.delta)}, {"%SAMPLES%", num(co.cover_samples)}, {"%VORONOI%", num(co.voronoi_samples)},
        {"%RANDOM%", num(co.random_candidates)}, {"%DIVIDE%", num(so.divide_threshold)},
        {"%SEED%", std::to_string(co.seed)}, {"%TIME%", num(so.time_limit_s)}};
    std::string text = kUsage;
    for (const auto& [key, value] : values) text.replace(text.find(key), std::strlen(key), value);
    return text;
}

// Command-line settings; the defaults are the library's (the *_init functions).
struct Args {
    std::string input, out_ma, out_obj, out_ply, candidates = "voronoi", surface_samples;
    std::string export_samples, export_candidates, solver = "exact", effort = "fast";
    std::string ignore_samples, force_in, force_out, connect = "auto";
    long target_count = 0;
    long divide = -1;  // -1: the library default
    double delta, scale = 0, time_limit;
    long samples, voronoi_samples, random_count, threads;
    unsigned long long seed;
    bool json = false, quiet = false, skip_uncoverable = false, evaluate = false;
    Args() {
        ca_context_desc cd;
        ca_context_desc_init(&cd);
        ca_candidate_options co;
        ca_candidate_options_init(&co);
        ca_select_options so;
        ca_select_options_init(&so);
        delta = so.delta;
        time_limit = so.time_limit_s;
        samples = co.cover_samples;
        voronoi_samples = co.voronoi_samples;
        random_count = co.random_candidates;
        seed = co.seed;
        threads = cd.threads;
    }
};

int usage_error(const std::string& msg) {
    std::fprintf(stderr, "coverage-axis: %s (see coverage-axis --help)\n", msg.c_str());
    return 2;
}

bool parse_number(const char* s, double& out) {
    char* end = nullptr;
    out = std::strtod(s, &end);
    return end != s && *end == '\0' && std::isfinite(out);
}
bool parse_count(const char* s, long& out, long min) {
    char* end = nullptr;
    out = std::strtol(s, &end, 10);
    return end != s && *end == '\0' && out >= min && out <= 100000000;
}

int parse_args(int argc, char** argv, Args& a) {
    for (int i = 1; i < argc; ++i) {
        std::string k = argv[i];
        auto value = [&](const char*& v) {
            if (i + 1 >= argc) return false;
            v = argv[++i];
            return true;
        };
        const char* v = nullptr;
        double d;
        if (k == "-h" || k == "--help") { std::fputs(usage_text().c_str(), stdout); return -1; }
        else if (k == "--json") a.json = true;
        else if (k == "--evaluate") a.evaluate = true;
        else if (k == "--quiet") a.quiet = true;
        else if (k == "--skip-uncoverable") a.skip_uncoverable = true;
        else if (k[0] == '-' && k.size() > 1) {
            if (!value(v)) return usage_error(k + " needs a value");
            if (k == "-o" || k == "--output") a.out_ma = v;
            else if (k == "--obj") a.out_obj = v;
            else if (k == "--ply") a.out_ply = v;
            else if (k == "--delta") { if (!parse_number(v, d) || d < 0) return usage_error("--delta takes a number >= 0"); a.delta = d; }
            else if (k == "--scale") { if (!parse_number(v, d) || d < 1) return usage_error("--scale takes a number >= 1"); a.scale = d; }
            else if (k == "--samples") { if (!parse_count(v, a.samples, 1)) return usage_error("--samples takes a count >= 1"); }
            else if (k == "--voronoi-samples") { if (!parse_count(v, a.voronoi_samples, 5)) return usage_error("--voronoi-samples takes a count >= 5"); }
            else if (k == "--candidates") a.candidates = v;
            else if (k == "--surface-samples") a.surface_samples = v;
            else if (k == "--solver") {
                a.solver = v;
                if (a.solver != "exact" && a.solver != "greedy" && a.solver != "capp") return usage_error("--solver takes exact, greedy or capp");
            }
            else if (k == "--effort") {
                a.effort = v;
                if (a.effort != "fast" && a.effort != "prove") return usage_error("--effort takes fast or prove");
            }
            else if (k == "--seed") { char* e; a.seed = std::strtoull(v, &e, 10); if (*e || e == v) return usage_error("--seed takes a non-negative integer"); }
            else if (k == "--time-limit") { if (!parse_number(v, d)) return usage_error("--time-limit takes seconds"); a.time_limit = d; }
            else if (k == "--threads") { if (!parse_count(v, a.threads, 0)) return usage_error("--threads takes a count >= 0"); }
            else if (k == "--divide") { if (!parse_count(v, a.divide, 0)) return usage_error("--divide takes a sample count >= 0"); }
            else if (k == "--target-count") { if (!parse_count(v, a.target_count, 1)) return usage_error("--target-count takes a count >= 1"); }
            else if (k == "--connect") {
                a.connect = v;
                if (a.connect != "auto" && a.connect != "medial" && a.connect != "power") return usage_error("--connect takes auto, medial or power");
            }
            else if (k == "--ignore-samples") a.ignore_samples = v;
            else if (k == "--force-in") a.force_in = v;
            else if (k == "--force-out") a.force_out = v;
            else if (k == "--export-samples") a.export_samples = v;
            else if (k == "--export-candidates") a.export_candidates = v;
            else return usage_error("unknown option " + k);
        } else if (a.input.empty()) a.input = k;
        else return usage_error("more than one input file: " + a.input + ", " + k);
    }
    if (a.input.empty()) return usage_error("no input file");
    if (a.candidates.rfind("random", 0) == 0 && a.candidates.size() > 6) {
        if (a.candidates[6] != ':' || !parse_count(a.candidates.c_str() + 7, a.random_count, 1))
            return usage_error("--candidates random:N takes a count >= 1");
        a.candidates = "random";
    }
    if (a.out_ma.empty()) {
        std::string stem = a.input;
        const size_t slash = stem.find_last_of('/');
        const size_t dot = stem.find_last_of('.');
        if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) stem.resize(dot);
        a.out_ma = stem + ".ma";
    }
    return 0;
}

// Progress bar on stderr, only when it is a terminal.
struct ProgressBar {
    bool enabled = false;
    std::string stage;
    int last = -1;
    // One line per stage, redrawn in place; a new line when the stage changes.
    static int32_t callback(void* user, const char* stage, double f) {
        auto* self = static_cast<ProgressBar*>(user);
        const int pct = std::min(100, std::max(0, int(f * 100)));
        if (self->stage != stage || pct != self->last) {
            if (!self->stage.empty() && self->stage != stage) std::fputc('\n', stderr);
            self->stage = stage;
            self->last = pct;
            std::fprintf(stderr, "\r%-12s [%-30s] %3d%%", stage, std::string(size_t(pct * 30 / 100), '#').c_str(), pct);
            std::fflush(stderr);
        }
        return 0;
    }
    void finish() {
        if (!stage.empty()) std::fputc('\n', stderr);
        stage.clear();
    }
};

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string json_escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '"' || c == '\\') { o += '\\'; o += c; }
        else if (static_cast<unsigned char>(c) < 0x20) { char b[8]; std::snprintf(b, sizeof b, "\\u%04x", c); o += b; }
        else o += c;
    }
    return o;
}

int library_error(ca_context* ctx, ca_status st, const char* step) {
    const char* hint = st == CA_ERROR_UNCOVERABLE ? "; raise --delta, add candidates, or pass --skip-uncoverable" : "";
    std::fprintf(stderr, "coverage-axis: %s failed: %s%s (%s)\n", step, ca_context_last_error(ctx), hint, ca_status_string(st));
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "evaluate") == 0) return cli::evaluate_command(argc, argv);
    Args a;
    const int pr = parse_args(argc, argv, a);
    if (pr < 0) return 0;
    if (pr > 0) return pr;
    const auto t_start = Clock::now();

    caio::MeshData mesh;
    std::string err;
    if (!caio::read_mesh(a.input, mesh, err)) { std::fprintf(stderr, "coverage-axis: %s\n", err.c_str()); return 3; }
    const double t_read = since(t_start);

    ProgressBar bar;
    bar.enabled = !a.quiet && !a.json && isatty(2);
    ca_context_desc desc;
    ca_context_desc_init(&desc);
    desc.threads = int32_t(a.threads);
    if (bar.enabled) { desc.progress = ProgressBar::callback; desc.progress_user = &bar; }
    ca_context* ctx = nullptr;
    if (ca_context_create(&desc, &ctx) != CA_OK) { std::fprintf(stderr, "coverage-axis: cannot create a context\n"); return 1; }
    struct Cleanup {
        ca_context* ctx; ca_candidate_set* set = nullptr; ca_selection* sel = nullptr; ca_skeleton* sk = nullptr;
        ~Cleanup() { ca_skeleton_destroy(sk); ca_selection_destroy(sel); ca_candidate_set_destroy(set); ca_context_destroy(ctx); }
    } owned{ctx};

    // ---- step 1: candidates (generated, or from files) ----
    auto t0 = Clock::now();
    ca_status st;
    const bool candidates_from_file = a.candidates != "voronoi" && a.candidates != "random";
    std::vector<double> file_samples, file_centers, file_radii, unused;
    if (!a.surface_samples.empty() && !caio::read_points(a.surface_samples, file_samples, unused, err)) {
        std::fprintf(stderr, "coverage-axis: %s\n", err.c_str());
        return 3;
    }
    if (candidates_from_file) {
        if (!caio::read_points(a.candidates, file_centers, file_radii, err)) { std::fprintf(stderr, "coverage-axis: %s\n", err.c_str()); return 3; }
        if (file_radii.size() * 3 != file_centers.size() || file_radii.empty()) {
            std::fprintf(stderr, "coverage-axis: %s: every candidate needs a radius (v x y z r)\n", a.candidates.c_str());
            return 3;
        }
    }
    // Generate unless both the samples and the candidates come from files; files then replace
    // the generated parts.
    if (!(candidates_from_file && !a.surface_samples.empty())) {
        const ca_surface_view view = cli::surface_view(mesh);
        ca_candidate_options co;
        ca_candidate_options_init(&co);
        co.generator = a.candidates == "random" ? CA_CANDIDATES_RANDOM : CA_CANDIDATES_VORONOI;
        co.cover_samples = uint32_t(a.samples);
        co.voronoi_samples = uint32_t(a.voronoi_samples);
        co.random_candidates = uint32_t(a.random_count);
        co.seed = a.seed;
        if ((st = ca_candidates(ctx, &view, &co, &owned.set)) != CA_OK) return library_error(ctx, st, "candidates");
    }
    if (candidates_from_file || !a.surface_samples.empty()) {
        // delta stays relative to the input's longest bbox side
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i + 2 < mesh.positions.size(); i += 3)
            for (size_t k = 0; k < 3; ++k) { lo[k] = std::min(lo[k], mesh.positions[i + k]); hi[k] = std::max(hi[k], mesh.positions[i + k]); }
        const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
        const double* sp = file_samples.empty() ? ca_candidate_set_samples(owned.set) : file_samples.data();
        const size_t sn = file_samples.empty() ? ca_candidate_set_sample_count(owned.set) : file_samples.size() / 3;
        const double* cp = file_centers.empty() ? ca_candidate_set_centers(owned.set) : file_centers.data();
        const double* rp = file_radii.empty() ? ca_candidate_set_radii(owned.set) : file_radii.data();
        const size_t cn = file_radii.empty() ? ca_candidate_set_count(owned.set) : file_radii.size();
        ca_candidate_set* replaced = nullptr;
        st = ca_candidates_from_arrays(ctx, sp, sn, 0, cp, 0, rp, 0, cn, std::isfinite(longest) && longest > 0 ? longest : 0, &replaced);
        if (st != CA_OK) return library_error(ctx, st, "candidates");
        ca_candidate_set_destroy(owned.set);
        owned.set = replaced;
    }
    const double t_candidates = since(t0);
    const size_t n_samples = ca_candidate_set_sample_count(owned.set), n_candidates = ca_candidate_set_count(owned.set);
    if (!a.export_samples.empty()) {
        std::vector<double> xyz(ca_candidate_set_samples(owned.set), ca_candidate_set_samples(owned.set) + 3 * n_samples);
        if (!caio::write_points(a.export_samples, xyz, {}, err)) { std::fprintf(stderr, "coverage-axis: %s\n", err.c_str()); return 3; }
    }
    if (!a.export_candidates.empty()) {
        std::vector<double> xyz(ca_candidate_set_centers(owned.set), ca_candidate_set_centers(owned.set) + 3 * n_candidates);
        std::vector<double> r(ca_candidate_set_radii(owned.set), ca_candidate_set_radii(owned.set) + n_candidates);
        if (!caio::write_points(a.export_candidates, xyz, r, err)) { std::fprintf(stderr, "coverage-axis: %s\n", err.c_str()); return 3; }
    }

    // ---- step 2: selection ----
    t0 = Clock::now();
    ca_select_options so;
    ca_select_options_init(&so);
    if (a.scale > 0) { so.dilation = CA_DILATE_SCALE; so.scale = a.scale; }
    else so.delta = a.delta;
    so.solver = a.solver == "greedy" ? CA_SOLVER_GREEDY : a.solver == "capp" ? CA_SOLVER_CAPP : CA_SOLVER_EXACT;
    so.time_limit_s = a.time_limit;
    so.effort = a.effort == "prove" ? CA_EFFORT_PROVE : CA_EFFORT_FAST;
    so.skip_uncoverable = a.skip_uncoverable ? 1 : 0;
    so.target_count = uint32_t(a.target_count);
    if (a.divide >= 0) so.divide_threshold = uint32_t(std::min<long>(a.divide, UINT32_MAX));
    // user control (paper 8.2): index files become per-sample / per-ball masks
    std::vector<uint8_t> ignorable, forced_in, forced_out;
    struct MaskFile { const std::string& path; size_t size; std::vector<uint8_t>& mask; const uint8_t** field; const char* what; };
    for (MaskFile m : {MaskFile{a.ignore_samples, n_samples, ignorable, &so.ignorable_samples, "sample"},
                       MaskFile{a.force_in, n_candidates, forced_in, &so.forced_in, "candidate"},
                       MaskFile{a.force_out, n_candidates, forced_out, &so.forced_out, "candidate"}}) {
        if (m.path.empty()) continue;
        std::vector<uint32_t> idx;
        if (!caio::read_indices(m.path, idx, err)) { std::fprintf(stderr, "coverage-axis: %s\n", err.c_str()); return 3; }
        m.mask.assign(m.size, 0);
        for (uint32_t i : idx) {
            if (i >= m.size) {
                std::fprintf(stderr, "coverage-axis: %s: %s index %u out of range (%zu %ss)\n", m.path.c_str(), m.what, i, m.size, m.what);
                return 3;
            }
            m.mask[i] = 1;
        }
        *m.field = m.mask.data();
    }
    if ((st = ca_select(ctx, owned.set, &so, &owned.sel)) != CA_OK) return library_error(ctx, st, "selection");
    const double t_select = since(t0);
    ca_select_stats ss;
    ss.struct_size = sizeof ss;
    ca_selection_stats(owned.sel, &ss);

    // ---- step 3: connection ----
    t0 = Clock::now();
    ca_connect_options cop;
    ca_connect_options_init(&cop);
    cop.method = a.connect == "medial" ? CA_CONNECT_MEDIAL : a.connect == "power" ? CA_CONNECT_POWER : CA_CONNECT_AUTO;
    if ((st = ca_connect(ctx, owned.set, owned.sel, &cop, &owned.sk)) != CA_OK) return library_error(ctx, st, "connection");
    const double t_connect = since(t0);
    ca_skeleton_stats ks;
    ks.struct_size = sizeof ks;
    ca_skeleton_stats_get(owned.sk, &ks);

    // ---- output files ----
    t0 = Clock::now();
    caio::SkeletonData sd;
    const size_t nv = ca_skeleton_vertex_count(owned.sk);
    sd.centers.assign(ca_skeleton_centers(owned.sk), ca_skeleton_centers(owned.sk) + 3 * nv);
    sd.radii.assign(ca_skeleton_radii(owned.sk), ca_skeleton_radii(owned.sk) + nv);
    sd.edges.assign(ca_skeleton_edges(owned.sk), ca_skeleton_edges(owned.sk) + 2 * ca_skeleton_edge_count(owned.sk));
    sd.faces.assign(ca_skeleton_faces(owned.sk), ca_skeleton_faces(owned.sk) + 3 * ca_skeleton_face_count(owned.sk));
    if (!caio::write_ma(a.out_ma, sd, err) || (!a.out_obj.empty() && !caio::write_obj(a.out_obj, sd, err)) ||
        (!a.out_ply.empty() && !caio::write_ply(a.out_ply, sd, err))) {
        std::fprintf(stderr, "coverage-axis: %s\n", err.c_str());
        return 3;
    }
    if (bar.enabled) bar.finish();
    const double t_write = since(t0);
    ca_evaluation ev{};
    double t_evaluate = 0;
    if (a.evaluate) {
        t0 = Clock::now();
        ca_skeleton_view view;
        ca_skeleton_view_init(&view);
        ca_skeleton_get_view(owned.sk, &view);
        ca_evaluate_options eo;
        ca_evaluate_options_init(&eo);
        if (!cli::evaluate(ctx, mesh, view, eo, ev)) return 1;
        t_evaluate = since(t0);
    }
    const double t_total = since(t_start);

    const size_t uncovered = ca_selection_uncovered_count(owned.sel);
    if (a.json) {
        std::printf("{\"input\":\"%s\",\"surface_samples\":%zu,\"candidates\":%zu,\"selected\":%zu,\"edges\":%llu,"
                    "\"faces\":%llu,\"components\":%llu,\"isolated\":%llu,\"betti1\":%lld,\"uncovered\":%zu,"
                    "\"optimal\":%s,\"objective\":%.0f,\"lower_bound\":%.0f,\"gap\":%.6g,\"delta\":%.9g,"
                    "\"solver\":\"%s\",\"effort\":\"%s\",\"connect\":\"%s\",\"probes\":%llu,\"parts\":%llu,\"output\":\"%s\",%s%s"
                    "\"time_s\":{\"read\":%.4f,\"candidates\":%.4f,\"select\":%.4f,\"connect\":%.4f,\"write\":%.4f,"
                    "\"evaluate\":%.4f,\"total\":%.4f}}\n",
                    json_escape(a.input).c_str(), n_samples, n_candidates, nv, (unsigned long long)ks.edges,
                    (unsigned long long)ks.faces, (unsigned long long)ks.components, (unsigned long long)ks.isolated,
                    (long long)ks.betti1, uncovered, ss.proven_optimal ? "true" : "false", ss.objective, ss.lower_bound,
                    ss.gap, ss.delta_absolute, a.solver.c_str(), a.effort.c_str(), ks.method == CA_CONNECT_MEDIAL ? "medial" : "power",
                    (unsigned long long)ss.probes, (unsigned long long)ss.parts, json_escape(a.out_ma).c_str(),
                    a.evaluate ? cli::evaluation_json(ev).c_str() : "", a.evaluate ? "," : "", t_read, t_candidates,
                    t_select, t_connect, t_write, t_evaluate, t_total);
    } else if (!a.quiet) {
        std::printf("input       %s (%zu vertices, %zu triangles)\n", a.input.c_str(), mesh.positions.size() / 3, mesh.triangles.size() / 3);
        std::printf("samples     %zu surface samples, %zu candidate balls (%s)\n", n_samples, n_candidates, a.candidates.c_str());
        if (so.dilation == CA_DILATE_OFFSET)
            std::printf("dilation    r + %.4g (delta %.4g of the longest bbox side)%s\n", ss.delta_absolute,
                        ss.delta_absolute / ca_candidate_set_reference_length(owned.set), a.target_count ? ", found by the target size" : "");
        else
            std::printf("dilation    r * %.4g%s\n", ss.scale_used, a.target_count ? ", found by the target size" : "");
        std::printf("selection   %zu balls, %s (lower bound %.0f, gap %.2f %%), solver %s%s%s\n", nv,
                    ss.proven_optimal ? "proven optimal" : "not proven optimal", ss.lower_bound, 100 * ss.gap, a.solver.c_str(),
                    a.solver == "exact" ? ", effort " : "", a.solver == "exact" ? a.effort.c_str() : "");
        if (a.solver == "exact" && a.effort == "fast" && !ss.proven_optimal)
            std::printf("            (--effort prove runs CBC until the cover is proven optimal)\n");
        std::printf("            reduced %llu x %llu -> %llu x %llu (%llu forced)\n", (unsigned long long)ss.rows_before,
                    (unsigned long long)ss.cols_before, (unsigned long long)ss.rows_after, (unsigned long long)ss.cols_after,
                    (unsigned long long)ss.forced);
        if (uncovered) std::printf("            %zu samples covered by no ball were skipped\n", uncovered);
        std::printf("skeleton    %s route: %zu vertices, %llu edges, %llu faces, %llu component(s), %llu isolated, b1 = %lld\n",
                    ks.method == CA_CONNECT_MEDIAL ? "medial" : "power", nv,
                    (unsigned long long)ks.edges, (unsigned long long)ks.faces, (unsigned long long)ks.components,
                    (unsigned long long)ks.isolated, (long long)ks.betti1);
        if (a.evaluate)
            std::printf("hausdorff   surface->skeleton %.3f %%, skeleton->surface %.3f %%, two-sided %.3f %% of the bbox diagonal\n",
                        ev.hd_surface_to_recon, ev.hd_recon_to_surface, ev.hd_two_sided);
        std::printf("time        read %.3f s, candidates %.3f s, select %.3f s, connect %.3f s, total %.3f s\n", t_read,
                    t_candidates, t_select, t_connect, t_total);
        std::printf("wrote       %s", a.out_ma.c_str());
        if (!a.out_obj.empty()) std::printf(", %s", a.out_obj.c_str());
        if (!a.out_ply.empty()) std::printf(", %s", a.out_ply.c_str());
        std::printf("\n");
    }
    return 0;
}
