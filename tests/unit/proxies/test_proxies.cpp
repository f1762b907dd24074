// test_proxies.cpp: engine proxies (lib/proxies) on meshes with known answers. A sphere gives one
// sphere, a capsule one capsule with its end points and radii; conservative proxies contain fresh
// samples of the triangles (drawn here, not the library's), checked with a brute-force distance to
// each primitive; inscribed proxies reach no farther outside the shape than the skeleton's own
// balls and edges (every shapes value), measured on fresh samples of both boundaries (the
// library's inside test and distance, themselves tested against brute force). Boxes: on an L of two planks, boxes leave far
// less volume outside than capsules; the cover's lower bound never exceeds its objective.
#include <doctest/doctest.h>

#include "distance.h"
#include "steps.h"
#include "support/brute_distance.h"
#include "support/fresh_samples.h"
#include "support/shapes.h"
#include "winding.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace {

// The skeleton of a mesh in the caller's units, from the default pipeline at small sample counts.
struct Pipeline {
    ca::CandidateSet set;
    ca::Skeleton skeleton;   // caller's units
};

Pipeline pipeline(const ca::Mesh& mesh, uint32_t cover = 400, uint32_t voronoi = 1200) {
    Pipeline p;
    ca::CandidateOptions co;
    co.cover_samples = cover;
    co.voronoi_samples = voronoi;
    ca::SurfaceInput surface;
    surface.mesh = mesh;
    REQUIRE(ca::candidates_step(surface, co, ca::Monitor{}, p.set).ok());
    ca::SelectRequest sr;
    sr.select.cover.time_limit_s = 0;
    ca::SelectResult sel;
    REQUIRE(ca::select_step(p.set, sr, ca::Monitor{}, sel).ok());
    ca::ConnectResult k;
    REQUIRE(ca::connect_step(p.set, sel.selection, ca::ConnectRequest{}, ca::Monitor{}, k).ok());
    p.skeleton = k.skeleton;
    for (ca::Ball& b : p.skeleton.balls) {
        b.center = p.set.surface.norm.to_user(b.center);
        b.radius *= p.set.surface.norm.scale;
    }
    return p;
}

double diagonal(const ca::Mesh& m) {
    ca::Vec3 lo = m.vertices[0], hi = lo;
    for (const ca::Vec3& v : m.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    return (hi - lo).norm();
}

// Brute force for any primitive: a box by its definition (every coordinate in its frame within
// the half-length; the signed distance's sign is all the checks need), the others by
// brute_distance (support/brute_distance.h).
double brute_distance_any(const ca::Proxy& p, const ca::Vec3& x) {
    if (p.kind != ca::ProxyKind::box) return brute_distance(p, x);
    const ca::Vec3 q = p.axes.transpose() * (x - p.a.center);
    double worst = -1e300;
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(q[k]) - p.half[k]);
    return worst;  // <= 0 exactly when x is in the box
}

// Points on the boundary of a primitive: from a random interpolated centre along a random
// direction to where the brute-force distance crosses 0 (once: the primitive is convex).
std::vector<ca::Vec3> fresh_boundary_samples(const ca::Proxy& p, size_t n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> g(0, 1);
    const double reach = (p.b.center - p.a.center).norm() + std::max(p.a.radius, p.b.radius) + 1e-9;
    std::vector<ca::Vec3> out;
    if (p.kind == ca::ProxyKind::box) {  // a uniform point of a face chosen by its area
        const double area[3] = {p.half.y() * p.half.z(), p.half.z() * p.half.x(), p.half.x() * p.half.y()};
        for (size_t i = 0; i < n; ++i) {
            double pick = u(rng) * (area[0] + area[1] + area[2]);
            int a = 0;
            while (a < 2 && pick > area[a]) pick -= area[a++];
            ca::Vec3 q;
            for (int k = 0; k < 3; ++k) q[k] = (2 * u(rng) - 1) * p.half[k];
            q[a] = (u(rng) < 0.5 ? -1 : 1) * p.half[a];
            out.push_back(p.a.center + p.axes * q);
        }
        return out;
    }
    for (size_t i = 0; i < n; ++i) {
        const double t = p.kind == ca::ProxyKind::sphere ? 0 : u(rng);
        const ca::Vec3 c = p.a.center + t * (p.b.center - p.a.center);
        ca::Vec3 d(g(rng), g(rng), g(rng));
        d.normalize();
        double lo = 0, hi = reach;
        for (int k = 0; k < 36; ++k) {
            const double m = 0.5 * (lo + hi);
            if (brute_distance(p, c + m * d) <= 0) lo = m;
            else hi = m;
        }
        out.push_back(c + lo * d);
    }
    return out;
}

// The farthest any of the points lies outside the mesh (the winding number's inside test and the
// exact distance, each checked against brute force in tests/unit/geometry).
double farthest_outside(const ca::Mesh& m, const std::vector<ca::Vec3>& pts) {
    const ca::WindingNumber winding(m);
    const ca::MeshDistance distance(m);
    double worst = 0;
    for (const ca::Vec3& x : pts)
        if (!winding.inside(x)) worst = std::max(worst, distance.distance(x));
    return worst;
}

ca::ProxyResult proxies(const Pipeline& p, ca::ProxyShapes shapes, ca::ProxyMode mode, uint32_t count) {
    ca::ProxyOptions opt;
    opt.shapes = shapes;
    opt.mode = mode;
    opt.count = count;
    opt.evaluate_samples = 5000;
    opt.volume_samples = 20000;
    ca::ProxyResult r;
    const ca::Status st = ca::proxies_step(p.set, p.skeleton, opt, ca::Monitor{}, r);
    INFO(st.message);
    REQUIRE(st.ok());
    REQUIRE(!r.proxies.empty());
    CHECK(r.proxies.size() <= count);
    return r;
}

}  // namespace

TEST_CASE("proxies: a sphere mesh gives one sphere at its centre and radius") {
    const ca::Mesh mesh = shapes::sphere(1.0, 24, 48);
    const double diag = diagonal(mesh);
    const Pipeline p = pipeline(mesh);
    for (ca::ProxyShapes shapes : {ca::ProxyShapes::spheres, ca::ProxyShapes::capsules})
        for (ca::ProxyMode mode : {ca::ProxyMode::inscribed, ca::ProxyMode::conservative}) {
            const ca::ProxyResult r = proxies(p, shapes, mode, 8);
            CAPTURE(int(shapes));
            CAPTURE(int(mode));
            REQUIRE(r.proxies.size() == 1);
            const ca::Proxy& s = r.proxies[0];
            CHECK(s.kind == ca::ProxyKind::sphere);
            CHECK(s.a.center.norm() < 0.02 * diag);
            CHECK(std::abs(s.a.radius - 1.0) < 0.02 * diag);
        }
}

TEST_CASE("proxies: a capsule mesh gives one capsule with its end points and radii") {
    const double half = 2.0, r = 0.5;
    const ca::Mesh mesh = shapes::capsule(half, r, 48, 32);
    const double diag = diagonal(mesh);
    const Pipeline p = pipeline(mesh);
    for (ca::ProxyMode mode : {ca::ProxyMode::inscribed, ca::ProxyMode::conservative}) {
        CAPTURE(int(mode));
        const ca::ProxyResult res = proxies(p, ca::ProxyShapes::capsules, mode, 8);
        REQUIRE(res.proxies.size() == 1);
        const ca::Proxy& c = res.proxies[0];
        REQUIRE(c.kind == ca::ProxyKind::capsule);
        const bool a_first = c.a.center.x() < c.b.center.x();
        const ca::Vec3 lo = a_first ? c.a.center : c.b.center, hi = a_first ? c.b.center : c.a.center;
        CHECK((lo - ca::Vec3(-half, 0, 0)).norm() < 0.02 * diag);
        CHECK((hi - ca::Vec3(half, 0, 0)).norm() < 0.02 * diag);
        CHECK(std::abs(c.a.radius - r) < 0.02 * diag);
        CHECK(std::abs(c.b.radius - r) < 0.02 * diag);
        CHECK(res.stats.hd_two_sided < 2.0);
    }
}

TEST_CASE("proxies: conservative proxies contain every fresh sample of the surface") {
    const std::vector<ca::Mesh> meshes = {shapes::torus(1.0, 0.3, 48, 16), shapes::capsule(1.5, 0.4, 32, 16),
                                          shapes::merged(shapes::box(1.0, 0.6, 0.4), shapes::sphere(0.4, 12, 24),
                                                         ca::Vec3(1.2, 0.3, 0.2))};
    for (size_t m = 0; m < meshes.size(); ++m) {
        CAPTURE(m);
        const Pipeline p = pipeline(meshes[m]);
        for (ca::ProxyShapes shapes : {ca::ProxyShapes::spheres, ca::ProxyShapes::capsules, ca::ProxyShapes::boxes,
                                       ca::ProxyShapes::all})
            for (uint32_t count : {3u, 12u}) {
                CAPTURE(int(shapes));
                CAPTURE(count);
                const ca::ProxyResult r = proxies(p, shapes, ca::ProxyMode::conservative, count);
                size_t outside = 0;
                for (const ca::Vec3& x : fresh_surface_samples(meshes[m], 10000, 7 + m)) {
                    double best = 1e300;
                    for (const ca::Proxy& q : r.proxies) best = std::min(best, brute_distance_any(q, x));
                    outside += best > 1e-12;
                }
                CHECK(outside == 0);
                for (const ca::Proxy& q : r.proxies) {
                    if (shapes == ca::ProxyShapes::spheres) CHECK(q.kind == ca::ProxyKind::sphere);
                    if (shapes == ca::ProxyShapes::capsules) CHECK(q.kind != ca::ProxyKind::box);
                    if (shapes == ca::ProxyShapes::boxes) CHECK(q.kind != ca::ProxyKind::capsule);
                }
                // the solver's lower bound holds for the objective it reached
                CHECK(r.stats.outside_lower_bound >= 0);
                CHECK(r.stats.outside_lower_bound <= r.stats.outside_objective * (1 + 1e-12) + 1e-300);
            }
    }
}

TEST_CASE("proxies: inscribed proxies reach no farther outside than the skeleton's balls and edges") {
    const std::vector<ca::Mesh> meshes = {shapes::torus(1.0, 0.3, 48, 16),
                                          shapes::merged(shapes::capsule(1.5, 0.4, 32, 16), shapes::sphere(0.6, 16, 32),
                                                         ca::Vec3(1.6, 0.4, 0))};
    for (size_t m = 0; m < meshes.size(); ++m) {
        CAPTURE(m);
        const ca::Mesh& mesh = meshes[m];
        const double diag = diagonal(mesh);
        const Pipeline p = pipeline(mesh);
        std::mt19937_64 rng(11 + m);
        double skeleton_out = 0;
        {
            ca::Skeleton sk = p.skeleton;
            ca::canonicalize(sk);
            std::vector<ca::Proxy> own;
            for (const ca::Ball& b : sk.balls) own.push_back({ca::ProxyKind::sphere, b, b});
            for (const auto& e : sk.edges) own.push_back({ca::ProxyKind::capsule, sk.balls[e[0]], sk.balls[e[1]]});
            std::vector<ca::Vec3> pts;
            for (const ca::Proxy& q : own)
                for (const ca::Vec3& x : fresh_boundary_samples(q, 200, rng)) pts.push_back(x);
            skeleton_out = farthest_outside(mesh, pts);
        }
        for (ca::ProxyShapes shapes : {ca::ProxyShapes::spheres, ca::ProxyShapes::capsules, ca::ProxyShapes::boxes,
                                       ca::ProxyShapes::all}) {
            CAPTURE(int(shapes));
            const ca::ProxyResult r = proxies(p, shapes, ca::ProxyMode::inscribed, 6);
            std::vector<ca::Vec3> pts;
            for (const ca::Proxy& q : r.proxies)
                for (const ca::Vec3& x : fresh_boundary_samples(q, 1000, rng)) pts.push_back(x);
            const double proxies_out = farthest_outside(mesh, pts);
            CAPTURE(skeleton_out / diag);
            CAPTURE(proxies_out / diag);
            CAPTURE(r.stats.outside_bound);
            CAPTURE(r.stats.skeleton_outside);
            CAPTURE(r.proxies.size());
            // the skeleton's value is itself a sample maximum: a thousandth of the diagonal of slack
            CHECK(proxies_out <= skeleton_out + 1e-3 * diag);

            CHECK(r.stats.outside_bound <= r.stats.skeleton_outside + 1e-9);
        }
    }
}

TEST_CASE("proxies: on an L of two planks, boxes leave far less volume outside than capsules") {
    // plank A: [0, 2] x [0, 0.2] x [0, 0.5]; plank B on its right end: [1.8, 2] x [0.2, 1.4] x [0, 0.5]
    const ca::Mesh mesh = shapes::merged(shapes::box(2.0, 0.2, 0.5), shapes::box(0.2, 1.2, 0.5), ca::Vec3(1.8, 0.2, 0));
    const Pipeline p = pipeline(mesh);
    const ca::ProxyResult capsules = proxies(p, ca::ProxyShapes::capsules, ca::ProxyMode::conservative, 8);
    for (ca::ProxyShapes shapes : {ca::ProxyShapes::boxes, ca::ProxyShapes::all}) {
        CAPTURE(int(shapes));
        const ca::ProxyResult r = proxies(p, shapes, ca::ProxyMode::conservative, 8);
        size_t boxes = 0;
        for (const ca::Proxy& q : r.proxies) boxes += q.kind == ca::ProxyKind::box;
        CHECK(boxes >= 1);
        CAPTURE(r.stats.outside_volume);
        CAPTURE(capsules.stats.outside_volume);
        CHECK(r.stats.outside_volume < 0.25 * capsules.stats.outside_volume);
        size_t outside = 0;
        for (const ca::Vec3& x : fresh_surface_samples(mesh, 10000, 3)) {
            double best = 1e300;
            for (const ca::Proxy& q : r.proxies) best = std::min(best, brute_distance_any(q, x));
            outside += best > 1e-12;
        }
        CHECK(outside == 0);
    }
}

TEST_CASE("proxies: the same proxies on any number of threads") {
    const Pipeline p = pipeline(shapes::torus(1.0, 0.3, 32, 12), 300, 900);
    for (ca::ProxyMode mode : {ca::ProxyMode::inscribed, ca::ProxyMode::conservative})
    for (ca::ProxyShapes shapes : {ca::ProxyShapes::capsules, ca::ProxyShapes::all}) {
        std::vector<ca::ProxyResult> runs;
        for (int threads : {1, 2}) {
            ca::ProxyOptions opt;
            opt.shapes = shapes;
            opt.mode = mode;
            opt.count = 5;
            opt.evaluate_samples = 2000;
            opt.volume_samples = 5000;
            opt.threads = threads;
            ca::ProxyResult r;
            REQUIRE(ca::proxies_step(p.set, p.skeleton, opt, ca::Monitor{}, r).ok());
            runs.push_back(r);
        }
        REQUIRE(runs[0].proxies.size() == runs[1].proxies.size());
        for (size_t i = 0; i < runs[0].proxies.size(); ++i) {
            const ca::Proxy &x = runs[0].proxies[i], &y = runs[1].proxies[i];
            CHECK(x.kind == y.kind);
            CHECK(x.a.center == y.a.center);
            CHECK(x.b.center == y.b.center);
            CHECK(x.a.radius == y.a.radius);
            CHECK(x.b.radius == y.b.radius);
            CHECK(x.axes == y.axes);
            CHECK(x.half == y.half);
        }
        CHECK(runs[0].stats.outside_objective == runs[1].stats.outside_objective);
        CHECK(runs[0].stats.outside_lower_bound == runs[1].stats.outside_lower_bound);
        CHECK(runs[0].stats.hd_two_sided == runs[1].stats.hd_two_sided);
        CHECK(runs[0].stats.outside_volume == runs[1].stats.outside_volume);
    }
}

TEST_CASE("proxies: bad requests fail with a clear status before any work") {
    const Pipeline p = pipeline(shapes::capsule(1.0, 0.4, 24, 12), 200, 600);
    ca::ProxyResult r;
    ca::ProxyOptions opt;
    opt.count = 0;
    ca::Status st = ca::proxies_step(p.set, p.skeleton, opt, ca::Monitor{}, r);
    CHECK(st.code == ca::Code::invalid_argument);
    CHECK(st.message.find("count") != std::string::npos);
    opt = ca::ProxyOptions{};
    opt.shapes = static_cast<ca::ProxyShapes>(4);
    st = ca::proxies_step(p.set, p.skeleton, opt, ca::Monitor{}, r);
    CHECK(st.code == ca::Code::invalid_argument);
    CHECK(st.message.find("shapes") != std::string::npos);
    opt = ca::ProxyOptions{};
    opt.mode = static_cast<ca::ProxyMode>(5);
    CHECK(ca::proxies_step(p.set, p.skeleton, opt, ca::Monitor{}, r).code == ca::Code::invalid_argument);
    opt = ca::ProxyOptions{};
    ca::Skeleton bad = p.skeleton;
    bad.balls[0].radius = std::nan("");
    CHECK(ca::proxies_step(p.set, bad, opt, ca::Monitor{}, r).code == ca::Code::invalid_input);
    bad = p.skeleton;
    bad.edges.push_back({0, uint32_t(bad.balls.size())});
    st = ca::proxies_step(p.set, bad, opt, ca::Monitor{}, r);
    CHECK(st.code == ca::Code::invalid_input);
    CHECK(st.message.find("edge") != std::string::npos);
    CHECK(ca::proxies_step(p.set, ca::Skeleton{}, opt, ca::Monitor{}, r).code == ca::Code::degenerate_input);
    ca::CandidateSet bare;   // caller arrays: no surface to make proxies of
    CHECK(ca::proxies_step(bare, p.skeleton, opt, ca::Monitor{}, r).code == ca::Code::invalid_argument);
    // a stopped monitor stops the step
    std::atomic<int> cancel{1};
    ca::Monitor stopped;
    stopped.cancel_flag = &cancel;
    CHECK(ca::proxies_step(p.set, p.skeleton, opt, stopped, r).code == ca::Code::cancelled);
}

TEST_CASE("proxies: a rotated box's signed distance matches brute force, and growth holds what it must") {
    // the box's surface sampled densely; the distance of an outside point is the nearest sample's,
    // of an inside point minus the nearest face's (brute force over the six faces)
    const Eigen::Matrix3d axes = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const ca::Vec3 c(0.3, -0.2, 0.5), half(0.4, 0.1, 0.25);
    const ca::Proxy box = ca::make_box(c, axes, half);
    std::vector<ca::Vec3> surface;
    const int n = 60;
    for (int f = 0; f < 3; ++f)
        for (int s = -1; s <= 1; s += 2)
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    ca::Vec3 local;
                    const int u = (f + 1) % 3, v = (f + 2) % 3;
                    local[f] = s * half[f];
                    local[u] = half[u] * (2.0 * i / n - 1);
                    local[v] = half[v] * (2.0 * j / n - 1);
                    surface.push_back(c + axes * local);
                }
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    const double spacing = 2 * half.maxCoeff() / n;
    for (int t = 0; t < 300; ++t) {
        const ca::Vec3 x = c + ca::Vec3(u(rng), u(rng), u(rng)) * 0.8;
        const ca::Vec3 local = axes.transpose() * (x - c);
        const bool inside = (local.cwiseAbs().array() <= half.array()).all();
        double nearest = 1e300;
        for (const ca::Vec3& s : surface) nearest = std::min(nearest, (x - s).norm());
        double face = 1e300;
        for (int k = 0; k < 3; ++k) face = std::min(face, half[k] - std::abs(local[k]));
        const double expected = inside ? -face : nearest;
        CHECK(std::abs(ca::proxy_distance(box, x) - expected) <= (inside ? 1e-12 : spacing));
        // grown by its own signed distance, the box holds the point
        if (!inside) CHECK(ca::proxy_distance(ca::shrunk(box, -ca::proxy_distance(box, x)), x) <= 1e-12);
    }
}
