// correspondence_step.cpp: the correspondence as one request: the surface's vertices and the
// caller's skeleton checked, then every vertex's nearest primitive and ball weights
// (correspondence.h).
#include "steps.h"

namespace ca {

Status correspondence_step(const SurfaceInput& surface, const Skeleton& skeleton, const CorrespondOptions& opt,
                           const Monitor& monitor, Correspondence& out) {
    out = Correspondence{};
    Status st = check_surface_input(surface);
    if (!st.ok()) return st;
    return correspond(surface.mesh.vertices, skeleton, opt, monitor, out);
}

}  // namespace ca
