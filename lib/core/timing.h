// timing.h: wall-clock time for the steps: seconds since a time point, and a Deadline (a time
// budget, possibly unlimited) that the steps test and share out. Steady clock, so changes of
// the system time do not move a deadline.
#pragma once
#include <chrono>
#include <cmath>
#include <limits>

namespace ca {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A point in time after which work stops, or none (unlimited, the default).
class Deadline {
public:
    Deadline() = default;
    // `seconds` after `start`; a budget that is not finite and positive is unlimited.
    static Deadline after(double seconds, Clock::time_point start = Clock::now()) {
        Deadline d;
        if (seconds > 0 && std::isfinite(seconds)) {
            d.limited_ = true;
            d.at_ = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
        }
        return d;
    }
    bool limited() const { return limited_; }
    bool expired() const { return limited_ && Clock::now() > at_; }
    // Seconds left (<= 0 once expired); +infinity when unlimited.
    double remaining() const {
        return limited_ ? std::chrono::duration<double>(at_ - Clock::now()).count()
                        : std::numeric_limits<double>::infinity();
    }
    // The remaining time as a time limit in the "0 = none" convention of the solvers' options.
    double limit_s() const { return limited_ ? remaining() : 0.0; }
    // A deadline `share` of the remaining time from now (unlimited stays unlimited).
    Deadline share(double share) const {
        if (!limited_) return *this;
        Deadline d = *this;
        const Clock::time_point now = Clock::now();
        d.at_ = now + std::chrono::duration_cast<Clock::duration>((at_ - now) * share);
        return d;
    }

    // The earlier of this deadline and `other`.
    Deadline earliest(const Deadline& other) const {
        if (!other.limited_) return *this;
        if (!limited_ || other.at_ < at_) return other;
        return *this;
    }

private:
    bool limited_ = false;
    Clock::time_point at_ = Clock::time_point::max();
};

}  // namespace ca
