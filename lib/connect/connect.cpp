// connect.cpp: the connection step's entry (connect_balls): checks the selection, runs the chosen
// route (power_route.cpp or medial_route.cpp), then the shared repairs (repairs.cpp).
#include "connect.h"

#include "distance.h"
#include "mesh_topology.h"
#include "parallel.h"

#include <algorithm>

namespace ca {

namespace {

// The mesh part nearest each ball's centre (mesh_topology.h numbering).
std::vector<uint32_t> ball_parts(const CandidateSet& set, const MeshTopology& topo, const std::vector<Ball>& balls) {
    const MeshDistance* distance = set.queries.distance.get();
    std::vector<uint32_t> part(balls.size(), 0);
    for (size_t i = 0; i < balls.size(); ++i) {
        uint32_t tri = 0;
        distance->distance(balls[i].center, nullptr, &tri);
        if (tri < topo.triangle_part.size()) part[i] = topo.triangle_part[tri];
    }
    return part;
}

// Qhull could not build the route's diagram (a nearly flat or degenerate set of samples).
bool diagram_failed(const Status& st) { return st.code == Code::geometry_failure || st.code == Code::degenerate_input; }

using namespace detail;

// The route and the repairs on the balls of `sel` (all of them inner or fallback balls).
Status connect_volume(const CandidateSet& set, const Selection& sel, const ConnectOptions& opt, const Monitor& monitor,
                      Skeleton& out, ConnectReport* report) {
    for (uint32_t i : sel.indices) out.balls.push_back(set.balls[i]);
    Status st;
    switch (opt.method) {
        case ConnectMethod::power: st = connect_power(set, sel, monitor, out); break;
        case ConnectMethod::medial: st = detail::connect_medial(set, sel, opt.threads, monitor, out); break;
        default: return fail(Code::invalid_argument, "unknown connection method");
    }
    // A diagram Qhull cannot build does not end the run: the medial route falls back to the power
    // route, and where that fails too the balls are left to the reconnection below.
    ConnectMethod route = opt.method;
    if (diagram_failed(st) && route == ConnectMethod::medial) {
        out.edges.clear(), out.faces.clear();
        st = connect_power(set, sel, monitor, out);
        route = ConnectMethod::power;
        if (report) report->method = route;
    }
    if (diagram_failed(st)) {
        out.edges.clear(), out.faces.clear();
        st = Status::success();
    }
    if (!st.ok()) return st;
    canonicalize(out);
    if (!monitor.report("connect", 0.5)) return monitor.stop_status("connect");
    const bool mesh = set.surface.kind().is_mesh();
    const MeshTopology& shape = set.surface.topology;   // genus -1 for point clouds
    if (report) report->genus = shape.genus;
    if ((opt.remove_outside || opt.fill_holes || opt.reconnect || opt.repair_loops) && out.balls.size() > 1) {
        const InsideTest test(set);
        const double h = (sel.delta > 0 ? sel.delta : 0.02) / 4;
        const int threads = resolve_threads(opt.threads);
        // Envelope rule (medial route only): the accepted bulge is the dilation delta. On the power
        // route it can cut a real loop through thin handles, so there only the centre-line rule
        // applies.
        const double tol = route == ConnectMethod::medial ? (sel.delta > 0 ? sel.delta : 0.02) : -1;
        std::vector<Tri> failed;   // faces that failed the removal test
        const long raw_b1 = route == ConnectMethod::medial && opt.fill_holes ? topology(out).betti1 : 0;
        if (opt.remove_outside && !remove_outside(test, h, tol, route == ConnectMethod::medial, threads, monitor, out, failed)) return monitor.stop_status("connect");
        if (!monitor.report("connect", 0.75)) return monitor.stop_status("connect");
        if (opt.fill_holes) {
            const bool medial = route == ConnectMethod::medial;
            const Skeleton before = medial ? out : Skeleton{};
            // loops of the medial mesh that survived removal (not those that removal added)
            const long target = medial ? std::min(raw_b1, topology(out).betti1) : 0;
            if (!fill_small_holes(test, h, tol, threads, monitor, failed, out)) return monitor.stop_status("connect");
            if (medial) keep_loops(before, target, out);
        }
        if (opt.reconnect) {
            std::vector<uint32_t> parts;
            if (mesh && topology(out).components > 1) parts = ball_parts(set, shape, out.balls);
            reconnect(test, h, tol, out, mesh ? &parts : nullptr);
        }
        canonicalize(out);
        if (opt.repair_loops && shape.genus >= 0) repair_loops(test, h, tol, shape.genus, out);
    }
    if (report && shape.genus >= 0) report->thin_handles = size_t(std::max(0L, shape.genus - topology(out).betti1));
    return Status::success();
}

}  // namespace

ConnectMethod resolve_method(const CandidateSet& set, ConnectMethod method) {
    if (method != ConnectMethod::automatic) return method;
    const bool mesh = set.surface.kind().is_mesh();
    const bool clean_cloud = set.queries.cloud_winding != nullptr && !set.noisy_cloud;
    return mesh || clean_cloud ? ConnectMethod::medial : ConnectMethod::power;
}

Status connect_balls(const CandidateSet& set, const Selection& sel, const ConnectOptions& options,
                     const Monitor& monitor, Skeleton& out, ConnectReport* report) {
    out = Skeleton{};
    if (report) *report = ConnectReport{};
    ConnectOptions opt = options;
    opt.method = resolve_method(set, options.method);
    if (report) report->method = opt.method;
    if (sel.indices.size() != sel.dilated_radii.size()) return fail(Code::internal, "inconsistent selection");
    for (uint32_t i : sel.indices)
        if (i >= set.balls.size()) return fail(Code::invalid_argument, "the selection does not belong to this candidate set");
    if (opt.method == ConnectMethod::medial && !set.surface.kind().is_mesh() && !set.queries.cloud_winding)
        return fail(Code::invalid_argument,
                    "the medial-axis connection needs a triangle mesh or a point cloud's winding number; use the "
                    "power-diagram route for candidate sets from caller arrays");
    if (set.surface_balls > set.balls.size()) return fail(Code::internal, "inconsistent candidate set");
    if (report) report->open_parts = set.surface.topology.open_parts();
    // the selection's surface balls, and the sub-selection of the others
    const size_t first_surface = set.balls.size() - set.surface_balls;
    std::vector<uint8_t> surface_ball(sel.indices.size(), 0);
    Selection inner = sel;
    inner.indices.clear(), inner.dilated_radii.clear();
    std::vector<uint32_t> position;   // of each inner ball in the selection
    for (size_t i = 0; i < sel.indices.size(); ++i) {
        if (sel.indices[i] >= first_surface) {
            surface_ball[i] = 1;
            continue;
        }
        inner.indices.push_back(sel.indices[i]);
        inner.dilated_radii.push_back(sel.dilated_radii[i]);
        position.push_back(uint32_t(i));
    }
    if (inner.indices.size() == sel.indices.size()) {
        const Status st = connect_volume(set, sel, opt, monitor, out, report);
        if (!st.ok()) return st;
    } else {
        Skeleton volume;
        if (!inner.indices.empty()) {
            const Status st = connect_volume(set, inner, opt, monitor, volume, report);
            if (!st.ok()) return st;
        }
        for (uint32_t i : sel.indices) out.balls.push_back(set.balls[i]);
        for (const auto& e : volume.edges) out.edges.push_back({position[e[0]], position[e[1]]});
        for (const Tri& f : volume.faces) out.faces.push_back({position[f[0]], position[f[1]], position[f[2]]});
        canonicalize(out);
        const Status st = connect_sheets(set, surface_ball, resolve_threads(opt.threads), monitor, out);
        if (!st.ok()) return st;
        if (report) report->surface_balls = size_t(std::count(surface_ball.begin(), surface_ball.end(), uint8_t(1)));
    }
    if (!monitor.report("connect", 1)) return monitor.stop_status("connect");
    return Status::success();
}

}  // namespace ca
