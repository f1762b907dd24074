// bench_common.h: helpers shared by the benchmark programs: listing model files, timing, and
// running the whole pipeline through the C ABI on a mesh file, running a program with a time bound.
#pragma once
#include "coverage_axis.h"
#include "mesh_io.h"
#include "surface_view.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace bench {

inline std::vector<std::string> list_files(const std::string& dir, const std::string& ext) {
    std::vector<std::string> out;
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d)) {
            std::string n = e->d_name;
            if (n.size() > ext.size() && n.compare(n.size() - ext.size(), ext.size(), ext) == 0) out.push_back(dir + "/" + n);
        }
        closedir(d);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// --only NAME[,NAME...]: true when `only` is empty or `name` starts with one of the names.
inline bool selected(const std::string& only, const std::string& name) {
    if (only.empty()) return true;
    size_t b = 0;
    while (b <= only.size()) {
        const size_t e = std::min(only.find(',', b), only.size());
        if (name.rfind(only.substr(b, e - b), 0) == 0) return true;
        b = e + 1;
    }
    return false;
}

// The arguments `[DATA_ROOT] [--only NAME[,NAME...]]` (root default ../shared/data).
inline void root_and_only(int argc, char** argv, std::string& root, std::string& only) {
    root = "../shared/data";
    only.clear();
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--only" && i + 1 < argc) only = argv[++i];
        else root = a;
    }
}

// The paper meshes, <root>/meshes/paper/*.obj; when there are none, says that `program` skipped them.
inline std::vector<std::string> paper_models(const char* program, const std::string& root) {
    std::vector<std::string> models = list_files(root + "/meshes/paper", ".obj");
    if (models.empty()) std::printf("%s: no models under %s/meshes/paper, skipped\n", program, root.c_str());
    return models;
}

inline std::string stem(const std::string& path) {
    std::string n = path.substr(path.find_last_of('/') + 1);
    return n.substr(0, n.find_last_of('.'));
}

inline double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The median (NaN when empty).
inline double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// What run_process saw.
struct ProcessRun {
    bool ran = false;          // the process ended by itself within its bound
    int exit_code = -1, signal = 0;
    double wall_s = 0;
    std::string out;           // its stdout
};

// Runs `args` (args[0] a path) with stdout to `out_path` (read back into `out`) and stderr to
// /dev/null, killed after `limit_s`.
inline ProcessRun run_process(const std::vector<std::string>& args, const std::string& out_path, double limit_s) {
    ProcessRun o;
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) return o;
    if (pid == 0) {
        const int fd = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        if (fd >= 0) dup2(fd, 1);
        if (null >= 0) dup2(null, 2);
        std::vector<char*> argv;
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (seconds_since(t0) > limit_s) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            o.wall_s = seconds_since(t0);
            return o;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    o.wall_s = seconds_since(t0);
    o.ran = true;
    if (WIFEXITED(status)) o.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) o.signal = WTERMSIG(status);
    std::ifstream in(out_path);
    std::stringstream ss;
    ss << in.rdbuf();
    o.out = ss.str();
    return o;
}

// The one clock of every bench's CPU times, as the benches print it above their tables.
constexpr const char* kCpuClock = "CPU time: getrusage(RUSAGE_SELF), user + system of every thread";

// CPU time of the whole process so far (user + system, every thread), seconds (kCpuClock).
inline double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

inline double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}

// The three options structs of a pipeline run, starting at the library's defaults.
struct DefaultOptions {
    ca_candidate_options candidates;
    ca_select_options select;
    ca_connect_options connect;
    DefaultOptions() {
        ca_candidate_options_init(&candidates);
        ca_select_options_init(&select);
        ca_connect_options_init(&connect);
    }
};

struct PipelineRun {
    ca_status status = CA_OK;
    std::string message;
    size_t samples = 0, candidates = 0, balls = 0, edges = 0, faces = 0, components = 0;
    long betti1 = 0;
    int optimal = 0;
    int32_t normals = CA_NORMALS_NONE;   // ca_candidate_set_normals: which normals a cloud used
    double gap = 0, t_candidates = 0, t_select = 0, t_connect = 0;
    ca_evaluation eval{};   // filled when run_pipeline is asked to evaluate
    double t_evaluate = 0;
    // With an alternative connection (run_pipeline's `alt`): the same selection connected by it,
    // its size and its evaluation (when evaluating).
    size_t alt_edges = 0, alt_faces = 0, alt_components = 0;
    long alt_betti1 = 0;
    double t_alt_connect = 0;
    ca_evaluation alt_eval{};
    // With a fitting connection (run_pipeline's `fitted`): the same selection connected and fitted,
    // its evaluation, the fit's own time and the cover samples it left uncovered.
    double t_fit = 0;
    size_t fit_uncovered = 0, fit_balls = 0, fit_open_parts = 0, fit_edges = 0, fit_faces = 0, fit_components = 0;
    long fit_betti1 = 0;
    ca_evaluation fit_eval{};
};

// Size and topology of a skeleton, and with `evaluate` its Hausdorff distances to the surface.
inline ca_status measure_skeleton(ca_context* ctx, const ca_surface_view& v, const ca_skeleton* sk, bool evaluate,
                                  size_t& edges, size_t& faces, size_t& components, long& betti1, ca_evaluation& eval) {
    ca_skeleton_stats ks;
    ks.struct_size = sizeof ks;
    ca_skeleton_stats_get(sk, &ks);
    edges = ks.edges;
    faces = ks.faces;
    components = ks.components;
    betti1 = long(ks.betti1);
    if (!evaluate) return CA_OK;
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    ca_skeleton_get_view(sk, &view);
    ca_evaluate_options eo;
    ca_evaluate_options_init(&eo);
    eval.struct_size = sizeof eval;
    return ca_evaluate(ctx, &v, &view, &eo, &eval);
}

// A selection by `so` (e.g. its target_count), connected at ca_connect's defaults and evaluated at
// ca_evaluate's. balls and hd (the two-sided Hausdorff distance, %) are set when status is CA_OK.
struct SelectionRun {
    ca_status status = CA_OK;
    size_t balls = 0;
    double hd = -1;
};
inline SelectionRun select_connect_evaluate(ca_context* ctx, const ca_surface_view& v, const ca_candidate_set* set,
                                       const ca_select_options& so) {
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    ca_evaluation ev{};
    size_t edges = 0, faces = 0, components = 0;
    long betti1 = 0;
    SelectionRun r;
    r.status = ca_select(ctx, set, &so, &sel);
    if (r.status == CA_OK) r.status = ca_connect(ctx, set, sel, nullptr, &sk);
    if (r.status == CA_OK) r.status = measure_skeleton(ctx, v, sk, true, edges, faces, components, betti1, ev);
    if (r.status == CA_OK) {
        r.balls = ca_skeleton_vertex_count(sk);
        r.hd = ev.hd_two_sided;
    }
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    return r;
}

// A view of packed positions, triangles (empty: a point cloud) and normals (empty: none); borrowed.
inline ca_surface_view view_of(const std::vector<double>& xyz, const std::vector<uint32_t>& tri, const std::vector<double>& nrm) {
    ca_surface_view v;
    ca_surface_view_init(&v);
    v.positions = xyz.data();
    v.vertex_count = xyz.size() / 3;
    v.triangles = tri.empty() ? nullptr : tri.data();
    v.triangle_count = tri.size() / 3;
    v.normals = nrm.empty() ? nullptr : nrm.data();
    v.normal_count = nrm.size() / 3;
    return v;
}

// A view of a mesh or point cloud read by examples/io, and the name of its normals (surface_view.h).
using caio::normals_name;
using caio::surface_view;

// The pipeline in a context of its own with `threads` worker threads (0: all cores).
inline PipelineRun run_pipeline(const caio::MeshData& mesh, const ca_candidate_options& co, const ca_select_options& so,
                                const ca_connect_options& cop, bool evaluate = false,
                                const ca_connect_options* alt = nullptr, const ca_connect_options* fitted = nullptr,
                                int32_t point_normals = CA_POINT_NORMALS_TRUSTED, int32_t threads = 0) {
    PipelineRun r;
    ca_context_desc desc;
    ca_context_desc_init(&desc);
    desc.threads = threads;
    ca_context* ctx = nullptr;
    ca_context_create(&desc, &ctx);
    ca_surface_view v = surface_view(mesh);
    v.point_normals = point_normals;
    ca_candidate_set* set = nullptr;
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    auto t = std::chrono::steady_clock::now();
    r.status = ca_candidates(ctx, &v, &co, &set);
    r.t_candidates = seconds_since(t);
    if (r.status == CA_OK) {
        r.samples = ca_candidate_set_sample_count(set);
        r.normals = ca_candidate_set_normals(set);
        r.candidates = ca_candidate_set_count(set);
        t = std::chrono::steady_clock::now();
        r.status = ca_select(ctx, set, &so, &sel);
        r.t_select = seconds_since(t);
    }
    if (r.status == CA_OK) {
        ca_select_stats ss;
        ss.struct_size = sizeof ss;
        ca_selection_stats(sel, &ss);
        r.optimal = ss.proven_optimal;
        r.gap = ss.gap;
        r.balls = ca_selection_count(sel);
        t = std::chrono::steady_clock::now();
        r.status = ca_connect(ctx, set, sel, &cop, &sk);
        r.t_connect = seconds_since(t);
    }
    if (r.status == CA_OK) {
        t = std::chrono::steady_clock::now();
        r.status = measure_skeleton(ctx, v, sk, evaluate, r.edges, r.faces, r.components, r.betti1, r.eval);
        r.t_evaluate = seconds_since(t);
        ca_skeleton* ak = nullptr;
        if (r.status == CA_OK && alt) {
            t = std::chrono::steady_clock::now();
            r.status = ca_connect(ctx, set, sel, alt, &ak);
            r.t_alt_connect = seconds_since(t);
            if (r.status == CA_OK)
                r.status = measure_skeleton(ctx, v, ak, evaluate, r.alt_edges, r.alt_faces, r.alt_components,
                                            r.alt_betti1, r.alt_eval);
        }
        ca_skeleton* fk = nullptr;
        if (r.status == CA_OK && fitted) {
            r.status = ca_connect(ctx, set, sel, fitted, &fk);
            if (r.status == CA_OK) {
                ca_skeleton_stats ks;
                ks.struct_size = sizeof ks;
                ca_skeleton_stats_get(fk, &ks);
                r.t_fit = ks.fit_time_s;
                r.fit_uncovered = size_t(ks.fit_uncovered);
                r.fit_balls = size_t(ks.vertices);
                r.fit_open_parts = size_t(ks.open_parts);
                r.status = measure_skeleton(ctx, v, fk, evaluate, r.fit_edges, r.fit_faces, r.fit_components,
                                            r.fit_betti1, r.fit_eval);
            }
        }
        if (r.status != CA_OK) r.message = ca_context_last_error(ctx);
        ca_skeleton_destroy(ak);
        ca_skeleton_destroy(fk);
    } else {
        r.message = ca_context_last_error(ctx);
    }
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return r;
}

// The set-cover instances of the reference code (<root>/reference/coverage_axis/): its mesh, its
// samples and candidates, a delta and the known optimum at it, and a row name.
struct ReferenceInstance {
    const char* mesh;
    const char* samples;
    const char* candidates;
    double delta;
    int known;
    const char* name;
};
inline const std::vector<ReferenceInstance>& reference_instances() {
    static const std::vector<ReferenceInstance> refs = {
        {"01Ants-12_mesh.off", "01Ants-12_mesh_samples_2000.obj", "01Ants-12_mesh_VD.txt", 0.02, 58, "Ant-12 d.02 (opt 58)"},
        {"01Ants-12_mesh.off", "01Ants-12_mesh_samples_2000.obj", "01Ants-12_mesh_VD.txt", 0.025, 50, "Ant-12 d.025 (opt 50)"},
        {"01Ants-27.off", "01Ants-27_samples_1500.obj", "01Ants-27_VD.txt", 0.03, 41, "Ant-27 d.03 (opt 41)"},
    };
    return refs;
}

// A reference instance as read: packed samples, candidate centres and radii, and its mesh's
// bounding box (min corner, longest side). read_reference prints the table row of an instance
// whose files are missing.
struct ReferenceData {
    std::vector<double> samples, centers, radii;
    double lo[3] = {1e300, 1e300, 1e300};
    double longest = 0;
};
inline bool read_reference(const std::string& root, const ReferenceInstance& ref, ReferenceData& out) {
    const std::string dir = root + "/reference/coverage_axis/";
    caio::MeshData mesh;
    std::vector<double> unused;
    std::string err;
    if (!caio::read_mesh(dir + ref.mesh, mesh, err) || !caio::read_points(dir + ref.samples, out.samples, unused, err) ||
        !caio::read_points(dir + ref.candidates, out.centers, out.radii, err)) {
        std::printf("| %s | missing: %s |\n", ref.name, err.c_str());
        return false;
    }
    double hi[3] = {-1e300, -1e300, -1e300};
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        out.lo[i % 3] = std::min(out.lo[i % 3], mesh.positions[i]);
        hi[i % 3] = std::max(hi[i % 3], mesh.positions[i]);
    }
    out.longest = std::max({hi[0] - out.lo[0], hi[1] - out.lo[1], hi[2] - out.lo[2]});
    return true;
}

// What run_isolated saw (plain data: it crosses a pipe).
struct Outcome {
    ca_status status = CA_OK;
    double seconds = 0;
    size_t triangles = 0, balls = 0;
    bool read_ok = false;
    char message[240] = {};
    double t_read = 0, t_candidates = 0, t_select = 0, t_connect = 0;   // the run's phases
};

// Reads `path` and runs the pipeline in a child process (fork) with `threads` worker threads (0:
// all cores): its time (read + pipeline) and peak RSS are its own, whatever ran before in this
// process.
inline Outcome run_isolated(const std::string& path, const ca_candidate_options& co, const ca_select_options& so,
                     const ca_connect_options& cop, double& peak_mb, int32_t threads = 0) {
    Outcome o;
    int fd[2];
    peak_mb = 0;
    if (pipe(fd) != 0) return o;
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        const auto t = std::chrono::steady_clock::now();
        caio::MeshData mesh;
        std::string err;
        o.read_ok = caio::read_mesh(path, mesh, err);
        o.t_read = seconds_since(t);
        if (o.read_ok) {
            o.triangles = mesh.triangles.size() / 3;
            PipelineRun r = run_pipeline(mesh, co, so, cop, false, nullptr, nullptr, CA_POINT_NORMALS_TRUSTED, threads);
            o.status = r.status;
            o.balls = r.balls;
            o.t_candidates = r.t_candidates;
            o.t_select = r.t_select;
            o.t_connect = r.t_connect;
            err = r.message;
        }
        o.seconds = seconds_since(t);
        std::snprintf(o.message, sizeof o.message, "%s", err.c_str());
        const ssize_t wrote = write(fd[1], &o, sizeof o);
        _exit(wrote == ssize_t(sizeof o) ? 0 : 1);
    }
    close(fd[1]);
    Outcome got;
    const bool complete = pid > 0 && read(fd[0], &got, sizeof got) == ssize_t(sizeof got);
    close(fd[0]);
    int wstatus = 0;
    rusage u{};
    if (pid > 0) wait4(pid, &wstatus, 0, &u);
    peak_mb = double(u.ru_maxrss) / 1024.0;
    if (!complete) std::snprintf(got.message, sizeof got.message, "the run died (wait status %d)", wstatus);
    return got;
}

}  // namespace bench
