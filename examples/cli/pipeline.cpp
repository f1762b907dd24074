// pipeline.cpp: one run of the tool through the library's C ABI: read the input, candidates
// (generated or from files), selection, connection, then the outputs (.ma, .obj, .ply, glTF,
// preview, colliders, bone colliders) and the JSON report. Failures come back as a Failure (never printed here),
// so the single run and the batch command report them alike.
#include "cli.h"
#include "gltf_physics.h"
#include "gltf_writer.h"
#include "output_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace cli {

Failure library_failure(ca_context* ctx, ca_status st, const std::string& step) {
    Failure f;
    const std::string name = ca_status_string(st);
    f.status = name.substr(0, name.find(':'));
    f.code = st;
    f.message = step + " failed: " + (ctx ? ca_context_last_error(ctx) : "");
    if (st == CA_ERROR_UNCOVERABLE) f.message += "; raise --delta, add candidates, pass --skip-uncoverable, or drop --volumetric-only";
    f.exit_code = 1;
    return f;
}

Failure file_failure(const std::string& message) {
    Failure f;
    f.status = "FILE_ERROR";
    f.message = message;
    f.exit_code = 3;
    return f;
}

Json error_json(const Failure& f) { return Json{{"status", f.status}, {"code", f.code}, {"message", f.message}}; }

bool evaluate(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton_view& skeleton,
              const ca_evaluate_options& options, ca_evaluation& out, Failure& failure) {
    const ca_surface_view view = surface_view(mesh);
    out.struct_size = sizeof out;
    const ca_status st = ca_evaluate(ctx, &view, &skeleton, &options, &out);
    if (st != CA_OK) failure = library_failure(ctx, st, "evaluation");
    return st == CA_OK;
}

void add_evaluation(Json& j, const ca_evaluation& e) {
    j["hd_surface_to_recon"] = e.hd_surface_to_recon;
    j["hd_recon_to_surface"] = e.hd_recon_to_surface;
    j["hd_two_sided"] = e.hd_two_sided;
    j["mean_surface_to_recon"] = e.mean_surface_to_recon;
    j["mean_recon_to_surface"] = e.mean_recon_to_surface;
    j["evaluate_surface_samples"] = e.surface_samples_used;
    j["evaluate_envelope_samples"] = e.envelope_samples_used;
}

Json report_header(const std::string& input) {
    return Json{{"format_version", kFormatVersion}, {"tool_version", CA_TOOL_VERSION}, {"library_version", library_version()},
                {"abi_version", ca_abi_version()}, {"input", input}};
}

Json skin_json(const caio::MeshData& mesh) {
    if (mesh.skin.empty()) return nullptr;
    return Json{{"joints", mesh.skin.joint_names.size()}, {"influences", mesh.skin.influences}};
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
double round4(double t) { return std::round(t * 1e4) / 1e4; }

// The library objects of one run, destroyed in reverse order.
struct Owned {
    ca_context* ctx = nullptr;
    ca_candidate_set* set = nullptr;
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    ca_proxy_set* proxies = nullptr;
    // Which normals the generated candidates used (CA_NORMALS_*) and whether the input was
    // flipped, read before a candidates file replaces the set.
    int32_t normals = CA_NORMALS_NONE;
    bool flipped = false;
    ~Owned() {
        ca_proxy_set_destroy(proxies);
        ca_skeleton_destroy(sk);
        ca_selection_destroy(sel);
        ca_candidate_set_destroy(set);
        ca_context_destroy(ctx);
    }
};

double longest_bbox_side(const caio::MeshData& mesh) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i + 2 < mesh.positions.size(); i += 3)
        for (size_t k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], mesh.positions[i + k]);
            hi[k] = std::max(hi[k], mesh.positions[i + k]);
        }
    const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    return std::isfinite(longest) && longest > 0 ? longest : 0;
}

// The context for the next step. With a whole-run budget (--time-limit), each step gets a fresh
// context whose time limit is what is left of the budget since `start`, so whichever stage is
// running when it runs out returns CA_ERROR_TIME_LIMIT naming itself; a step that would start
// with nothing left fails the same way. Results outlive the context that made them.
bool context_for(Owned& owned, const ca_context_desc& desc, double budget_s, Clock::time_point start,
                 const std::string& step, Failure& failure) {
    if (owned.ctx && budget_s <= 0) return true;
    ca_context_desc d = desc;
    if (budget_s > 0) {
        d.time_limit_s = budget_s - since(start);
        if (d.time_limit_s <= 0) {
            failure = library_failure(nullptr, CA_ERROR_TIME_LIMIT, step);
            failure.message = step + " failed: time limit reached before " + step;
            return false;
        }
    }
    ca_context_destroy(owned.ctx);
    owned.ctx = nullptr;
    const ca_status st = ca_context_create(&d, &owned.ctx);
    if (st != CA_OK) return failure = library_failure(nullptr, st, "context"), false;
    return true;
}

// Step 1: generated candidates, with the sample and ball files (if any) replacing their parts.
bool make_candidates(Owned& owned, const caio::MeshData& mesh, const RunOptions& o, Failure& failure) {
    std::string err;
    const bool from_file = o.candidate_kind != "voronoi" && o.candidate_kind != "random";
    std::vector<double> file_samples, file_centers, file_radii, unused;
    if (!o.surface_samples_file.empty() && !caio::read_points(o.surface_samples_file, file_samples, unused, err))
        return failure = file_failure(err), false;
    if (from_file) {
        if (!caio::read_points(o.candidate_kind, file_centers, file_radii, err)) return failure = file_failure(err), false;
        if (file_radii.size() * 3 != file_centers.size() || file_radii.empty())
            return failure = file_failure(o.candidate_kind + ": every candidate needs a radius (v x y z r)"), false;
    }
    ca_status st;
    if (!(from_file && !o.surface_samples_file.empty())) {
        const ca_surface_view view = surface_view(mesh, o.point_normals);
        if ((st = ca_candidates(owned.ctx, &view, &o.candidates, &owned.set)) != CA_OK)
            return failure = library_failure(owned.ctx, st, "candidates"), false;
        owned.normals = ca_candidate_set_normals(owned.set);
        owned.flipped = ca_candidate_set_flipped(owned.set) != 0;
    }
    if (from_file || !o.surface_samples_file.empty()) {
        // delta stays relative to the input's longest bbox side
        const double* sp = file_samples.empty() ? ca_candidate_set_samples(owned.set) : file_samples.data();
        const size_t sn = file_samples.empty() ? ca_candidate_set_sample_count(owned.set) : file_samples.size() / 3;
        const double* cp = file_centers.empty() ? ca_candidate_set_centers(owned.set) : file_centers.data();
        const double* rp = file_radii.empty() ? ca_candidate_set_radii(owned.set) : file_radii.data();
        const size_t cn = file_radii.empty() ? ca_candidate_set_count(owned.set) : file_radii.size();
        ca_candidate_set* replaced = nullptr;
        st = ca_candidates_from_arrays(owned.ctx, sp, sn, 0, cp, 0, rp, 0, cn, longest_bbox_side(mesh), &replaced);
        if (st != CA_OK) return failure = library_failure(owned.ctx, st, "candidates"), false;
        ca_candidate_set_destroy(owned.set);
        owned.set = replaced;
    }
    return true;
}

bool export_candidates(const ca_candidate_set* set, const Outputs& out, Failure& failure) {
    std::string err;
    const size_t ns = ca_candidate_set_sample_count(set), nc = ca_candidate_set_count(set);
    if (!out.export_samples.empty()) {
        const std::vector<double> xyz(ca_candidate_set_samples(set), ca_candidate_set_samples(set) + 3 * ns);
        if (!caio::write_points(out.export_samples, xyz, {}, err)) return failure = file_failure(err), false;
    }
    if (!out.export_candidates.empty()) {
        const std::vector<double> xyz(ca_candidate_set_centers(set), ca_candidate_set_centers(set) + 3 * nc);
        const std::vector<double> r(ca_candidate_set_radii(set), ca_candidate_set_radii(set) + nc);
        if (!caio::write_points(out.export_candidates, xyz, r, err)) return failure = file_failure(err), false;
    }
    return true;
}

// Step 2: the user-control index files become per-sample / per-ball masks, then the cover.
bool make_selection(Owned& owned, const RunOptions& o, Failure& failure) {
    ca_select_options so = o.select;
    const size_t n_samples = ca_candidate_set_sample_count(owned.set), n_candidates = ca_candidate_set_count(owned.set);
    std::vector<uint8_t> ignorable, forced_in, forced_out;
    struct MaskFile {
        const std::string& path;
        size_t size;
        std::vector<uint8_t>& mask;
        const uint8_t** field;
        size_t* count;
        const char* what;
    };
    for (MaskFile m :
         {MaskFile{o.ignore_samples_file, n_samples, ignorable, &so.ignorable_samples, &so.ignorable_samples_count, "sample"},
          MaskFile{o.force_in_file, n_candidates, forced_in, &so.forced_in, &so.forced_in_count, "candidate"},
          MaskFile{o.force_out_file, n_candidates, forced_out, &so.forced_out, &so.forced_out_count, "candidate"}}) {
        if (m.path.empty()) continue;
        std::vector<uint32_t> idx;
        std::string err;
        if (!caio::read_indices(m.path, idx, err)) return failure = file_failure(err), false;
        m.mask.assign(m.size, 0);
        for (uint32_t i : idx) {
            if (i >= m.size)
                return failure = file_failure(m.path + ": " + m.what + " index " + std::to_string(i) + " out of range (" +
                                              std::to_string(m.size) + " " + m.what + "s)"),
                       false;
            m.mask[i] = 1;
        }
        *m.field = m.mask.data();
        *m.count = m.mask.size();
    }
    const ca_status st = ca_select(owned.ctx, owned.set, &so, &owned.sel);
    if (st == CA_ERROR_TARGET_NOT_REACHED) {  // the run goes on with the best selection; exit 4 at the end
        failure = library_failure(owned.ctx, st, "selection");
        failure.message = std::string(ca_context_last_error(owned.ctx)) +
                          "; the outputs hold that skeleton (raise --samples or add --fit to search further)";
        failure.exit_code = 4;
        return true;
    }
    if (st != CA_OK) return failure = library_failure(owned.ctx, st, "selection"), false;
    return true;
}

caio::SkeletonData skeleton_data(const ca_skeleton* sk) {
    caio::SkeletonData sd;
    const size_t nv = ca_skeleton_vertex_count(sk);
    sd.centers.assign(ca_skeleton_centers(sk), ca_skeleton_centers(sk) + 3 * nv);
    sd.radii.assign(ca_skeleton_radii(sk), ca_skeleton_radii(sk) + nv);
    sd.edges.assign(ca_skeleton_edges(sk), ca_skeleton_edges(sk) + 2 * ca_skeleton_edge_count(sk));
    sd.faces.assign(ca_skeleton_faces(sk), ca_skeleton_faces(sk) + 3 * ca_skeleton_face_count(sk));
    return sd;
}

// The proxies' primitives, and how an engine places each, as the writers take them.
std::vector<caio::ProxyData> proxy_data(const ca_proxy_set* p) {
    std::vector<caio::ProxyData> out(ca_proxy_set_count(p));
    const int32_t* kinds = ca_proxy_set_kinds(p);
    const double *centers = ca_proxy_set_centers(p), *radii = ca_proxy_set_radii(p);
    for (size_t i = 0; i < out.size(); ++i) {
        caio::ProxyData& d = out[i];
        d.kind = kinds[i];
        for (int k = 0; k < 3; ++k) {
            d.a[k] = centers[6 * i + size_t(k)];
            d.b[k] = centers[6 * i + 3 + size_t(k)];
        }
        d.radius_a = radii[2 * i];
        d.radius_b = radii[2 * i + 1];
        ca_proxy_placement pl;
        pl.struct_size = sizeof pl;
        ca_proxy_set_placement(p, i, &pl);   // i < count: cannot fail
        caio::ColliderShape& c = d.placed;
        c.kind = pl.kind;
        for (int k = 0; k < 3; ++k) {
            c.translation[k] = pl.center[k];
            c.size[k] = 2 * pl.half_extents[k];
        }
        for (int k = 0; k < 4; ++k) c.rotation[k] = pl.rotation[k];
        c.radius_top = pl.radius_top;
        c.radius_bottom = pl.radius_bottom;
        c.height = pl.height;
    }
    return out;
}

// The proxies' stats (--json's "proxies" and the --proxies-json file's fields).
Json proxy_stats_json(const ca_proxy_stats& s, const RunOptions& o, size_t count) {
    return Json{{"shapes", o.proxies},
                {"mode", o.proxy_mode},
                {"count", count},
                {"count_limit", o.proxy.count},
                {"hd_surface_to_proxies", s.hd_surface_to_proxies},
                {"hd_proxies_to_surface", s.hd_proxies_to_surface},
                {"hd_two_sided", s.hd_two_sided},
                {"mean_surface_to_proxies", s.mean_surface_to_proxies},
                {"mean_proxies_to_surface", s.mean_proxies_to_surface},
                {"outside_bound", s.outside_bound},
                {"skeleton_outside", s.skeleton_outside},
                {"union_volume", s.union_volume},
                {"outside_volume", s.outside_volume},
                {"radius_change", s.radius_change},
                {"diagonal", s.diagonal},
                {"candidates", s.candidates},
                {"surface_cells", s.surface_cells},
                {"time_s", s.time_s}};
}

// --proxies-json: {"proxies": [one object per primitive], then the stats}.
bool write_proxies_json(const std::string& path, const std::vector<caio::ProxyData>& proxies, const Json& stats,
                        Failure& failure) {
    Json list = Json::array();
    for (const caio::ProxyData& p : proxies) {
        const Json a = {p.a[0], p.a[1], p.a[2]}, b = {p.b[0], p.b[1], p.b[2]};
        const caio::ColliderShape& c = p.placed;
        if (p.kind == CA_PROXY_CAPSULE)
            list.push_back({{"kind", "capsule"}, {"a", a}, {"radius_a", p.radius_a}, {"b", b}, {"radius_b", p.radius_b}});
        else if (p.kind == CA_PROXY_BOX)
            list.push_back({{"kind", "box"}, {"center", a}, {"rotation", {c.rotation[0], c.rotation[1], c.rotation[2], c.rotation[3]}},
                            {"half_extents", {c.size[0] / 2, c.size[1] / 2, c.size[2] / 2}}});
        else list.push_back({{"kind", "sphere"}, {"center", a}, {"radius", p.radius_a}});
    }
    Json doc = {{"proxies", list}};
    for (const auto& [key, value] : stats.items()) doc[key] = value;
    std::string err;
    if (!caio::write_bytes(path, doc.dump(1) + "\n", err)) return failure = file_failure(err), false;
    return true;
}

bool write_outputs(const caio::MeshData& mesh, const caio::SkeletonData& sd, const std::vector<caio::ProxyData>& proxies,
                   const RunOptions& o, const Outputs& out, Failure& failure) {
    std::string err;
    if (!caio::write_ma(out.ma, sd, err) || (!out.obj.empty() && !caio::write_obj(out.obj, sd, err)) ||
        (!out.ply.empty() && !caio::write_ply(out.ply, sd, err)) ||
        (!out.gltf.empty() && !caio::write_gltf(out.gltf, sd, err, proxies)) ||
        (!out.colliders.empty() && !caio::write_colliders(out.colliders, mesh, proxies, err)) ||
        (!out.preview.empty() && !caio::write_preview(out.preview, mesh, sd, o.preview, err)))
        return failure = file_failure(err), false;
    return true;
}

Json outputs_json(const Outputs& out) {
    Json j = {{"ma", out.ma}};
    for (const auto& [key, path] : {std::pair<const char*, const std::string&>{"obj", out.obj}, {"ply", out.ply},
                                    {"gltf", out.gltf}, {"preview", out.preview}, {"proxies_json", out.proxies_json},
                                    {"correspondence", out.correspondence}, {"rig", out.rig}, {"colliders", out.colliders},
                                    {"bone_colliders", out.bone_colliders}, {"bone_colliders_json", out.bone_colliders_json}})
        if (!path.empty()) j[key] = path;
    return j;
}

// Seconds each stage of a run took, for the report.
struct StageTimes {
    double read = 0, candidates = 0, select = 0, connect = 0, write = 0, evaluate = 0, proxies = 0;
};

// --proxies: the engine proxies of the skeleton, their data for the writers and their stats.
bool run_proxies(Owned& owned, const RunOptions& o, std::vector<caio::ProxyData>& proxies, Json& proxy_stats,
                  Failure& failure) {
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    ca_skeleton_get_view(owned.sk, &view);
    const ca_status st = ca_proxies(owned.ctx, owned.set, &view, &o.proxy, &owned.proxies);
    if (st != CA_OK) return failure = library_failure(owned.ctx, st, "proxies"), false;
    ca_proxy_stats ps;
    ps.struct_size = sizeof ps;
    ca_proxy_set_stats(owned.proxies, &ps);
    proxies = proxy_data(owned.proxies);
    proxy_stats = proxy_stats_json(ps, o, proxies.size());
    return true;
}

// The skeleton's fields of the report.
void add_skeleton_fields(Json& j, const ca_skeleton_stats& ks, size_t selected) {
    j["selected"] = selected;
    j["edges"] = ks.edges;
    j["faces"] = ks.faces;
    j["components"] = ks.components;
    j["isolated"] = ks.isolated;
    j["betti1"] = ks.betti1;
    j["genus"] = ks.genus;
    j["thin_handles"] = ks.thin_handles;
    j["medial_balls"] = ks.medial_balls;
    j["surface_balls"] = ks.surface_balls;
    j["open_parts"] = ks.open_parts;
    if (ks.fitted) {
        j["fit"] = {{"error_before", ks.fit_error_before}, {"error_after", ks.fit_error_after},
                    {"time_s", ks.fit_time_s}, {"uncovered", ks.fit_uncovered}};
    }
}

// The selection's fields of the report.
void add_selection_fields(Json& j, const ca_select_stats& ss, const Owned& owned, const RunOptions& o) {
    j["uncovered"] = ca_selection_uncovered_count(owned.sel);
    j["optimal"] = ss.proven_optimal != 0;
    j["objective"] = std::llround(ss.objective);
    j["lower_bound"] = std::llround(ss.lower_bound);
    j["gap"] = ss.gap;
    j["delta"] = ss.delta_absolute;
    j["scale"] = ss.scale_used;
    j["reference_length"] = ca_candidate_set_reference_length(owned.set);
    j["solver"] = o.solver;
    j["effort"] = o.effort;
}

// The --json report of a finished run.
Json run_report(const std::string& input, const caio::MeshData& mesh, const Owned& owned, size_t selected,
                const ca_skeleton_stats& ks, const ca_select_stats& ss, const RunOptions& o, const Outputs& out,
                const Json& rig_report, const ca_evaluation* ev, const Json& proxy_stats, const Outcome& r,
                const StageTimes& t, double total) {
    Json j = report_header(input);
    j["input_vertices"] = mesh.positions.size() / 3;
    j["input_triangles"] = mesh.triangles.size() / 3;
    j["input_normals"] = mesh.triangles.empty() && !mesh.normals.empty();
    j["dropped"] = mesh.dropped;
    j["skin"] = skin_json(mesh);
    j["normals"] = normals_name(owned.normals);
    j["flipped"] = owned.flipped;
    j["surface_samples"] = ca_candidate_set_sample_count(owned.set);
    j["candidates"] = ca_candidate_set_count(owned.set);
    j["outliers"] = ca_candidate_set_outlier_count(owned.set);
    j["normals_replaced"] = ca_candidate_set_normals_replaced(owned.set);
    add_skeleton_fields(j, ks, selected);
    add_selection_fields(j, ss, owned, o);
    j["connect"] = ks.method == CA_CONNECT_MEDIAL ? "medial" : "power";
    j["probes"] = ss.probes;
    j["parts"] = ss.parts;
    j["reduction"] = {{"rows_before", ss.rows_before}, {"cols_before", ss.cols_before}, {"rows_after", ss.rows_after},
                      {"cols_after", ss.cols_after}, {"forced", ss.forced}};
    j["output"] = out.ma;
    j["outputs"] = outputs_json(out);
    for (auto& [key, value] : rig_report.items()) j[key] = value;
    if (ev) add_evaluation(j, *ev);
    if (!o.proxies.empty()) j["proxies"] = proxy_stats;
    // --target-count: the HD of what was written (the library's search measured the default
    // connection, fitted with --fit, which --connect changes)
    if (o.select.target_count > 0) j["hd_reached"] = ev->hd_two_sided;
    else if (ss.hd_reached >= 0) j["hd_reached"] = ss.hd_reached;
    else j["hd_reached"] = nullptr;
    if (o.select.target_error > 0) {
        j["target_reached"] = !r.target_missed;
        // no lower bound on the count is known (docs/fidelity.md): null, never a guess
        j["balls_lower_bound"] = nullptr;
    }
    if (r.target_missed) j["error"] = error_json(r.failure);
    j["time_s"] = {{"read", round4(t.read)},       {"candidates", round4(t.candidates)}, {"select", round4(t.select)},
                   {"connect", round4(t.connect)}, {"write", round4(t.write)},           {"evaluate", round4(t.evaluate)},
                   {"proxies", round4(t.proxies)}, {"total", round4(total)}};
    return j;
}

}  // namespace

Outcome run_pipeline(const std::string& input, const RunOptions& o, const Outputs& out, ca_progress_fn progress,
                     void* progress_user, ca_log_fn log) {
    Outcome r;
    StageTimes t;
    const auto t_start = Clock::now();
    caio::MeshData mesh;
    std::string err;
    if (!read_input(input, o.format, o.read, mesh, err)) return r.failure = file_failure(err), r;
    if (!(out.bone_colliders.empty() && out.bone_colliders_json.empty()) && mesh.skin.empty() && out.rig.empty())
        return r.failure = bone_skin_missing(input), r;   // before the skeleton is made, not after
    t.read = since(t_start);

    Owned owned;
    ca_context_desc desc;
    ca_context_desc_init(&desc);
    desc.threads = o.threads;
    desc.progress = progress;
    desc.progress_user = progress_user;
    desc.log = log;
    desc.log_user = progress_user;
    ca_status st;
    if (!context_for(owned, desc, o.time_limit_s, t_start, "candidates", r.failure)) return r;

    auto t0 = Clock::now();
    if (!make_candidates(owned, mesh, o, r.failure) || !export_candidates(owned.set, out, r.failure)) return r;
    t.candidates = since(t0);

    t0 = Clock::now();
    if (!context_for(owned, desc, o.time_limit_s, t_start, "selection", r.failure) || !make_selection(owned, o, r.failure))
        return r;
    r.target_missed = r.failure.exit_code == 4;
    t.select = since(t0);
    ca_select_stats ss;
    ss.struct_size = sizeof ss;
    ca_selection_stats(owned.sel, &ss);

    t0 = Clock::now();
    if (!context_for(owned, desc, o.time_limit_s, t_start, "connection", r.failure)) return r;
    if ((st = ca_connect(owned.ctx, owned.set, owned.sel, &o.connect, &owned.sk)) != CA_OK)
        return r.failure = library_failure(owned.ctx, st, "connection"), r;
    t.connect = since(t0);
    ca_skeleton_stats ks;
    ks.struct_size = sizeof ks;
    ca_skeleton_stats_get(owned.sk, &ks);

    // --proxies: engine proxies of the skeleton, before the writers (glTF holds them)
    std::vector<caio::ProxyData> proxies;
    Json proxy_stats;
    if (!o.proxies.empty()) {
        t0 = Clock::now();
        if (!context_for(owned, desc, o.time_limit_s, t_start, "proxies", r.failure) ||
            !run_proxies(owned, o, proxies, proxy_stats, r.failure))
            return r;
        t.proxies = since(t0);
    }

    t0 = Clock::now();
    const caio::SkeletonData sd = skeleton_data(owned.sk);
    if (!write_outputs(mesh, sd, proxies, o, out, r.failure)) return r;
    if (!out.proxies_json.empty() && !write_proxies_json(out.proxies_json, proxies, proxy_stats, r.failure)) return r;
    Json rig_report = Json::object();
    if (!(out.correspondence.empty() && out.rig.empty()) &&
        (!context_for(owned, desc, o.time_limit_s, t_start, "rig", r.failure) ||
         !write_rig_outputs(owned.ctx, mesh, owned.sk, o, out, proxies, rig_report, r.failure)))
        return r;
    if (!(out.bone_colliders.empty() && out.bone_colliders_json.empty()) &&
        (!context_for(owned, desc, o.time_limit_s, t_start, "bone colliders", r.failure) ||
         !write_bone_outputs(owned.ctx, input, mesh, owned.set, owned.sk, o, out, rig_report, r.failure)))
        return r;
    t.write = since(t0);

    // --target-count: the tool measures the HD it reached (--target-error: the library did)
    const bool evaluate_run = o.evaluate || o.select.target_count > 0;
    ca_evaluation ev{};
    if (evaluate_run) {
        t0 = Clock::now();
        ca_skeleton_view view;
        ca_skeleton_view_init(&view);
        ca_skeleton_get_view(owned.sk, &view);
        if (!context_for(owned, desc, o.time_limit_s, t_start, "evaluation", r.failure)) return r;
        if (!evaluate(owned.ctx, mesh, view, o.evaluation, ev, r.failure)) return r;
        t.evaluate = since(t0);
    }

    r.report = run_report(input, mesh, owned, sd.radii.size(), ks, ss, o, out, rig_report, evaluate_run ? &ev : nullptr,
                          proxy_stats, r, t, since(t_start));
    r.ok = true;
    return r;
}

}  // namespace cli
