// test_skeleton.cpp: canonicalize() and topology() (components, isolated balls, Betti-1 over GF(2)).
#include <doctest/doctest.h>

#include "skeleton.h"

using namespace ca;

namespace {

Skeleton with_balls(size_t n) {
    Skeleton s;
    for (size_t i = 0; i < n; ++i) s.balls.push_back({Vec3(double(i), 0, 0), 0.1});
    return s;
}

// A closed n x m torus grid (n, m >= 3) as a 2-complex: V = nm, E = 3nm, F = 2nm.
Skeleton torus(uint32_t n, uint32_t m) {
    Skeleton s = with_balls(size_t(n) * m);
    auto id = [&](uint32_t i, uint32_t j) { return (i % n) * m + (j % m); };
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = 0; j < m; ++j) {
            s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    canonicalize(s);
    return s;
}

}  // namespace

TEST_CASE("canonicalize sorts, de-duplicates and adds face edges") {
    Skeleton s = with_balls(4);
    s.edges = {{2, 1}, {1, 2}, {3, 3}, {0, 3}};
    s.faces = {{2, 0, 1}, {1, 2, 0}, {0, 0, 1}};
    canonicalize(s);
    REQUIRE(s.faces.size() == 1);
    CHECK(s.faces[0] == Tri{0, 1, 2});
    const std::vector<std::array<uint32_t, 2>> expected{{0, 1}, {0, 2}, {0, 3}, {1, 2}};
    CHECK(s.edges == expected);
}

TEST_CASE("topology: a loop of three edges has b1 = 1, filled it has b1 = 0") {
    Skeleton s = with_balls(3);
    s.edges = {{0, 1}, {1, 2}, {0, 2}};
    TopologyStats t = topology(s);
    CHECK(t.components == 1);
    CHECK(t.isolated == 0);
    CHECK(t.betti1 == 1);

    s.faces = {{0, 1, 2}};
    t = topology(s);
    CHECK(t.components == 1);
    CHECK(t.betti1 == 0);
}

TEST_CASE("topology: components and isolated balls") {
    Skeleton s = with_balls(6);
    s.edges = {{0, 1}, {1, 2}, {3, 4}};
    TopologyStats t = topology(s);
    CHECK(t.components == 3);   // {0,1,2}, {3,4}, {5}
    CHECK(t.isolated == 1);
    CHECK(t.betti1 == 0);

    Skeleton two = with_balls(6);
    two.faces = {{0, 1, 2}, {3, 4, 5}};
    t = topology(two);
    CHECK(t.components == 2);
    CHECK(t.isolated == 0);
    CHECK(t.betti1 == 0);

    Skeleton empty;
    t = topology(empty);
    CHECK(t.components == 0);
    CHECK(t.betti1 == 0);
}

TEST_CASE("topology: tetrahedron surface has b1 = 0, two loops have b1 = 2") {
    Skeleton tet = with_balls(4);
    tet.faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    TopologyStats t = topology(tet);
    CHECK(t.components == 1);
    CHECK(t.betti1 == 0);

    // figure eight: two triangles of edges sharing ball 0
    Skeleton eight = with_balls(5);
    eight.edges = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {3, 4}, {0, 4}};
    CHECK(topology(eight).betti1 == 2);
}

TEST_CASE("topology: torus triangulation has b1 = 2") {
    Skeleton s = torus(6, 5);
    CHECK(s.balls.size() == 30);
    CHECK(s.edges.size() == 90);
    CHECK(s.faces.size() == 60);
    TopologyStats t = topology(s);
    CHECK(t.components == 1);
    CHECK(t.betti1 == 2);

    // remove one face: b2 drops to 0, b1 stays 2
    s.faces.pop_back();
    CHECK(topology(s).betti1 == 2);
}

TEST_CASE("topology: a few thousand faces") {
    Skeleton s = torus(60, 40);   // 4800 faces
    TopologyStats t = topology(s);
    CHECK(t.components == 1);
    CHECK(t.betti1 == 2);
}
