// rig_step.cpp: the rig as one request: the surface's vertices, the skeleton and the options
// checked, then the curve skeleton (curve_tree), its joints (place_joints) and the vertices' joint
// weights (skin_points).
#include "steps.h"

namespace ca {

Status rig_step(const SurfaceInput& surface, const Skeleton& skeleton, const RigOptions& opt, const Monitor& monitor,
                Rig& out) {
    out = Rig{};
    Status st = check_surface_input(surface);
    if (!st.ok()) return st;
    st = check_points(surface.mesh.vertices);
    if (!st.ok()) return st;
    st = check_skeleton(skeleton);
    if (!st.ok()) return st;
    st = check_options(opt.correspond);
    if (!st.ok()) return st;
    CurveTree tree;
    st = curve_tree(skeleton, opt, tree);
    if (!st.ok()) return st;
    if (monitor.stopped()) return monitor.stop_status("rig");
    place_joints(skeleton, tree, opt, out);
    st = skin_points(surface.mesh.vertices, skeleton, opt, monitor, out);
    if (!st.ok()) out = Rig{};
    return st;
}

}  // namespace ca
