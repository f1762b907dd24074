// ca_connect.cpp: step 3 at the C boundary: the options converted for the core's step
// (lib/steps/connect_step.cpp), the skeleton's arrays and stats in the caller's units, and its
// getters. A skeleton copies what it needs: it outlives its set and selection.
#include "conversions.h"
#include "results.h"

using ca::Status;
using ca::Vec3;
using namespace capi;

namespace {

// The skeleton's arrays and stats in the caller's units.
void publish(ca_skeleton& r, const ca::ConnectResult& c, const ca::Normalization& n) {
    const ca::Skeleton& sk = c.skeleton;
    std::vector<Vec3> centers(sk.balls.size());
    for (size_t i = 0; i < centers.size(); ++i) centers[i] = sk.balls[i].center;
    fill(r.centers, r.allocator, centers, n);
    r.radii.assign(r.allocator, centers.size());
    for (size_t i = 0; i < centers.size(); ++i) r.radii.data[i] = sk.balls[i].radius * n.scale;
    r.edges.assign(r.allocator, 2 * sk.edges.size());
    for (size_t i = 0; i < sk.edges.size(); ++i) { r.edges.data[2 * i] = sk.edges[i][0]; r.edges.data[2 * i + 1] = sk.edges[i][1]; }
    r.faces.assign(r.allocator, 3 * sk.faces.size());
    for (size_t i = 0; i < sk.faces.size(); ++i)
        for (int k = 0; k < 3; ++k) r.faces.data[3 * i + size_t(k)] = sk.faces[i][size_t(k)];
    ca_skeleton_stats& s = r.stats;
    s.struct_size = sizeof s;
    s.vertices = sk.balls.size();
    s.edges = sk.edges.size();
    s.faces = sk.faces.size();
    s.components = c.topology.components;
    s.isolated = c.topology.isolated;
    s.betti1 = c.topology.betti1;
    s.time_s = c.time_s;
    s.method = static_cast<int32_t>(c.report.method);
    s.fitted = c.fitted ? 1 : 0;
    s.fit_time_s = c.fit.time_s;
    s.fit_error_before = 100 * c.fit.error_before;
    s.fit_error_after = 100 * c.fit.error_after;
    s.fit_uncovered = c.fit.uncovered;
    s.genus = c.report.genus;
    s.thin_handles = c.report.thin_handles;
    s.surface_balls = c.report.surface_balls;
    s.medial_balls = sk.balls.size() - c.report.surface_balls;
    s.open_parts = c.report.open_parts;
}

}  // namespace

extern "C" {

ca_status ca_connect(ca_context* ctx, const ca_candidate_set* set, const ca_selection* selection,
                     const ca_connect_options* options, ca_skeleton** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        ca_connect_options o;
        Status st = read_arguments({{out, "out"}, {set, "set"}, {selection, "selection"}}, options, o);
        if (!st.ok()) return st;
        if (selection->set != set)
            return ca::fail(ca::Code::invalid_argument, "the selection was made from another candidate set");
        ca::ConnectResult result;
        st = ca::connect_step(set->core, selection->core, to_core(o, ctx->desc.threads), ctx->monitor(), result);
        if (!st.ok()) return st;
        capi::Pending<ca_skeleton> res(capi::make_result<ca_skeleton>(ctx));
        publish(*res.obj, result, set->core.surface.norm);
        *out = res.release();
        return Status::success();
    });
}

void ca_skeleton_destroy(ca_skeleton* s) { destroy_result(s); }
size_t ca_skeleton_vertex_count(const ca_skeleton* s) { return s ? s->radii.size : 0; }
const double* ca_skeleton_centers(const ca_skeleton* s) { return s ? s->centers.data : nullptr; }
const double* ca_skeleton_radii(const ca_skeleton* s) { return s ? s->radii.data : nullptr; }
size_t ca_skeleton_edge_count(const ca_skeleton* s) { return s ? s->edges.size / 2 : 0; }
const uint32_t* ca_skeleton_edges(const ca_skeleton* s) { return s ? s->edges.data : nullptr; }
size_t ca_skeleton_face_count(const ca_skeleton* s) { return s ? s->faces.size / 3 : 0; }
const uint32_t* ca_skeleton_faces(const ca_skeleton* s) { return s ? s->faces.data : nullptr; }

ca_status ca_skeleton_stats_get(const ca_skeleton* sk, ca_skeleton_stats* stats) {
    if (!sk || !stats) return CA_ERROR_NULL_POINTER;
    return guarded_status([&] { return write_output(sk->stats, stats); });
}

ca_status ca_skeleton_get_view(const ca_skeleton* sk, ca_skeleton_view* v) {
    if (!sk || !v) return CA_ERROR_NULL_POINTER;
    ca_skeleton_view view = defaults<ca_skeleton_view>();
    view.centers = sk->centers.data;
    view.radii = sk->radii.data;
    view.vertex_count = sk->radii.size;
    view.edges = sk->edges.data;
    view.edge_count = sk->edges.size / 2;
    view.faces = sk->faces.data;
    view.face_count = sk->faces.size / 3;
    return guarded_status([&] { return write_output(view, v); });
}

}  // extern "C"
