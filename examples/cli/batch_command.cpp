// batch_command.cpp: `coverage-axis batch -O OUTDIR [-j N] [options] INPUT...`: many inputs
// (a folder expands to its mesh files, sorted), N at a time on threads, each with its own
// ca_context and max(1, threads / N) worker threads so the jobs share the cores. Each input
// writes OUTDIR/<stem>.ma and the outputs --write asks for; stdout has one JSON line per input
// (in input order). A sidecar OUT.sidecar.json beside each output records the input's content
// hash, the options and the output's hash: a rerun skips an input whose outputs all match.
#include "cli.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

namespace cli {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> expand_inputs(const std::vector<std::string>& args) {
    std::vector<std::string> inputs;
    for (const std::string& a : args) {
        std::error_code ec;
        if (!fs::is_directory(a, ec)) {
            inputs.push_back(a);
            continue;
        }
        std::vector<std::string> found;
        for (const auto& entry : fs::directory_iterator(a, ec))
            if (entry.is_regular_file(ec) && is_mesh_file(entry.path().string())) found.push_back(entry.path().string());
        std::sort(found.begin(), found.end());
        inputs.insert(inputs.end(), found.begin(), found.end());
    }
    return inputs;
}

std::string sidecar_path(const std::string& output) { return output + ".sidecar.json"; }

bool read_json(const std::string& path, Json& out) {
    std::ifstream in(path);
    if (!in) return false;
    out = Json::parse(in, nullptr, false);
    return !out.is_discarded();
}

std::vector<std::string> output_paths(const Outputs& out) {
    std::vector<std::string> paths;
    for (const std::string* p : {&out.ma, &out.obj, &out.ply, &out.gltf, &out.preview})
        if (!p->empty()) paths.push_back(*p);
    return paths;
}

// The stored report if every output exists, has a sidecar with this key and still has the
// content the sidecar recorded.
bool up_to_date(const Outputs& out, const Json& key, Json& report) {
    for (const std::string& p : output_paths(out)) {
        Json side;
        if (!read_json(sidecar_path(p), side) || side.value("key", Json()) != key ||
            side.value("output_hash", std::string()) != file_hash(p))
            return false;
        if (p == out.ma) report = side.value("report", Json());
    }
    return report.is_object();
}

bool write_sidecars(const Outputs& out, const Json& key, const Json& report, std::string& error) {
    for (const std::string& p : output_paths(out)) {
        Json side = {{"output", p}, {"output_hash", file_hash(p)}, {"key", key}};
        if (p == out.ma) side["report"] = report;
        std::ofstream f(sidecar_path(p));
        f << side.dump(1) << "\n";
        if (!f) {
            error = sidecar_path(p) + ": cannot write";
            return false;
        }
    }
    return true;
}

struct Job {
    std::string input;
    Outputs out;
    std::string collision;  // non-empty: another input already writes these outputs
};

// One input: skipped, run, or failed; the JSON line for it.
Json run_job(const Job& job, const RunOptions& o, const Json& options, bool force, bool& ok) {
    ok = false;
    if (!job.collision.empty()) {
        Json j = report_header(job.input);
        j["error"] = error_json(file_failure(job.out.ma + ": also the output of " + job.collision + " (same file stem)"));
        return j;
    }
    const Json key = {{"tool_version", CA_TOOL_VERSION}, {"input_hash", file_hash(job.input)}, {"options", options}};
    Json report;
    if (!force && up_to_date(job.out, key, report)) {
        report["skipped"] = true;
        ok = !report.contains("error");  // a stored run that missed its target error

        return report;
    }
    std::error_code ec;
    for (const std::string& p : output_paths(job.out)) fs::remove(sidecar_path(p), ec);
    const Outcome r = run_pipeline(job.input, o, job.out);
    if (!r.ok) {
        Json j = report_header(job.input);
        j["error"] = error_json(r.failure);
        return j;
    }
    std::string err;
    if (!write_sidecars(job.out, key, r.report, err)) {
        Json j = report_header(job.input);
        j["error"] = error_json(file_failure(err));
        return j;
    }
    report = r.report;
    report["skipped"] = false;
    ok = !r.target_missed;  // the outputs are written; the line carries the error
    return report;
}

}  // namespace

int batch_command(int argc, char** argv) {
    RunOptions o;
    std::string outdir;
    std::vector<std::string> args, extra;
    unsigned jobs = 1;
    bool force = false;
    CLI::App app{"Runs many inputs: OUTDIR/<stem>.ma (and the --write outputs) per input, one JSON line per input on "
                 "stdout; a rerun skips inputs whose outputs are up to date.",
                 "coverage-axis batch"};
    app.add_option("INPUT", args, "mesh files, or folders (their mesh files, sorted)")->required();
    app.add_option("-O,--output-dir", outdir, "the folder for the outputs (created if missing)")->required();
    app.add_option("-j,--jobs", jobs, "inputs run at once; each gets max(1, threads / jobs) worker threads")
        ->capture_default_str()->check(CLI::Range(1u, 1024u));
    std::string write_list;
    app.add_option("--write", write_list, "also write per input: obj, ply, glb or gltf, png or svg (comma-separated)");
    app.add_flag("--force", force, "redo inputs whose outputs are up to date");
    add_run_options(app, o);
    app.footer("Exit codes: 0 every input succeeded (or was up to date), 1 some input failed (its JSON line has "
               "\"error\"), 2 bad command line, 3 OUTDIR cannot be created. See docs/cli.md.");
    std::string err;
    const int parsed = parse_command_line(app, argc, argv, err);
    if (parsed == 2) std::fprintf(stderr, "coverage-axis batch: %s\n", err.c_str());
    if (parsed >= 0) return parsed;
    for (size_t at = 0; at < write_list.size();) {
        const size_t comma = std::min(write_list.find(',', at), write_list.size());
        extra.push_back(write_list.substr(at, comma - at));
        at = comma + 1;
    }
    for (const std::string& x : extra)
        if (x != "obj" && x != "ply" && x != "glb" && x != "gltf" && x != "png" && x != "svg") {
            std::fprintf(stderr, "coverage-axis batch: --write takes obj, ply, glb, gltf, png, svg, not '%s'\n", x.c_str());
            return 2;
        }
    auto has = [&](const char* k) { return std::find(extra.begin(), extra.end(), k) != extra.end(); };
    if (!finish_run_options(app, o, err) || (has("glb") && has("gltf")) || (has("png") && has("svg"))) {
        if (err.empty()) err = "--write takes one of glb/gltf and one of png/svg";
        std::fprintf(stderr, "coverage-axis batch: %s (see coverage-axis batch --help)\n", err.c_str());
        return 2;
    }
    std::error_code ec;
    fs::create_directories(outdir, ec);
    if (!fs::is_directory(outdir, ec)) {
        std::fprintf(stderr, "coverage-axis batch: cannot create %s\n", outdir.c_str());
        return 3;
    }

    std::vector<Job> list;
    std::map<std::string, std::string> owner;  // output stem -> the input that writes it
    for (const std::string& input : expand_inputs(args)) {
        Job job;
        job.input = input;
        const std::string base = (fs::path(outdir) / fs::path(input).stem()).string();
        job.out.ma = base + ".ma";
        if (has("obj")) job.out.obj = base + ".obj";
        if (has("ply")) job.out.ply = base + ".ply";
        if (has("glb") || has("gltf")) job.out.gltf = base + (has("glb") ? ".glb" : ".gltf");
        if (has("png") || has("svg")) job.out.preview = base + (has("png") ? ".png" : ".svg");
        auto [it, fresh] = owner.emplace(base, input);
        if (!fresh) job.collision = it->second;
        list.push_back(job);
    }

    const unsigned cores = o.threads > 0 ? unsigned(o.threads) : std::max(1u, std::thread::hardware_concurrency());
    const unsigned workers = std::max(1u, std::min<unsigned>(jobs, unsigned(list.size())));
    RunOptions per_job = o;
    per_job.threads = int32_t(std::max(1u, cores / workers));
    const Json options = options_json(o);

    std::vector<Json> lines(list.size());
    std::vector<char> done(list.size(), 0);
    std::atomic<size_t> next{0};
    std::atomic<bool> all_ok{true};
    std::mutex print_mutex;
    size_t printed = 0;
    auto worker = [&]() {
        for (size_t i; (i = next++) < list.size();) {
            bool ok = false;
            Json line = run_job(list[i], per_job, options, force, ok);
            if (!ok) all_ok = false;
            std::lock_guard<std::mutex> lock(print_mutex);
            lines[i] = std::move(line);
            done[i] = 1;
            for (; printed < list.size() && done[printed]; ++printed) {  // in input order, as soon as possible
                std::printf("%s\n", lines[printed].dump().c_str());
                std::fflush(stdout);
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned w = 1; w < workers; ++w) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    return all_ok ? 0 : 1;
}

}  // namespace cli
