// connect_step.cpp: step 3 as one request: the selection connected on the route the request
// names (automatic: resolve_method's choice), then fitted when the request asks (automatic: a
// selection sized by target_count, thoroughly, or one a target_error search judged fitted, once)
// and the set has a triangle mesh to fit to. The covered fit connects again (fit_covered), the
// selection grown by the balls that repair the cover.
#include "steps.h"

namespace ca {

std::optional<FitOptions> fit_options(const ConnectRequest& request, const CandidateSet& set, const Selection* selection) {
    const bool mesh = set.surface.kind().is_mesh();
    FitMode mode = request.fit;
    if (mode == FitMode::automatic)
        mode = !selection                     ? FitMode::off
               : selection->sized_by_count    ? FitMode::thorough
               : selection->judged_fitted     ? FitMode::once
                                              : FitMode::off;
    if (mode == FitMode::off || !mesh || request.fit_iterations <= 0) return std::nullopt;
    FitOptions fo;
    fo.iterations = uint32_t(request.fit_iterations);
    fo.thorough = mode == FitMode::thorough;
    fo.keep_cover = mode == FitMode::covered;
    fo.threads = request.connect.threads;
    return fo;
}

Status connect_step(const CandidateSet& set, const Selection& selection, const ConnectRequest& request,
                    const Monitor& monitor, ConnectResult& out) {
    out = ConnectResult{};
    const ConnectMethod method = request.connect.method;
    if (method != ConnectMethod::power && method != ConnectMethod::medial && method != ConnectMethod::automatic)
        return fail(Code::invalid_argument, "unknown connection method " + std::to_string(int32_t(method)));
    if (request.fit != FitMode::automatic && request.fit != FitMode::off && request.fit != FitMode::once &&
        request.fit != FitMode::thorough && request.fit != FitMode::covered)
        return fail(Code::invalid_argument, "fit must be -1 (auto), 0, 1, 2 or 3, not " + std::to_string(int32_t(request.fit)));
    if (request.fit_iterations < 0) return fail(Code::invalid_argument, "fit_iterations must be >= 0");
    const auto t0 = Clock::now();
    Status st = connect_balls(set, selection, request.connect, monitor, out.skeleton, &out.report);
    if (!st.ok()) return st;
    const std::optional<FitOptions> fo = fit_options(request, set, &selection);
    if (fo) {
        st = fo->keep_cover ? fit_covered(set, selection, *fo, request.connect, monitor, out.skeleton, out.fit, &out.report)
                            : fit_skeleton(set, selection, *fo, monitor, out.skeleton, out.fit);
        if (!st.ok()) return st;
        out.fitted = true;
    }
    out.topology = topology(out.skeleton);
    out.time_s = seconds_since(t0);
    return Status::success();
}

}  // namespace ca
