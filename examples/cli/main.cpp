// main.cpp: the coverage-axis command-line tool: mesh or point cloud in, medial skeleton out
// (.ma, and on request .obj / .ply / glTF / a preview picture), through the library's C ABI only.
// Prints a one-screen summary, or one JSON object with --json (also on failure). Commands:
// `coverage-axis INPUT [options]`, `coverage-axis batch ...`, `coverage-axis evaluate ...`.
// Exit codes: 0 success, 1 the library refused or failed, 2 bad command line, 3 a file could
// not be read or written (a reader that crashed or ran past its limits included). The internal
// command `--internal-read` is the child process that reads an input through assimp
// (isolated_read.cpp).
#include "cli.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <unistd.h>

namespace {

// Progress bar on stderr, only when it is a terminal: one line per stage, redrawn in place.
struct ProgressBar {
    std::string stage;
    int last = -1;
    std::string detail;  // the searches' last note: "probe k of at most n: ...; best so far ..."
    void draw(int pct) const {
        std::fprintf(stderr, "\r%-12s [%-30s] %3d%%%s%s\x1b[K", stage.c_str(), std::string(size_t(pct * 30 / 100), '#').c_str(),
                     pct, detail.empty() ? "" : "  ", detail.c_str());
        std::fflush(stderr);
    }
    static int32_t callback(void* user, const char* stage, double f) {
        auto* self = static_cast<ProgressBar*>(user);
        const int pct = std::min(100, std::max(0, int(f * 100)));
        if (self->stage != stage || pct != self->last) {
            if (!self->stage.empty() && self->stage != stage) {
                std::fputc('\n', stderr);
                self->detail.clear();
            }
            self->stage = stage;
            self->last = pct;
            self->draw(pct);
        }
        return 0;
    }
    // the search's notes (info, "target error: probe ...") go beside its bar: probe k of n, best so far
    static void log(void* user, int32_t level, const char* message) {
        auto* self = static_cast<ProgressBar*>(user);
        const std::string m = message;
        const std::string prefix = "target error: probe ";
        if (level != 1 || m.compare(0, prefix.size(), prefix) != 0) return;
        self->detail = m.substr(std::string("target error: ").size());
        self->draw(std::max(self->last, 0));
    }
    void finish() {
        if (!stage.empty()) std::fputc('\n', stderr);
        stage.clear();
    }
};

std::string default_ma_path(const std::string& input) {
    std::string stem = input;
    const size_t slash = stem.find_last_of('/'), dot = stem.find_last_of('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) stem.resize(dot);
    return stem + ".ma";
}

void print_summary(const cli::Json& j, const cli::RunOptions& o) {
    auto u = [&](const char* k) { return j[k].get<unsigned long long>(); };
    std::printf("input       %s (%llu vertices, %llu triangles)\n", j["input"].get<std::string>().c_str(), u("input_vertices"),
                u("input_triangles"));
    const cli::Json& skin = j["skin"];
    if (!skin.is_null())
        std::printf("skin        %llu joints, %llu weights per vertex\n", skin["joints"].get<unsigned long long>(),
                    skin["influences"].get<unsigned long long>());
    const cli::Json& dropped = j["dropped"];
    if (!dropped.empty()) {
        std::string parts;
        for (const auto& d : dropped) parts += (parts.empty() ? "" : "; ") + d.get<std::string>();
        if (parts.size() > 240) parts = parts.substr(0, 240) + "... (--json lists them)";
        std::printf("warning     dropped, as assimp's validation refuses them and the tool never uses them: %s\n",
                    parts.c_str());
    }
    if (u("input_triangles") == 0 && j["normals"] != "none") {
        const std::string used = j["normals"].get<std::string>();
        const char* how = used == "given"      ? "the file's, used as given"
                          : used == "oriented" ? "the file's, re-oriented"
                                               : j["input_normals"].get<bool>() ? "estimated by PCA (the file's replaced) and oriented"
                                                                                 : "estimated by PCA and oriented (the file has none)";
        std::printf("normals     %s%s\n", how, j["flipped"].get<bool>() ? "; they pointed inward and were flipped" : "");
    }
    std::printf("samples     %llu surface samples, %llu candidate balls (%s)\n", u("surface_samples"), u("candidates"),
                o.candidate_kind.c_str());
    if (u("outliers")) std::printf("            %llu cloud points dropped as outliers\n", u("outliers"));
    if (u("normals_replaced"))
        std::printf("            %llu zero normals (none given) replaced by estimated ones\n", u("normals_replaced"));
    const bool target = o.select.target_count > 0, target_error = o.select.target_error > 0;
    if (o.select.dilation == CA_DILATE_OFFSET)
        std::printf("dilation    r + %.4g (delta %.4g of the longest bbox side)%s\n", j["delta"].get<double>(),
                    j["delta"].get<double>() / j["reference_length"].get<double>(),
                    target ? ", found by the target size" : target_error ? ", found by the target error" : "");
    else
        std::printf("dilation    r * %.4g%s\n", j["scale"].get<double>(), target ? ", found by the target size" : "");
    const bool optimal = j["optimal"].get<bool>(), exact = o.select.solver == CA_SOLVER_EXACT;
    std::printf("selection   %llu balls, %s (lower bound %lld, gap %.2f %%), solver %s%s%s\n", u("selected"),
                optimal ? "proven optimal" : "not proven optimal", j["lower_bound"].get<long long>(), 100 * j["gap"].get<double>(),
                o.solver.c_str(), exact ? ", effort " : "", exact ? o.effort.c_str() : "");
    if (exact && o.select.effort == CA_EFFORT_FAST && !optimal)
        std::printf("            (--effort prove runs CBC until the cover is proven optimal)\n");
    const cli::Json& red = j["reduction"];
    std::printf("            reduced %llu x %llu -> %llu x %llu (%llu forced)\n", red["rows_before"].get<unsigned long long>(),
                red["cols_before"].get<unsigned long long>(), red["rows_after"].get<unsigned long long>(),
                red["cols_after"].get<unsigned long long>(), red["forced"].get<unsigned long long>());
    if (u("uncovered")) std::printf("            %llu samples covered by no ball were skipped\n", u("uncovered"));
    std::printf("skeleton    %s route: %llu vertices, %llu edges, %llu faces, %llu component(s), %llu isolated, b1 = %lld\n",
                j["connect"].get<std::string>().c_str(), u("selected"), u("edges"), u("faces"), u("components"), u("isolated"),
                j["betti1"].get<long long>());
    if (u("surface_balls") || u("open_parts"))
        std::printf("            %llu medial and %llu surface balls (on open sheets and thin parts), %llu open part(s)\n",
                    u("medial_balls"), u("surface_balls"), u("open_parts"));
    if (target_error) {
        const double hd = j["hd_reached"].get<double>();
        std::printf("target      two-sided HD %.3f %% %s %.4g %% of the bbox diagonal (%llu probes; no lower bound on the "
                    "balls is known)%s\n", hd,
                    hd <= o.select.target_error ? "<=" : ">", o.select.target_error, u("probes"),
                    hd <= o.select.target_error ? "" : ": not reached, the lowest HD found");
    } else if (target) {
        std::printf("target      %llu balls at most: two-sided HD reached %.3f %% of the bbox diagonal\n",
                    (unsigned long long)o.select.target_count, j["hd_reached"].get<double>());
    }
    const long long genus = j["genus"].get<long long>();
    if (genus >= 0)
        std::printf("topology    input genus %lld, %llu handle(s) too thin for the dilation to keep a loop\n", genus,
                    u("thin_handles"));
    else
        std::printf("topology    input genus unknown (open, non-manifold or a point cloud): loops not checked\n");
    if (o.evaluate)
        std::printf("hausdorff   surface->skeleton %.3f %%, skeleton->surface %.3f %%, two-sided %.3f %% of the bbox diagonal\n",
                    j["hd_surface_to_recon"].get<double>(), j["hd_recon_to_surface"].get<double>(), j["hd_two_sided"].get<double>());
    if (j.contains("rig"))
        std::printf("rig         %llu joints, %llu branches\n", j["rig"]["joints"].get<unsigned long long>(),
                    j["rig"]["branches"].get<unsigned long long>());
    if (j.contains("proxies")) {
        const cli::Json& p = j["proxies"];
        std::printf("proxies     %llu of at most %llu (%s, %s): two-sided HD %.3f %% of the bbox diagonal, %.3g of the "
                    "union's volume outside the shape\n",
                    p["count"].get<unsigned long long>(), p["count_limit"].get<unsigned long long>(),
                    p["shapes"].get<std::string>().c_str(), p["mode"].get<std::string>().c_str(),
                    p["hd_two_sided"].get<double>(),
                    p["union_volume"].get<double>() > 0 ? p["outside_volume"].get<double>() / p["union_volume"].get<double>() : 0.0);
    }
    if (j.contains("bone_colliders")) {
        const cli::Json& b = j["bone_colliders"];
        std::printf("bones       %llu colliders (%s) on the %llu joints of the %s's skin, %llu skipped: %.2f %% of the parts' "
                    "samples held, %.3g of the union's volume outside the shape\n",
                    b["count"].get<unsigned long long>(), b["mode"].get<std::string>().c_str(), b["joints"].get<unsigned long long>(),
                    b["skin"].get<std::string>().c_str(), b["joints_skipped"].get<unsigned long long>(),
                    100 * b["contained_fraction"].get<double>(),
                    b["union_volume"].get<double>() > 0 ? b["outside_volume"].get<double>() / b["union_volume"].get<double>() : 0.0);
    }
    const cli::Json& t = j["time_s"];
    std::printf("time        read %.3f s, candidates %.3f s, select %.3f s, connect %.3f s, total %.3f s\n", t["read"].get<double>(),
                t["candidates"].get<double>(), t["select"].get<double>(), t["connect"].get<double>(), t["total"].get<double>());
    std::string wrote;
    for (const auto& item : j["outputs"].items()) wrote += (wrote.empty() ? "" : ", ") + item.value().get<std::string>();
    std::printf("wrote       %s\n", wrote.c_str());
}

// A failure: the JSON error object on stdout with --json, else one line on stderr.
int report_failure(const cli::Failure& f, bool json, const std::string& input) {
    if (json) {
        cli::Json j = cli::report_header(input);
        j["error"] = cli::error_json(f);
        std::printf("%s\n", j.dump().c_str());
    } else {
        std::string suffix;
        if (f.code >= 0) suffix = std::string(" (") + ca_status_string(f.code) + ")";
        std::fprintf(stderr, "coverage-axis: %s%s\n", f.message.c_str(), suffix.c_str());
    }
    return f.exit_code;
}

int single_run(int argc, char** argv) {
    cli::RunOptions o;
    cli::Outputs out;
    std::string input;
    bool json = false, quiet = false;
    CLI::App app{"Coverage Axis skeletons: a mesh or oriented point cloud in, a medial skeleton (balls, edges, faces) out.\n"
                 "  coverage-axis batch -O OUTDIR [-j N] [options] INPUT...   (see coverage-axis batch --help)\n"
                 "  coverage-axis evaluate INPUT SKELETON.ma [--json]         (see coverage-axis evaluate --help)",
                 "coverage-axis"};
    app.set_version_flag("--version", cli::version_text());
    app.add_option("INPUT", input, "a mesh or oriented point cloud file (- = standard input, with --format)")->required();
    const std::string files = "Output files";
    app.add_option("-o,--output", out.ma, "the skeleton as .ma (default: INPUT's stem + .ma)")->group(files);
    app.add_option("--obj", out.obj, "also write .obj (v, l, f; no radii)")->group(files);
    app.add_option("--ply", out.ply, "also write .ply (radius property, edge element)")->group(files);
    app.add_option("--gltf", out.gltf, "also write glTF 2.0: OUT.glb or OUT.gltf (balls, edges, faces, _RADIUS)")->group(files);
    app.add_option("--proxies-json", out.proxies_json, "write the engine proxies (--proxies) and their errors as JSON")->group(files);
    app.add_option("--colliders", out.colliders,
                   "write the input mesh with the engine proxies (--proxies) as glTF physics colliders: OUT.glb or OUT.gltf")
        ->group(files);
    app.add_option("--bone-colliders", out.bone_colliders,
                   "write the skinned input (a glTF written back, else a new .glb; an unskinned input with --rig: the rig) "
                   "with one collider per bone on its joint node as glTF physics (VRM: spring-bone colliders too): "
                   "OUT.glb or OUT.gltf")
        ->group(files);
    app.add_option("--bone-colliders-json", out.bone_colliders_json,
                   "write the bone colliders (placed in their joints' frames) and their stats as JSON")
        ->group(files);
    app.add_option("--preview", out.preview, "also draw the mesh and the skeleton: OUT.png or OUT.svg")->group(files);
    app.add_option("--export-samples", out.export_samples, "write the covered surface samples (v x y z)")->group(files);
    app.add_option("--export-candidates", out.export_candidates, "write the candidate balls (v x y z r)")->group(files);
    app.add_option("--correspondence", out.correspondence,
                   "also write each input vertex's skeleton balls and weights, nearest primitive and branch: FILE.json")
        ->group(files);
    app.add_option("--rig", out.rig, "also write the input skinned to a rig of the skeleton: OUT.glb")->group(files);
    const std::string rig = "Rig (--rig, --correspondence; docs/rig.md)";
    app.add_option("--rig-root", o.rig.root, "the root joint's ball (-1: the largest)")->capture_default_str()->group(rig);
    app.add_option("--max-joints", o.rig.max_joints, "at most this many joints")->capture_default_str()->group(rig);
    app.add_option("--joint-spacing", o.rig.joint_spacing, "joints this far apart along branches (fraction of the longest side)")
        ->capture_default_str()->group(rig);
    app.add_option("--min-branch", o.rig.min_branch, "keep branches whose tip reaches past every tree ball by this x its radius")
        ->capture_default_str()->group(rig);
    app.add_option("--smoothing", o.rig.smoothing, "the weights' blend width, in median ball radii")->capture_default_str()->group(rig);
    cli::add_run_options(app, o);
    app.add_flag("--json", json, "print one JSON object on stdout (on failure too: {\"error\": ...})");
    app.add_flag("--quiet", quiet, "no summary, no progress bar");
    app.footer("Exit codes: 0 success, 1 the library refused or failed, 2 bad command line, 3 a file could not be "
               "read or written. Fields and formats: docs/cli.md.");
    json = std::any_of(argv + 1, argv + argc, [](const char* a) { return std::strcmp(a, "--json") == 0; });
    std::string err;
    const int parsed = cli::parse_command_line(app, argc, argv, err);
    if (parsed == 2) return report_failure({"USAGE_ERROR", -1, err, 2}, json, input);
    if (parsed >= 0) return parsed;
    if (!cli::finish_run_options(app, o, err)) return report_failure({"USAGE_ERROR", -1, err + " (see coverage-axis --help)", 2}, json, input);
    if (!out.proxies_json.empty() && o.proxies.empty())
        return report_failure({"USAGE_ERROR", -1, "--proxies-json needs --proxies spheres|capsules (see coverage-axis --help)", 2}, json, input);
    if (!out.colliders.empty() && o.proxies.empty())
        return report_failure({"USAGE_ERROR", -1, "--colliders needs --proxies spheres|capsules (see coverage-axis --help)", 2}, json, input);
    if (out.bone_colliders.empty() && out.bone_colliders_json.empty())
        for (const char* flag : {"--bone-mode", "--skip-bones", "--bone-min-size", "--bone-min-share"})
            if (app.count(flag))
                return report_failure({"USAGE_ERROR", -1, std::string(flag) + " needs --bone-colliders or --bone-colliders-json", 2},
                                      json, input);
    if (out.ma.empty() && input == "-")
        return report_failure({"USAGE_ERROR", -1, "reading standard input needs -o OUT.ma", 2}, json, input);
    if (out.ma.empty()) out.ma = default_ma_path(input);

    ProgressBar bar;
    const bool show_bar = !quiet && !json && isatty(2);
    const cli::Outcome r =
        cli::run_pipeline(input, o, out, show_bar ? ProgressBar::callback : nullptr, &bar, show_bar ? ProgressBar::log : nullptr);
    if (show_bar) bar.finish();
    if (!r.ok) return report_failure(r.failure, json, input);
    if (json) std::printf("%s\n", r.report.dump().c_str());
    else if (!quiet) print_summary(r.report, o);
    // a target error not reached: the outputs are written, the exit status says it was missed
    if (r.target_missed) {
        if (!json) std::fprintf(stderr, "coverage-axis: %s (%s)\n", r.failure.message.c_str(), ca_status_string(r.failure.code));
        return r.failure.exit_code;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--internal-read") == 0) return cli::read_child_command(argc, argv);
    if (argc > 1 && std::strcmp(argv[1], "evaluate") == 0) return cli::evaluate_command(argc - 1, argv + 1);
    if (argc > 1 && std::strcmp(argv[1], "batch") == 0) return cli::batch_command(argc - 1, argv + 1);
    return single_run(argc, argv);
}
