// run_steps.h: the steps of one run of the tool, which pipeline.cpp puts in order: the library
// objects a run owns and the context each step gets (pipeline.cpp), the candidates
// (candidate_step.cpp), the selection (selection_step.cpp), the engine proxies
// (proxy_outputs.cpp), the skeleton's files (skeleton_outputs.cpp) and the JSON report
// (run_report.cpp). Every step returns false with the Failure set; none prints.
#pragma once
#include "cli.h"

#include <chrono>
#include <vector>

namespace cli {

using Clock = std::chrono::steady_clock;
// Seconds from `t` to now.
inline double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Seconds each stage of a run took, for the report.
struct StageTimes {
    double read = 0, candidates = 0, select = 0, connect = 0, write = 0, evaluate = 0, proxies = 0;
};

// The library objects of one run (destroyed in reverse order) and the contexts its steps get.
struct Run {
    ca_context* ctx = nullptr;
    ca_candidate_set* set = nullptr;
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    ca_proxy_set* proxies = nullptr;
    // Which normals the generated candidates used (CA_NORMALS_*) and whether the input was
    // flipped, read before a candidates file replaces the set.
    int32_t normals = CA_NORMALS_NONE;
    bool flipped = false;
    ca_context_desc desc;      // every step's context: the threads, the progress and log callbacks
    double budget_s = 0;       // --time-limit: the whole run's budget; 0 = none
    Clock::time_point start;   // the run's start, reading included
    StageTimes times;

    Run(const RunOptions& o, ca_progress_fn progress, void* progress_user, ca_log_fn log = nullptr);
    ~Run();
    Run(const Run&) = delete;
    Run& operator=(const Run&) = delete;
    // The context for the step named `step`. With a whole-run budget, each step gets a fresh
    // context whose time limit is what is left of the budget, so whichever stage is running when
    // it runs out returns CA_ERROR_TIME_LIMIT naming itself; a step that would start with nothing
    // left fails the same way. Results outlive the context that made them.
    bool context_for(const std::string& step, Failure& failure);
};

// candidate_step.cpp: generated candidates, with the sample and ball files (if any) replacing
// their parts; then --export-samples and --export-candidates.
bool make_candidates(Run& run, const caio::MeshData& mesh, const RunOptions& o, Failure& failure);
bool export_candidates(const ca_candidate_set* set, const Outputs& out, Failure& failure);

// selection_step.cpp: the user-control index files become per-sample / per-ball masks, then the
// cover. A target error not reached is no failure: `failure` says so with exit code 4.
bool make_selection(Run& run, const RunOptions& o, Failure& failure);

// proxy_outputs.cpp: --proxies (the engine proxies of the skeleton, their data for the writers and
// their stats) and --proxies-json.
bool run_proxies(Run& run, const RunOptions& o, std::vector<caio::ProxyData>& proxies, Json& proxy_stats,
                 Failure& failure);
bool write_proxies_json(const std::string& path, const std::vector<caio::ProxyData>& proxies, const Json& stats,
                        Failure& failure);

// skeleton_outputs.cpp: the skeleton as the writers take it, and its files (.ma, .obj, .ply,
// glTF, colliders, preview).
caio::SkeletonData skeleton_data(const ca_skeleton* sk);
bool write_outputs(const caio::MeshData& mesh, const caio::SkeletonData& sd, const std::vector<caio::ProxyData>& proxies,
                   const RunOptions& o, const Outputs& out, Failure& failure);

// run_report.cpp: the --json report of a finished run, from what its steps gave.
struct RunResults {
    ca_select_stats select{};
    ca_skeleton_stats skeleton{};
    size_t selected = 0;              // the skeleton's vertices
    Json rig = Json::object();        // "rig" and "bone_colliders", when written
    Json proxy_stats;                 // --proxies' stats
    bool evaluated = false;           // --evaluate or --target-count: `evaluation` holds the result
    ca_evaluation evaluation{};
};
Json run_report(const std::string& input, const caio::MeshData& mesh, const Run& run, const RunResults& results,
                const RunOptions& o, const Outputs& out, const Outcome& r);

}  // namespace cli
