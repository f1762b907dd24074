// test_threads.cpp: the thread count the caller asks for is honoured by every step (candidates,
// selection, connection, evaluation): with 1 the process never runs a second worker thread,
// and the results are the same as with all cores. Linux only (threads counted in /proc).
#include <doctest/doctest.h>

#include "candidates.h"
#include "connect.h"
#include "evaluate.h"
#include "selection.h"
#include "support/shapes.h"

#include <atomic>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#ifdef __linux__
namespace {

int threads_now() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8));
    return -1;
}

struct Outcome {
    std::vector<uint32_t> selected;
    size_t edges = 0, faces = 0;
    double hd = 0;
    int most_threads = 0;  // the most threads seen while the steps ran, this test's sampler included
};

// The whole pipeline with `threads` workers on a torus, while a sampler thread watches the
// process's thread count.
Outcome pipeline(int threads) {
    std::atomic<bool> stop{false};
    std::atomic<int> most{0};
    std::thread sampler([&] {
        while (!stop.load()) {
            const int n = threads_now();
            if (n > most.load()) most.store(n);
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
    });
    Outcome out;
    ca::Surface surface;
    const ca::Mesh mesh = shapes::torus(1.0, 0.3, 64, 24);
    REQUIRE(ca::prepare_surface(ca::Mesh(mesh), {}, surface).ok());
    ca::CandidateOptions co;
    co.threads = threads;
    ca::CandidateSet set;
    REQUIRE(ca::generate_candidates(std::move(surface), co, ca::Monitor{}, set).ok());
    ca::SelectOptions so;
    so.threads = threads;
    so.cover.time_limit_s = 0;
    ca::Selection sel;
    REQUIRE(ca::select_balls(set, so, ca::Monitor{}, sel).ok());
    ca::ConnectOptions cop;
    cop.method = ca::ConnectMethod::power;
    cop.threads = threads;
    ca::Skeleton sk;
    REQUIRE(ca::connect_balls(set, sel, cop, ca::Monitor{}, sk).ok());
    ca::EvaluateOptions eo;
    eo.threads = threads;
    eo.surface_samples = 2000;
    eo.envelope_samples = 5000;
    ca::EvaluateResult er;
    REQUIRE(ca::evaluate(set.surface.mesh, sk, eo, ca::Monitor{}, er).ok());
    stop = true;
    sampler.join();
    out.selected = sel.indices;
    out.edges = sk.edges.size();
    out.faces = sk.faces.size();
    out.hd = er.hd_two_sided;
    out.most_threads = most.load();
    return out;
}

}  // namespace

TEST_CASE("threads: one worker thread means no second thread in any step, and the same results") {
    const int before = threads_now();
    REQUIRE(before >= 1);
    const Outcome serial = pipeline(1);
    CHECK(serial.most_threads <= before + 1);  // the test's own sampler only
    const Outcome parallel = pipeline(3);
    CHECK(parallel.most_threads > before + 1);  // the check above can fail: workers are seen
    CHECK(parallel.selected == serial.selected);
    CHECK(parallel.edges == serial.edges);
    CHECK(parallel.faces == serial.faces);
    CHECK(parallel.hd == serial.hd);
}
#endif
