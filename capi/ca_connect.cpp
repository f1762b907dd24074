// ca_connect.cpp: step 3 at the C boundary: edges and triangles between the selected balls, and
// the skeleton's getters. A skeleton copies what it needs: it outlives its set and selection.
#include "conversions.h"
#include "results.h"
#include "struct_size.h"

#include "connect.h"
#include "fit.h"
#include "skeleton.h"

#include <chrono>

using ca::Code;
using ca::Status;
using ca::Vec3;
using namespace capi;

extern "C" {

ca_status ca_connect(ca_context* ctx, const ca_candidate_set* set, const ca_selection* selection,
                     const ca_connect_options* options, ca_skeleton** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        Status st = check_pointers({{out, "out"}, {set, "set"}, {selection, "selection"}});
        if (!st.ok()) return st;
        if (selection->set != set)
            return ca::fail(Code::invalid_argument, "the selection was made from another candidate set");
        ca_connect_options o;
        st = read_input(options, o);
        if (!st.ok()) return st;
        if (o.method != CA_CONNECT_POWER && o.method != CA_CONNECT_MEDIAL && o.method != CA_CONNECT_AUTO)
            return ca::fail(Code::invalid_argument, "unknown connection method " + std::to_string(o.method));
        const ca::Monitor monitor = ctx->monitor();  // one budget for connection and fit
        const auto t0 = std::chrono::steady_clock::now();
        const ca::ConnectOptions co = connect_options(o, set->core, ctx->desc.threads);
        ca::Skeleton sk;
        ca::ConnectReport report;
        st = ca::connect_balls(set->core, selection->core, co, monitor, sk, &report);
        if (!st.ok()) return st;
        if (o.fit < 0 || o.fit > 2)
            return ca::fail(Code::invalid_argument, "fit must be 0, 1 or 2, not " + std::to_string(o.fit));
        if (o.fit_iterations < 0) return ca::fail(Code::invalid_argument, "fit_iterations must be >= 0");
        ca::FitStats fs;
        const std::optional<ca::FitOptions> fo = fit_options(o, set->core, ctx->desc.threads);
        const bool fitted = fo.has_value();
        if (fitted) {
            st = ca::fit_skeleton(set->core, selection->core, *fo, monitor, sk, fs);
            if (!st.ok()) return st;
        }
        const ca::TopologyStats topo = ca::topology(sk);
        capi::Pending<ca_skeleton> res(capi::make_result<ca_skeleton>(ctx));
        ca_skeleton& r = *res.obj;
        const ca::Normalization& n = set->core.surface.norm;
        std::vector<Vec3> c(sk.balls.size());
        for (size_t i = 0; i < c.size(); ++i) c[i] = sk.balls[i].center;
        fill(r.centers, r.allocator, c, n);
        r.radii.assign(r.allocator, c.size());
        for (size_t i = 0; i < c.size(); ++i) r.radii.data[i] = sk.balls[i].radius * n.scale;
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
        s.components = topo.components;
        s.isolated = topo.isolated;
        s.betti1 = topo.betti1;
        s.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        s.method = static_cast<int32_t>(co.method);
        s.fitted = fitted ? 1 : 0;
        s.fit_time_s = fs.time_s;
        s.fit_error_before = 100 * fs.error_before;
        s.fit_error_after = 100 * fs.error_after;
        s.fit_uncovered = fs.uncovered;
        s.genus = report.genus;
        s.thin_handles = report.thin_handles;
        s.surface_balls = report.surface_balls;
        s.medial_balls = sk.balls.size() - report.surface_balls;
        s.open_parts = report.open_parts;
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
