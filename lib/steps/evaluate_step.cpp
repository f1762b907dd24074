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

    st = check_skeleton(skeleton);
    if (!st.ok()) return st;
    const Normalization& n = surf.norm;
    Skeleton sk;
    for (const Ball& b : skeleton.balls) sk.balls.push_back({n.to_internal(b.center), b.radius / n.scale});
    sk.edges = skeleton.edges;
    sk.faces = skeleton.faces;
    st = evaluate(surf.mesh, sk, opt, monitor, out);
    if (!st.ok()) return st;
    out.diagonal *= n.scale;
    return Status::success();
}

}  // namespace ca
