// test_writers.cpp: unit tests of the glTF writer and the preview picture (examples/io): the .glb
// read back (its JSON chunk parsed with nlohmann-json, its buffers decoded: counts, accessor
// min/max, radii, ball nodes) and the PNG decoded with stb_image (size, background, the ball).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "gltf_writer.h"
#include "preview.h"

namespace {

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("ca_writers_" + std::to_string(getpid()) + "_" + name)).string();
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

uint32_t u32(const std::string& s, size_t at) {
    uint32_t v;
    std::memcpy(&v, s.data() + at, 4);
    return v;
}

// A tetrahedron of four balls: six edges, two faces.
caio::SkeletonData tetrahedron() {
    caio::SkeletonData s;
    s.centers = {0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0, -4};
    s.radii = {0.5, 0.25, 1.5, 0.75};
    s.edges = {0, 1, 0, 2, 0, 3, 1, 2, 1, 3, 2, 3};
    s.faces = {0, 1, 2, 0, 2, 3};
    return s;
}

// An octahedron of radius 1 about the origin.
caio::MeshData octahedron() {
    caio::MeshData m;
    m.positions = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    m.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    return m;
}

}  // namespace

TEST_CASE("write_gltf: the .glb reads back with the skeleton's counts, bounds, radii and ball nodes") {
    const caio::SkeletonData s = tetrahedron();
    const std::string path = temp_path("t.glb");
    std::string err;
    REQUIRE(caio::write_gltf(path, s, err));
    const std::string glb = slurp(path);
    std::filesystem::remove(path);
    REQUIRE(glb.size() > 28);
    CHECK(u32(glb, 0) == 0x46546C67u);  // "glTF"
    CHECK(u32(glb, 4) == 2);
    CHECK(u32(glb, 8) == glb.size());
    const uint32_t json_len = u32(glb, 12);
    CHECK(u32(glb, 16) == 0x4E4F534Au);  // "JSON"
    CHECK(json_len % 4 == 0);
    const nlohmann::json doc = nlohmann::json::parse(glb.substr(20, json_len));
    const uint32_t bin_len = u32(glb, 20 + json_len);
    CHECK(u32(glb, 24 + json_len) == 0x004E4942u);  // "BIN\0"
    CHECK(28 + json_len + bin_len == glb.size());
    CHECK(doc["buffers"][0]["byteLength"] == bin_len);
    const char* bin = glb.data() + 28 + json_len;
    CHECK(doc["asset"]["version"] == "2.0");

    nlohmann::json skeleton;
    for (const auto& m : doc["meshes"])
        if (m["name"] == "skeleton") skeleton = m;
    REQUIRE(skeleton["primitives"].size() == 2);
    const auto& lines = skeleton["primitives"][0];
    const auto& triangles = skeleton["primitives"][1];
    CHECK(lines["mode"] == 1);
    CHECK(triangles["mode"] == 4);
    auto floats = [&](int accessor) {
        const auto& a = doc["accessors"][accessor];
        const auto& v = doc["bufferViews"][a["bufferView"].get<int>()];
        CHECK(a["componentType"] == 5126);
        const size_t n = a["count"].get<size_t>() * (a["type"] == "VEC3" ? 3 : 1);
        std::vector<float> out(n);
        std::memcpy(out.data(), bin + v["byteOffset"].get<size_t>(), n * sizeof(float));
        return out;
    };
    auto indices = [&](int accessor) {
        const auto& a = doc["accessors"][accessor];
        const auto& v = doc["bufferViews"][a["bufferView"].get<int>()];
        CHECK(a["componentType"] == 5125);
        std::vector<uint32_t> out(a["count"].get<size_t>());
        std::memcpy(out.data(), bin + v["byteOffset"].get<size_t>(), out.size() * 4);
        return out;
    };
    const int pos_acc = lines["attributes"]["POSITION"], rad_acc = lines["attributes"]["_RADIUS"];
    CHECK(triangles["attributes"]["POSITION"] == pos_acc);
    const std::vector<float> pos = floats(pos_acc), rad = floats(rad_acc);
    REQUIRE(pos.size() == 12);
    REQUIRE(rad.size() == 4);
    for (size_t i = 0; i < 12; ++i) CHECK(pos[i] == doctest::Approx(s.centers[i]));
    for (size_t i = 0; i < 4; ++i) CHECK(rad[i] == doctest::Approx(s.radii[i]));
    // min/max of the centres: x in [0, 2], y in [0, 3], z in [-4, 0]; radii in [0.25, 1.5]
    CHECK(doc["accessors"][pos_acc]["min"] == nlohmann::json({0.0, 0.0, -4.0}));
    CHECK(doc["accessors"][pos_acc]["max"] == nlohmann::json({2.0, 3.0, 0.0}));
    CHECK(doc["accessors"][rad_acc]["min"][0] == 0.25);
    CHECK(doc["accessors"][rad_acc]["max"][0] == 1.5);
    CHECK(indices(lines["indices"]) == s.edges);
    CHECK(indices(triangles["indices"]) == s.faces);

    // one node per ball: the shared sphere mesh, at the centre, scaled by the radius
    const auto& children = doc["nodes"][0]["children"];
    REQUIRE(children.size() == 4);
    for (size_t i = 0; i < 4; ++i) {
        const auto& n = doc["nodes"][children[i].get<int>()];
        CHECK(n["mesh"] == 0);
        CHECK(n["scale"] == nlohmann::json({s.radii[i], s.radii[i], s.radii[i]}));
        CHECK(n["translation"] == nlohmann::json({s.centers[3 * i], s.centers[3 * i + 1], s.centers[3 * i + 2]}));
    }
    // the unit sphere's vertices lie on the unit sphere
    const std::vector<float> sphere = floats(doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]);
    REQUIRE(sphere.size() > 30);
    for (size_t i = 0; i < sphere.size(); i += 3)
        CHECK(std::sqrt(sphere[i] * sphere[i] + sphere[i + 1] * sphere[i + 1] + sphere[i + 2] * sphere[i + 2]) ==
              doctest::Approx(1.0).epsilon(1e-6));
}

TEST_CASE("write_gltf: refuses bad indices and unknown extensions, writes a skeleton of balls only") {
    caio::SkeletonData s = tetrahedron();
    std::string err;
    CHECK_FALSE(caio::write_gltf(temp_path("t.fbx"), s, err));
    CHECK(err.find(".glb or .gltf") != std::string::npos);
    s.faces.push_back(0), s.faces.push_back(1), s.faces.push_back(9);
    CHECK_FALSE(caio::write_gltf(temp_path("bad.glb"), s, err));
    CHECK(err.find("out of range") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(temp_path("bad.glb")));
    s.edges.clear();
    s.faces.clear();
    const std::string path = temp_path("balls.gltf");
    REQUIRE(caio::write_gltf(path, s, err));
    const nlohmann::json doc = nlohmann::json::parse(slurp(path));
    std::filesystem::remove(path);
    CHECK(doc["meshes"].size() == 1);  // no skeleton mesh without edges and faces
    CHECK(doc["nodes"][0]["children"].size() == 4);
    CHECK(doc["nodes"][0].count("mesh") == 0);
}

TEST_CASE("write_gltf: engine proxies are collider nodes under \"proxies\" with their parameters in extras") {
    const caio::SkeletonData s = tetrahedron();
    caio::ProxyData sphere, capsule;
    sphere.a[0] = 1, sphere.a[1] = 2, sphere.a[2] = 3, sphere.radius_a = 0.5;
    sphere.placed.translation[0] = 1, sphere.placed.translation[1] = 2, sphere.placed.translation[2] = 3;
    sphere.placed.radius_top = sphere.placed.radius_bottom = 0.5;
    capsule.kind = 1;
    capsule.a[0] = -1, capsule.radius_a = 0.25;
    capsule.b[0] = 3, capsule.b[2] = 2, capsule.radius_b = 0.75;
    capsule.placed.kind = 1;
    capsule.placed.translation[0] = 1, capsule.placed.translation[2] = 1;
    capsule.placed.rotation[2] = -0.6, capsule.placed.rotation[3] = 0.8;
    capsule.placed.radius_top = 0.75, capsule.placed.radius_bottom = 0.25, capsule.placed.height = std::sqrt(20.0);
    std::string err;
    const std::string path = temp_path("proxies.gltf");
    REQUIRE(caio::write_gltf(path, s, err, {sphere, capsule}));
    const nlohmann::json doc = nlohmann::json::parse(slurp(path));
    std::filesystem::remove(path);
    REQUIRE(doc["scenes"][0]["nodes"].size() == 2);
    const nlohmann::json& group = doc["nodes"][doc["scenes"][0]["nodes"][1].get<size_t>()];
    CHECK(group["name"] == "proxies");
    REQUIRE(group["children"].size() == 2);
    const nlohmann::json& a = doc["nodes"][group["children"][0].get<size_t>()];
    const nlohmann::json& b = doc["nodes"][group["children"][1].get<size_t>()];
    CHECK(a["extras"] == nlohmann::json{{"kind", "sphere"}, {"center", {1.0, 2.0, 3.0}}, {"radius", 0.5}});
    CHECK(a["translation"] == nlohmann::json{1.0, 2.0, 3.0});
    CHECK(a.count("scale") == 0);   // a collider's node is not scaled: the ball mesh is its child's
    const nlohmann::json& ball = doc["nodes"][a["children"][0].get<size_t>()];
    CHECK(ball["mesh"] == 0);
    CHECK(ball["scale"] == nlohmann::json{0.5, 0.5, 0.5});
    CHECK(b["extras"] == nlohmann::json{{"kind", "capsule"}, {"a", {-1.0, 0.0, 0.0}}, {"radius_a", 0.25},
                                        {"b", {3.0, 0.0, 2.0}}, {"radius_b", 0.75}});
    CHECK(b["translation"] == nlohmann::json{1.0, 0.0, 1.0});   // the segment's midpoint
    CHECK(b["rotation"] == nlohmann::json{0.0, 0.0, -0.6, 0.8});
    CHECK(b.count("mesh") == 0);
    // the colliders: KHR_implicit_shapes at the document level, referenced from the nodes
    const nlohmann::json& shapes = doc["extensions"]["KHR_implicit_shapes"]["shapes"];
    REQUIRE(shapes.size() == 2);
    CHECK(a["extensions"]["KHR_physics_rigid_bodies"] == nlohmann::json{{"collider", {{"geometry", {{"shape", 0}}}}}});
    CHECK(b["extensions"]["KHR_physics_rigid_bodies"] == nlohmann::json{{"collider", {{"geometry", {{"shape", 1}}}}}});
    CHECK(shapes[0] == nlohmann::json{{"type", "sphere"}, {"sphere", {{"radius", 0.5}}}});
    CHECK(shapes[1] == nlohmann::json{{"type", "capsule"},
                                      {"capsule", {{"height", std::sqrt(20.0)}, {"radiusTop", 0.75}, {"radiusBottom", 0.25}}}});
    // a tapered capsule has no OMI twin, so no shape gets one
    CHECK(doc["extensionsUsed"] == nlohmann::json{"KHR_implicit_shapes", "KHR_physics_rigid_bodies"});
    CHECK(a["extensions"].count("OMI_physics_body") == 0);
    capsule.radius_b = std::nan("");
    CHECK_FALSE(caio::write_gltf(path, s, err, {capsule}));
    CHECK(err.find("NaN") != std::string::npos);
    capsule.radius_b = 0.75;
    capsule.placed.rotation[0] = INFINITY;
    CHECK_FALSE(caio::write_gltf(path, s, err, {capsule}));
    CHECK(err.find("NaN or infinite") != std::string::npos);
}

TEST_CASE("automatic_view: the direction of the largest projected bounding-box area") {
    caio::MeshData m;
    m.positions = {0, 0, 0, 1, 2, 4};  // extents 1, 2, 4: face areas (8, 4, 2)
    double az = 0, el = 0;
    caio::automatic_view(m, 'y', az, el);
    CHECK(az == doctest::Approx(std::atan2(8.0, 2.0) * 180 / M_PI));
    CHECK(el == doctest::Approx(std::atan2(4.0, std::hypot(8.0, 2.0)) * 180 / M_PI));
    // brute force over directions: no direction has a larger projected area
    const double pi = M_PI, best = 8 * std::cos(el * pi / 180) * std::sin(az * pi / 180) + 4 * std::sin(el * pi / 180) +
                                   2 * std::cos(el * pi / 180) * std::cos(az * pi / 180);
    for (int a = 0; a <= 90; a += 3)
        for (int e = 0; e <= 90; e += 3) {
            const double A = a * pi / 180, E = e * pi / 180;
            CHECK(8 * std::cos(E) * std::sin(A) + 4 * std::sin(E) + 2 * std::cos(E) * std::cos(A) <= best + 1e-9);
        }
}

TEST_CASE("write_preview: a PNG of the requested size, white around the mesh, the ball drawn in its middle") {
    caio::SkeletonData s;
    s.centers = {0, 0, 0};
    s.radii = {0.5};
    caio::PreviewOptions o;
    o.width = 64;
    o.height = 48;
    o.automatic_view = false;
    o.azimuth_deg = 0;
    o.elevation_deg = 0;
    const std::string path = temp_path("p.png");
    std::string err;
    REQUIRE(caio::write_preview(path, octahedron(), s, o, err));
    int w = 0, h = 0, channels = 0;
    unsigned char* px = stbi_load(path.c_str(), &w, &h, &channels, 3);
    std::filesystem::remove(path);
    REQUIRE(px != nullptr);
    CHECK(w == 64);
    CHECK(h == 48);
    auto at = [&](int x, int y, int k) { return int(px[(y * w + x) * 3 + k]); };
    for (int k = 0; k < 3; ++k) CHECK(at(1, 1, k) == 255);  // background
    // the mesh (grey) beyond the ball: looking along z, the octahedron's tip (0.9, 0) is outside the ball
    const int cx = 32, cy = 24, tip = cx + int(0.75 * 0.92 * 48 / 2);
    CHECK(at(tip, cy, 0) < 250);
    CHECK(std::abs(at(tip, cy, 0) - at(tip, cy, 2)) < 30);
    // the ball (radius 0.5, about 11 pixels) over the mesh beside its dark centre dot: bluer than grey
    CHECK(at(cx + 5, cy + 3, 2) > at(cx + 5, cy + 3, 0) + 20);
    CHECK(at(cx, cy, 0) < 100);  // the centre dot
    stbi_image_free(px);

    o.width = 8;
    CHECK_FALSE(caio::write_preview(temp_path("small.png"), octahedron(), s, o, err));
    o.width = 64;
    CHECK_FALSE(caio::write_preview(temp_path("p.jpg"), octahedron(), s, o, err));
    CHECK(err.find(".png or .svg") != std::string::npos);
    const std::string svg = temp_path("p.svg");
    REQUIRE(caio::write_preview(svg, octahedron(), s, o, err));
    const std::string text = slurp(svg);
    std::filesystem::remove(svg);
    CHECK(text.find("width=\"64\" height=\"48\"") != std::string::npos);
    CHECK(text.find("url(#ball)") != std::string::npos);
}
