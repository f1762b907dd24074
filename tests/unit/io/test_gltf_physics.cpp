// test_gltf_physics.cpp: the glTF physics writer (examples/io/gltf_physics.h): colliders under a
// turned and moved parent land where their world placement says (the parent's transform composed
// with the node's, here with Eigen); kinematic bodies and Godot's OMI twins (capsule height
// including the caps) when every shape has one; a shape without volume keeps its node but gets no
// collider; write_colliders' .glb read back (the mesh, the collider nodes) and its refusals.
#include <doctest/doctest.h>

#include "gltf_physics.h"
#include "io_test_util.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>

namespace {

using nlohmann::json;

json empty_document() {
    return {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", json::array()}}}}, {"nodes", json::array()}};
}

caio::ColliderShape box(double x, double y, double z) {
    caio::ColliderShape c;
    c.kind = 2;
    c.translation[0] = x, c.translation[1] = y, c.translation[2] = z;
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
    c.rotation[0] = q.x(), c.rotation[1] = q.y(), c.rotation[2] = q.z(), c.rotation[3] = q.w();
    c.size[0] = 1, c.size[1] = 2, c.size[2] = 3;
    return c;
}

Eigen::Quaterniond quat(const json& r) { return Eigen::Quaterniond(r[3].get<double>(), r[0].get<double>(), r[1].get<double>(), r[2].get<double>()); }

}  // namespace

TEST_CASE("add_colliders: under a moved and turned parent, each collider lands at its world placement") {
    json doc = empty_document();
    const Eigen::Quaterniond parent_q(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
    const Eigen::Vector3d parent_t(1, 2, 3);
    doc["nodes"].push_back({{"name", "bone"}, {"translation", {1, 2, 3}},
                            {"rotation", {parent_q.x(), parent_q.y(), parent_q.z(), parent_q.w()}}});
    doc["scenes"][0]["nodes"].push_back(0);
    caio::gltf::ColliderOptions o;
    o.parent = 0;
    for (int k = 0; k < 3; ++k) o.parent_translation[k] = parent_t[k];
    o.parent_rotation[0] = parent_q.x(), o.parent_rotation[1] = parent_q.y(), o.parent_rotation[2] = parent_q.z(),
    o.parent_rotation[3] = parent_q.w();
    o.kinematic = true;
    caio::ColliderShape capsule;
    capsule.kind = 1, capsule.radius_top = capsule.radius_bottom = 0.5, capsule.height = 2;
    capsule.translation[0] = 4;
    const std::vector<caio::ColliderShape> shapes = {box(-1, 5, 2), capsule};
    const std::vector<size_t> nodes = caio::gltf::add_colliders(doc, shapes, o);
    REQUIRE(nodes.size() == 2);
    CHECK(doc["nodes"][0]["children"] == json{nodes[0], nodes[1]});
    CHECK(doc["scenes"][0]["nodes"] == json{0});   // no group node: the parent was given
    for (size_t i = 0; i < 2; ++i) {
        const json& n = doc["nodes"][nodes[i]];
        const Eigen::Vector3d t(n["translation"][0].get<double>(), n["translation"][1].get<double>(), n["translation"][2].get<double>());
        const Eigen::Quaterniond q = n.contains("rotation") ? quat(n["rotation"]) : Eigen::Quaterniond::Identity();
        const Eigen::Vector3d world_t = parent_q * t + parent_t;
        const Eigen::Quaterniond world_q = parent_q * q;
        const caio::ColliderShape& c = shapes[i];
        const Eigen::Quaterniond want(c.rotation[3], c.rotation[0], c.rotation[1], c.rotation[2]);
        CHECK((world_t - Eigen::Vector3d(c.translation[0], c.translation[1], c.translation[2])).norm() < 1e-12);
        CHECK(world_q.angularDistance(want) < 1e-9);
        CHECK(n["extensions"]["KHR_physics_rigid_bodies"]["motion"] == json{{"isKinematic", true}});
        CHECK(n["extensions"]["OMI_physics_body"]["motion"] == json{{"type", "kinematic"}});
    }
    // every shape has an OMI twin: a box, and a capsule of equal radii whose OMI height has its caps
    const json& omi = doc["extensions"]["OMI_physics_shape"]["shapes"];
    REQUIRE(omi.size() == 2);
    CHECK(omi[0] == json{{"type", "box"}, {"box", {{"size", {1.0, 2.0, 3.0}}}}});
    CHECK(omi[1] == json{{"type", "capsule"}, {"capsule", {{"radius", 0.5}, {"height", 3.0}}}});
    CHECK(doc["extensions"]["KHR_implicit_shapes"]["shapes"][1] ==
          json{{"type", "capsule"}, {"capsule", {{"height", 2.0}, {"radiusTop", 0.5}, {"radiusBottom", 0.5}}}});
    CHECK(doc["extensionsUsed"] == json{"KHR_implicit_shapes", "KHR_physics_rigid_bodies", "OMI_physics_shape", "OMI_physics_body"});
}

TEST_CASE("add_colliders: a shape without volume keeps its node and gets no collider") {
    json doc = empty_document();
    caio::ColliderShape point;   // a sphere of radius 0
    caio::ColliderShape flat = box(0, 0, 0);
    flat.size[1] = 0;
    caio::ColliderShape ball;
    ball.radius_top = ball.radius_bottom = 1;
    const std::vector<size_t> nodes = caio::gltf::add_colliders(doc, {point, flat, ball}, caio::gltf::ColliderOptions{});
    REQUIRE(nodes.size() == 3);
    CHECK(doc["scenes"][0]["nodes"] == json{0});
    CHECK(doc["nodes"][0]["name"] == "colliders");
    CHECK(doc["nodes"][nodes[0]].count("extensions") == 0);
    CHECK(doc["nodes"][nodes[1]].count("extensions") == 0);
    CHECK(doc["nodes"][nodes[2]]["extensions"]["KHR_physics_rigid_bodies"] == json{{"collider", {{"geometry", {{"shape", 0}}}}}});
    CHECK(doc["nodes"][nodes[2]]["extensions"]["KHR_physics_rigid_bodies"].count("motion") == 0);   // static
    CHECK(doc["extensions"]["KHR_implicit_shapes"]["shapes"].size() == 1);
    json none = empty_document();
    caio::gltf::add_colliders(none, {point}, caio::gltf::ColliderOptions{});
    CHECK(none.count("extensionsUsed") == 0);
}

TEST_CASE("write_colliders: the mesh and its colliders as .glb, read back, and bad inputs refused") {
    iotest::TempDir dir;
    caio::MeshData mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    mesh.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    caio::ProxyData p;
    p.kind = 0;
    p.a[0] = p.a[1] = p.a[2] = 0.25;
    p.radius_a = p.radius_b = 1;
    p.placed.translation[0] = p.placed.translation[1] = p.placed.translation[2] = 0.25;
    p.placed.radius_top = p.placed.radius_bottom = 1;
    std::string err;
    const std::string path = dir.path("tet.glb");
    REQUIRE(caio::write_colliders(path, mesh, {p}, err));
    const std::string bytes = iotest::slurp(path);
    uint32_t json_length = 0;
    std::memcpy(&json_length, bytes.data() + 12, 4);
    const json doc = json::parse(bytes.substr(20, json_length));
    CHECK(doc["nodes"][0] == json{{"name", "mesh"}, {"mesh", 0}});
    CHECK(doc["accessors"][0]["count"] == 4);
    CHECK(doc["accessors"][1]["count"] == 12);
    const json& group = doc["nodes"][1];
    CHECK(group["name"] == "colliders");
    CHECK(doc["nodes"][group["children"][0].get<size_t>()]["translation"] == json{0.25, 0.25, 0.25});
    CHECK(doc["extensions"]["KHR_implicit_shapes"]["shapes"] == json{{{"type", "sphere"}, {"sphere", {{"radius", 1.0}}}}});
    REQUIRE(caio::write_colliders(dir.path("tet.gltf"), mesh, {p}, err));
    CHECK(json::parse(iotest::slurp(dir.path("tet.gltf")))["buffers"][0]["uri"].get<std::string>().rfind("data:", 0) == 0);

    CHECK_FALSE(caio::write_colliders(dir.path("tet.obj"), mesh, {p}, err));
    CHECK(err.find(".glb or .gltf") != std::string::npos);
    caio::MeshData cloud = mesh;
    cloud.triangles.clear();
    CHECK_FALSE(caio::write_colliders(dir.path("cloud.glb"), cloud, {p}, err));
    CHECK(err.find("triangle mesh") != std::string::npos);
    mesh.triangles[0] = 4;
    CHECK_FALSE(caio::write_colliders(dir.path("bad.glb"), mesh, {p}, err));
    CHECK(err.find("out of range") != std::string::npos);
    mesh.triangles[0] = 0;
    p.placed.height = NAN;
    CHECK_FALSE(caio::write_colliders(dir.path("nan.glb"), mesh, {p}, err));
    CHECK(err.find("NaN") != std::string::npos);
}
