// cli.h: pieces the command-line tool's commands (single run, batch, evaluate) share: the run
// options (bound to the library's option structs, so their defaults are the library's), the
// pipeline from an input file to the written outputs and a JSON report, and the error shape.
#pragma once
#include "coverage_axis.h"
#include "mesh_io.h"
#include "preview.h"
#include "surface_view.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <string>

namespace cli {

using Json = nlohmann::ordered_json;

// Version of the JSON reports (bumped when a field changes meaning or goes away).
constexpr int kFormatVersion = 1;

// Bounds on reading one input through assimp, which runs in a child process (read_input).
struct ReadLimits {
    double time_s = 60;      // wall clock from the start of the read; past it the reader is stopped
    double memory_mib = 0;   // the reader's address space; 0 = 512 MiB + 128 bytes per input byte
};

// Everything that decides a run's results. The structs start as the library's *_init defaults.
struct RunOptions {
    ca_candidate_options candidates;
    ca_select_options select;
    ca_connect_options connect;
    ca_evaluate_options evaluation;
    ca_rig_options rig;                      // --rig and --correspondence (its smoothing too)
    ca_proxy_options proxy;                  // --proxies: engine proxies of the skeleton
    ca_bone_collider_options bone;           // --bone-colliders: a collider per bone of the skin
    std::string bone_mode;                   // inscribed | conservative
    std::string skip_bones;                  // --skip-bones: joint names, comma-separated
    std::string format;                      // input format name; "" = by extension
    std::string candidate_kind = "voronoi";  // voronoi | random | a ball file
    std::string normals = "given";           // a point cloud's normals: given | unoriented | estimate
    int32_t point_normals = CA_POINT_NORMALS_TRUSTED;   // `normals` as CA_POINT_NORMALS_*
    std::string solver, effort, connect_route;
    std::string proxies;                     // "" (none) | spheres | capsules
    std::string proxy_mode;                  // inscribed | conservative
    std::string surface_samples_file, ignore_samples_file, force_in_file, force_out_file;
    bool evaluate = false;
    caio::PreviewOptions preview;
    std::string view = "auto", up, preview_size;
    int32_t threads = 0;  // 0 = all cores
    double time_limit_s = 0;  // --time-limit: the whole run's budget, from the start of reading; 0 = none
    ReadLimits read;          // --read-time-limit (else --time-limit's budget), --read-memory-limit
    RunOptions();
};

// Where one run writes (empty = not written).
struct Outputs {
    std::string ma, obj, ply, gltf, preview, export_samples, export_candidates;
    std::string correspondence, rig;   // --correspondence FILE.json, --rig OUT.glb
    std::string proxies_json;   // the engine proxies (--proxies) and their stats
    std::string colliders;      // --colliders OUT.glb: the input mesh with the proxies as glTF physics
    std::string bone_colliders;       // --bone-colliders OUT.glb: the skinned input with a collider per bone
    std::string bone_colliders_json;  // --bone-colliders-json FILE.json: those colliders and their stats
};

// A failed run: a library status (CA_ERROR_*, exit 1) or a tool error (FILE_ERROR exit 3,
// USAGE_ERROR exit 2; code -1).
struct Failure {
    std::string status;
    int code = -1;
    std::string message;
    int exit_code = 1;
};

struct Outcome {
    bool ok = false;
    Json report;      // the --json fields
    Failure failure;  // !ok: why; ok with target_missed: the target not reached (exit 4)
    bool target_missed = false;  // --target-error not reached: the outputs hold the lowest HD found
};

// The options of a run, on a single run's or the batch command's command line.
void add_run_options(CLI::App& app, RunOptions& o);
// Turns the parsed strings into option values; false with a message on a bad combination.
bool finish_run_options(const CLI::App& app, RunOptions& o, std::string& error);
// The options as JSON (for batch sidecars): every value that can change an output.
Json options_json(const RunOptions& o);

// Reads `input`, runs candidates -> selection -> connection, writes `out` and reports. `log`, when
// set, gets the library's notes with progress_user.
Outcome run_pipeline(const std::string& input, const RunOptions& o, const Outputs& out, ca_progress_fn progress = nullptr,
                     void* progress_user = nullptr, ca_log_fn log = nullptr);

Json error_json(const Failure& f);
Failure library_failure(ca_context* ctx, ca_status st, const std::string& step);
Failure file_failure(const std::string& message);
// format_version, tool_version, library_version, abi_version, input: the start of every report.
Json report_header(const std::string& input);
// The report's "skin": {"joints": N, "influences": K} for a mesh read with a skin, else null.
Json skin_json(const caio::MeshData& mesh);

// The surface view of a file's mesh or cloud, and the report's name of the normals (surface_view.h).
using caio::normals_name;
using caio::surface_view;
// Evaluates a skeleton against the input surface (Hausdorff distances, see ca_evaluate).
bool evaluate(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton_view& skeleton,
              const ca_evaluate_options& options, ca_evaluation& out, Failure& failure);
// The evaluation's JSON fields (hd_two_sided, ...), added to `j`.
void add_evaluation(Json& j, const ca_evaluation& e);
// "coverage-axis X.Y.Z (library X.Y.Z, ABI N)"
std::string version_text();
std::string library_version();
// FNV-1a 64 of a file's bytes as 16 hex digits ("" if it cannot be read).
std::string file_hash(const std::string& path);
// Reads a mesh or point cloud as caio::read_mesh does (`format` "" = by extension). An input that
// goes to assimp is read in a child process (this executable's `--internal-read`) bounded by
// `limits`: a crash, an abort, a hang or runaway memory there becomes a false return with a
// message naming the file. Other formats are read in this process.
bool read_input(const std::string& path, const std::string& format, const ReadLimits& limits, caio::MeshData& out,
                std::string& error);
// The child side of read_input: `coverage-axis --internal-read PATH FORMAT SECONDS MIB`.
int read_child_command(int argc, char** argv);
// Readable mesh files: the extensions a folder given to batch expands to.
bool is_mesh_file(const std::string& path);
// Parses a command line: -1 to go on; the exit code after --help or --version (printed); or 2
// for a bad command line, with a one-line `error` (unknown option, a second input, a bad value).
int parse_command_line(CLI::App& app, int argc, char** argv, std::string& error);

// The skeleton's view (ca_skeleton_get_view), for the calls that take one (skeleton_outputs.cpp).
ca_skeleton_view skeleton_view(const ca_skeleton* sk);

// The rig of the skeleton over the input's surface (ca_rig_build with --rig's options; rig_outputs.cpp):
// null, with `failure` set, when the library refuses.
using RigPtr = std::unique_ptr<ca_rig, void (*)(ca_rig*)>;
RigPtr build_rig(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton* sk, const RunOptions& o, Failure& failure);

// --correspondence and --rig (rig_outputs.cpp): nothing when neither is asked for; adds "rig"
// (joints, branches) to the report.
// The rig file carries the engine proxies (if any) as colliders.
bool write_rig_outputs(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton* sk, const RunOptions& o,
                       const Outputs& out, const std::vector<caio::ProxyData>& proxies, Json& report, Failure& failure);

// --bone-colliders and --bone-colliders-json (bone_outputs.cpp): nothing when neither is asked
// for; a collider per joint of the input's skin (or, for an input without one, of the rig that
// --rig writes), written and reported as "bone_colliders". An input with no skin and no --rig is a
// usage error (exit 2).
// The usage error of --bone-colliders on an input without a skin and without --rig.
Failure bone_skin_missing(const std::string& input);
bool write_bone_outputs(ca_context* ctx, const std::string& input, const caio::MeshData& mesh, const ca_candidate_set* set,
                        const ca_skeleton* sk, const RunOptions& o, const Outputs& out, Json& report, Failure& failure);

int evaluate_command(int argc, char** argv);
int batch_command(int argc, char** argv);

}  // namespace cli
