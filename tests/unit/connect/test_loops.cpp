// test_loops.cpp: repair_loops on synthetic skeletons with a known spurious loop: a square of
// balls inside a box (the loop is filled by a fan of two triangles) and a square around the gap
// of a U-shaped solid (no fan stays inside: the edge across the gap, its longest, is cut).
#include <doctest/doctest.h>

#include "candidates.h"
#include "connect.h"
#include "support/shapes.h"

namespace {

ca::CandidateSet shape(ca::Mesh mesh) {
    ca::CandidateSet set;
    set.surface.topology = ca::mesh_topology(mesh);
    set.surface.mesh = std::move(mesh);
    REQUIRE(ca::build_mesh_queries(set.surface.mesh, 1, {}, set.queries));   // as the candidate step builds them
    return set;
}

ca::Skeleton square(const std::vector<ca::Vec3>& corners, double radius) {
    ca::Skeleton s;
    for (const ca::Vec3& c : corners) s.balls.push_back({c, radius});
    s.edges = {{0, 1}, {1, 2}, {2, 3}, {0, 3}};
    ca::canonicalize(s);
    return s;
}

}  // namespace

TEST_CASE("repair_loops: a square inside a box is filled") {
    const ca::CandidateSet set = shape(shapes::box(3, 3, 1));
    const ca::InsideTest test(set);
    ca::Skeleton s = square({{0.5, 0.5, 0.5}, {2.5, 0.5, 0.5}, {2.5, 2.5, 0.5}, {0.5, 2.5, 0.5}}, 0.4);
    REQUIRE(ca::topology(s).betti1 == 1);
    CHECK(ca::detail::repair_loops(test, 0.05, -1, 0, s) == 0);
    const ca::TopologyStats t = ca::topology(s);
    CHECK(t.betti1 == 0);
    CHECK(t.components == 1);
    CHECK(s.faces.size() == 2);   // a fan over the square
    CHECK(s.edges.size() == 5);   // with one diagonal
    // genus 1 (or unknown): the loop is kept
    ca::Skeleton kept = square({{0.5, 0.5, 0.5}, {2.5, 0.5, 0.5}, {2.5, 2.5, 0.5}, {0.5, 2.5, 0.5}}, 0.4);
    CHECK(ca::detail::repair_loops(test, 0.05, -1, 1, kept) == 0);
    CHECK(ca::topology(kept).betti1 == 1);
    CHECK(ca::detail::repair_loops(test, 0.05, -1, -1, kept) == 0);
    CHECK(ca::topology(kept).betti1 == 1);
}

TEST_CASE("repair_loops: a square around the gap of a U is cut at its longest edge") {
    // arms [0,1] x [0,3] and [2,3] x [0,3] on a base [0,3] x [0,1], all 1 thick
    const ca::Mesh u = shapes::merged(shapes::merged(shapes::box(1, 3, 1), shapes::box(1, 3, 1), {2, 0, 0}),
                                      shapes::box(3, 1, 1));
    const ca::CandidateSet set = shape(u);
    const ca::InsideTest test(set);
    // ball 3 lower than ball 2 so that the edge across the gap (2-3) is the longest
    ca::Skeleton s = square({{0.5, 0.5, 0.5}, {2.5, 0.5, 0.5}, {2.5, 2.2, 0.5}, {0.5, 2.5, 0.5}}, 0.4);
    s.edges = {{0, 1}, {1, 2}, {0, 3}, {2, 3}};
    ca::canonicalize(s);
    CHECK(ca::detail::repair_loops(test, 0.05, -1, 0, s) == 0);
    const ca::TopologyStats t = ca::topology(s);
    CHECK(t.betti1 == 0);
    CHECK(t.components == 1);
    CHECK(s.faces.empty());
    const std::vector<std::array<uint32_t, 2>> expected = {{0, 1}, {0, 3}, {1, 2}};
    CHECK(s.edges == expected);
    // genus 1: the loop is kept, and thin_handles counts nothing missing
    ca::Skeleton kept = square({{0.5, 0.5, 0.5}, {2.5, 0.5, 0.5}, {2.5, 2.2, 0.5}, {0.5, 2.5, 0.5}}, 0.4);
    CHECK(ca::detail::repair_loops(test, 0.05, -1, 1, kept) == 0);
    // a tree has no loop for a genus-1 shape's handle
    ca::Skeleton tree = s;
    CHECK(ca::detail::repair_loops(test, 0.05, -1, 1, tree) == 1);
}
