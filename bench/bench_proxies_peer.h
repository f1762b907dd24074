// bench_proxies_peer.h: what bench_proxies needs to set proxies beside V-HACD's convex hulls: the
// hulls read back from bench/vhacd/vhacd_driver (run as a process of its own), a point-in-hull
// test by planes, and one measure of any union of convex pieces (primitives or hulls) against the
// model: fresh surface samples inside, volume outside and volume missed (Monte Carlo with the
// library's winding-number inside test), how far it sticks out, and its size in bytes.
#pragma once
#include "bench_common.h"
#include "distance.h"
#include "parallel.h"
#include "proxies.h"
#include "support/fresh_samples.h"
#include "winding.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace bench {

// A convex hull as V-HACD returns it, with its planes (outward unit normal n and offset d: a point
// x is inside when n.x + d <= 0 for every plane) and bounding box.
struct Hull {
    std::vector<ca::Vec3> points;
    std::vector<ca::Tri> triangles;
    std::vector<Eigen::Vector4d> planes;
    ca::Vec3 lo, hi;
};

// Planes from the triangles, each turned to face away from the mean of the points (the hull is
// convex, so the mean is inside; this does not trust the triangles' winding). Degenerate
// triangles give no plane.
inline void hull_planes(Hull& h) {
    h.planes.clear();
    ca::Vec3 mean = ca::Vec3::Zero();
    h.lo = ca::Vec3::Constant(1e300);
    h.hi = -h.lo;
    for (const ca::Vec3& p : h.points) {
        mean += p;
        h.lo = h.lo.cwiseMin(p);
        h.hi = h.hi.cwiseMax(p);
    }
    if (h.points.empty()) return;
    mean /= double(h.points.size());
    for (const ca::Tri& t : h.triangles) {
        const ca::Vec3 &a = h.points[t[0]], &b = h.points[t[1]], &c = h.points[t[2]];
        ca::Vec3 n = (b - a).cross(c - a);
        const double len = n.norm();
        if (!(len > 0)) continue;
        n /= len;
        double d = -n.dot(a);
        if (n.dot(mean) + d > 0) n = -n, d = -d;
        h.planes.emplace_back(n.x(), n.y(), n.z(), d);
    }
}

// x in the hull, up to `eps` (a length) outside its planes.
inline bool in_hull(const Hull& h, const ca::Vec3& x, double eps) {
    if ((x.array() < h.lo.array() - eps).any() || (x.array() > h.hi.array() + eps).any()) return false;
    for (const Eigen::Vector4d& p : h.planes)
        if (p.x() * x.x() + p.y() * x.y() + p.z() * x.z() + p.w() > eps) return false;
    return !h.planes.empty();
}

// V-HACD's result for one hull count.
struct VhacdRun {
    bool ok = false;
    std::string note;   // why not, when not ok
    std::vector<Hull> hulls;
    double seconds = 0; // its Compute call, as the driver timed it
};

// Runs `driver` on the mesh (written to `dir`) for at most `max_hulls` hulls, killed after `limit_s`.
inline VhacdRun run_vhacd(const std::string& driver, const std::string& dir, const ca::Mesh& mesh, uint32_t max_hulls,
                          double limit_s) {
    VhacdRun r;
    const std::string in = dir + "/vhacd_in.bin", out = dir + "/vhacd_out.bin";
    {
        FILE* f = std::fopen(in.c_str(), "wb");
        if (!f) { r.note = "cannot write its input"; return r; }
        const uint32_t counts[2] = {uint32_t(mesh.vertices.size()), uint32_t(mesh.triangles.size())};
        bool ok = std::fwrite(counts, sizeof counts, 1, f) == 1;
        for (const ca::Vec3& v : mesh.vertices) ok = ok && std::fwrite(v.data(), sizeof(double), 3, f) == 3;
        for (const ca::Tri& t : mesh.triangles) ok = ok && std::fwrite(t.data(), sizeof(uint32_t), 3, f) == 3;
        if (std::fclose(f) != 0 || !ok) { r.note = "cannot write its input"; return r; }
    }
    std::remove(out.c_str());
    const ProcessRun p = run_process({driver, in, out, std::to_string(max_hulls)}, dir + "/vhacd_stdout.txt", limit_s);
    std::remove(in.c_str());
    if (!p.ran) { r.note = "killed after " + std::to_string(int(limit_s)) + " s"; return r; }
    if (p.signal) { r.note = "crashed (signal " + std::to_string(p.signal) + ")"; return r; }
    if (p.exit_code != 0) { r.note = "failed (exit " + std::to_string(p.exit_code) + ")"; return r; }
    FILE* f = std::fopen(out.c_str(), "rb");
    uint32_t count = 0;
    bool ok = f && std::fread(&r.seconds, sizeof r.seconds, 1, f) == 1 && std::fread(&count, sizeof count, 1, f) == 1;
    for (uint32_t h = 0; ok && h < count; ++h) {
        uint32_t n[2];
        ok = std::fread(n, sizeof n, 1, f) == 1;
        Hull hull;
        hull.points.resize(ok ? n[0] : 0);
        hull.triangles.resize(ok ? n[1] : 0);
        for (ca::Vec3& v : hull.points) ok = ok && std::fread(v.data(), sizeof(double), 3, f) == 3;
        for (ca::Tri& t : hull.triangles) {
            ok = ok && std::fread(t.data(), sizeof(uint32_t), 3, f) == 3;
            ok = ok && t[0] < n[0] && t[1] < n[0] && t[2] < n[0];
        }
        hull_planes(hull);
        r.hulls.push_back(std::move(hull));
    }
    if (f) std::fclose(f);
    std::remove(out.c_str());
    r.ok = ok;
    if (!ok) r.note = "unreadable output";
    return r;
}

// A union of convex pieces: primitives (ca::Proxy) or hulls, never both.
struct ConvexUnion {
    std::vector<ca::Proxy> proxies;
    std::vector<Hull> hulls;
    std::vector<ca::Vec3> lo, hi;   // per piece, its bounding box

    static ConvexUnion of(std::vector<ca::Proxy> ps) {
        ConvexUnion u;
        for (const ca::Proxy& p : ps) {
            ca::Vec3 l, h;
            if (p.kind == ca::ProxyKind::box) {
                const ca::Vec3 reach = p.axes.cwiseAbs() * p.half;
                l = p.a.center - reach;
                h = p.a.center + reach;
            } else {
                l = (p.a.center.array() - p.a.radius).matrix().cwiseMin((p.b.center.array() - p.b.radius).matrix());
                h = (p.a.center.array() + p.a.radius).matrix().cwiseMax((p.b.center.array() + p.b.radius).matrix());
            }
            u.lo.push_back(l);
            u.hi.push_back(h);
        }
        u.proxies = std::move(ps);
        return u;
    }
    static ConvexUnion of(std::vector<Hull> hs) {
        ConvexUnion u;
        for (const Hull& h : hs) {
            u.lo.push_back(h.lo);
            u.hi.push_back(h.hi);
        }
        u.hulls = std::move(hs);
        return u;
    }
    size_t count() const { return lo.size(); }
    // x in some piece; hulls up to `eps` outside their planes (points on a face count as inside)
    bool contains(const ca::Vec3& x, double eps) const {
        for (size_t i = 0; i < count(); ++i) {
            if ((x.array() < lo[i].array() - eps).any() || (x.array() > hi[i].array() + eps).any()) continue;
            if (hulls.empty() ? ca::proxy_distance(proxies[i], x) <= 0 : in_hull(hulls[i], x, eps)) return true;
        }
        return false;
    }
    void bounds(ca::Vec3& l, ca::Vec3& h) const {
        for (size_t i = 0; i < count(); ++i) {
            l = l.cwiseMin(lo[i]);
            h = h.cwiseMax(hi[i]);
        }
    }
    // What an engine stores as float32: a sphere 4 floats (centre, radius), a capsule 8 (two
    // centres, two radii), a box 10 (centre, half-lengths, rotation quaternion); a hull its
    // vertices (3 floats) and triangles (3 uint32).
    size_t bytes() const {
        size_t b = 0;
        for (const ca::Proxy& p : proxies) b += 4 * (p.kind == ca::ProxyKind::sphere ? 4 : p.kind == ca::ProxyKind::capsule ? 8 : 10);
        for (const Hull& h : hulls) b += 12 * (h.points.size() + h.triangles.size());
        return b;
    }
    // About n points on the pieces' boundaries, area-weighted (each in the union): a hull's
    // triangles; a sphere; a tapered capsule's two spheres and the cone tangent to both; a box's faces.
    std::vector<ca::Vec3> boundary_samples(size_t n, uint64_t seed) const {
        if (!hulls.empty()) {
            ca::Mesh m;
            for (const Hull& h : hulls) {
                const uint32_t base = uint32_t(m.vertices.size());
                m.vertices.insert(m.vertices.end(), h.points.begin(), h.points.end());
                for (const ca::Tri& t : h.triangles) m.triangles.push_back({base + t[0], base + t[1], base + t[2]});
            }
            return m.triangles.empty() ? std::vector<ca::Vec3>{} : fresh_surface_samples(m, n, seed);
        }
        const double pi = 3.14159265358979323846;
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        auto direction = [&] {
            const double z = 2 * u(rng) - 1, t = 2 * pi * u(rng), s = std::sqrt(std::max(0.0, 1 - z * z));
            return ca::Vec3(s * std::cos(t), s * std::sin(t), z);
        };
        auto area = [&](const ca::Proxy& p, double& band) {
            band = 0;
            if (p.kind == ca::ProxyKind::box)
                return 8 * (p.half.x() * p.half.y() + p.half.y() * p.half.z() + p.half.z() * p.half.x());
            const double ra = p.a.radius, rb = p.b.radius, len = (p.b.center - p.a.center).norm();
            if (p.kind == ca::ProxyKind::capsule && len > std::abs(ra - rb)) band = pi * (ra + rb) * len;
            return 4 * pi * (ra * ra + (p.kind == ca::ProxyKind::capsule ? rb * rb : 0)) + band;
        };
        double total = 0, band = 0;
        for (const ca::Proxy& p : proxies) total += area(p, band);
        std::vector<ca::Vec3> out;
        for (const ca::Proxy& p : proxies) {
            const double a = area(p, band);
            const size_t k = total > 0 ? size_t(std::ceil(double(n) * a / total)) : 0;
            for (size_t i = 0; i < k; ++i) {
                if (p.kind == ca::ProxyKind::box) {
                    // a face by area, then a point on it
                    const ca::Vec3& h = p.half;
                    const double f[3] = {h.y() * h.z(), h.x() * h.z(), h.x() * h.y()};
                    double pick = u(rng) * (f[0] + f[1] + f[2]);
                    int axis = pick < f[0] ? 0 : pick < f[0] + f[1] ? 1 : 2;
                    ca::Vec3 local(h.x() * (2 * u(rng) - 1), h.y() * (2 * u(rng) - 1), h.z() * (2 * u(rng) - 1));
                    local[axis] = u(rng) < 0.5 ? -h[axis] : h[axis];
                    out.push_back(p.a.center + p.axes * local);
                    continue;
                }
                const double ra = p.a.radius, rb = p.kind == ca::ProxyKind::capsule ? p.b.radius : 0;
                double pick = u(rng) * a;
                if ((pick -= 4 * pi * ra * ra) < 0) { out.push_back(p.a.center + ra * direction()); continue; }
                if ((pick -= 4 * pi * rb * rb) < 0) { out.push_back(p.b.center + rb * direction()); continue; }
                // the cone: its outward normal m makes m.w = s with the axis w, s = (ra - rb) / len;
                // it touches ball a at a + ra m and ball b at b + rb m; points along the line
                // between, weighted by their distance from the axis
                const double len = (p.b.center - p.a.center).norm(), s = (ra - rb) / len, c = std::sqrt(1 - s * s);
                const ca::Vec3 w = (p.b.center - p.a.center) / len;
                const ca::Vec3 e1 = w.unitOrthogonal(), e2 = w.cross(e1);
                const double phi = 2 * pi * u(rng);
                const ca::Vec3 m = s * w + c * (std::cos(phi) * e1 + std::sin(phi) * e2);
                double t = u(rng);
                while (u(rng) * std::max(ra, rb) > (1 - t) * ra + t * rb) t = u(rng);
                out.push_back((1 - t) * (p.a.center + ra * m) + t * (p.b.center + rb * m));
            }
        }
        return out;
    }
};

// The model and the samples every union is measured on.
struct PeerModel {
    ca::Mesh mesh;
    bool closed = false;
    double volume = 0, diagonal = 0;
    ca::Vec3 lo, hi;
    std::shared_ptr<const ca::WindingNumber> winding;
    std::shared_ptr<const ca::MeshDistance> distance;
    std::vector<ca::Vec3> fresh;        // surface samples
    std::vector<ca::Vec3> volume_points;  // Monte Carlo points in `box_lo`..`box_hi`
    std::vector<uint8_t> inside;        // per volume point: in the model
    ca::Vec3 box_lo, box_hi;
};

struct UnionMeasure {
    double inside_pct = NAN;     // % of the fresh surface samples in the union
    double outside_pct = NAN;    // volume of the union outside the model, % of the model's volume
    double missed_pct = NAN;     // volume of the model outside the union, %
    double stick_out_pct = NAN;  // farthest boundary sample outside the model, % of the diagonal
    size_t bytes = 0;
};

// Monte Carlo points in a box holding the model and every union (one set for all of them, so
// that their volumes are compared on the same points), each tested inside the model once.
inline void volume_points(PeerModel& m, const std::vector<const ConvexUnion*>& unions, size_t n, uint64_t seed) {
    m.box_lo = m.lo;
    m.box_hi = m.hi;
    for (const ConvexUnion* u : unions) u->bounds(m.box_lo, m.box_hi);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    m.volume_points.resize(n);
    const ca::Vec3 e = m.box_hi - m.box_lo;
    for (ca::Vec3& x : m.volume_points) x = m.box_lo + ca::Vec3(e.x() * u(rng), e.y() * u(rng), e.z() * u(rng));
    m.inside.assign(n, 0);
    ca::parallel_for(n, ca::resolve_threads(0), n, ca::Monitor{}, "inside", [&](size_t b, size_t f) {
        for (size_t i = b; i < f; ++i) m.inside[i] = m.winding->inside(m.volume_points[i]);
    });
}

// The union measured on the model: surface inside always; the volumes and the stick-out only on
// a closed model.
inline UnionMeasure measure_union(const PeerModel& m, const ConvexUnion& u, size_t boundary_samples) {
    UnionMeasure r;
    r.bytes = u.bytes();
    const double eps = 1e-9 * m.diagonal;
    const int threads = ca::resolve_threads(0);
    std::vector<uint8_t> in_fresh(m.fresh.size()), in_volume(m.closed ? m.volume_points.size() : 0);
    ca::parallel_for(in_fresh.size(), threads, in_fresh.size(), ca::Monitor{}, "fresh", [&](size_t b, size_t f) {
        for (size_t i = b; i < f; ++i) in_fresh[i] = u.contains(m.fresh[i], eps);
    });
    size_t held = 0;
    for (uint8_t h : in_fresh) held += h;
    r.inside_pct = 100 * double(held) / double(std::max<size_t>(1, m.fresh.size()));
    if (!m.closed) return r;
    ca::parallel_for(in_volume.size(), threads, in_volume.size(), ca::Monitor{}, "volume", [&](size_t b, size_t f) {
        for (size_t i = b; i < f; ++i) in_volume[i] = u.contains(m.volume_points[i], eps);
    });
    size_t outside = 0, missed = 0;
    for (size_t i = 0; i < in_volume.size(); ++i) {
        outside += in_volume[i] && !m.inside[i];
        missed += !in_volume[i] && m.inside[i];
    }
    const ca::Vec3 e = m.box_hi - m.box_lo;
    const double per_point = e.x() * e.y() * e.z() / double(std::max<size_t>(1, in_volume.size())) / m.volume;
    r.outside_pct = 100 * double(outside) * per_point;
    r.missed_pct = 100 * double(missed) * per_point;
    const std::vector<ca::Vec3> edge = u.boundary_samples(boundary_samples, 31);
    std::vector<double> out(edge.size(), 0);
    ca::parallel_for(edge.size(), threads, edge.size(), ca::Monitor{}, "stick-out", [&](size_t b, size_t f) {
        for (size_t i = b; i < f; ++i)
            if (!m.winding->inside(edge[i])) out[i] = m.distance->distance(edge[i]);
    });
    double far = 0;
    for (double d : out) far = std::max(far, d);
    r.stick_out_pct = 100 * far / m.diagonal;
    return r;
}

}  // namespace bench
