// test_mesh_topology.cpp: genus per connected part from the Euler characteristic, on meshes of
// known genus (sphere 0, torus 1, the bundled genus-3 solid 3, two parts), and -1 for open and
// non-manifold parts.
#include <doctest/doctest.h>

#include "mesh_topology.h"
#include "support/mesh_convert.h"
#include "support/shapes.h"

#include <atomic>
#include <string>

namespace {

ca::Mesh bundled(const char* name) {
    ca::Mesh mesh;
    std::string error;
    REQUIRE_MESSAGE(read_core_mesh(std::string(CA_TEST_DATA) + name, mesh, error), error);
    return mesh;
}

}  // namespace

TEST_CASE("mesh_topology: closed meshes of known genus") {
    CHECK(ca::mesh_topology(shapes::sphere(1.0)).genus == 0);
    CHECK(ca::mesh_topology(shapes::box(1, 2, 3)).genus == 0);
    CHECK(ca::mesh_topology(shapes::torus(1.0, 0.3)).genus == 1);
    const ca::MeshTopology g3 = ca::mesh_topology(bundled("/genus3.obj"));
    CHECK(g3.genus == 3);
    CHECK(g3.part_genus.size() == 1);
    CHECK(ca::mesh_topology(bundled("/torus.obj")).genus == 1);
}

TEST_CASE("mesh_topology: parts are counted separately and summed") {
    const ca::Mesh two = shapes::merged(shapes::sphere(1.0, 12, 24), shapes::torus(1.0, 0.3, 24, 12), {4, 0, 0});
    const ca::MeshTopology t = ca::mesh_topology(two);
    REQUIRE(t.part_genus.size() == 2);
    CHECK(t.part_genus[0] == 0);
    CHECK(t.part_genus[1] == 1);
    CHECK(t.genus == 1);
    CHECK(t.triangle_part.front() == 0);
    CHECK(t.triangle_part.back() == 1);
}

TEST_CASE("mesh_topology: open and non-manifold parts are unknown") {
    ca::Mesh open = shapes::sphere(1.0, 12, 24);
    open.triangles.pop_back();   // a hole
    CHECK(ca::mesh_topology(open).genus == -1);
    // one part open, the other closed: the total is unknown, the closed part's genus is known
    const ca::MeshTopology mixed = ca::mesh_topology(shapes::merged(open, shapes::box(1, 1, 1), {4, 0, 0}));
    REQUIRE(mixed.part_genus.size() == 2);
    CHECK(mixed.part_genus[0] == -1);
    CHECK(mixed.part_genus[1] == 0);
    CHECK(mixed.genus == -1);
    // three triangles on one edge (a box with a fin)
    ca::Mesh fin = shapes::box(1, 1, 1);
    fin.vertices.push_back({0.5, -1, 0});
    fin.triangles.push_back({0, 1, uint32_t(fin.vertices.size() - 1)});
    CHECK(ca::mesh_topology(fin).genus == -1);
    CHECK(ca::mesh_topology(ca::Mesh{}).genus == -1);
}

TEST_CASE("mesh_topology: vertices at equal positions are welded") {
    // the box as a soup: every triangle with its own three vertices
    const ca::Mesh box = shapes::box(1, 1, 1);
    ca::Mesh soup;
    for (const ca::Tri& f : box.triangles) {
        const uint32_t base = uint32_t(soup.vertices.size());
        for (uint32_t v : f) soup.vertices.push_back(box.vertices[v]);
        soup.triangles.push_back({base, base + 1, base + 2});
    }
    const ca::MeshTopology t = ca::mesh_topology(soup);
    CHECK(t.part_genus.size() == 1);
    CHECK(t.genus == 0);
}

TEST_CASE("half-edge buckets: a stop request gives empty buckets, none gives the same buckets as no monitor") {
    const ca::Mesh m = shapes::torus(1.0, 0.3, 200, 100);   // 40 000 triangles
    const ca::HalfEdgeBuckets plain = ca::half_edge_buckets(m);
    REQUIRE(plain.start.size() == m.vertices.size() + 1);
    CHECK(plain.key.size() == 3 * m.triangles.size());
    std::atomic<int> flag{0};
    ca::Monitor monitor;
    monitor.cancel_flag = &flag;
    const ca::HalfEdgeBuckets unasked = ca::half_edge_buckets(m, {}, monitor);
    CHECK(unasked.start == plain.start);
    CHECK(unasked.key == plain.key);
    flag = 1;
    const ca::HalfEdgeBuckets stopped = ca::half_edge_buckets(m, {}, monitor);
    CHECK(stopped.start.empty());
    CHECK(stopped.key.empty());
}
