// bench_concurrency.cpp: many jobs in one process against the same jobs in separate processes.
// For each input (the 0 A.D. skeletal elephant, bird_dove, cup and desk_table from the data root,
// and the generated 2 000 000-triangle torus), N copies run at once, at N = 1, 2 and the core
// count: as N threads of this process, each with its own ca_context, and as N forked processes.
// Every job gets max(1, cores / N) worker threads, as `coverage-axis batch -j N` gives them, and
// runs the whole pipeline through the C ABI at the defaults (candidates, the exact cover with its
// LP, connection). A job repeats its input until it has run about a second, so the small inputs
// are timed too. Printed per input and N: the least wall time of three rounds of both, the
// throughput ratio threads / processes (the target is >= 0.8), the minor page faults and
// voluntary context switches of each, and whether every job gave the skeleton the single run
// gave (the same seed). Then the
// exact cover's solver calls alone (Clp's LP, a node-limited CBC search) by N threads at once.
// usage: bench_concurrency [DATA_ROOT] [--only NAME[,NAME...]]   (default ../shared/data; the
// names: the inputs' file stems, torus_2m, solver_lp, solver_cbc)
#include "bench_common.h"
#include "bench_inputs.h"

#include "setcover_internal.h"

#include <atomic>
#include <cmath>
#include <cstring>
#include <thread>

namespace {

// What a job saw (plain data: it crosses a pipe from a child process).
struct JobResult {
    ca_status status = CA_OK;
    size_t balls = 0, edges = 0, faces = 0;
};

// The pipeline once on `mesh` with its own context of `threads` worker threads.
JobResult run_once(const caio::MeshData& mesh, int threads) {
    const bench::DefaultOptions o;
    const bench::PipelineRun p = bench::run_pipeline(mesh, o.candidates, o.select, o.connect, false, nullptr, nullptr,
                                                     CA_POINT_NORMALS_TRUSTED, threads);
    return JobResult{p.status, p.balls, p.edges, p.faces};
}

// `reps` runs; the result of the last, or the first that differs from `want` (a changed skeleton
// shows).
JobResult run_job(const caio::MeshData& mesh, int threads, int reps, const JobResult& want) {
    JobResult last;
    for (int i = 0; i < reps; ++i) {
        last = run_once(mesh, threads);
        if (last.status != want.status || last.balls != want.balls || last.edges != want.edges || last.faces != want.faces)
            return last;
    }
    return last;
}

constexpr int kTries = 3;

struct Round {
    double seconds = 0;
    long minor_faults = 0, voluntary_switches = 0;
    bool same = true;   // every job gave `want`
};

bool same_as(const JobResult& a, const JobResult& b) {
    return a.status == b.status && a.balls == b.balls && a.edges == b.edges && a.faces == b.faces;
}

// N jobs as threads of this process.
Round as_threads(const caio::MeshData& mesh, int n, int threads, int reps, const JobResult& want) {
    std::vector<JobResult> got(static_cast<size_t>(n));
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    const auto t = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int j = 1; j < n; ++j) pool.emplace_back([&, j] { got[size_t(j)] = run_job(mesh, threads, reps, want); });
    got[0] = run_job(mesh, threads, reps, want);
    for (auto& th : pool) th.join();
    Round r;
    r.seconds = bench::seconds_since(t);
    getrusage(RUSAGE_SELF, &after);
    r.minor_faults = after.ru_minflt - before.ru_minflt;
    r.voluntary_switches = after.ru_nvcsw - before.ru_nvcsw;
    for (const JobResult& g : got) r.same = r.same && same_as(g, want);
    return r;
}

// N jobs as forked processes (this process has no other thread when it forks).
Round as_processes(const caio::MeshData& mesh, int n, int threads, int reps, const JobResult& want) {
    Round r;
    std::vector<int> pipes;
    std::vector<pid_t> pids;
    const auto t = std::chrono::steady_clock::now();
    for (int j = 0; j < n; ++j) {
        int fd[2];
        if (pipe(fd) != 0) { r.same = false; break; }
        const pid_t pid = fork();
        if (pid == 0) {
            close(fd[0]);
            const JobResult g = run_job(mesh, threads, reps, want);
            const ssize_t wrote = write(fd[1], &g, sizeof g);
            _exit(wrote == ssize_t(sizeof g) ? 0 : 1);
        }
        close(fd[1]);
        if (pid < 0) { close(fd[0]); r.same = false; break; }
        pipes.push_back(fd[0]);
        pids.push_back(pid);
    }
    for (size_t j = 0; j < pids.size(); ++j) {
        JobResult g;
        const bool complete = read(pipes[j], &g, sizeof g) == ssize_t(sizeof g);
        close(pipes[j]);
        int wstatus = 0;
        rusage u{};
        wait4(pids[j], &wstatus, 0, &u);
        r.minor_faults += u.ru_minflt;
        r.voluntary_switches += u.ru_nvcsw;
        r.same = r.same && complete && same_as(g, want);
    }
    r.seconds = bench::seconds_since(t);
    return r;
}

// A random covering problem: `rows` rows, `cols` columns of `per_col` distinct rows each (fixed
// LCG), every row covered by at least one column.
ca::sc::Problem random_cover(uint32_t rows, uint32_t cols, uint32_t per_col) {
    ca::sc::Problem P;
    P.R = rows;
    P.C = cols;
    uint64_t s = 12345;
    auto next = [&](uint32_t n) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t((s >> 33) % n);
    };
    P.cptr.push_back(0);
    std::vector<uint8_t> hit(rows, 0);
    for (uint32_t c = 0; c < cols; ++c) {
        std::vector<uint32_t> col;
        if (c < rows) col.push_back(c);  // the first `rows` columns cover every row once
        while (col.size() < per_col) {
            const uint32_t r = next(rows);
            if (std::find(col.begin(), col.end(), r) == col.end()) col.push_back(r);
        }
        std::sort(col.begin(), col.end());
        P.crow.insert(P.crow.end(), col.begin(), col.end());
        P.cptr.push_back(uint32_t(P.crow.size()));
    }
    for (uint32_t c = 0; c < cols; ++c) P.col_id.push_back(c);
    for (uint32_t r = 0; r < rows; ++r) P.row_id.push_back(r);
    ca::sc::fill_rows(P);
    return P;
}

// Wall time of `n` threads each calling `solve` once: the least of three tries (other work on the
// machine only ever adds time).
template <class Solve>
double in_threads(int n, Solve&& solve) {
    double least = 1e300;
    for (int attempt = 0; attempt < 3; ++attempt) {
        const auto t = std::chrono::steady_clock::now();
        std::vector<std::thread> pool;
        for (int j = 1; j < n; ++j) pool.emplace_back(solve);
        solve();
        for (auto& th : pool) th.join();
        least = std::min(least, bench::seconds_since(t));
    }
    return least;
}

// The solver calls of the exact cover alone: Clp's LP (lp_duals) and a node-limited CBC search
// (run_cbc) on one random covering problem, by N threads at once. Without a lock between them N
// calls on N cores take as long as one; behind one process-wide lock N times as long.
void solver_calls(const std::vector<int>& ns, const std::string& only) {
    const ca::sc::Problem P = random_cover(500, 1200, 8);
    const std::vector<uint32_t> greedy = ca::sc::greedy_cover(P);
    ca::sc::CbcSettings cs;
    cs.max_nodes = 10;
    cs.heuristics = false;
    cs.lean = true;
    cs.strong_branching = false;
    std::printf("\n## The solver calls alone, N threads at once (a random covering problem, 500 rows x 1200 columns; the least wall time of 3 tries)\n\n");
    std::printf("| call | N | wall s | wall / wall at N = 1 |\n|---|---|---|---|\n");
    double lp1 = 0, cbc1 = 0;
    for (int n : bench::selected(only, "solver_lp") ? ns : std::vector<int>{}) {
        const double lp = in_threads(n, [&] { (void)ca::sc::lp_duals(P, 0); });
        if (n == 1) lp1 = lp;
        std::printf("| Clp LP (lp_duals) | %d | %.3f | %.2f |\n", n, lp, lp / lp1);
    }
    for (int n : bench::selected(only, "solver_cbc") ? ns : std::vector<int>{}) {
        const double cbc = in_threads(n, [&] { (void)ca::sc::run_cbc(P, greedy.size(), cs); });
        if (n == 1) cbc1 = cbc;
        std::printf("| CBC, 10 nodes (run_cbc) | %d | %.3f | %.2f |\n", n, cbc, cbc / cbc1);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows as they come (a pipe would hold them)
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<int> ns = {1, 2, cores};
    std::sort(ns.begin(), ns.end());
    ns.erase(std::unique(ns.begin(), ns.end()), ns.end());

    struct Input { std::string name; caio::MeshData mesh; };
    std::vector<Input> inputs;
    for (const char* rel : {"real/0ad/skeletal_elephant_african_forest.obj", "meshes/paper/bird_dove.obj",
                            "meshes/paper/cup.obj", "meshes/paper/desk_table.obj"}) {
        const std::string path = root + "/" + rel;
        if (!bench::selected(only, bench::stem(path))) continue;
        Input in{bench::stem(path), {}};
        std::string err;
        if (!caio::read_mesh(path, in.mesh, err)) {
            std::printf("bench_concurrency: %s missing (%s), skipped\n", path.c_str(), err.c_str());
            continue;
        }
        inputs.push_back(std::move(in));
    }
    if (bench::selected(only, "torus_2m")) inputs.push_back({"torus_2m", bench::torus(2000, 500)});

    std::printf("\n## N jobs at once: threads of one process against separate processes (%d cores)\n\n", cores);
    std::printf("Each job: the whole pipeline at the defaults through the C ABI with its own context and "
                "max(1, %d / N) worker threads, repeated (reps) to run about a second; the least wall time of %d "
                "rounds. Throughput ratio = processes' wall time / threads' wall time (target >= 0.8).\n\n",
                cores, kTries);
    std::printf("| input | tris | N | threads/job | reps | threads s | processes s | ratio | faults threads | "
                "faults processes | vol. switches threads | vol. switches processes | same skeleton |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    double worst = 1e300;
    for (const Input& in : inputs) {
        // the reference result and the time of one run with every core, for the repetitions
        const auto t = std::chrono::steady_clock::now();
        const JobResult want = run_once(in.mesh, cores);
        const double one = bench::seconds_since(t);
        if (want.status != CA_OK) {
            std::printf("| %s | failed (status %d) |\n", in.name.c_str(), int(want.status));
            continue;
        }
        const int reps = std::max(1, int(std::ceil(1.0 / std::max(one, 1e-3))));
        for (int n : ns) {
            const int threads = std::max(1, cores / n);
            // the least wall time of kTries rounds of each, alternating (other work on the
            // machine only ever adds time); the counts of the last round
            Round th, pr;
            double th_least = 1e300, pr_least = 1e300;
            bool same = true;
            for (int attempt = 0; attempt < kTries; ++attempt) {
                th = as_threads(in.mesh, n, threads, reps, want);
                pr = as_processes(in.mesh, n, threads, reps, want);
                th_least = std::min(th_least, th.seconds);
                pr_least = std::min(pr_least, pr.seconds);
                same = same && th.same && pr.same;
            }
            th.seconds = th_least;
            pr.seconds = pr_least;
            th.same = pr.same = same;
            const double ratio = pr.seconds / th.seconds;
            worst = std::min(worst, ratio);
            std::printf("| %s | %zu | %d | %d | %d | %.3f | %.3f | %.2f | %ld | %ld | %ld | %ld | %s |\n", in.name.c_str(),
                        in.mesh.triangles.size() / 3, n, threads, reps, th.seconds, pr.seconds, ratio, th.minor_faults,
                        pr.minor_faults, th.voluntary_switches, pr.voluntary_switches,
                        th.same && pr.same ? "yes" : "NO");
        }
    }
    if (bench::selected(only, "solver_lp") || bench::selected(only, "solver_cbc")) solver_calls(ns, only);
    if (worst < 1e300)
        std::printf("\nlowest throughput ratio threads / processes: %.2f (target >= 0.8); peak RSS of this process %.0f MB\n",
                    worst, bench::peak_rss_mb());
    return 0;
}
