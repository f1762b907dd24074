// test_connect.cpp: both connection routes (power diagram, medial axis) on shapes with known
// skeleton topology: torus (one loop), genus-3 solid (three loops), capsule (a path), two disjoint
// spheres (two components), a thin plate (a sheet: triangles). Every element of every skeleton
// must stay inside the shape (rule in `leaves_shape`). Plus the medial route's refusal of point
// clouds and cancellation, the inside test's exact shortcuts against direct evaluation on a
// closed and an open mesh, and the medial route's reconnection preferring segments that pass the
// envelope rule, and on an open, inward-facing tube with a curved rim no element bulging out
// through the hole cap.
#include <doctest/doctest.h>

#include "candidates.h"
#include "connect.h"
#include "distance.h"
#include "envelope.h"
#include "mesh_io.h"
#include "selection.h"
#include "support/mesh_convert.h"
#include "support/shapes.h"
#include "union_find.h"
#include "winding.h"
#include "rng.h"

#include <atomic>
#include <cmath>
#include <string>

namespace {

const ca::ConnectMethod kRoutes[] = {ca::ConnectMethod::power, ca::ConnectMethod::medial};
const char* route_name(ca::ConnectMethod m) { return m == ca::ConnectMethod::power ? "power" : "medial"; }

struct Prepared {
    ca::CandidateSet set;
    ca::Selection sel;
};

// A cover of `set` that does not depend on time: a heuristic, or the exact solver without a time
// limit (required to prove optimality).
ca::Selection select(const ca::CandidateSet& set, ca::Solver solver) {
    ca::SelectOptions sopt;
    sopt.cover.time_limit_s = 0;
    sopt.cover.effort = ca::Effort::prove;
    sopt.cover.solver = solver;
    ca::Selection sel;
    const ca::Status st = ca::select_balls(set, sopt, ca::Monitor{}, sel);
    REQUIRE_MESSAGE(st.ok(), st.message);
    if (solver == ca::Solver::exact) REQUIRE(sel.cover.proven_optimal == 1);
    return sel;
}

// Candidates and selection at the default options, in internal units. The exact solver runs
// without a time limit and must prove its cover optimal, so that the cover does not depend on
// the machine's load (a cover cut short by a time limit differs from run to run). The plate uses
// the greedy cover: CBC needs seconds to prove the optimum on its flat faces.
Prepared prepare(ca::Mesh mesh, ca::Solver solver = ca::Solver::exact) {
    Prepared p;
    ca::Surface surface;
    ca::Status st = ca::prepare_surface(std::move(mesh), {}, surface);
    REQUIRE_MESSAGE(st.ok(), st.message);
    ca::Monitor monitor;
    st = ca::generate_candidates(std::move(surface), {}, monitor, p.set);
    REQUIRE_MESSAGE(st.ok(), st.message);
    p.sel = select(p.set, solver);
    return p;
}

ca::Skeleton connect(const Prepared& p, ca::ConnectMethod method) {
    ca::ConnectOptions opt;
    opt.method = method;
    ca::Skeleton sk;
    const ca::Status st = ca::connect_balls(p.set, p.sel, opt, ca::Monitor{}, sk);
    REQUIRE_MESSAGE(st.ok(), st.message);
    return sk;
}

// The number of edges and triangles that leave the shape. Test points: along every edge and on a
// barycentric grid over every triangle, spacing delta/8 (internal units). A point is fine when it
// lies within 0.95 x the undilated radius of one of the element's own balls (inner balls), or its
// generalised winding number is > 1/2, or it is within delta/4 of the surface (tolerance for the
// library's coarser delta/4 grid). Any other point makes its element leave the shape.
size_t leaves_shape(const Prepared& p, const ca::Skeleton& sk) {
    const ca::Mesh& mesh = p.set.surface.mesh;
    const ca::WindingNumber winding(mesh);
    const ca::MeshDistance distance(mesh);
    const double h = p.sel.delta / 8, tol = p.sel.delta / 4;
    auto fine = [&](const ca::Vec3& q, std::initializer_list<uint32_t> own) {
        for (uint32_t v : own)
            if ((q - sk.balls[v].center).norm() < 0.95 * sk.balls[v].radius) return true;
        return winding(q) > 0.5 || distance.distance_below(q, 2 * tol) <= tol;
    };
    size_t bad = 0;
    for (const auto& e : sk.edges) {
        const ca::Vec3 a = sk.balls[e[0]].center, b = sk.balls[e[1]].center;
        const int n = std::max(1, int(std::ceil((b - a).norm() / h)));
        for (int i = 1; i < n; ++i)
            if (!fine(a + (b - a) * (double(i) / n), {e[0], e[1]})) { ++bad; break; }
    }
    for (const ca::Tri& f : sk.faces) {
        const ca::Vec3 a = sk.balls[f[0]].center, b = sk.balls[f[1]].center, c = sk.balls[f[2]].center;
        const int n = std::max(1, int(std::ceil(std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()}) / h)));
        bool ok = true;
        for (int i = 0; i <= n && ok; ++i)
            for (int j = 0; i + j <= n && ok; ++j)
                ok = fine((a * i + b * j + c * (n - i - j)) / double(n), {f[0], f[1], f[2]});
        bad += !ok;
    }
    return bad;
}

ca::Mesh read_obj(const std::string& path) {
    ca::Mesh mesh;
    std::string error;
    REQUIRE_MESSAGE(read_core_mesh(path, mesh, error), error);
    return mesh;
}

}  // namespace

TEST_CASE("test_connect: torus gives one loop") {
    const Prepared p = prepare(shapes::torus(1.0, 0.3));
    for (ca::ConnectMethod m : kRoutes) {
        const std::string route = route_name(m);
        CAPTURE(route);
        const ca::Skeleton sk = connect(p, m);
        const ca::TopologyStats t = ca::topology(sk);
        CHECK(t.components == 1);
        CHECK(t.isolated == 0);
        CHECK(t.betti1 == 1);
        CHECK(leaves_shape(p, sk) == 0);
    }
}

TEST_CASE("test_connect: genus-3 solid gives three loops") {
    // Several covers (exact optimum, greedy, Coverage Axis++): the medial route keeps the medial
    // mesh's three loops on each (removed triangles are collapsed, not left as holes: some covers
    // gave b1 = 4 or 5). The power route's triangulation can leave a hole of more than 4 edges
    // (b1 = 4; its hole filling takes 3- and 4-edge holes only): on the heuristic covers, and on
    // the optimum that the multi-start local search finds. It is checked on the optimum, for
    // keeping the three handles open (b1 >= 3) and at most that one extra hole.
    Prepared p = prepare(read_obj(std::string(CA_TEST_DATA) + "/genus3.obj"));
    const ca::Solver solvers[] = {ca::Solver::exact, ca::Solver::greedy, ca::Solver::capp};
    for (ca::Solver solver : solvers) {
        CAPTURE(int(solver));
        if (solver != ca::Solver::exact) p.sel = select(p.set, solver);
        for (ca::ConnectMethod m : kRoutes) {
            if (m == ca::ConnectMethod::power && solver != ca::Solver::exact) continue;
            const std::string route = route_name(m);
            CAPTURE(route);
            const ca::Skeleton sk = connect(p, m);
            const ca::TopologyStats t = ca::topology(sk);
            CHECK(t.components == 1);
            if (m == ca::ConnectMethod::power) {
                CHECK(t.betti1 >= 3);
                CHECK(t.betti1 <= 4);
            } else {
                CHECK(t.betti1 == 3);
            }
            CHECK(leaves_shape(p, sk) == 0);
        }
    }
}

TEST_CASE("test_connect: capsule gives a path") {
    const Prepared p = prepare(shapes::capsule(2.0, 0.5));
    REQUIRE(p.sel.indices.size() >= 3);
    for (ca::ConnectMethod m : kRoutes) {
        const std::string route = route_name(m);
        CAPTURE(route);
        const ca::Skeleton sk = connect(p, m);
        const ca::TopologyStats t = ca::topology(sk);
        CHECK(t.components == 1);
        CHECK(t.betti1 == 0);
        CHECK(sk.edges.size() == sk.balls.size() - 1);   // a tree ...
        size_t max_degree = 0;                            // ... that is a path
        std::vector<size_t> degree(sk.balls.size(), 0);
        for (const auto& e : sk.edges) max_degree = std::max({max_degree, ++degree[e[0]], ++degree[e[1]]});
        CHECK(max_degree <= 2);
        CHECK(sk.faces.empty());
        CHECK(leaves_shape(p, sk) == 0);
    }
}

TEST_CASE("test_connect: two disjoint spheres give two components") {
    const Prepared p = prepare(shapes::merged(shapes::sphere(1.0, 24, 48), shapes::sphere(1.0, 24, 48), {3.0, 0, 0}));
    for (ca::ConnectMethod m : kRoutes) {
        const std::string route = route_name(m);
        CAPTURE(route);
        const ca::Skeleton sk = connect(p, m);
        const ca::TopologyStats t = ca::topology(sk);
        CHECK(t.components == 2);
        CHECK(t.betti1 == 0);
        CHECK(leaves_shape(p, sk) == 0);
    }
}

TEST_CASE("test_connect: a thin plate gives a connected sheet of triangles") {
    const Prepared p = prepare(shapes::box(1.0, 1.0, 0.05), ca::Solver::greedy);
    REQUIRE(p.sel.indices.size() >= 3);
    for (ca::ConnectMethod m : kRoutes) {
        const std::string route = route_name(m);
        CAPTURE(route);
        const ca::Skeleton sk = connect(p, m);
        const ca::TopologyStats t = ca::topology(sk);
        CHECK(t.components == 1);
        CHECK(!sk.faces.empty());
        CHECK(leaves_shape(p, sk) == 0);
    }
}

TEST_CASE("test_connect: the medial route needs a surface, both routes take a point cloud and can be cancelled") {
    const ca::Mesh sphere = shapes::sphere(1.0, 24, 48);
    ca::Surface cloud;
    std::vector<ca::Vec3> normals;
    for (const ca::Vec3& v : sphere.vertices) normals.push_back(v.normalized());
    REQUIRE(ca::prepare_surface(ca::Mesh{sphere.vertices, {}}, normals, cloud).ok());
    ca::CandidateSet set;
    ca::Monitor monitor;
    REQUIRE(ca::generate_candidates(std::move(cloud), {}, monitor, set).ok());
    ca::Selection sel;
    REQUIRE(ca::select_balls(set, {}, monitor, sel).ok());
    ca::ConnectOptions opt;
    ca::Skeleton sk;
    for (ca::ConnectMethod m : kRoutes) {   // a cloud has its winding number: both routes connect it
        opt.method = m;
        CHECK(ca::connect_balls(set, sel, opt, monitor, sk).ok());
        CHECK(sk.balls.size() == sel.indices.size());
    }
    // the same balls without the surface (a set from caller arrays): only the power route
    ca::CandidateSet bare;
    bare.balls = set.balls;
    bare.cover_samples = set.cover_samples;
    bare.dense_samples = set.dense_samples;
    opt.method = ca::ConnectMethod::medial;
    const ca::Status st = ca::connect_balls(bare, sel, opt, monitor, sk);
    CHECK(st.code == ca::Code::invalid_argument);
    CHECK(st.message.find("mesh") != std::string::npos);
    opt.method = ca::ConnectMethod::power;
    CHECK(ca::connect_balls(bare, sel, opt, monitor, sk).ok());

    const Prepared p = prepare(shapes::capsule(2.0, 0.5, 48, 32));
    std::atomic<int> cancel{1};
    ca::Monitor stop;
    stop.cancel_flag = &cancel;
    for (ca::ConnectMethod m : kRoutes) {
        opt.method = m;
        CHECK(ca::connect_balls(p.set, p.sel, opt, stop, sk).code == ca::Code::cancelled);
    }
}

namespace {

// InsideTest::segment_inside / triangle_inside (with their probe shortcuts) against the rule
// evaluated directly at every test point, on local edges and triangles of candidate balls.
// Returns how many elements passed and failed (both must occur for the check to mean anything).
std::pair<int, int> compare_inside_test(ca::Mesh mesh) {
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(std::move(mesh), {}, surface).ok());
    ca::CandidateSet set;
    REQUIRE(ca::generate_candidates(std::move(surface), {}, ca::Monitor{}, set).ok());
    const ca::InsideTest test(set);
    const ca::WindingNumber winding(set.surface.mesh);
    const ca::MeshDistance distance(set.surface.mesh);
    const double h = 0.005;
    auto point_ok = [&](const ca::Vec3& q, double r, double tol, double outside_tol,
                        std::initializer_list<const ca::Ball*> own) {
        if (tol >= 0 && r - tol > 0 && !(distance.distance_below(q, r - tol) >= r - tol)) return false;
        for (const ca::Ball* b : own)
            if ((q - b->center).squaredNorm() < 0.95 * 0.95 * b->radius * b->radius) return true;
        if (winding.inside(q)) return true;
        return outside_tol > 0 && distance.distance_below(q, outside_tol) < outside_tol;
    };
    auto segment = [&](const ca::Ball& a, const ca::Ball& b, double tol, double outside_tol) {
        const int n = std::max(1, int(std::ceil((b.center - a.center).norm() / h)));
        for (int i = 1; i < n; ++i) {
            const double t = double(i) / n;
            if (!point_ok(a.center + (b.center - a.center) * t, (1 - t) * a.radius + t * b.radius, tol, outside_tol, {&a, &b}))
                return false;
        }
        return true;
    };
    auto triangle = [&](const ca::Ball& a, const ca::Ball& b, const ca::Ball& c, double tol) {
        const int n = std::max(1, int(std::ceil(std::max({(b.center - a.center).norm(), (c.center - b.center).norm(),
                                                          (a.center - c.center).norm()}) / h)));
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const int k = n - i - j;
                if (i == n || j == n || k == n) continue;
                const ca::Vec3 q = (a.center * i + b.center * j + c.center * k) / double(n);
                if (!point_ok(q, (a.radius * i + b.radius * j + c.radius * k) / double(n), tol, 0, {&a, &b, &c}))
                    return false;
            }
        return true;
    };
    ca::Rng rng(11);
    const auto& balls = set.balls;
    int pass = 0, fail = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const ca::Ball& a = balls[size_t(rng.uniform() * double(balls.size())) % balls.size()];
        // two partners among balls at most 0.3 away (skeleton elements are local)
        std::vector<size_t> near;
        for (size_t i = 0; i < balls.size(); ++i)
            if ((balls[i].center - a.center).norm() < 0.3) near.push_back(i);
        const ca::Ball& b = balls[near[size_t(rng.uniform() * double(near.size())) % near.size()]];
        const ca::Ball& c = balls[near[size_t(rng.uniform() * double(near.size())) % near.size()]];
        for (double tol : {-1.0, 0.02}) {
            const bool seg = test.segment_inside(a, b, h, tol, trial % 2 ? h : 0);
            CHECK(seg == segment(a, b, tol, trial % 2 ? h : 0));
            const bool tri = test.triangle_inside(a, b, c, h, tol);
            CHECK(tri == triangle(a, b, c, tol));
            (seg ? pass : fail)++;
            (tri ? pass : fail)++;
        }
    }
    return {pass, fail};
}

}  // namespace

TEST_CASE("test_connect: the inside test's shortcuts decide like direct evaluation") {
    SUBCASE("closed mesh (genus 3)") {
        const auto [pass, fail] = compare_inside_test(read_obj(std::string(CA_TEST_DATA) + "/genus3.obj"));
        CHECK(pass > 50);
        CHECK(fail > 50);
    }
    SUBCASE("open mesh (torus with a hole: the winding number is not integer-valued)") {
        ca::Mesh torus = shapes::torus(1.0, 0.3, 48, 16);
        torus.triangles.erase(torus.triangles.begin(), torus.triangles.begin() + 300);
        const auto [pass, fail] = compare_inside_test(std::move(torus));
        CHECK(pass > 50);
        CHECK(fail > 50);
    }
}

TEST_CASE("test_connect: medial reconnection takes a segment that passes the envelope rule when one exists") {
    // After the repairs every edge that fails the envelope rule was added by the reconnection's
    // centre-line pass. That pass may only run when no envelope-valid segment joins two
    // components of the envelope-valid edges. Fails with a centre-line-only reconnection (cow_spot
    // and fox then have 5 and 36 envelope-valid joining segments left).
    for (const std::string model : {"/cow_spot.obj", "/fox.obj", "/fish.obj"}) {
        CAPTURE(model);
        const Prepared p = prepare(read_obj(CA_TEST_DATA + model), ca::Solver::greedy);
        const ca::Skeleton sk = connect(p, ca::ConnectMethod::medial);
        const ca::InsideTest test(p.set);
        const double delta = p.sel.delta, h = delta / 4;
        ca::UnionFind uf(sk.balls.size());
        for (const auto& e : sk.edges)
            if (test.segment_inside(sk.balls[e[0]], sk.balls[e[1]], h, delta)) uf.unite(e[0], e[1]);
        size_t joinable = 0;
        for (uint32_t i = 0; i < sk.balls.size(); ++i)
            for (uint32_t j = i + 1; j < sk.balls.size(); ++j)
                if (uf.find(i) != uf.find(j) && test.segment_inside(sk.balls[i], sk.balls[j], h, delta, h)) ++joinable;
        CHECK(joinable == 0);
        CHECK(ca::topology(sk).components == 1);
    }
}


TEST_CASE("test_connect: skeleton loops match the input's genus on the bundled meshes") {
    // Medial route (the default for meshes). The fox (genus 0) had a spurious loop before loop
    // repair; the torus and the genus-3 solid keep one loop per handle.
    struct Case { const char* model; long genus, b1; };
    for (const Case c : {Case{"/torus.obj", 1, 1}, Case{"/genus3.obj", 3, 3}, Case{"/fox.obj", 0, 0}}) {
        CAPTURE(c.model);
        const Prepared p = prepare(read_obj(std::string(CA_TEST_DATA) + c.model));
        ca::ConnectOptions opt;
        opt.method = ca::ConnectMethod::medial;
        ca::Skeleton sk;
        ca::ConnectReport report;
        REQUIRE(ca::connect_balls(p.set, p.sel, opt, ca::Monitor{}, sk, &report).ok());
        const ca::TopologyStats t = ca::topology(sk);
        CHECK(report.genus == c.genus);
        CHECK(t.betti1 == c.b1);
        CHECK(t.components == 1);
        CHECK(report.thin_handles == size_t(c.genus - c.b1));
        CHECK(leaves_shape(p, sk) == 0);
    }
}

TEST_CASE("test_connect: on an open mesh no element's reconstruction bulges out through a curved hole cap") {
    // A tube of radius 1 around the z axis, closed at z = 0 by a disc, open at the top along the
    // rim z = 2 + 0.8 sin(2 phi); faces inward. Its cap (a fan from the rim's centroid, z = 2) is a
    // saddle: balls clamped to it touch it from below, and a slab between balls under its two high
    // lobes crosses it where it dips. Measured against the capped solid, the boundary of the
    // reconstruction stays within 1.5 delta outside it (the envelope rule's delta, plus sampling);
    // without the caps in the rule it reaches more than 5 delta out through the hole.
    const int rings = 24, seg = 64;
    const double pi = 3.14159265358979323846;
    ca::Mesh tube;
    tube.vertices.push_back({0, 0, 0});
    for (int i = 1; i <= rings; ++i)
        for (int j = 0; j < seg; ++j) {
            const double ph = 2 * pi * j / seg;
            const double r = i <= 4 ? i / 4.0 : 1.0;
            const double z = i <= 4 ? 0.0 : (double(i) / rings - 4.0 / rings) / (1 - 4.0 / rings) * (2 + 0.8 * std::sin(2 * ph));
            tube.vertices.push_back({r * std::cos(ph), r * std::sin(ph), z});
        }
    auto v = [&](int i, int j) { return uint32_t(1 + i * seg + (j % seg)); };
    for (int j = 0; j < seg; ++j) tube.triangles.push_back({0, v(0, j), v(0, j + 1)});   // inward
    for (int i = 0; i + 1 < rings; ++i)
        for (int j = 0; j < seg; ++j) {
            tube.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
            tube.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
        }
    REQUIRE(ca::signed_volume(tube) + ca::signed_volume(ca::hole_caps(tube)) < 0);
    const Prepared p = prepare(tube, ca::Solver::greedy);
    CHECK(p.set.surface.flipped);
    REQUIRE(p.set.queries.cap_distance);
    const ca::Skeleton sk = connect(p, ca::ConnectMethod::medial);
    // the capped solid, internal units
    ca::Mesh solid = p.set.surface.mesh;
    const ca::Mesh caps = ca::hole_caps(solid);
    const uint32_t offset = uint32_t(solid.vertices.size());
    solid.vertices.insert(solid.vertices.end(), caps.vertices.begin(), caps.vertices.end());
    for (const ca::Tri& t : caps.triangles) solid.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const ca::MeshDistance distance(solid);
    const ca::WindingNumber winding(solid);
    ca::Skeleton canonical = sk;
    ca::canonicalize(canonical);
    const ca::eval::Envelope env(canonical.balls, ca::eval::envelope_primitives(canonical));
    std::vector<ca::Vec3> boundary;
    REQUIRE(ca::eval::sample_boundary(env, ca::eval::boundary_pieces(canonical), 100000, 1, 1e-9, 1, ca::Monitor{},
                                      "test", 0, 1, boundary));
    double out = 0;
    for (const ca::Vec3& x : boundary)
        if (!winding.inside(x)) out = std::max(out, distance.distance(x));
    const double delta = 0.02;   // the default offset, internal units
    CHECK(out < 1.5 * delta);
}
