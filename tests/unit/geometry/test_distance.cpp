// test_distance.cpp: closest point on a triangle against a dense barycentric grid search
// (degenerate triangles included), the AABB tree against the brute-force minimum, and
// distance_below against the exact distance.
#include "distance.h"
#include "rng.h"
#include <doctest/doctest.h>
#include <cmath>
#include <limits>

using namespace ca;

namespace {

Vec3 rand_vec(Rng& rng, double lo, double hi) {
    return {lo + rng.uniform() * (hi - lo), lo + rng.uniform() * (hi - lo), lo + rng.uniform() * (hi - lo)};
}

// A UV sphere (stacks x slices, 2 * slices * (stacks - 1) triangles) plus a random soup.
Mesh test_mesh(uint32_t stacks, uint32_t slices, uint32_t soup, uint64_t seed) {
    const double pi = 3.14159265358979323846;
    Mesh m;
    m.vertices.push_back({0, 0, 1});
    for (uint32_t i = 1; i < stacks; ++i)
        for (uint32_t j = 0; j < slices; ++j) {
            const double th = pi * i / stacks, ph = 2 * pi * j / slices;
            m.vertices.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
        }
    m.vertices.push_back({0, 0, -1});
    const uint32_t south = uint32_t(m.vertices.size() - 1);
    auto id = [&](uint32_t i, uint32_t j) { return 1 + (i - 1) * slices + j % slices; };
    for (uint32_t j = 0; j < slices; ++j) {
        m.triangles.push_back({0, id(1, j), id(1, j + 1)});
        m.triangles.push_back({south, id(stacks - 1, j + 1), id(stacks - 1, j)});
        for (uint32_t i = 1; i + 1 < stacks; ++i) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    Rng rng(seed);
    for (uint32_t k = 0; k < soup; ++k) {
        const Vec3 c = rand_vec(rng, -2, 2);
        const uint32_t b = uint32_t(m.vertices.size());
        for (int v = 0; v < 3; ++v) m.vertices.push_back(c + rand_vec(rng, -0.2, 0.2));
        m.triangles.push_back({b, b + 1, b + 2});
    }
    return m;
}

}  // namespace

TEST_CASE("distance: closest point on a triangle vs dense barycentric grid search") {
    Rng rng(42);
    const int N = 120;   // grid step 1/N in barycentric coordinates
    for (int trial = 0; trial < 120; ++trial) {
        Vec3 a = rand_vec(rng, -1, 1), b = rand_vec(rng, -1, 1), c = rand_vec(rng, -1, 1);
        switch (trial % 6) {   // degenerate cases
            case 1: b = a; break;                                  // repeated vertex
            case 2: c = a + 0.3 * (b - a); break;                  // collinear, c between
            case 3: c = a + 1.7 * (b - a); break;                  // collinear, c beyond
            case 4: b = a; c = a; break;                           // a point
            case 5: c = a + 0.5 * (b - a) + Vec3(1e-9, 0, 0); break;   // needle
            default: break;
        }
        for (int k = 0; k < 6; ++k) {
            const Vec3 p = rand_vec(rng, -1.5, 1.5);
            const Vec3 cp = closest_point_on_triangle(p, a, b, c);
            REQUIRE(cp.allFinite());
            double grid = std::numeric_limits<double>::infinity(), on = grid;
            for (int i = 0; i <= N; ++i)
                for (int j = 0; i + j <= N; ++j) {
                    const Vec3 g = a + (double(i) / N) * (b - a) + (double(j) / N) * (c - a);
                    grid = std::min(grid, (g - p).norm());
                    on = std::min(on, (g - cp).norm());
                }
            const double h = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / N;
            const double d = (cp - p).norm();
            CHECK(d <= grid + 1e-12);   // no grid point of the triangle is closer
            CHECK(d >= grid - h);       // and the grid comes within its resolution
            CHECK(on <= h);             // the result lies on the triangle
        }
    }
    // the vertex, edge and face regions on a simple triangle
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    CHECK((closest_point_on_triangle(Vec3(-1, -1, 2), a, b, c) - a).norm() == 0.0);
    CHECK((closest_point_on_triangle(Vec3(2, -0.5, 0), a, b, c) - b).norm() == 0.0);
    CHECK((closest_point_on_triangle(Vec3(0.5, -1, 3), a, b, c) - Vec3(0.5, 0, 0)).norm() < 1e-15);
    CHECK((closest_point_on_triangle(Vec3(1, 1, -1), a, b, c) - Vec3(0.5, 0.5, 0)).norm() < 1e-15);
    CHECK((closest_point_on_triangle(Vec3(0.2, 0.3, 5), a, b, c) - Vec3(0.2, 0.3, 0)).norm() < 1e-15);
}

TEST_CASE("distance: AABB tree equals brute force") {
    const Mesh mesh = test_mesh(40, 64, 2000, 3);   // 4992 sphere + 2000 soup triangles
    const MeshDistance md(mesh);
    Rng rng(11);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p = i % 4 == 0 ? rand_vec(rng, -10, 10) : rand_vec(rng, -2.5, 2.5);
        Vec3 cp;
        uint32_t t = ~0u;
        const double d = md.distance(p, &cp, &t);
        const double ref = mesh_distance_brute_force(mesh, p);
        CHECK(std::abs(d - ref) <= 1e-12);
        REQUIRE(t < mesh.triangles.size());
        const Tri& f = mesh.triangles[t];
        const Vec3 expect = closest_point_on_triangle(p, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
        CHECK((cp - expect).norm() == 0.0);
        CHECK(std::abs((cp - p).norm() - d) <= 1e-12);
        // a point on the sphere or a vertex: distance 0
        if (i % 50 == 0) CHECK(md.distance(mesh.vertices[i % mesh.vertices.size()]) == 0.0);
    }
    CHECK(md.distance(Vec3(0, 0, 0)) == doctest::Approx(mesh_distance_brute_force(mesh, Vec3(0, 0, 0))));
}

TEST_CASE("distance: distance_below is consistent with distance") {
    const Mesh mesh = test_mesh(20, 32, 300, 8);
    const MeshDistance md(mesh);
    Rng rng(21);
    int below = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = rand_vec(rng, -3, 3);
        const double d = md.distance(p);
        const double upper = rng.uniform() * 1.0;
        const double r = md.distance_below(p, upper);
        if (d < upper) {
            CHECK(r == d);
            ++below;
        } else {
            CHECK(r == upper);
        }
        CHECK(md.distance_below(p, std::numeric_limits<double>::infinity()) == d);
        CHECK(md.distance_below(p, 0.0) == 0.0);
    }
    CHECK(below > 200);
    CHECK(below < 1900);
}

TEST_CASE("distance: unit cube, degenerate and empty meshes, move") {
    Mesh cube;
    for (int i = 0; i < 8; ++i) cube.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    MeshDistance md(cube);
    CHECK(md.distance(Vec3(0.5, 0.5, 0.5)) == doctest::Approx(0.5));
    CHECK(md.distance(Vec3(2, 0.5, 0.5)) == doctest::Approx(1.0));
    CHECK(md.distance(Vec3(2, 2, 2)) == doctest::Approx(std::sqrt(3.0)));
    CHECK(md.distance(Vec3(0.5, 0.2, 0.3)) == doctest::Approx(0.2));

    Mesh degenerate;
    degenerate.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {std::nan(""), 0, 0}};
    degenerate.triangles = {{0, 1, 2}, {1, 1, 1}, {0, 0, 2}, {0, 1, 3}, {0, 1, 9}};   // last two ignored
    const MeshDistance dd(degenerate);
    CHECK(dd.distance(Vec3(1, 1, 0)) == doctest::Approx(1.0));
    CHECK(dd.distance(Vec3(3, 0, 0)) == doctest::Approx(1.0));
    CHECK(mesh_distance_brute_force(degenerate, Vec3(-1, 0, 0)) == doctest::Approx(1.0));

    const Mesh empty;
    const MeshDistance de(empty);
    CHECK(std::isinf(de.distance(Vec3(0, 0, 0))));
    CHECK(de.distance_below(Vec3(0, 0, 0), 2.0) == 2.0);
    CHECK(std::isinf(mesh_distance_brute_force(empty, Vec3(0, 0, 0))));

    MeshDistance moved(std::move(md));
    CHECK(moved.distance(Vec3(2, 0.5, 0.5)) == doctest::Approx(1.0));
    moved = MeshDistance(empty);
    CHECK(std::isinf(moved.distance(Vec3(0, 0, 0))));
}
