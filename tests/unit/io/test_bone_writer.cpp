// test_bone_writer.cpp: the bone colliders' writer (bone_writer.h) read back through the glTF
// reader and the file's own JSON: a new skinned .glb from a hand-made skin (8 influences, a vertex
// with no weight, joint rest matrices that are not the inverse binds), the same file written back
// as a glTF input (its nodes kept, colliders added under the joints), and refused inputs.
#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "bone_writer.h"
#include "gltf_builder.h"
#include "io_test_util.h"
#include "mesh_io.h"

namespace {

using caio::gltf::json;

json glb_json(const std::string& path) {
    const std::string bytes = iotest::slurp(path);
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return json::parse(bytes.substr(20, length));
}

std::vector<double> column_major(const Eigen::Matrix4d& m) { return std::vector<double>(m.data(), m.data() + 16); }

// A tetrahedron skinned to a chain of 3 joints, 8 influences, vertex 3 with no weight; the
// inverse binds turn and move, the rest pose turns each joint 30 degrees more than the bind.
caio::MeshData skinned_tetrahedron() {
    caio::MeshData m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    m.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    caio::SkinData& s = m.skin;
    s.joint_names = {"root", "mid", "tip"};
    s.parents = {-1, 0, 1};
    for (int j = 0; j < 3; ++j) {
        Eigen::Affine3d bind = Eigen::Translation3d(0, 0.4 * j, 0) * Eigen::AngleAxisd(0.3 * j, Eigen::Vector3d::UnitZ());
        const Eigen::Matrix4d ibm = bind.matrix().inverse();
        const Eigen::Matrix4d rest = bind.matrix() * Eigen::Affine3d(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitX())).matrix();
        for (double v : column_major(ibm)) s.inverse_bind.push_back(v);
        for (double v : column_major(rest)) s.joint_world.push_back(v);
    }
    s.influences = 8;
    s.vertex_joints.assign(4 * 8, 0);
    s.vertex_weights.assign(4 * 8, 0.0);
    const double w[3][3] = {{1, 0, 0}, {0.25, 0.75, 0}, {0, 0.5, 0.5}};
    for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) {
            s.vertex_joints[8 * v + 7 - k] = uint32_t(k);   // the last slots: the writer keeps slot order
            s.vertex_weights[8 * v + 7 - k] = w[v][k];
        }
    return m;
}

std::vector<caio::BoneCollider> two_colliders() {
    caio::BoneCollider a, b;
    a.joint = 0;
    a.placed.kind = 0;
    a.placed.translation[0] = 0.1;
    a.placed.radius_top = a.placed.radius_bottom = 0.3;
    b.joint = 2;
    b.placed.kind = 1;
    b.placed.translation[1] = 0.2;
    const double h = std::sqrt(0.5);
    b.placed.rotation[0] = h;   // 90 degrees about x
    b.placed.rotation[3] = h;
    b.placed.radius_top = 0.1;
    b.placed.radius_bottom = 0.2;
    b.placed.height = 0.5;
    return {a, b};
}

// Each collider's node: a child of its joint's node with the placement as its local transform and
// a kinematic collider of the right shape.
void check_colliders(const json& doc, const caio::BoneCollidersWritten& w, const std::vector<caio::BoneCollider>& colliders,
                     const std::vector<int32_t>& joint_nodes) {
    const json& shapes = doc["extensions"]["KHR_implicit_shapes"]["shapes"];
    REQUIRE(w.collider_nodes.size() == colliders.size());
    for (size_t i = 0; i < colliders.size(); ++i) {
        CAPTURE(i);
        const caio::ColliderShape& c = colliders[i].placed;
        CHECK(w.joint_nodes[i] == joint_nodes[colliders[i].joint]);
        const json& joint = doc["nodes"][size_t(w.joint_nodes[i])];
        bool child = false;
        for (const json& k : joint["children"]) child = child || k == w.collider_nodes[i];
        CHECK(child);
        const json& node = doc["nodes"][size_t(w.collider_nodes[i])];
        for (int k = 0; k < 3; ++k) CHECK(node["translation"][k].get<double>() == doctest::Approx(c.translation[k]));
        const json r = node.value("rotation", json{0.0, 0.0, 0.0, 1.0});
        for (int k = 0; k < 4; ++k) CHECK(r[k].get<double>() == doctest::Approx(c.rotation[k]));
        const json& body = node["extensions"]["KHR_physics_rigid_bodies"];
        CHECK(body["motion"]["isKinematic"] == true);
        const json& shape = shapes[size_t(body["collider"]["geometry"]["shape"])];
        if (c.kind == 1) {
            CHECK(shape["type"] == "capsule");
            CHECK(shape["capsule"]["radiusTop"].get<double>() == doctest::Approx(c.radius_top));
            CHECK(shape["capsule"]["radiusBottom"].get<double>() == doctest::Approx(c.radius_bottom));
            CHECK(shape["capsule"]["height"].get<double>() == doctest::Approx(c.height));
        } else {
            CHECK(shape["type"] == "sphere");
            CHECK(shape["sphere"]["radius"].get<double>() == doctest::Approx(c.radius_top));
        }
    }
}

}  // namespace

TEST_CASE("bone writer: a new skinned glb reads back with its skin, rest pose and colliders on the joints") {
    const caio::MeshData mesh = skinned_tetrahedron();
    const auto colliders = two_colliders();
    iotest::TempDir dir;
    caio::BoneCollidersWritten w;
    std::string err;
    REQUIRE_MESSAGE(caio::write_bone_colliders(dir.path("b.glb"), "in.fbx", mesh, colliders, true, w, err), err);
    CHECK_FALSE(w.rewritten);
    CHECK_FALSE(w.vrm);
    caio::MeshData back;
    REQUIRE_MESSAGE(caio::read_mesh(dir.path("b.glb"), back, err), err);
    const caio::SkinData &s = back.skin, &given = mesh.skin;
    CHECK(s.joint_names == given.joint_names);
    CHECK(s.parents == given.parents);
    CHECK(back.positions == mesh.positions);
    for (size_t i = 0; i < 48; ++i) {
        CHECK(s.inverse_bind[i] == doctest::Approx(given.inverse_bind[i]).epsilon(1e-6));
        CHECK(s.joint_world[i] == doctest::Approx(given.joint_world[i]).epsilon(1e-6));   // not inverse(IBM)
    }
    // weights per vertex and joint; the vertex with none is bound wholly to the root
    for (size_t v = 0; v < 4; ++v) {
        double per_joint[3] = {0, 0, 0}, want[3] = {0, 0, 0};
        for (size_t k = 0; k < s.influences; ++k) per_joint[s.vertex_joints[v * s.influences + k]] += s.vertex_weights[v * s.influences + k];
        for (size_t k = 0; k < 8; ++k) want[given.vertex_joints[8 * v + k]] += given.vertex_weights[8 * v + k];
        if (v == 3) want[0] = 1;
        for (int j = 0; j < 3; ++j) CHECK(per_joint[j] == doctest::Approx(want[j]).epsilon(1e-6));
    }
    check_colliders(glb_json(dir.path("b.glb")), w, colliders, s.gltf_nodes);
}

TEST_CASE("bone writer: a glTF input is written back with its nodes and its own colliders kept") {
    const caio::MeshData mesh = skinned_tetrahedron();
    const auto colliders = two_colliders();
    iotest::TempDir dir;
    caio::BoneCollidersWritten first, second;
    std::string err;
    REQUIRE_MESSAGE(caio::write_bone_colliders(dir.path("a.glb"), "in.fbx", mesh, colliders, true, first, err), err);
    caio::MeshData input;
    REQUIRE_MESSAGE(caio::read_mesh(dir.path("a.glb"), input, err), err);
    REQUIRE(caio::rewrites_input(dir.path("a.glb"), input));
    // as a self-contained .gltf this time
    REQUIRE_MESSAGE(caio::write_bone_colliders(dir.path("b.gltf"), dir.path("a.glb"), input, {colliders[1]}, true, second, err), err);
    CHECK(second.rewritten);
    const json before = glb_json(dir.path("a.glb"));
    const json after = json::parse(iotest::slurp(dir.path("b.gltf")));
    CHECK(after["nodes"].size() == before["nodes"].size() + 1);
    for (size_t n = 0; n < before["nodes"].size(); ++n) CHECK(after["nodes"][n]["name"] == before["nodes"][n]["name"]);
    CHECK(after["skins"] == before["skins"]);
    // the first file's colliders are still there, with their shapes
    for (int n : first.collider_nodes) CHECK(after["nodes"][size_t(n)] == before["nodes"][size_t(n)]);
    const json& shapes_before = before["extensions"]["KHR_implicit_shapes"]["shapes"];
    for (size_t k = 0; k < shapes_before.size(); ++k) CHECK(after["extensions"]["KHR_implicit_shapes"]["shapes"][k] == shapes_before[k]);
    check_colliders(after, second, {colliders[1]}, input.skin.gltf_nodes);
    caio::MeshData back;
    REQUIRE_MESSAGE(caio::read_mesh(dir.path("b.gltf"), back, err), err);
    CHECK(back.skin.joint_names == mesh.skin.joint_names);
    CHECK(back.positions == mesh.positions);
}

TEST_CASE("bone writer: bad colliders, skins and paths are refused and nothing is written") {
    const caio::MeshData mesh = skinned_tetrahedron();
    iotest::TempDir dir;
    caio::BoneCollidersWritten w;
    std::string err;
    auto refused = [&](const std::string& name, const caio::MeshData& m, const std::vector<caio::BoneCollider>& c,
                       const char* what) {
        CAPTURE(what);
        err.clear();
        CHECK_FALSE(caio::write_bone_colliders(dir.path(name), "in.fbx", m, c, true, w, err));
        CHECK(err.find(what) != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir.path(name)));
    };
    refused("x.obj", mesh, two_colliders(), "ends in .glb or .gltf");
    auto c = two_colliders();
    c[0].joint = 3;
    refused("j.glb", mesh, c, "joint is out of range");
    c = two_colliders();
    c[1].placed.radius_top = NAN;
    refused("n.glb", mesh, c, "NaN or infinite");
    caio::MeshData bad = mesh;
    bad.skin.inverse_bind[5] = INFINITY;
    refused("i.glb", bad, two_colliders(), "inverse bind matrix is not finite");
    bad = mesh;
    bad.skin = caio::SkinData{};
    refused("s.glb", bad, two_colliders(), "no skin");
}
