// run_options.cpp: the run options on the command line (CLI11). Every option is bound to a field
// of the library's option structs, filled by its ca_*_options_init, so --help prints the
// library's defaults. Also: the options as JSON for batch sidecars, and the version text.
#include "cli.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>
#include <vector>

#ifndef CA_TOOL_VERSION
#error "CA_TOOL_VERSION is set by CMake (the project version)"
#endif

namespace cli {
namespace {

using Names = std::vector<std::pair<std::string, int32_t>>;
const Names kSolvers = {{"exact", CA_SOLVER_EXACT}, {"greedy", CA_SOLVER_GREEDY}, {"capp", CA_SOLVER_CAPP}};
const Names kEfforts = {{"fast", CA_EFFORT_FAST}, {"prove", CA_EFFORT_PROVE}};
const Names kRoutes = {{"auto", CA_CONNECT_AUTO}, {"medial", CA_CONNECT_MEDIAL}, {"power", CA_CONNECT_POWER}};
const Names kProxyModes = {{"inscribed", CA_PROXY_INSCRIBED}, {"conservative", CA_PROXY_CONSERVATIVE}};
const Names kProxyShapes = {{"spheres", CA_PROXY_SHAPES_SPHERES}, {"capsules", CA_PROXY_SHAPES_CAPSULES},
                            {"boxes", CA_PROXY_SHAPES_BOXES}, {"all", CA_PROXY_SHAPES_ALL}};
const Names kGenerators = {{"voronoi", CA_CANDIDATES_VORONOI}, {"random", CA_CANDIDATES_RANDOM}};
const Names kNormals = {{"given", CA_POINT_NORMALS_TRUSTED}, {"unoriented", CA_POINT_NORMALS_UNORIENTED},
                        {"estimate", CA_POINT_NORMALS_ESTIMATE}};

std::string name_of(const Names& names, int32_t value) {
    for (const auto& n : names)
        if (n.second == value) return n.first;
    return std::to_string(value);
}
int32_t value_of(const Names& names, const std::string& name) {
    for (const auto& n : names)
        if (n.first == name) return n.second;
    return -1;
}
std::vector<std::string> keys(const Names& names) {
    std::vector<std::string> k;
    for (const auto& n : names) k.push_back(n.first);
    return k;
}

// A number >= lo (CLI11's NonNegativeNumber prints the largest double in its message).
CLI::Validator at_least(double lo) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", lo);
    const std::string bound = text;
    return CLI::Validator(
        [lo, bound](std::string& s) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(s.c_str(), &end);
            if (end == s.c_str() || *end || !std::isfinite(v) || v < lo) return "takes a number >= " + bound + ", not " + s;
            return "";
        },
        ">= " + bound);
}

}  // namespace

std::string file_hash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    uint64_t h = 1469598103934665603ull;
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            h ^= static_cast<unsigned char>(buf[i]);
            h *= 1099511628211ull;
        }
        if (!in) break;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

RunOptions::RunOptions() {
    ca_candidate_options_init(&candidates);
    ca_select_options_init(&select);
    ca_connect_options_init(&connect);
    ca_evaluate_options_init(&evaluation);
    ca_rig_options_init(&rig);
    ca_proxy_options_init(&proxy);
    ca_bone_collider_options_defaults(&bone, sizeof bone);
    ca_context_desc desc;
    ca_context_desc_init(&desc);
    threads = desc.threads;
    candidate_kind = name_of(kGenerators, candidates.generator);
    solver = name_of(kSolvers, select.solver);
    effort = name_of(kEfforts, select.effort);
    connect_route = name_of(kRoutes, connect.method);
    proxy_mode = name_of(kProxyModes, proxy.mode);
    bone_mode = name_of(kProxyModes, bone.mode);
    up = std::string(1, preview.up);
    preview_size = std::to_string(preview.width) + "x" + std::to_string(preview.height);
}

void add_run_options(CLI::App& app, RunOptions& o) {
    const std::string sampling = "Sampling and candidates", cover = "Cover (set cover of the samples)",
                      connect = "Connection", control = "User control", look = "Preview picture";
    app.add_option("--format", o.format, "input format instead of the extension (needed for - = standard input): " +
                                            caio::readable_formats())
        ->group(sampling);
    app.add_option("--read-time-limit", o.read.time_s,
                   "seconds an input read through assimp may take (the read runs in a child process, stopped past "
                   "this); given --time-limit, that budget, or the smaller if both are given")
        ->capture_default_str()->group(sampling);
    app.add_option("--read-memory-limit", o.read.memory_mib,
                   "address space in MiB of the process reading an input through assimp (0 = 512 + 128 bytes per "
                   "input byte)")
        ->capture_default_str()->check(at_least(0))->group(sampling);
    app.add_option("--samples", o.candidates.cover_samples, "surface samples to cover")
        ->capture_default_str()->check(CLI::Range(1u, 100000000u))->group(sampling);
    app.add_option("--voronoi-samples", o.candidates.voronoi_samples, "samples whose inner Voronoi vertices are candidates")
        ->capture_default_str()->check(CLI::Range(5u, 100000000u))->group(sampling);
    app.add_option("--candidates", o.candidate_kind,
                   "voronoi | random[:N] (N default " + std::to_string(o.candidates.random_candidates) +
                       ") | FILE (v x y z r lines)")
        ->capture_default_str()->group(sampling);
    app.add_option("--surface-samples", o.surface_samples_file, "cover these samples (v x y z, input units) instead of sampling")
        ->group(sampling);
    app.add_option("--seed", o.candidates.seed, "random seed")->capture_default_str()->group(sampling);
    app.add_flag("--volumetric-only",
                 "inner balls only: no surface balls on open sheets, cards, planes and thin parts (their samples are then "
                 "uncoverable, a flat mesh has no candidates)")
        ->group(sampling);
    app.add_option("--normals", o.normals,
                   "a point cloud's normals: given (oriented; checked, re-oriented if their signs disagree) | "
                   "unoriented (re-oriented) | estimate (ignored, estimated from the points)")
        ->capture_default_str()->check(CLI::IsMember(keys(kNormals)))->group(sampling);

    app.add_option("--delta", o.select.delta, "dilation offset, fraction of the longest bbox side")
        ->capture_default_str()->check(at_least(0))->group(cover);
    app.add_option("--scale", o.select.scale, "dilate by scaling r' = r * S instead of the offset")
        ->capture_default_str()->check(at_least(1))->group(cover);
    app.add_option("--solver", o.solver, "set-cover solver")->capture_default_str()->check(CLI::IsMember(keys(kSolvers)))->group(cover);
    app.add_option("--effort", o.effort,
                   "exact solver: fast (LP bound + local search; CBC only for a one-ball gap on a small kernel) | "
                   "prove (CBC until proven optimal)")
        ->capture_default_str()->check(CLI::IsMember(keys(kEfforts)))->group(cover);
    app.add_option("--time-limit", o.select.time_limit_s,
                   "budget of the whole run in seconds, the exact solver's included (<= 0: none)")
        ->capture_default_str()->group(cover);
    app.add_option("--target-count", o.select.target_count, "at most K balls: the lowest two-sided HD among 9 deltas from the smallest that achieves it "
                   "(--scale: the smallest scale; 0 = off; docs/fidelity.md)")
        ->capture_default_str()->check(CLI::Range(0u, 100000000u))->group(cover);
    app.add_option("--target-error", o.select.target_error,
                   "the fewest balls whose two-sided Hausdorff distance is at most E % of the bbox diagonal, by a "
                   "search over delta from --delta (0 = off; docs/fidelity.md)")
        ->capture_default_str()->check(at_least(0))->group(cover);
    app.add_option("--divide", o.select.divide_threshold, "divide and conquer above N surface samples (0 = never)")
        ->capture_default_str()->group(cover);
    app.add_flag("--skip-uncoverable", "ignore samples no ball covers instead of failing")->group(cover);

    app.add_option("--connect", o.connect_route, "auto (medial for meshes and clean point clouds, power for noisy ones) | medial | power")
        ->capture_default_str()->check(CLI::IsMember(keys(kRoutes)))->group(connect);
    app.add_flag("--fit", "fit the balls' centres and radii to the surface after connecting; the --target-error and "
                 "--target-count searches then measure fitted skeletons (docs/fidelity.md)")
        ->group(connect);
    app.add_flag("--fit-thorough", "--fit, and a second fit with twice the boundary samples; the one of lower two-sided HD "
                 "is written (3-6x the fit's time; docs/fidelity.md). The default with --target-count on a mesh")
        ->group(connect);
    app.add_flag("--fit-covered", "--fit, then the cover samples it uncovered covered again by added unfitted balls and a "
                 "refit that keeps the cover: every cover sample stays within the dilated radius of a ball (docs/fidelity.md)")
        ->group(connect);
    app.add_flag("--no-fit", "no fit, also with --target-count (whose skeleton the library fits thoroughly by default)")
        ->group(connect);

    app.add_option("--ignore-samples", o.ignore_samples_file, "indices (0-based) of samples that need not be covered")->group(control);
    app.add_option("--force-in", o.force_in_file, "indices of candidate balls that must be selected")->group(control);
    app.add_option("--force-out", o.force_out_file, "indices of candidate balls that must not be selected")->group(control);

    app.add_option("--view", o.view, "AZIMUTH,ELEVATION in degrees, or auto (the largest projected bbox area)")
        ->capture_default_str()->group(look);
    app.add_option("--up", o.up, "the model's up axis: y or z")->capture_default_str()->check(CLI::IsMember({"y", "z"}))->group(look);
    app.add_option("--preview-size", o.preview_size, "WIDTHxHEIGHT in pixels")->capture_default_str()->group(look);

    const std::string engine = "Engine proxies (docs/proxies.md)";
    app.add_option("--proxies", o.proxies,
                   "also choose primitives for game engines from the skeleton: spheres; capsules (tapered capsules and "
                   "spheres); boxes (oriented boxes and spheres); all (each part takes the primitive that serves it best)")
        ->check(CLI::IsMember(keys(kProxyShapes)))->group(engine);
    app.add_option("--proxy-count", o.proxy.count, "at most K proxies")->capture_default_str()->check(at_least(1))->group(engine);
    app.add_option("--proxy-mode", o.proxy_mode, "inscribed (inside the shape) | conservative (containing the surface)")
        ->capture_default_str()->check(CLI::IsMember(keys(kProxyModes)))->group(engine);
    const std::string bones = "Bone colliders (--bone-colliders, --bone-colliders-json; docs/bone_colliders.md)";
    app.add_option("--bone-mode", o.bone_mode, "conservative (each collider holds its bone's part) | inscribed (inside the body)")
        ->capture_default_str()->check(CLI::IsMember(keys(kProxyModes)))->group(bones);
    app.add_option("--skip-bones", o.skip_bones, "joints to give no collider: NAME[,NAME...] (names as the skin gives them)")
        ->group(bones);
    app.add_option("--bone-min-size", o.bone.min_size, "drop colliders whose radius is below this % of the bbox diagonal")
        ->capture_default_str()->check(at_least(0))->group(bones);
    app.add_option("--bone-min-share", o.bone.min_share,
                   "no collider for a joint that dominates less than this fraction of the surface area")
        ->capture_default_str()->check(at_least(0))->group(bones);
    app.add_flag("--evaluate", o.evaluate, "measure the skeleton: Hausdorff distances in % of the bbox diagonal");
    app.add_option("--threads", o.threads, "worker threads (0 = all cores)")->capture_default_str()->check(at_least(0));
}

bool finish_run_options(const CLI::App& app, RunOptions& o, std::string& error) {
    if (app.count("--scale")) o.select.dilation = CA_DILATE_SCALE;
    o.select.skip_uncoverable = app.count("--skip-uncoverable") ? 1 : 0;
    o.candidates.volumetric_only = app.count("--volumetric-only") ? 1 : 0;
    // --time-limit bounds the whole run; without it only the solver's default budget applies
    if (app.count("--time-limit")) o.time_limit_s = std::isfinite(o.select.time_limit_s) ? std::max(0.0, o.select.time_limit_s) : 0.0;
    if (!(o.read.time_s > 0) || !std::isfinite(o.read.time_s)) {
        error = "--read-time-limit takes a number of seconds > 0";
        return false;
    }
    // ... the read included: it bounds an assimp read unless --read-time-limit sets a smaller bound
    if (o.time_limit_s > 0)
        o.read.time_s = app.count("--read-time-limit") ? std::min(o.read.time_s, o.time_limit_s) : o.time_limit_s;
    o.select.solver = value_of(kSolvers, o.solver);
    o.point_normals = value_of(kNormals, o.normals);
    o.select.effort = value_of(kEfforts, o.effort);
    o.connect.method = value_of(kRoutes, o.connect_route);
    o.proxy.mode = value_of(kProxyModes, o.proxy_mode);
    if (o.proxies.empty() && (app.count("--proxy-count") || app.count("--proxy-mode"))) {
        error = "--proxy-count and --proxy-mode need --proxies spheres|capsules|boxes|all";
        return false;
    }
    if (!o.proxies.empty()) o.proxy.shapes = value_of(kProxyShapes, o.proxies);
    o.bone.mode = value_of(kProxyModes, o.bone_mode);
    if (app.count("--no-fit") && (app.count("--fit") || app.count("--fit-thorough") || app.count("--fit-covered"))) {
        error = "--no-fit cannot be combined with --fit, --fit-thorough or --fit-covered";
        return false;
    }
    if (app.count("--fit-thorough") && app.count("--fit-covered")) {
        error = "--fit-thorough cannot be combined with --fit-covered";
        return false;
    }
    // no flag: the library's default (CA_FIT_AUTO)
    if (app.count("--fit-thorough")) o.connect.fit = CA_FIT_THOROUGH;
    else if (app.count("--fit-covered")) o.connect.fit = CA_FIT_COVERED;
    else if (app.count("--fit")) o.connect.fit = CA_FIT_ONCE;
    else if (app.count("--no-fit")) o.connect.fit = CA_FIT_OFF;
    // the delta searches measure the default connection, fitted with --fit; with --fit-thorough the
    // probes take the regular fit, which the written (thorough) one is never farther than
    o.select.probe_fit = o.connect.fit == CA_FIT_ONCE || o.connect.fit == CA_FIT_THOROUGH ? 1 : 0;
    if (o.select.target_error > 0 && o.connect.method != CA_CONNECT_AUTO) {
        error = "--target-error measures the default connection: it does not take --connect " + o.connect_route;
        return false;
    }
    if (o.candidate_kind.rfind("random", 0) == 0 && o.candidate_kind.size() > 6) {
        const std::string n = o.candidate_kind.substr(7);
        char* end = nullptr;
        const unsigned long v = o.candidate_kind[6] == ':' && !n.empty() ? std::strtoul(n.c_str(), &end, 10) : 0;
        if (!end || *end || v < 1 || v > 100000000ul) {
            error = "--candidates random:N takes a count >= 1";
            return false;
        }
        o.candidates.random_candidates = uint32_t(v);
        o.candidate_kind = "random";
    }
    if (o.candidate_kind == "random") o.candidates.generator = CA_CANDIDATES_RANDOM;
    o.preview.up = o.up[0];
    if (o.view != "auto") {
        char tail = 0;
        if (std::sscanf(o.view.c_str(), "%lf,%lf%c", &o.preview.azimuth_deg, &o.preview.elevation_deg, &tail) != 2) {
            error = "--view takes AZIMUTH,ELEVATION in degrees or auto";
            return false;
        }
        o.preview.automatic_view = false;
    }
    char tail = 0;
    if (std::sscanf(o.preview_size.c_str(), "%dx%d%c", &o.preview.width, &o.preview.height, &tail) != 2 ||
        o.preview.width < 16 || o.preview.height < 16 || o.preview.width > 8192 || o.preview.height > 8192) {
        error = "--preview-size takes WIDTHxHEIGHT, 16..8192 pixels each";
        return false;
    }
    return true;
}

Json options_json(const RunOptions& o) {
    auto file = [](const std::string& path) -> Json {
        if (path.empty()) return nullptr;
        return Json{{"path", path}, {"hash", file_hash(path)}};
    };
    const ca_select_options& s = o.select;
    return Json{{"format", o.format},
                {"candidates", o.candidate_kind == "voronoi" || o.candidate_kind == "random" ? Json(o.candidate_kind)
                                                                                            : file(o.candidate_kind)},
                {"samples", o.candidates.cover_samples},
                {"voronoi_samples", o.candidates.voronoi_samples},
                {"random_candidates", o.candidates.random_candidates},
                {"connect_samples", o.candidates.connect_samples},
                {"seed", o.candidates.seed},
                {"volumetric_only", o.candidates.volumetric_only != 0},
                {"normals", o.normals},
                {"surface_samples", file(o.surface_samples_file)},
                {"dilation", s.dilation == CA_DILATE_SCALE ? "scale" : "offset"},
                {"delta", s.delta},
                {"scale", s.scale},
                {"solver", o.solver},
                {"effort", o.effort},
                {"time_limit_s", s.time_limit_s},
                {"skip_uncoverable", s.skip_uncoverable != 0},
                {"target_count", s.target_count},
                {"target_tolerance", s.target_tolerance},
                {"target_error", s.target_error},
                {"divide", s.divide_threshold},
                {"ignore_samples", file(o.ignore_samples_file)},
                {"force_in", file(o.force_in_file)},
                {"force_out", file(o.force_out_file)},
                {"connect", o.connect_route},
                {"fit", o.connect.fit},
                {"remove_outside", o.connect.remove_outside},
                {"fill_holes", o.connect.fill_holes},
                {"reconnect", o.connect.reconnect},
                {"proxies", o.proxies.empty() ? Json(nullptr) : Json(o.proxies)},
                {"proxy_count", o.proxy.count},
                {"proxy_mode", o.proxy_mode},
                {"evaluate", o.evaluate},
                {"evaluate_samples", {o.evaluation.surface_samples, o.evaluation.envelope_samples, o.evaluation.seed}},
                {"view", o.view},
                {"up", o.up},
                {"preview_size", o.preview_size}};
}

std::string library_version() {
    return ca_version_string();
}

std::string version_text() {
    return std::string("coverage-axis ") + CA_TOOL_VERSION + " (library " + library_version() + ", ABI " +
           std::to_string(ca_abi_version()) + ")";
}

bool is_mesh_file(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos) return false;
    // .ma is this tool's own output (assimp would take it for something else): never an input
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext != "ma" && caio::is_readable_format(ext);
}

namespace {

// Arguments left over after parsing: an unknown option or a second input.
std::string extras_error(const CLI::App& app) {
    const std::vector<std::string> extras = app.remaining();
    for (const std::string& x : extras)
        if (x.size() > 1 && x[0] == '-') return "unknown option " + x;
    if (!extras.empty() && app.get_name() == "coverage-axis")
        return "more than one input file (" + extras[0] + "); coverage-axis batch runs many";
    if (!extras.empty()) return "unexpected argument " + extras[0];
    return "";
}

}  // namespace

int parse_command_line(CLI::App& app, int argc, char** argv, std::string& error) {
    app.allow_extras();  // so that leftovers get a clear one-line message instead of CLI11's
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        error = e.what();
    }
    if (error.empty()) error = extras_error(app);
    if (error.empty()) return -1;
    error += " (see " + app.get_name() + " --help)";
    return 2;
}

}  // namespace cli
