// skeleton_outputs.cpp: the skeleton of a run as the writers and the later library calls take it,
// and its files: .ma (always), .obj, .ply, glTF (with the engine proxies, if any), --colliders (the
// input mesh with the proxies as glTF physics) and the preview picture.
#include "gltf_physics.h"
#include "gltf_writer.h"
#include "run_steps.h"

namespace cli {

ca_skeleton_view skeleton_view(const ca_skeleton* sk) {
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    ca_skeleton_get_view(sk, &view);
    return view;
}

caio::SkeletonData skeleton_data(const ca_skeleton* sk) {
    caio::SkeletonData sd;
    const size_t nv = ca_skeleton_vertex_count(sk);
    sd.centers.assign(ca_skeleton_centers(sk), ca_skeleton_centers(sk) + 3 * nv);
    sd.radii.assign(ca_skeleton_radii(sk), ca_skeleton_radii(sk) + nv);
    sd.edges.assign(ca_skeleton_edges(sk), ca_skeleton_edges(sk) + 2 * ca_skeleton_edge_count(sk));
    sd.faces.assign(ca_skeleton_faces(sk), ca_skeleton_faces(sk) + 3 * ca_skeleton_face_count(sk));
    return sd;
}

bool write_outputs(const caio::MeshData& mesh, const caio::SkeletonData& sd, const std::vector<caio::ProxyData>& proxies,
                   const RunOptions& o, const Outputs& out, Failure& failure) {
    std::string err;
    if (!caio::write_ma(out.ma, sd, err) || (!out.obj.empty() && !caio::write_obj(out.obj, sd, err)) ||
        (!out.ply.empty() && !caio::write_ply(out.ply, sd, err)) ||
        (!out.gltf.empty() && !caio::write_gltf(out.gltf, sd, err, proxies)) ||
        (!out.colliders.empty() && !caio::write_colliders(out.colliders, mesh, proxies, err)) ||
        (!out.preview.empty() && !caio::write_preview(out.preview, mesh, sd, o.preview, err)))
        return failure = file_failure(err), false;
    return true;
}

}  // namespace cli
