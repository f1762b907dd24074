// pipeline.cpp: one run of the tool through the library's C ABI, its steps in order: read the
// input, candidates (generated or from files), selection, connection, the engine proxies, the
// outputs (.ma, .obj, .ply, glTF, preview, colliders, rig, bone colliders), the evaluation, then
// the JSON report; each stage timed, each step given its context (run_steps.h has the steps).
// Failures come back as a Failure (never printed here), so the single run and the batch command
// report them alike.
#include "run_steps.h"

namespace cli {

Run::Run(const RunOptions& o, ca_progress_fn progress, void* progress_user, ca_log_fn log)
    : budget_s(o.time_limit_s), start(Clock::now()) {
    ca_context_desc_init(&desc);
    desc.threads = o.threads;
    desc.progress = progress;
    desc.progress_user = progress_user;
    desc.log = log;
    desc.log_user = progress_user;
}

Run::~Run() {
    ca_proxy_set_destroy(proxies);
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

bool Run::context_for(const std::string& step, Failure& failure) {
    if (ctx && budget_s <= 0) return true;
    ca_context_desc d = desc;
    if (budget_s > 0) {
        d.time_limit_s = budget_s - since(start);
        if (d.time_limit_s <= 0) {
            failure = library_failure(nullptr, CA_ERROR_TIME_LIMIT, step);
            failure.message = step + " failed: time limit reached before " + step;
            return false;
        }
    }
    ca_context_destroy(ctx);
    ctx = nullptr;
    const ca_status st = ca_context_create(&d, &ctx);
    if (st != CA_OK) return failure = library_failure(nullptr, st, "context"), false;
    return true;
}

namespace {

// The input, read (in a child process for assimp's formats); --bone-colliders' need of a skin is
// checked here, before the skeleton is made, not after.
bool read_step(const std::string& input, const RunOptions& o, const Outputs& out, caio::MeshData& mesh, Failure& failure) {
    std::string err;
    if (!read_input(input, o.format, o.read, mesh, err)) return failure = file_failure(err), false;
    if (!(out.bone_colliders.empty() && out.bone_colliders_json.empty()) && mesh.skin.empty() && out.rig.empty())
        return failure = bone_skin_missing(input), false;
    return true;
}

// The skeleton: candidates (and their export), selection, connection, with their stats. A target
// error not reached marks the outcome and the run goes on.
bool skeleton_steps(Run& run, const caio::MeshData& mesh, const RunOptions& o, const Outputs& out, RunResults& results,
                    Outcome& r) {
    if (!run.context_for("candidates", r.failure)) return false;
    auto t0 = Clock::now();
    if (!make_candidates(run, mesh, o, r.failure) || !export_candidates(run.set, out, r.failure)) return false;
    run.times.candidates = since(t0);

    t0 = Clock::now();
    if (!run.context_for("selection", r.failure) || !make_selection(run, o, r.failure)) return false;
    r.target_missed = r.failure.exit_code == 4;
    run.times.select = since(t0);
    results.select.struct_size = sizeof results.select;
    ca_selection_stats(run.sel, &results.select);

    t0 = Clock::now();
    if (!run.context_for("connection", r.failure)) return false;
    const ca_status st = ca_connect(run.ctx, run.set, run.sel, &o.connect, &run.sk);
    if (st != CA_OK) return r.failure = library_failure(run.ctx, st, "connection"), false;
    run.times.connect = since(t0);
    results.skeleton.struct_size = sizeof results.skeleton;
    ca_skeleton_stats_get(run.sk, &results.skeleton);
    return true;
}

// --proxies: the engine proxies of the skeleton, made before the writers (glTF holds them).
bool proxy_step(Run& run, const RunOptions& o, std::vector<caio::ProxyData>& proxies, RunResults& results,
                Failure& failure) {
    if (o.proxies.empty()) return true;
    const auto t0 = Clock::now();
    if (!run.context_for("proxies", failure) || !run_proxies(run, o, proxies, results.proxy_stats, failure)) return false;
    run.times.proxies = since(t0);
    return true;
}

// The files, timed as one stage: the skeleton's, --proxies-json, then --correspondence / --rig and
// the bone colliders, each of those two with its context.
bool write_step(Run& run, const std::string& input, const caio::MeshData& mesh, const std::vector<caio::ProxyData>& proxies,
                const RunOptions& o, const Outputs& out, RunResults& results, Failure& failure) {
    const auto t0 = Clock::now();
    const caio::SkeletonData sd = skeleton_data(run.sk);
    results.selected = sd.radii.size();
    if (!write_outputs(mesh, sd, proxies, o, out, failure)) return false;
    if (!out.proxies_json.empty() && !write_proxies_json(out.proxies_json, proxies, results.proxy_stats, failure))
        return false;
    if (!(out.correspondence.empty() && out.rig.empty()) &&
        (!run.context_for("rig", failure) ||
         !write_rig_outputs(run.ctx, mesh, run.sk, o, out, proxies, results.rig, failure)))
        return false;
    if (!(out.bone_colliders.empty() && out.bone_colliders_json.empty()) &&
        (!run.context_for("bone colliders", failure) ||
         !write_bone_outputs(run.ctx, input, mesh, run.set, run.sk, o, out, results.rig, failure)))
        return false;
    run.times.write = since(t0);
    return true;
}

// --evaluate; and --target-count, where the tool measures the HD it reached (with --target-error
// the library did).
bool evaluation_step(Run& run, const caio::MeshData& mesh, const RunOptions& o, RunResults& results, Failure& failure) {
    if (!(o.evaluate || o.select.target_count > 0)) return true;
    const auto t0 = Clock::now();
    const ca_skeleton_view view = skeleton_view(run.sk);
    if (!run.context_for("evaluation", failure) || !evaluate(run.ctx, mesh, view, o.evaluation, results.evaluation, failure))
        return false;
    run.times.evaluate = since(t0);
    results.evaluated = true;
    return true;
}

}  // namespace

Outcome run_pipeline(const std::string& input, const RunOptions& o, const Outputs& out, ca_progress_fn progress,
                     void* progress_user, ca_log_fn log) {
    Outcome r;
    Run run(o, progress, progress_user, log);
    caio::MeshData mesh;
    if (!read_step(input, o, out, mesh, r.failure)) return r;
    run.times.read = since(run.start);

    RunResults results;
    std::vector<caio::ProxyData> proxies;
    if (!skeleton_steps(run, mesh, o, out, results, r) || !proxy_step(run, o, proxies, results, r.failure) ||
        !write_step(run, input, mesh, proxies, o, out, results, r.failure) ||
        !evaluation_step(run, mesh, o, results, r.failure))
        return r;
    r.report = run_report(input, mesh, run, results, o, out, r);
    r.ok = true;
    return r;
}

}  // namespace cli
