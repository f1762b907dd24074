// evaluate_step.cpp: the evaluation as one request: the caller's surface prepared (normals are not
// needed: distances only), the caller's skeleton checked and brought to the surface's internal
// units, and the distances measured (evaluate.h).
#include "steps.h"

#include <algorithm>
#include <cmath>

namespace ca {

Status evaluate_step(SurfaceInput surface, const Skeleton& skeleton, const EvaluateOptions& opt,
                     const Monitor& monitor, EvaluateResult& out) {
    out = EvaluateResult{};
    Status st = check_surface_input(surface);
    if (!st.ok()) return st;
    if (opt.surface_samples == 0 || opt.envelope_samples == 0)
        return fail(Code::invalid_argument, "surface_samples and envelope_samples must be at least 1");
    Surface surf;
    st = prepare_surface(std::move(surface.mesh), {}, surf, false);
    if (!st.ok()) return st;
    if (monitor.stopped()) return monitor.stop_status("surface");

    const size_t nv = skeleton.balls.size();
    if (nv == 0) return fail(Code::degenerate_input, "the skeleton has no vertices");
    const Normalization& n = surf.norm;
    Skeleton sk;
    for (size_t i = 0; i < nv; ++i) {
        const Ball& b = skeleton.balls[i];
        if (!b.center.allFinite() || !(std::isfinite(b.radius) && b.radius >= 0))
            return fail(Code::invalid_input, "skeleton ball " + std::to_string(i) + " has a NaN, infinite or negative value");
        sk.balls.push_back({n.to_internal(b.center), b.radius / n.scale});
    }
    for (size_t e = 0; e < skeleton.edges.size(); ++e) {
        const auto& edge = skeleton.edges[e];
        if (edge[0] >= nv || edge[1] >= nv)
            return fail(Code::invalid_input, "skeleton edge " + std::to_string(e) + " references vertex " +
                                                 std::to_string(std::max(edge[0], edge[1])) + " of " + std::to_string(nv));
    }
    for (size_t f = 0; f < skeleton.faces.size(); ++f)
        for (uint32_t v : skeleton.faces[f])
            if (v >= nv)
                return fail(Code::invalid_input, "skeleton face " + std::to_string(f) + " references vertex " +
                                                     std::to_string(v) + " of " + std::to_string(nv));
    sk.edges = skeleton.edges;
    sk.faces = skeleton.faces;
    st = evaluate(surf.mesh, sk, opt, monitor, out);
    if (!st.ok()) return st;
    out.diagonal *= n.scale;
    return Status::success();
}

}  // namespace ca
