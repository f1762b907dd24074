// selection.cpp: dilation, coverage and the set-cover solve, glued together.
#include "selection.h"

#include <chrono>
#include <cmath>

namespace ca {

double dilate(double radius, const SelectOptions& opt) {
    return opt.dilation == Dilation::offset ? radius + opt.delta : radius * opt.scale;
}

Status select_balls(const CandidateSet& set, const SelectOptions& opt, const Monitor& monitor, Selection& out) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    out = Selection{};
    if (opt.dilation == Dilation::offset && !(std::isfinite(opt.delta) && opt.delta >= 0))
        return fail(Code::invalid_argument, "delta must be a finite number >= 0");
    if (opt.dilation == Dilation::scale && !(std::isfinite(opt.scale) && opt.scale >= 1))
        return fail(Code::invalid_argument, "scale must be a finite number >= 1");
    if (set.balls.empty()) return fail(Code::no_candidates, "the candidate set has no balls");
    if (set.cover_samples.empty()) return fail(Code::degenerate_input, "the candidate set has no surface samples");

    std::vector<Vec3> centers(set.balls.size());
    std::vector<double> radii(set.balls.size()), dilated(set.balls.size());
    for (size_t i = 0; i < set.balls.size(); ++i) {
        centers[i] = set.balls[i].center;
        radii[i] = set.balls[i].radius;
        dilated[i] = dilate(radii[i], opt);
    }
    Coverage cov;
    Status st = build_coverage(set.cover_samples, centers, dilated, monitor, cov);
    if (!st.ok()) return st;
    out.time_coverage_s = std::chrono::duration<double>(Clock::now() - t0).count();

    CoverOptions cover = opt.cover;
    cover.centers = &centers;
    cover.radii = &radii;
    if (!monitor.report("selection", 0)) return fail(Code::cancelled, "cancelled");
    st = solve_set_cover(cov, cover, opt.skip_uncoverable, monitor, out.cover);
    if (!st.ok()) return st;
    if (!monitor.report("selection", 1)) return fail(Code::cancelled, "cancelled");
    out.indices = out.cover.selected;
    for (uint32_t i : out.indices) out.dilated_radii.push_back(dilated[i]);
    out.delta = opt.dilation == Dilation::offset ? opt.delta : 0;
    out.time_total_s = std::chrono::duration<double>(Clock::now() - t0).count();
    return Status::success();
}

}  // namespace ca
