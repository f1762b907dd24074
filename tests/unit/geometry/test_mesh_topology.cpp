// test_mesh_topology.cpp: genus per connected part from the Euler characteristic, on meshes of
// known genus (sphere 0, torus 1, the bundled genus-3 solid 3, two parts), and -1 for open and
// non-manifold parts; closedness, and the caps and topology the surface preparation keeps.
#include <doctest/doctest.h>

#include "hole_caps.h"
#include "mesh_topology.h"
#include "surface.h"
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

TEST_CASE("mesh_topology: closed means every edge balanced, not only two triangles on it") {
    CHECK(ca::mesh_topology(shapes::box(1, 1, 1)).closed);
    CHECK(ca::mesh_topology(shapes::torus(1.0, 0.3, 24, 12)).closed);
    ca::Mesh open = shapes::sphere(1.0, 12, 24);
    open.triangles.pop_back();
    CHECK_FALSE(ca::mesh_topology(open).closed);
    // one face turned: still two triangles on every edge (genus known), but its edges unbalanced
    ca::Mesh turned = shapes::box(1, 1, 1);
    std::swap(turned.triangles[0][1], turned.triangles[0][2]);
    const ca::MeshTopology t = ca::mesh_topology(turned);
    CHECK(t.genus == 0);
    CHECK_FALSE(t.closed);
    // an out-of-range corner is no surface: not closed, and the rest is still counted
    ca::Mesh bad = shapes::box(1, 1, 1);
    bad.triangles.push_back({0, 1, uint32_t(bad.vertices.size())});
    const ca::MeshTopology b = ca::mesh_topology(bad);
    CHECK_FALSE(b.closed);
    CHECK(b.genus == 0);
    CHECK(b.triangle_part.size() == bad.triangles.size());
}

TEST_CASE("prepare_surface: the caps and topology it keeps are those of the prepared mesh") {
    // an open box (no top) given inside out: prepared, it is flipped, and its caps with it
    ca::Mesh box = shapes::box(1, 2, 3);
    ca::Mesh open;
    open.vertices = box.vertices;
    for (const ca::Tri& f : box.triangles) {
        bool top = true;
        for (uint32_t v : f) top = top && box.vertices[v].z() > 2.9;
        if (!top) open.triangles.push_back({f[0], f[2], f[1]});
    }
    REQUIRE(open.triangles.size() + 2 == box.triangles.size());
    ca::Surface s;
    REQUIRE(ca::prepare_surface(open, {}, s).ok());
    CHECK(s.flipped);
    const ca::Mesh caps = ca::hole_caps(s.mesh);
    REQUIRE(caps.triangles.size() == 4);   // a fan over the four edges of the missing top
    CHECK(s.caps.triangles == caps.triangles);
    CHECK(s.caps.vertices == caps.vertices);
    CHECK_FALSE(s.topology.closed);
    CHECK(s.topology.genus == -1);
    // a torus: closed, genus 1, no caps
    ca::Surface t;
    REQUIRE(ca::prepare_surface(shapes::torus(1.0, 0.3, 24, 12), {}, t).ok());
    CHECK(t.topology.closed);
    CHECK(t.topology.genus == 1);
    CHECK(t.caps.triangles.empty());
    CHECK(t.topology.triangle_part.size() == t.mesh.triangles.size());
}
