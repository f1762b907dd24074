// test_parallel.cpp: the fork-join helpers of lib/parallel.h: every index is done exactly once,
// an exception on a worker thread reaches the caller (instead of terminating the process), and
// a task run beside the caller gives its result and its exception through wait().
#include <doctest/doctest.h>

#include "parallel.h"

#include <atomic>
#include <stdexcept>
#include <vector>

TEST_CASE("parallel: run_workers calls every worker once and passes on a worker's exception") {
    std::vector<int> calls(5, 0);
    ca::run_workers(5, [&](size_t w) { calls[w]++; });
    CHECK(calls == std::vector<int>(5, 1));
    std::atomic<int> done{0};
    CHECK_THROWS_AS(ca::run_workers(4,
                                    [&](size_t w) {
                                        if (w == 2) throw std::runtime_error("worker 2");
                                        done++;
                                    }),
                    std::runtime_error);
    CHECK(done.load() == 3);  // the others ran to their end before the exception was passed on
    ca::run_workers(0, [&](size_t) { done++; });
    CHECK(done.load() == 3);
}

TEST_CASE("parallel: parallel_for covers every index once and passes on an exception from a worker range") {
    const size_t n = 10000;
    std::vector<int> hit(n, 0);
    CHECK(ca::parallel_for(n, 3, 1024, ca::Monitor{}, "test", [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) hit[i]++;
    }));
    CHECK(hit == std::vector<int>(n, 1));
    // the last item of each batch lies in the last worker's range, never the calling thread's
    CHECK_THROWS_AS(ca::parallel_for(n, 3, 1024, ca::Monitor{}, "test",
                                     [&](size_t b, size_t e) {
                                         if (e % 1024 == 0 && b > e - 1024) throw std::runtime_error("range");
                                     }),
                    std::runtime_error);
}

TEST_CASE("parallel: Beside runs its task and hands over its exception at wait") {
    int value = 0;
    {
        ca::Beside task([&] { value = 42; });
        task.wait();
        CHECK(value == 42);
    }
    ca::Beside failing([] { throw std::runtime_error("beside"); });
    CHECK_THROWS_AS(failing.wait(), std::runtime_error);
    failing.wait();  // the exception is handed over once
}
