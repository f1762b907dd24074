// test_winding.cpp: generalised winding numbers: exact values on closed meshes (cube, sphere,
// torus), the hierarchical approximation against the brute-force sum (closed, open, soup),
// inverted orientation, signed volume, degenerate and empty input, the stored far-field polynomial.
#include "bvh.h"
#include "distance.h"
#include "far_field.h"
#include "winding.h"
#include "rng.h"
#include "support/shapes.h"
#include <doctest/doctest.h>
#include <Eigen/Geometry>
#include <cmath>

using namespace ca;

namespace {

constexpr double kPi = 3.14159265358979323846;

Mesh unit_cube() {   // [0,1]^3, outward-facing
    Mesh m;
    for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

Mesh merge(Mesh a, const Mesh& b) {
    const uint32_t off = uint32_t(a.vertices.size());
    a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (Tri f : b.triangles) a.triangles.push_back({f[0] + off, f[1] + off, f[2] + off});
    return a;
}

Mesh inverted(Mesh m) {
    for (Tri& f : m.triangles) std::swap(f[1], f[2]);
    return m;
}

Vec3 random_point(Rng& rng, const Vec3& lo, const Vec3& hi) {
    return {lo.x() + rng.uniform() * (hi.x() - lo.x()), lo.y() + rng.uniform() * (hi.y() - lo.y()),
            lo.z() + rng.uniform() * (hi.z() - lo.z())};
}

// Compares the approximation with the exact sum on `n` random points of the box, ignoring the
// points closer than `margin` to the surface. Returns the largest difference.
double max_error(const Mesh& mesh, double beta, int n, const Vec3& lo, const Vec3& hi, double margin,
                 int* compared = nullptr, int* disagreements = nullptr) {
    const WindingNumber w(mesh, beta);
    const MeshDistance dist(mesh);
    Rng rng(1234);
    double err = 0;
    int count = 0, bad = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3 q = random_point(rng, lo, hi);
        if (dist.distance_below(q, margin) < margin) continue;
        const double exact = winding_number_brute_force(mesh, q), fast = w(q);
        REQUIRE(std::isfinite(fast));
        err = std::max(err, std::abs(fast - exact));
        bad += w.inside(q) != (exact > 0.5);
        ++count;
    }
    if (compared) *compared = count;
    if (disagreements) *disagreements = bad;
    return err;
}

}  // namespace

TEST_CASE("winding: unit cube, inside 1, outside 0, signed volume 1, inverted -1") {
    const Mesh cube = unit_cube();
    CHECK(signed_volume(cube) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(signed_volume(inverted(cube)) == doctest::Approx(-1.0).epsilon(1e-12));
    const WindingNumber w(cube), wi(inverted(cube));
    Rng rng(7);
    for (int i = 0; i < 200; ++i) {
        const Vec3 in = random_point(rng, Vec3::Constant(0.01), Vec3::Constant(0.99));
        const Vec3 out = random_point(rng, Vec3::Constant(-2), Vec3::Constant(3));
        const bool out_inside = (out.array() > 0).all() && (out.array() < 1).all();
        CHECK(winding_number_brute_force(cube, in) == doctest::Approx(1.0).epsilon(1e-9));
        CHECK(w(in) == doctest::Approx(1.0).epsilon(1e-9));   // inside, every node is near: exact sums
        CHECK(wi(in) == doctest::Approx(-1.0).epsilon(1e-9));
        CHECK(w.inside(in));
        CHECK_FALSE(wi.inside(in));
        if (!out_inside) {
            CHECK(std::abs(winding_number_brute_force(cube, out)) < 1e-9);
            CHECK(std::abs(w(out)) < 0.01);
            CHECK_FALSE(w.inside(out));
        }
    }
    // just inside a face
    CHECK(winding_number_brute_force(cube, Vec3(0.5, 0.5, 1e-3)) == doctest::Approx(1.0).epsilon(1e-9));
}

TEST_CASE("winding: sphere and torus, exact winding number matches the analytic inside test") {
    const Mesh mesh = merge(shapes::icosphere(1.0, 4, Vec3(0, 0, 0)), shapes::torus(1.2, 0.4, 64, 32, Vec3(3, 0, 0)));
    REQUIRE(mesh.triangles.size() == 5120 + 4096);
    CHECK(signed_volume(mesh) > 0);
    const WindingNumber w(mesh);
    Rng rng(99);
    int checked = 0;
    for (int i = 0; i < 1500; ++i) {
        const Vec3 q = random_point(rng, Vec3(-1.5, -2, -1), Vec3(5, 2, 1));
        const double ds = q.norm() - 1.0;   // analytic signed distances (polygon error < 0.01)
        const Vec3 t = q - Vec3(3, 0, 0);
        const double dt = std::hypot(std::hypot(t.x(), t.y()) - 1.2, t.z()) - 0.4;
        if (std::abs(ds) < 0.03 || std::abs(dt) < 0.03) continue;
        const bool in = ds < 0 || dt < 0;
        const double fast = w(q);
        CHECK(std::abs(fast - (in ? 1.0 : 0.0)) < 0.01);
        CHECK(w.inside(q) == in);
        if (i % 10 == 0) CHECK(std::abs(winding_number_brute_force(mesh, q) - (in ? 1.0 : 0.0)) < 1e-6);
        ++checked;
    }
    CHECK(checked > 1000);
    const WindingNumber wi(inverted(mesh));
    CHECK(std::abs(wi(Vec3(0, 0, 0)) + 1.0) < 0.01);
    CHECK(std::abs(wi(Vec3(4.2, 0, 0)) + 1.0) < 0.01);
    CHECK(signed_volume(inverted(mesh)) == doctest::Approx(-signed_volume(mesh)));
    // volume of the polygonal sphere + torus, close to the analytic 4/3 pi + 2 pi^2 R r^2
    CHECK(signed_volume(mesh) == doctest::Approx(4.0 / 3.0 * kPi + 2 * kPi * kPi * 1.2 * 0.16).epsilon(0.01));
}

TEST_CASE("winding: hierarchical approximation vs brute force (closed, open, soup)") {
    const Mesh closed = merge(shapes::icosphere(1.0, 4, Vec3(0, 0, 0)), shapes::torus(1.2, 0.4, 64, 32, Vec3(3, 0, 0)));
    const Vec3 lo(-2, -2.5, -1.5), hi(5.5, 2.5, 1.5);
    int compared = 0, bad = 0;
    const double err2 = max_error(closed, 2.0, 800, lo, hi, 0.02, &compared, &bad);
    CHECK(compared > 700);
    CHECK(err2 < 0.01);   // beta = 2, points at least 0.02 from the surface (measured 5.6e-3)
    CHECK(bad == 0);
    // the approximation improves with beta
    CHECK(max_error(closed, 4.0, 200, lo, hi, 0.02) < err2);

    // open: a sphere with a cap removed (w varies continuously through the hole)
    Mesh open = shapes::icosphere(1.0, 4, Vec3(0, 0, 0));
    std::vector<Tri> kept;
    for (const Tri& f : open.triangles)
        if ((open.vertices[f[0]] + open.vertices[f[1]] + open.vertices[f[2]]).z() / 3 < 0.7) kept.push_back(f);
    open.triangles = kept;
    REQUIRE(open.triangles.size() < 5120);
    CHECK(max_error(open, 2.0, 600, Vec3::Constant(-1.5), Vec3::Constant(1.5), 0.02) < 0.01);
    const WindingNumber wo(open);
    CHECK(wo(Vec3(0, 0, 0)) > 0.6);
    CHECK(wo(Vec3(0, 0, 0)) < 0.99);

    // soup: 3000 random triangles of random size and orientation
    Mesh soup;
    Rng rng(5);
    for (uint32_t i = 0; i < 3000; ++i) {
        const Vec3 c = random_point(rng, Vec3::Constant(-1), Vec3::Constant(1));
        for (int k = 0; k < 3; ++k) soup.vertices.push_back(c + 0.1 * random_point(rng, Vec3::Constant(-1), Vec3::Constant(1)));
        soup.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    CHECK(max_error(soup, 2.0, 500, Vec3::Constant(-1.5), Vec3::Constant(1.5), 0.02) < 0.02);
}

TEST_CASE("winding: far field, degenerate triangles, empty mesh, move") {
    const Mesh sphere = shapes::icosphere(1.0, 3, Vec3(0.3, -0.2, 0.1));
    const WindingNumber w(sphere);
    for (const Vec3& q : {Vec3(10, 0, 0), Vec3(0, -50, 3), Vec3(1e4, 1e4, 1e4)})
        CHECK(std::abs(w(q) - winding_number_brute_force(sphere, q)) < 1e-6);

    // zero-area triangles (repeated and collinear vertices) change nothing and give no NaN
    Mesh cube = unit_cube();
    cube.vertices.push_back({2, 2, 2});
    cube.triangles.insert(cube.triangles.end(), {{0, 0, 0}, {1, 1, 3}, {0, 7, 7}, {0, 8, 8}});
    cube.vertices.push_back({0.5, 0.5, 0.5});   // collinear with vertices 0 and 7
    cube.triangles.push_back({0, 9, 7});
    cube.triangles.push_back({0, 1, 42});        // out-of-range index: ignored
    for (int i = 0; i < 20; ++i) cube.triangles.push_back({9, 9, 9});   // enough for a 2-level tree
    WindingNumber wd(cube);
    for (const Vec3& q : {Vec3(0.5, 0.5, 0.5), Vec3(0.25, 0.25, 0.25), Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(3, 0, 0)}) {
        CHECK(std::isfinite(wd(q)));
        CHECK(std::isfinite(winding_number_brute_force(cube, q)));
    }
    CHECK(wd(Vec3(0.5, 0.5, 0.5)) == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(wd(Vec3(0.25, 0.25, 0.25)) == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(std::abs(wd(Vec3(3, 0, 0))) < 1e-3);   // approximated (the tree has several levels)
    CHECK(std::abs(winding_number_brute_force(cube, Vec3(3, 0, 0))) < 1e-12);
    CHECK(signed_volume(cube) == doctest::Approx(1.0).epsilon(1e-12));

    const Mesh empty;
    const WindingNumber we(empty);
    CHECK(we(Vec3(0, 0, 0)) == 0.0);
    CHECK(winding_number_brute_force(empty, Vec3(0, 0, 0)) == 0.0);
    CHECK(signed_volume(empty) == 0.0);

    WindingNumber moved(std::move(wd));
    CHECK(moved(Vec3(0.5, 0.5, 0.5)) == doctest::Approx(1.0).epsilon(1e-9));
    moved = WindingNumber(empty);
    CHECK(moved(Vec3(0.5, 0.5, 0.5)) == 0.0);
}

TEST_CASE("winding: open meshes decide inside at w > 1/2, also where w lies in (0.3, 0.5)") {
    // A cube without its top face and the lower half of a sphere: above the hole the winding
    // number falls through (0.3, 0.5) and (0.5, 0.7), so a threshold other than 1/2 shows.
    Mesh cube = unit_cube();
    std::vector<Tri> sides;
    for (const Tri& f : cube.triangles)
        if (cube.vertices[f[0]].z() + cube.vertices[f[1]].z() + cube.vertices[f[2]].z() < 3) sides.push_back(f);
    cube.triangles = sides;
    REQUIRE(cube.triangles.size() == 10);
    Mesh bowl = shapes::icosphere(1.0, 3, Vec3(0, 0, 0));
    std::vector<Tri> lower;
    for (const Tri& f : bowl.triangles)
        if ((bowl.vertices[f[0]] + bowl.vertices[f[1]] + bowl.vertices[f[2]]).z() < 0) lower.push_back(f);
    bowl.triangles = lower;
    struct Case { const Mesh* mesh; Vec3 axis_point; };
    for (const Case& c : {Case{&cube, Vec3(0.5, 0.5, 0)}, Case{&bowl, Vec3(0, 0, 0)}}) {
        const WindingNumber w(*c.mesh);
        int low = 0, high = 0;
        for (int i = 0; i <= 200; ++i) {
            // along the axis through the hole, from inside to above it, and slightly off-axis
            const Vec3 q = c.axis_point + Vec3(0.05, -0.03, -0.4 + 2.0 * i / 200.0);
            const double exact = winding_number_brute_force(*c.mesh, q);
            CHECK(w.inside(q) == (exact > 0.5));
            low += exact > 0.3 && exact < 0.49;
            high += exact > 0.51 && exact < 0.7;
        }
        CHECK(low >= 3);
        CHECK(high >= 3);
    }
}

TEST_CASE("winding: inside(q) is w(q) > 1/2 exactly, also where w crosses 1/2 within one ulp") {
    // inside() decides from a cheaper walk and falls back to w() only inside its rounding bound;
    // the bisected crossings put w within an ulp of 1/2, where a bound too small shows.
    Mesh open_cube = unit_cube();
    std::vector<Tri> sides;
    for (const Tri& f : open_cube.triangles)
        if (open_cube.vertices[f[0]].z() + open_cube.vertices[f[1]].z() + open_cube.vertices[f[2]].z() < 3)
            sides.push_back(f);
    open_cube.triangles = sides;
    Mesh bowl = shapes::icosphere(1.0, 2, Vec3(0, 0, 0));
    std::vector<Tri> lower;
    for (const Tri& f : bowl.triangles)
        if ((bowl.vertices[f[0]] + bowl.vertices[f[1]] + bowl.vertices[f[2]]).z() < 0) lower.push_back(f);
    bowl.triangles = lower;
    Mesh sphere = shapes::icosphere(1.0, 3, Vec3(0.1, -0.2, 0.3));
    Mesh cube = unit_cube();
    Rng rng(99);
    int crossings = 0, compared = 0;
    for (const Mesh* mesh : {&cube, &sphere, &open_cube, &bowl}) {
        const WindingNumber w(*mesh);
        auto agree = [&](const Vec3& q) {
            CHECK(w.inside(q) == (w(q) > 0.5));
            const double exact = winding_number_brute_force(*mesh, q);
            if (std::abs(exact - 0.5) > 0.01) {
                CHECK(w.inside(q) == (exact > 0.5));
                ++compared;
            }
        };
        Vec3 lo = mesh->vertices[0], hi = lo;
        for (const Vec3& v : mesh->vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
        const Vec3 pad = 0.3 * (hi - lo);
        for (int i = 0; i < 300; ++i) agree(random_point(rng, lo - pad, hi + pad));
        for (const Tri& f : mesh->triangles) {   // just off every face, both sides
            const Vec3 c = (mesh->vertices[f[0]] + mesh->vertices[f[1]] + mesh->vertices[f[2]]) / 3.0;
            const Vec3 n = (mesh->vertices[f[1]] - mesh->vertices[f[0]]).cross(mesh->vertices[f[2]] - mesh->vertices[f[0]]).normalized();
            for (double h : {1e-9, 1e-6, 1e-3}) agree(c + h * n), agree(c - h * n);
        }
        // segments from random points to random points: where w is on both sides of 1/2, bisect
        // to two adjacent points (w of the one above 1/2 exceeds it by rounding only)
        for (int i = 0; i < 400; ++i) {
            Vec3 a = random_point(rng, lo - pad, hi + pad), b = random_point(rng, lo - pad, hi + pad);
            if ((w(a) > 0.5) == (w(b) > 0.5)) continue;
            for (int k = 0; k < 200; ++k) {
                const Vec3 mid = 0.5 * (a + b);
                if (mid == a || mid == b) break;
                ((w(mid) > 0.5) == (w(a) > 0.5) ? a : b) = mid;
            }
            CHECK(w.inside(a) == (w(a) > 0.5));
            CHECK(w.inside(b) == (w(b) > 0.5));
            ++crossings;
        }
    }
    CHECK(crossings >= 200);
    CHECK(compared >= 1000);
}

TEST_CASE("winding: the tree and the expansions built on 2 to 16 threads equal one thread's") {
    const Mesh mesh = merge(shapes::icosphere(1.0, 4, Vec3(0, 0, 0)), shapes::torus(1.2, 0.4, 64, 32, Vec3(3, 0, 0)));
    const auto one = detail::build_triangle_tree(mesh, 1);
    REQUIRE(one->bvh.nodes.size() > 1000);
    // 3 threads: four subtrees on three workers; 16: four levels split before the workers start
    for (int threads : {2, 3, 4, 8, 16}) {
        INFO("threads ", threads);
        const auto two = detail::build_triangle_tree(mesh, threads);
        REQUIRE(one->bvh.nodes.size() == two->bvh.nodes.size());
        CHECK(one->bvh.order == two->bvh.order);
        CHECK(one->tris == two->tris);
        size_t differ = 0;
        for (size_t n = 0; n < one->bvh.nodes.size(); ++n) {
            const detail::BvhNode &a = one->bvh.nodes[n], &b = two->bvh.nodes[n];
            differ += a.lo != b.lo || a.hi != b.hi || a.begin != b.begin || a.end != b.end || a.left != b.left ||
                      a.right != b.right;
        }
        CHECK(differ == 0);
    }
    const WindingNumber w1(one, 2.0, 1);
    for (int threads : {2, 3, 4, 16}) {
        INFO("far fields on ", threads, " threads");
        const WindingNumber w2(one, 2.0, threads);
        Rng rng(11);
        size_t unequal = 0;
        for (int i = 0; i < 300; ++i) {
            const Vec3 q = random_point(rng, Vec3(-2, -2.5, -1.5), Vec3(5.5, 2.5, 1.5));
            unequal += w1(q) != w2(q);
        }
        CHECK(unequal == 0);
    }
}

TEST_CASE("winding: a far field's stored polynomial equals the expansion's three terms") {
    // random moments (Q not symmetric: the polynomial must read all nine entries as eval does),
    // evaluated in every direction from 2 to 1000 radii away
    Rng rng(5);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
    double worst = 0;
    for (int i = 0; i < 200; ++i) {
        detail::Expansion e;
        e.centre = Vec3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3));
        e.radius = uniform(0.01, 2);
        const double s = e.radius;
        for (int k = 0; k < 3; ++k) e.N[k] = uniform(-1, 1) * s * s;
        for (int k = 0; k < 9; ++k) e.M.data()[k] = uniform(-1, 1) * s * s * s;
        for (auto& q : e.Q)
            for (int k = 0; k < 9; ++k) q.data()[k] = uniform(-1, 1) * s * s * s * s;
        const detail::FarField f(e, 2.0);
        CHECK(f.reach2 == doctest::Approx(4 * e.radius * e.radius));
        for (int j = 0; j < 20; ++j) {
            const Vec3 dir = random_point(rng, Vec3::Constant(-1), Vec3::Constant(1)).normalized();
            const Vec3 q = e.centre + e.radius * std::pow(10.0, uniform(0.3, 3)) * dir;
            // scale: the size of the terms (each at most ~|N| / |r|^2 in magnitude)
            const double scale = e.N.norm() / (q - e.centre).squaredNorm() + 1e-300;
            worst = std::max(worst, std::abs(f.eval(q) - e.eval(q)) / scale);
        }
    }
    CHECK(worst < 1e-12);
}
