// bench_cancel.cpp: how fast a cancel and a time limit take effect on a large mesh. A generated
// torus of 2 M triangles runs through ca_candidates and ca_select on a worker thread; the main
// thread requests a cancel at several points of the run and measures the time from the request
// to the call's return. Then a context with a time limit measures how far past its budget each
// step returns. The CPU time the process spends from a cancel request to the return (all threads)
// is the work done after the request, which a loaded machine does not inflate. Prints the stages of the uncancelled run (when each first reported progress,
// and the longest gap between two progress calls) and the worst latency. usage: bench_cancel [MAJOR MINOR] (2 * MAJOR * MINOR
// triangles; default 2000 500)
#include "bench_common.h"
#include "support/shapes.h"

#include <atomic>
#include <string>
#include <thread>

namespace {

// The progress calls of one run: when each stage first reported, and the longest gap between
// two calls (a cancel request is seen at the latest at the next call).
struct StageLog {
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now(), last = t0;
    std::string stage, gap_from, gap_to;
    double gap = 0;
    static int32_t record(void* user, const char* stage, double) {
        StageLog& l = *static_cast<StageLog*>(user);
        const auto now = std::chrono::steady_clock::now();
        const double since_last = std::chrono::duration<double>(now - l.last).count();
        if (since_last > l.gap) l.gap = since_last, l.gap_from = l.stage, l.gap_to = stage;
        if (l.stage != stage) std::printf("| %s | %.3f |\n", stage, std::chrono::duration<double>(now - l.t0).count());
        l.stage = stage;
        l.last = now;
        return 0;
    }
};


struct Run {
    ca_status status = CA_OK;
    double seconds = 0;
};

// ca_candidates then ca_select on `ctx`, timed from the start.
Run pipeline(ca_context* ctx, const ca_surface_view& v, std::atomic<bool>& finished) {
    Run r;
    const auto t0 = std::chrono::steady_clock::now();
    ca_candidate_set* set = nullptr;
    r.status = ca_candidates(ctx, &v, nullptr, &set);
    if (r.status == CA_OK) {
        ca_selection* sel = nullptr;
        r.status = ca_select(ctx, set, nullptr, &sel);
        ca_selection_destroy(sel);
    }
    ca_candidate_set_destroy(set);
    r.seconds = bench::seconds_since(t0);
    finished = true;
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    const int major = argc > 2 ? std::atoi(argv[1]) : 2000, minor = argc > 2 ? std::atoi(argv[2]) : 500;
    const ca::Mesh m = shapes::torus(1.0, 0.3, major, minor);
    std::vector<double> pos;
    for (const ca::Vec3& p : m.vertices) pos.insert(pos.end(), {p.x(), p.y(), p.z()});
    ca_surface_view v;
    ca_surface_view_init(&v);
    v.positions = pos.data();
    v.vertex_count = m.vertices.size();
    v.triangles = &m.triangles[0][0];
    v.triangle_count = m.triangles.size();
    std::printf("\n## Cancel and time-limit latency (torus, %zu triangles)\n\n", m.triangles.size());

    std::atomic<bool> finished{false};
    {
        StageLog log;
        ca_context_desc d;
        ca_context_desc_init(&d);
        d.progress = StageLog::record;
        d.progress_user = &log;
        ca_context* c = nullptr;
        if (ca_context_create(&d, &c) != CA_OK) return 1;
        std::printf("| stage | first progress call at s |\n|---|---|\n");
        pipeline(c, v, finished);
        std::printf("\nlongest gap between progress calls: %.3f s (from %s to %s)\n\n", log.gap, log.gap_from.c_str(),
                    log.gap_to.c_str());
        ca_context_destroy(c);
    }
    ca_context* ctx = nullptr;
    if (ca_context_create(nullptr, &ctx) != CA_OK) return 1;
    const Run full = pipeline(ctx, v, finished);
    std::printf("uncancelled ca_candidates + ca_select: %.2f s (status %d)\n\n", full.seconds, int(full.status));
    std::printf("%s\n\n", bench::kCpuClock);
    std::printf("| cancel at s | returned after s | latency s | CPU s after the request | status |\n|---|---|---|---|---|\n");
    double worst = 0, worst_cpu = 0;
    // requests every 4 % of the uncancelled run, so that no stage of more than about 0.1 s is missed
    for (int step = 0; step < 25; ++step) {
        const double at = (0.02 + 0.04 * step) * full.seconds;
        ca_context_clear_cancel(ctx);
        finished = false;
        Run r;
        std::thread worker([&] { r = pipeline(ctx, v, finished); });
        const auto t0 = std::chrono::steady_clock::now();
        while (!finished && bench::seconds_since(t0) < at) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        const double requested = bench::seconds_since(t0), cpu_at_request = bench::cpu_seconds();
        ca_context_request_cancel(ctx);
        worker.join();
        const double latency = r.seconds - requested, cpu_after = bench::cpu_seconds() - cpu_at_request;
        if (r.status == CA_ERROR_CANCELLED) worst = std::max(worst, latency), worst_cpu = std::max(worst_cpu, cpu_after);
        std::printf("| %.2f | %.2f | %.3f | %.3f | %s |\n", requested, r.seconds, latency, cpu_after,
                    ca_status_string(r.status));
    }
    ca_context_destroy(ctx);
    std::printf("\nworst cancel latency: %.3f s (CPU after the request: %.3f s)\n\n", worst, worst_cpu);

    std::printf("| time limit s | returned after s | overrun s | status |\n|---|---|---|---|\n");
    for (double limit : {0.5, 2.0, 5.0}) {
        ca_context_desc d;
        ca_context_desc_init(&d);
        d.time_limit_s = limit;
        ca_context* c = nullptr;
        if (ca_context_create(&d, &c) != CA_OK) return 1;
        const auto t0 = std::chrono::steady_clock::now();
        ca_candidate_set* set = nullptr;
        const ca_status st = ca_candidates(c, &v, nullptr, &set);
        const double s = bench::seconds_since(t0);
        std::printf("| %.1f | %.2f | %.3f | %s |\n", limit, s, s - limit, ca_status_string(st));
        ca_candidate_set_destroy(set);
        ca_context_destroy(c);
    }
    return 0;
}
