// parallel.h: fork-join with std::thread: a fixed set of workers (run_workers), a loop over
// index ranges built on it (parallel_for), and one task run beside the caller (Beside). The
// loop cuts work into batches; between batches the calling thread reports progress (callbacks
// never run on worker threads) and stops early when the monitor says so.
// A thread that cannot be started (std::system_error) leaves its work to the calling thread:
// the results are the same either way.
#pragma once
#include "common.h"

#include <algorithm>
#include <exception>
#include <functional>
#include <system_error>
#include <thread>
#include <vector>

namespace ca {

inline int resolve_threads(int32_t requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw ? int(hw) : 1;
}

// Calls work(w) for every w in [0, workers): w >= 1 on threads of their own, w = 0 on the
// calling thread, then joins them. An exception thrown by a call is passed on (the one of the
// lowest w) after all calls have ended. A thread that cannot be started leaves its w to the
// calling thread.
template <class Work>
void run_workers(size_t workers, Work&& work) {
    std::vector<std::exception_ptr> errors(workers);
    auto guarded = [&](size_t w) {
        try {  // not a handler: carries the exception to the calling thread (rethrown below)
            work(w);
        } catch (...) {
            errors[w] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    size_t started = 1;
    try {
        for (; started < workers; ++started) pool.emplace_back(guarded, started);
    } catch (const std::system_error&) {  // no thread to be had: the calling thread does the rest
    }
    for (size_t w = started; w < workers; ++w) guarded(w);
    if (workers > 0) guarded(0);
    for (auto& t : pool) t.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
}

// Calls body(begin, end) over [0, n) in batches of `batch` items split across `threads`; after
// each batch reports progress from + (to - from) * done / n of `stage`. Returns false if cancelled.
template <class Body>
bool parallel_for(size_t n, int threads, size_t batch, const Monitor& monitor, const char* stage, double from,
                  double to, Body&& body) {
    threads = std::max(1, threads);
    batch = std::max<size_t>(batch, 1);
    for (size_t start = 0; start < n; start += batch) {
        const size_t stop = std::min(n, start + batch);
        const size_t len = stop - start;
        const size_t workers = std::min<size_t>(size_t(threads), len);
        if (workers <= 1) {
            body(start, stop);
        } else {
            const size_t chunk = (len + workers - 1) / workers;
            run_workers(workers, [&](size_t w) {
                const size_t b = start + w * chunk, e = std::min(stop, b + chunk);
                if (b < e) body(b, e);
            });
        }
        if (!monitor.report(stage, from + (to - from) * (double(stop) / double(n)))) return false;
    }
    return true;
}

// The same, reporting the whole of `stage` (0 to 1).
template <class Body>
bool parallel_for(size_t n, int threads, size_t batch, const Monitor& monitor, const char* stage, Body&& body) {
    return parallel_for(n, threads, batch, monitor, stage, 0.0, 1.0, std::forward<Body>(body));
}

// Runs a task on another thread while the caller goes on; wait() joins it and passes on its
// exception. The task must not call the monitor. Without a thread (`on_thread` false, or none
// can be started) it runs in the constructor.
class Beside {
public:
    explicit Beside(std::function<void()> task, bool on_thread = true) : task_(std::move(task)) {
        if (!on_thread) {
            run();
            return;
        }
        try {
            thread_ = std::thread([this] { run(); });
        } catch (const std::system_error&) {  // no thread to be had: the task runs here
            run();
        }
    }
    Beside(const Beside&) = delete;
    Beside& operator=(const Beside&) = delete;
    ~Beside() {
        if (thread_.joinable()) thread_.join();
    }
    void wait() {
        if (thread_.joinable()) thread_.join();
        if (error_) {
            std::exception_ptr e = error_;
            error_ = nullptr;
            std::rethrow_exception(e);
        }
    }

private:
    void run() {
        try {  // not a handler: carries the exception to wait()
            task_();
        } catch (...) {
            error_ = std::current_exception();
        }
    }
    std::function<void()> task_;
    std::exception_ptr error_;
    std::thread thread_;
};

}  // namespace ca
