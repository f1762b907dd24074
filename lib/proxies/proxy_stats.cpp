// proxy_stats.cpp: what the proxies achieve. The errors are those evaluate.h measures for a
// skeleton whose balls are the primitives' balls and whose edges are the capsules (the union of
// spheres and medial cones is exactly the union of the primitives); with boxes, which evaluate.h
// does not know, the same measures on samples of the union's boundary taken here. The volume of the union and of
// its part outside the shape are Monte Carlo estimates: seeded uniform points in the primitives'
// bounding box, in the union when some primitive's signed distance is <= 0, outside the shape
// when the winding-number inside test says so (docs/proxies.md).
#include "proxies.h"

#include "distance.h"
#include "evaluate.h"
#include "kdtree.h"
#include "parallel.h"
#include "rng.h"
#include "sampling.h"
#include "winding.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

namespace ca {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A point of p's boundary: from an inner point (a box's or sphere's centre, a point of a capsule's
// segment) along `dir` to where the signed distance is 0 (the primitive is convex, so the ray
// leaves it once), by bisection.
Vec3 boundary_point(const Proxy& p, const Vec3& from, const Vec3& dir) {
    double lo = 0, hi = 2 * ((p.b.center - p.a.center).norm() + std::max(p.a.radius, p.b.radius) + p.half.norm()) + 1e-12;
    for (int it = 0; it < 60; ++it) {
        const double m = 0.5 * (lo + hi);
        (proxy_distance(p, from + m * dir) <= 0 ? lo : hi) = m;
    }
    return from + 0.5 * (lo + hi) * dir;
}

// What evaluate.h measures, for primitives it does not know (boxes): samples of the union's
// boundary (each primitive's boundary in proportion to its area, kept where no other primitive
// holds them), the surface samples' distances to the union (outside: the exact signed distance;
// inside: the nearest boundary sample) and the boundary samples' distances to the surface.
Status union_hausdorff(const Mesh& mesh, const std::vector<Proxy>& proxies, const ProxyOptions& opt, const Monitor& monitor,
                       ProxyStats& out) {
    Vec3 lo = mesh.vertices.front(), hi = lo;
    for (const Vec3& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double diag = (hi - lo).norm(), tol = 1e-9 * diag;
    std::vector<double> area;
    for (const Proxy& p : proxies) {
        if (p.kind == ProxyKind::box) area.push_back(8 * (p.half.x() * p.half.y() + p.half.y() * p.half.z() + p.half.z() * p.half.x()));
        else {
            const double r = std::max(p.a.radius, p.b.radius);
            area.push_back(4 * kPi * r * r + kPi * (p.a.radius + p.b.radius) * (p.b.center - p.a.center).norm());
        }
    }
    const double total = std::max(std::accumulate(area.begin(), area.end(), 0.0), 1e-300);
    Rng rng(opt.seed ^ 0x6A09E667F3BCC909ull);
    std::vector<Vec3> boundary;
    for (size_t j = 0; j < proxies.size(); ++j) {
        const Proxy& p = proxies[j];
        const size_t n = std::max<size_t>(16, size_t(double(opt.evaluate_samples) * area[j] / total));
        for (size_t i = 0; i < n; ++i) {
            Vec3 x;
            if (p.kind == ProxyKind::box) {
                // a face in proportion to its area, a uniform point on it
                const double fa[3] = {p.half.y() * p.half.z(), p.half.z() * p.half.x(), p.half.x() * p.half.y()};
                double pick = rng.uniform() * (fa[0] + fa[1] + fa[2]);
                int a = 0;
                while (a < 2 && pick > fa[a]) pick -= fa[a++];
                Vec3 q;
                for (int k = 0; k < 3; ++k) q[k] = (2 * rng.uniform() - 1) * p.half[k];
                q[a] = (rng.uniform() < 0.5 ? -1 : 1) * p.half[a];
                x = p.a.center + p.axes * q;
            } else {
                const double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform(), rho = std::sqrt(std::max(0.0, 1 - z * z));
                const Vec3 dir(rho * std::cos(phi), rho * std::sin(phi), z);
                const Vec3 from = p.a.center + rng.uniform() * (p.b.center - p.a.center);
                x = boundary_point(p, from, dir);
            }
            bool held = false;
            for (size_t k = 0; k < proxies.size() && !held; ++k) held = k != j && proxy_distance(proxies[k], x) < -tol;
            if (!held) boundary.push_back(x);
        }
    }
    if (boundary.empty())
        for (const Proxy& p : proxies) boundary.push_back(p.a.center);
    std::vector<Vec3> samples = sample_surface(mesh, opt.evaluate_samples, opt.seed ^ 0xBB67AE8584CAA73Bull);
    samples.insert(samples.end(), mesh.vertices.begin(), mesh.vertices.end());
    const PointTree nearest(boundary);
    std::vector<double> d_se(samples.size()), d_es(boundary.size());
    const int threads = resolve_threads(opt.threads);
    if (!parallel_for(samples.size(), threads, 4096, monitor, "proxies", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                double f = std::numeric_limits<double>::infinity();
                for (const Proxy& p : proxies) f = std::min(f, proxy_distance(p, samples[i]));
                d_se[i] = f > -tol ? std::max(f, 0.0) : nearest.distance(samples[i]);
            }
        }))
        return monitor.stop_status("proxies");
    const MeshDistance md(mesh);
    if (!parallel_for(boundary.size(), threads, 4096, monitor, "proxies", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) d_es[i] = md.distance(boundary[i]);
        }))
        return monitor.stop_status("proxies");
    auto max_mean = [&](const std::vector<double>& d, double& mx, double& mean) {
        mx = 0;
        double sum = 0;
        for (double x : d) {
            mx = std::max(mx, x);
            sum += x;
        }
        mx *= 100 / diag;
        mean = d.empty() ? 0 : 100 * sum / double(d.size()) / diag;
    };
    max_mean(d_se, out.hd_surface_to_proxies, out.mean_surface_to_proxies);
    max_mean(d_es, out.hd_proxies_to_surface, out.mean_proxies_to_surface);
    out.hd_two_sided = std::max(out.hd_surface_to_proxies, out.hd_proxies_to_surface);
    out.diagonal = diag;
    return Status::success();
}

}  // namespace

bool union_volumes(const std::vector<Proxy>& proxies, const ShapeQueries& shape, size_t samples, uint64_t seed,
                   int threads, const Monitor& monitor, const char* stage, double& union_volume,
                   double& outside_volume) {
    union_volume = outside_volume = 0;
    if (proxies.empty() || samples == 0) return true;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Proxy& p : proxies) {
        const auto box = proxy_box(p);
        lo = lo.cwiseMin(box.first);
        hi = hi.cwiseMax(box.second);
    }
    const size_t n = samples;
    std::vector<Vec3> points(n);
    Rng rng(seed);
    for (Vec3& x : points)
        for (int k = 0; k < 3; ++k) x[k] = lo[k] + (hi[k] - lo[k]) * rng.uniform();
    std::vector<uint8_t> where(n, 0);   // 1: in the union, inside the shape; 2: in the union, outside
    if (!parallel_for(n, threads, 4096, monitor, stage, [&](size_t b, size_t e) {
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
        return false;
    size_t in_union = 0, outside = 0;
    for (uint8_t w : where) {
        in_union += w != 0;
        outside += w == 2;
    }
    const Vec3 extent = hi - lo;
    const double box = extent.x() * extent.y() * extent.z();
    union_volume = box * double(in_union) / double(n);
    outside_volume = box * double(outside) / double(n);
    return true;
}

Status proxy_stats(const Mesh& mesh, const std::vector<Proxy>& proxies, const ShapeQueries& shape,
                   const ProxyOptions& opt, const Monitor& monitor, ProxyStats& out) {
    out = ProxyStats{};
    if (proxies.empty()) return fail(Code::internal, "proxies: no primitive chosen");
    const bool boxes = std::any_of(proxies.begin(), proxies.end(), [](const Proxy& p) { return p.kind == ProxyKind::box; });
    Skeleton sk;
    for (const Proxy& p : proxies) {
        sk.balls.push_back(p.a);
        if (p.kind == ProxyKind::capsule) {
            sk.balls.push_back(p.b);
            sk.edges.push_back({uint32_t(sk.balls.size() - 2), uint32_t(sk.balls.size() - 1)});
        }
    }
    if (boxes) {
        Status st = union_hausdorff(mesh, proxies, opt, monitor, out);
        if (!st.ok()) return st;
    } else {
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
    }
    for (const Proxy& p : proxies) out.outside_bound = std::max(out.outside_bound, outside_bound(p, shape));
    out.outside_bound *= 100 / out.diagonal;

    // ---- Monte Carlo volumes ----
    if (!union_volumes(proxies, shape, opt.volume_samples, opt.seed ^ 0x3C6EF372FE94F82Bull, resolve_threads(opt.threads),
                       monitor, "proxies", out.union_volume, out.outside_volume))
        return monitor.stop_status("proxies");
    return Status::success();
}

}  // namespace ca
