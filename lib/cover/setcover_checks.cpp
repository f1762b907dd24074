// setcover_checks.cpp: the set cover's front part (setcover_internal.h, prepare): the coverage lists
// checked, the masks applied, and the samples no allowed ball covers found.
#include "setcover_internal.h"

#include <algorithm>
#include <string>

namespace ca {
namespace sc {

namespace {

std::string uncoverable_message(const std::vector<uint32_t>& unc, size_t m) {
    std::string msg = std::to_string(unc.size()) + " of " + std::to_string(m) +
                      " samples are covered by no candidate ball (first: ";
    for (size_t i = 0; i < unc.size() && i < 10; ++i) {
        if (i) msg += ", ";
        msg += std::to_string(unc[i]);
    }
    if (unc.size() > 10) msg += ", ...";
    msg += ")";
    return msg;
}

// Ascending (strictly) list check, branch-free over the list.
bool strictly_ascending(const uint32_t* l, uint32_t len) {
    uint32_t bad = 0;
    for (uint32_t k = 1; k < len; ++k) bad |= uint32_t(l[k] <= l[k - 1]);
    return bad == 0;
}

// Checks the ball -> sample lists; `count[j]` gets the number of balls covering sample j.
Status check_coverage(const Coverage& cov, std::vector<uint32_t>& count) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (m >= UINT32_MAX || n >= UINT32_MAX) return fail(Code::invalid_input, "set cover: too many samples or balls");
    if (cov.ball_ptr.size() != n + 1 || cov.ball_ptr[0] != 0 || cov.ball_ptr[n] != cov.ball_samples.size())
        return fail(Code::invalid_input, "set cover: malformed coverage (ball_ptr)");
    for (size_t a = 0; a < n; ++a) {
        const uint32_t b = cov.ball_ptr[a], e = cov.ball_ptr[a + 1];
        if (e < b) return fail(Code::invalid_input, "set cover: malformed coverage (ball_ptr)");
        if (!strictly_ascending(cov.ball_samples.data() + b, e - b))
            return fail(Code::invalid_input, "set cover: ball sample list not strictly ascending");
        if (e > b && cov.ball_samples[e - 1] >= m) return fail(Code::invalid_input, "set cover: sample index out of range");
    }
    count.assign(m, 0);
    for (uint32_t j : cov.ball_samples) count[j]++;
    return Status::success();
}

// Cheap check that cov's sample -> ball direction can be trusted: right sizes, per-sample
// counts match the ball -> sample direction (`count`), lists ascending and in range.
bool transpose_consistent(const Coverage& cov, const std::vector<uint32_t>& count) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    if (cov.sample_ptr.size() != m + 1 || cov.sample_ptr[0] != 0 || cov.sample_ptr[m] != cov.ball_samples.size() ||
        cov.sample_balls.size() != cov.ball_samples.size())
        return false;
    for (size_t j = 0; j < m; ++j) {
        const uint32_t b = cov.sample_ptr[j], e = cov.sample_ptr[j + 1];
        if (e < b || e - b != count[j] || !strictly_ascending(cov.sample_balls.data() + b, e - b)) return false;
        if (e > b && cov.sample_balls[e - 1] >= n) return false;
    }
    return true;
}

}  // namespace

Status prepare(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, Prepared& pr) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    std::vector<uint32_t> count;
    Status st = check_coverage(cov, count);
    if (!st.ok()) return st;
    pr.transpose_ok = transpose_consistent(cov, count);
    if (!opt.ignorable_samples.empty() && opt.ignorable_samples.size() != m)
        return fail(Code::invalid_argument, "set cover: ignorable_samples must have 0 or n_samples entries");
    if (!opt.forced_in.empty() && opt.forced_in.size() != n)
        return fail(Code::invalid_argument, "set cover: forced_in must have 0 or n_balls entries");
    if (!opt.forced_out.empty() && opt.forced_out.size() != n)
        return fail(Code::invalid_argument, "set cover: forced_out must have 0 or n_balls entries");
    pr.required.assign(m, 1);
    pr.allowed.assign(n, 1);
    pr.locked.assign(n, 0);
    for (size_t j = 0; j < opt.ignorable_samples.size(); ++j)
        if (opt.ignorable_samples[j]) pr.required[j] = 0;
    for (size_t a = 0; a < opt.forced_out.size(); ++a)
        if (opt.forced_out[a]) pr.allowed[a] = 0;
    for (size_t a = 0; a < opt.forced_in.size(); ++a)
        if (opt.forced_in[a]) {
            if (!pr.allowed[a]) return fail(Code::invalid_argument, "set cover: a ball is both forced in and forced out");
            pr.locked[a] = 1;
        }
    // count[j] becomes the number of allowed balls covering j
    for (size_t a = 0; a < n; ++a)
        if (!pr.allowed[a])
            for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k) count[cov.ball_samples[k]]--;
    for (uint32_t j = 0; j < m; ++j)
        if (pr.required[j] && count[j] == 0) pr.uncovered.push_back(j);
    if (!pr.uncovered.empty()) {
        if (!skip_uncoverable) return fail(Code::uncoverable, uncoverable_message(pr.uncovered, m));
        for (uint32_t j : pr.uncovered) pr.required[j] = 0;
    }
    for (uint8_t v : pr.required) pr.rows_before += v;
    for (uint8_t v : pr.allowed) pr.cols_before += v;
    return Status::success();
}

}  // namespace sc
}  // namespace ca
