// common.h: the small vocabulary every pipeline step shares: points, meshes, balls, the
// status a step returns (the core never throws and never prints), cancellation/progress,
// and a portable seeded random generator (same numbers on every platform for a seed).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
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
};

struct Status {
    Code code = Code::ok;
    std::string message;
    bool ok() const { return code == Code::ok; }
    static Status success() { return {}; }
};
inline Status fail(Code c, std::string msg) { return Status{c, std::move(msg)}; }

// Progress and cancellation. `report` is called on the caller's thread only; it returns
// false when the work must stop (the caller's progress callback asked for it, or another
// thread requested a cancel). Steps check it between chunks of work.
struct Monitor {
    std::function<bool(const char* stage, double fraction)> progress;  // may be empty
    const std::atomic<int>* cancel_flag = nullptr;                        // may be null
    bool report(const char* stage, double fraction) const {
        if (cancel_flag && cancel_flag->load(std::memory_order_relaxed)) return false;
        if (progress) return progress(stage, fraction);
        return true;
    }
    bool cancelled() const { return cancel_flag && cancel_flag->load(std::memory_order_relaxed); }
};

// splitmix64-seeded xoshiro256**: fixed algorithm, so a seed gives the same stream everywhere
// (std:: distributions are implementation-defined, so they are not used for results).
class Rng {
public:
    explicit Rng(uint64_t seed) {
        for (auto& s : s_) {
            seed += 0x9E3779B97F4A7C15ull;
            uint64_t z = seed;
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
            s = z ^ (z >> 31);
        }
    }
    uint64_t next() {
        const uint64_t result = rotl(s_[1] * 5, 7) * 9;
        const uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0]; s_[3] ^= s_[1]; s_[1] ^= s_[2]; s_[0] ^= s_[3];
        s_[2] ^= t; s_[3] = rotl(s_[3], 45);
        return result;
    }
    double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }  // [0,1)
    uint64_t below(uint64_t n) { return n ? next() % n : 0; }
private:
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    uint64_t s_[4];
};

}  // namespace ca
