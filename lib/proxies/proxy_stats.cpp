// proxy_stats.cpp: what the proxies achieve. The errors are those evaluate.h measures for a
// skeleton whose balls are the primitives' balls and whose edges are the capsules (the union of
// spheres and medial cones is exactly the union of the primitives). The volume of the union and of
// its part outside the shape are Monte Carlo estimates: seeded uniform points in the primitives'
// bounding box, in the union when some primitive's signed distance is <= 0, outside the shape
// when the winding-number inside test says so (docs/proxies.md).
#include "proxies.h"

#include "evaluate.h"
#include "parallel.h"
#include "rng.h"
#include "winding.h"

#include <algorithm>
#include <atomic>
#include <limits>

namespace ca {

Status proxy_stats(const Mesh& mesh, const std::vector<Proxy>& proxies, const ShapeQueries& shape,
                   const ProxyOptions& opt, const Monitor& monitor, ProxyStats& out) {
    out = ProxyStats{};
    if (proxies.empty()) return fail(Code::internal, "proxies: no primitive chosen");
    Skeleton sk;
    for (const Proxy& p : proxies) {
        sk.balls.push_back(p.a);
        if (p.kind == ProxyKind::capsule) {
            sk.balls.push_back(p.b);
            sk.edges.push_back({uint32_t(sk.balls.size() - 2), uint32_t(sk.balls.size() - 1)});
        }
    }
    EvaluateOptions eo;
    eo.surface_samples = opt.evaluate_samples;
    eo.envelope_samples = opt.evaluate_samples;
    eo.seed = opt.seed;
    eo.threads = opt.threads;
    EvaluateResult er;
    Status st = evaluate(mesh, sk, eo, monitor, er);
    if (!st.ok()) return st;
    out.hd_surface_to_proxies = er.hd_surface_to_recon;
    out.mean_surface_to_proxies = er.mean_surface_to_recon;
    out.hd_proxies_to_surface = er.hd_recon_to_surface;
    out.mean_proxies_to_surface = er.mean_recon_to_surface;
    out.hd_two_sided = er.hd_two_sided;
    out.diagonal = er.diagonal;
    for (const Proxy& p : proxies) out.outside_bound = std::max(out.outside_bound, outside_bound(p, shape));
    out.outside_bound *= 100 / out.diagonal;

    // ---- Monte Carlo volumes ----
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Ball& b : sk.balls) {
        lo = lo.cwiseMin(b.center - Vec3::Constant(b.radius));
        hi = hi.cwiseMax(b.center + Vec3::Constant(b.radius));
    }
    const size_t n = opt.volume_samples;
    std::vector<Vec3> points(n);
    Rng rng(opt.seed ^ 0x3C6EF372FE94F82Bull);
    for (Vec3& x : points)
        for (int k = 0; k < 3; ++k) x[k] = lo[k] + (hi[k] - lo[k]) * rng.uniform();
    std::vector<uint8_t> where(n, 0);   // 1: in the union, inside the shape; 2: in the union, outside
    if (!parallel_for(n, resolve_threads(opt.threads), 4096, monitor, "proxies", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                bool in = false;
                for (const Proxy& p : proxies)
                    if (proxy_distance(p, points[i]) <= 0) {
                        in = true;
                        break;
                    }
                if (in) where[i] = shape.winding->inside(points[i]) ? 1 : 2;
            }
        }))
        return monitor.stop_status("proxies");
    size_t in_union = 0, outside = 0;
    for (uint8_t w : where) {
        in_union += w != 0;
        outside += w == 2;
    }
    const Vec3 extent = hi - lo;
    const double box = extent.x() * extent.y() * extent.z();
    out.union_volume = box * double(in_union) / double(n);
    out.outside_volume = box * double(outside) / double(n);
    return Status::success();
}

}  // namespace ca
