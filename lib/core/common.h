// common.h: the small vocabulary every pipeline step shares: points, meshes, balls, the
// status a step returns (the core never throws and never prints), and cancellation/progress.
#pragma once
#include "timing.h"
#include "large_pages.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ca {

using Vec3 = Eigen::Vector3d;
using Tri = std::array<uint32_t, 3>;

struct Mesh {
    std::vector<Vec3> vertices;
    std::vector<Tri> triangles;
};

struct Ball {
    Vec3 center;
    double radius = 0;
};

// Numeric values mirror ca_status in include/coverage_axis.h.
enum class Code : int32_t {
    ok = 0,
    invalid_argument = 1,
    null_pointer = 2,
    struct_size = 3,
    invalid_input = 4,      // NaN/Inf, out-of-range index, ...
    degenerate_input = 5,   // empty, zero area, too few distinct points, coplanar
    uncoverable = 6,        // some samples are covered by no candidate ball
    geometry_failure = 7,   // Qhull failed on every fallback
    solver_failure = 8,     // CBC failed
    cancelled = 9,
    out_of_memory = 10,
    buffer_too_small = 11,
    internal = 12,
    no_candidates = 13,
    time_limit = 14,        // the call's time budget ran out
    target_not_reached = 15,  // a search ended above its target; its best result is still returned
};

struct Status {
    Code code = Code::ok;
    std::string message;
    bool ok() const { return code == Code::ok; }
    static Status success() { return {}; }
};
inline Status fail(Code c, std::string msg) { return Status{c, std::move(msg)}; }

// Progress, cancellation, the call's time budget and the caller's log. `report` is called on the
// caller's thread only; it returns false when the work must stop (the caller's progress callback
// asked for it, another thread requested a cancel, or the deadline passed). Steps check it between
// chunks of work; loops that run without reporting call `stopped()` every `kCheckEvery` items,
// which costs an atomic load and a clock read. A step that stopped returns `stop_status(stage)`.
// `note` hands a message to the caller's log (the library never prints), on the caller's thread.
struct Monitor {
    static constexpr size_t kCheckEvery = 4096;
    std::function<bool(const char* stage, double fraction)> progress;  // may be empty
    const std::atomic<int>* cancel_flag = nullptr;                        // may be null
    Deadline deadline;                                                    // the whole call's budget
    // level 0 debug, 1 info, 2 warning; may be empty
    std::function<void(int32_t level, const std::string& message)> log;
    void note(int32_t level, const std::string& message) const {
        if (log) log(level, message);
    }
    bool report(const char* stage, double fraction) const {
        if (stopped()) return false;
        if (progress) return progress(stage, fraction);
        return true;
    }
    bool cancelled() const { return cancel_flag && cancel_flag->load(std::memory_order_relaxed); }
    bool stopped() const { return cancelled() || deadline.expired(); }
    // True every kCheckEvery-th item i when the work must stop (for loops over many items).
    bool stopped_at(size_t i) const { return i % kCheckEvery == 0 && stopped(); }
    // Why a step stopped: the time limit (naming the stage) or a cancel (callback or request).
    Status stop_status(const char* stage) const {
        if (!cancelled() && deadline.expired())
            return fail(Code::time_limit, std::string("time limit reached in ") + stage);
        return fail(Code::cancelled, std::string(stage) + ": cancelled");
    }
};

// Sizes `v` to n copies of `value`, kCheckEvery * 64 items at a time with a stop test before each
// chunk (false when stopped). Filling a fresh allocation touches each of its pages, and the page
// faults of a buffer of tens of megabytes take longer than a cancel may wait (large_pages.h).
template <class T>
bool fill_checked(std::vector<T>& v, size_t n, const T& value, const Monitor& monitor) {
    v.clear();
    reserve_large(v, n);
    while (v.size() < n) {
        if (monitor.stopped()) return false;
        v.resize(std::min(n, v.size() + Monitor::kCheckEvery * 64), value);
    }
    return true;
}

}  // namespace ca
